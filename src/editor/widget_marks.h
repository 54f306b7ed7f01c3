#pragma once
// Where named widgets were drawn this frame, for the test log: an xdotool test (and the
// tutorial's screenshots) click a widget by its name — "plan: add step", "menu: Object" — not by
// a guessed pixel. Nothing is recorded unless the editor runs with --test-log.
#include <array>
#include <map>
#include <string>

namespace corbel::editor::marks {

using Rect = std::array<float, 4>;  // x0, y0, x1, y1 in window pixels

void enable(bool on);
bool enabled();
// Forgets the last frame's widgets: call once a frame before anything is drawn.
void beginFrame();
// The rectangle of the last ImGui item under `name` (a later mark of the same name wins).
void mark(const std::string& name);
// Everything marked since beginFrame.
const std::map<std::string, Rect>& all();

// ImGui::Combo over zero-separated `items`, with the combo marked as `name`, and again as
// "name = item" for the item it shows, and, while open, each item as "name: item".
bool combo(const char* label, int* current, const char* items, const std::string& name);

}  // namespace corbel::editor::marks
