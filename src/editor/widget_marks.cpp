#include "editor/widget_marks.h"

#include <imgui.h>

#include <cstring>
#include <vector>

namespace corbel::editor::marks {

namespace {
bool on = false;
std::map<std::string, Rect> shown;
}  // namespace

void enable(bool value) { on = value; }
bool enabled() { return on; }

void beginFrame() { shown.clear(); }

void mark(const std::string& name) {
  if (!on) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  shown[name] = {a.x, a.y, b.x, b.y};
}

const std::map<std::string, Rect>& all() { return shown; }

bool combo(const char* label, int* current, const char* items, const std::string& name) {
  std::vector<const char*> list;
  for (const char* p = items; *p; p += std::strlen(p) + 1) list.push_back(p);
  const bool valid = *current >= 0 && *current < static_cast<int>(list.size());
  bool changed = false;
  if (ImGui::BeginCombo(label, valid ? list[*current] : "")) {
    for (int i = 0; i < static_cast<int>(list.size()); ++i) {
      if (ImGui::Selectable(list[i], i == *current) && i != *current) {
        *current = i;
        changed = true;
      }
      mark(name + ": " + list[i]);
      if (i == *current) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  mark(name);
  if (*current >= 0 && *current < static_cast<int>(list.size())) mark(name + " = " + list[*current]);  // what it shows
  return changed;
}

}  // namespace corbel::editor::marks
