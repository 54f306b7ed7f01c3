// The command search (F3, or Ctrl+Shift+P): a field over a list of every command in the menus,
// filtered and ranked as the user types (editor/command_search.h); Up and Down choose, Enter or
// a click runs, Esc closes.
#include "editor/app.h"

#include "editor/command_search.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

namespace corbel::editor {

namespace {

std::string menuPath(const std::string& menu) {
  std::string p;
  for (char c : menu) p += c == '/' ? std::string(" > ") : std::string(1, c);
  return p;
}

}  // namespace

void App::openCommandSearch() {
  searchOpen_ = true;
  searchText_[0] = 0;
  searchPick_ = 0;
}

void App::drawCommandSearch() {
  bool focus = false;
  if (searchOpen_) {
    ImGui::OpenPopup("Command search");
    searchOpen_ = false;
    focus = true;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float w = std::min(600.0f * uiScale(), vp->Size.x - 40);
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + (vp->Size.x - w) / 2, vp->Pos.y + ImGui::GetFrameHeight() * 3),
                          ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, 0));
  std::string chosen;
  searchShown_ = ImGui::BeginPopup("Command search");
  if (searchShown_) {
    std::vector<CommandEntry> entries;
    std::vector<const Action*> of;
    for (const Action& a : actions_.all()) {
      if (a.menu.empty() || !a.run) continue;  // the hidden aliases repeat a command of the menus
      entries.push_back({a.id, menuPath(a.menu), a.label, a.help});
      of.push_back(&a);
    }
    if (focus) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool edited = ImGui::InputTextWithHint("##query", "Search commands (type words; Enter runs, Esc closes)",
                                                 searchText_, sizeof searchText_);
    const std::vector<std::size_t> found = searchCommands(entries, searchText_);
    if (edited) searchPick_ = 0;
    if (ImGui::IsKeyPressed(GLFW_KEY_DOWN)) searchPick_ = std::min(searchPick_ + 1, int(found.size()) - 1);
    if (ImGui::IsKeyPressed(GLFW_KEY_UP)) searchPick_ = std::max(searchPick_ - 1, 0);
    searchPick_ = std::clamp(searchPick_, 0, std::max(0, int(found.size()) - 1));
    if (ImGui::IsKeyPressed(GLFW_KEY_ENTER) || ImGui::IsKeyPressed(GLFW_KEY_KP_ENTER)) {
      if (!found.empty() && actions_.isEnabled(*of[found[searchPick_]])) chosen = of[found[searchPick_]]->id;
      ImGui::CloseCurrentPopup();
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) ImGui::CloseCurrentPopup();
    const int shown = std::min<int>(int(found.size()), 14);
    for (int i = 0; i < shown; ++i) {
      const Action& a = *of[found[i]];
      const bool enabled = actions_.isEnabled(a);
      const std::string text = entries[found[i]].path + " > " + a.label;
      ImGui::PushID(i);
      ImGui::BeginDisabled(!enabled);
      if (ImGui::Selectable(text.c_str(), i == searchPick_) && enabled) {
        chosen = a.id;
        ImGui::CloseCurrentPopup();
      }
      ImGui::EndDisabled();
      if (i == searchPick_) ImGui::SetScrollHereY();
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", a.help.c_str());
      const std::string key = a.shortcut.text();
      if (!key.empty()) {
        ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(key.c_str()).x);
        ImGui::TextDisabled("%s", key.c_str());
      }
      ImGui::PopID();
    }
    if (found.size() > std::size_t(shown)) ImGui::TextDisabled("%zu more; type more words", found.size() - shown);
    if (found.empty()) ImGui::TextDisabled("No command matches");
    ImGui::EndPopup();
  }
  if (!chosen.empty())
    if (const Action* a = actions_.find(chosen)) runAction(*a);
}

}  // namespace corbel::editor
