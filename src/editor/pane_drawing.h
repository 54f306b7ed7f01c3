#pragma once
// What the plan and profile panes share: hit distances in pixels, the profile colours, which
// pane keys go to, and where an anchor lies on the plan. Private to the panes' files.
#include "core/document.h"
#include "core/geometry.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace corbel::editor::panes {

// Keys go to the pane under the pointer or with focus (Delete there removes the selected
// corner, point, step or feature, never the object).
inline bool keysHere() { return ImGui::IsWindowFocused() || ImGui::IsWindowHovered(); }

// Edge colours by profile index (the paper's colour coding of Fig. 4).
inline ImU32 profileColor(int i) {
  static const ImU32 palette[] = {IM_COL32(230, 90, 70, 255),   IM_COL32(70, 130, 230, 255),
                                  IM_COL32(90, 190, 90, 255),   IM_COL32(220, 170, 40, 255),
                                  IM_COL32(170, 90, 210, 255),  IM_COL32(40, 190, 190, 255),
                                  IM_COL32(230, 120, 180, 255), IM_COL32(150, 150, 150, 255)};
  return palette[static_cast<std::size_t>(i) % (sizeof palette / sizeof palette[0])];
}

inline double distToSegment(ImVec2 p, ImVec2 a, ImVec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
  return std::sqrt(ex * ex + ey * ey);
}

inline double dist(ImVec2 a, ImVec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

inline bool keyPressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }

// A dimension label (pane_dimensions.cpp): `text` on a dark plate beside the segment a–b (pixels),
// on its right (side 1, as seen going from a to b) or its left (side −1), with ticks at its ends;
// on the other side, or pushed in, where it would leave the draw list's clip rectangle.
void dimensionLabel(ImDrawList* dl, ImVec2 a, ImVec2 b, const char* text, float side);
// The number being typed, in a box at `at` (a corner of the pane): "Length: 3.5 m (Enter sets
// it, Esc drops it)".
void typedBox(ImVec2 at, const std::string& text, const char* unit);

// Where an anchor lies on its wall in the plan (the plan pane draws input edges).
inline std::optional<Vec2> anchorOnPlan(const ExtrusionSpec& spec, const Anchor& a) { return anchorPoint(spec, a); }

}  // namespace corbel::editor::panes
