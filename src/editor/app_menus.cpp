// The editor's commands as the user meets them, all read from the action registry
// (app_actions.cpp): shortcut dispatch (a kernel pane's keys first), the menu bar and F1's help.
#include "editor/app.h"

#include "editor/gestures.h"
#include "editor/menu_order.h"
#include "editor/new_objects.h"
#include "editor/shape_gallery.h"
#include "editor/widget_marks.h"
#include "extrude/edit.h"
#include "kifs/kernel.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

namespace corbel::editor {

void App::handleShortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || fileDialog_.isOpen() || searchShown_ || transform_.active() || pushPull_.active()) return;  // a transform or the search takes the keys
  for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
    if (!ImGui::IsKeyPressed(key, false)) continue;
    const Action* a = actions_.match(key, io.KeyCtrl, io.KeyShift, io.KeyAlt);
    // A key without Ctrl or Alt belongs to the kernel's pane under the pointer or with focus
    // (Delete there removes a corner, not the object).
    // Function keys (F1 help, F3 search) are no pane's.
    if (a && paneHasKeys_ && !a->shortcut.ctrl && !a->shortcut.alt && !(key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25))
      continue;
    if (a && actions_.isEnabled(*a) && a->run) {
      runAction(*a);
      break;
    }
  }
}

// Whether the window under the pointer or with focus is one of the right pane's (a kernel's
// panel), after the panels of this frame are drawn.
bool App::rightPaneHasKeys(const Rect& pane) const {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  auto inPane = [&](const ImGuiWindow* w) {
    return w && w->RootWindow && w->RootWindow->Pos.x >= pane.x - 1 && w->RootWindow->Pos.y >= pane.y - 1;
  };
  return inPane(g.HoveredWindow) || inPane(g.NavWindow);
}

void App::drawMenuBar() {
  if (!ImGui::BeginMainMenuBar()) return;
  for (const std::string& menu : menuBarOrder(actions_.all())) {
    if (ImGui::BeginMenu(menu.c_str())) {
      drawMenuItems(menu);
      ImGui::EndMenu();
    }
    marks::mark("menu: " + menu);
  }
  ImGui::EndMainMenuBar();
}

// The items of menu path `menu` ("Object/Add"), in the registry's order; an action deeper in
// the path ("Object/Add/Masonry") makes a submenu where the first of its kind would stand.
void App::drawMenuItems(const std::string& menu) {
  std::vector<std::string> submenus;
  for (const Action& a : actions_.all()) {
    if (a.menu != menu) {
      if (a.menu.size() <= menu.size() + 1 || a.menu.compare(0, menu.size() + 1, menu + "/") != 0) continue;
      const std::string rest = a.menu.substr(menu.size() + 1), sub = rest.substr(0, rest.find('/'));
      if (std::find(submenus.begin(), submenus.end(), sub) != submenus.end()) continue;
      submenus.push_back(sub);
      if (a.separatorBefore) ImGui::Separator();
      if (ImGui::BeginMenu(sub.c_str())) {
        drawMenuItems(menu + "/" + sub);
        ImGui::EndMenu();
      }
      marks::mark("menu: " + menu + "/" + sub);
      continue;
    }
    if (a.separatorBefore) ImGui::Separator();
    std::string label = a.label;
    if (a.id == "edit.undo" && history_.canUndo()) label += " " + history_.undoLabel();
    if (a.id == "edit.redo" && history_.canRedo()) label += " " + history_.redoLabel();
    const std::string shortcut = a.shortcut.text();
    if (ImGui::MenuItem(label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), a.checked && a.checked(),
                        actions_.isEnabled(a)) &&
        a.run)
      runAction(a);
    marks::mark("action: " + a.id);
    if (ImGui::IsItemHovered() && !a.help.empty()) ImGui::SetTooltip("%s", a.help.c_str());
    if (a.id == "file.open") {
      if (ImGui::BeginMenu("Open Recent", !recent_.paths().empty())) {
        for (const std::string& p : recent_.paths())
          if (ImGui::MenuItem(p.c_str())) {
            const std::string chosen = p;
            openFile(chosen);
            break;
          }
        ImGui::EndMenu();
      }
    }
  }
}

void App::drawHelp() {
  if (!showHelp_) return;
  // Most of the window, centred, so the whole list reads without scrolling a small box.
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x * 0.8f, vp->Size.y * 0.8f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Keyboard shortcuts and gestures", &showHelp_)) {
    helpFilter_.Draw("Filter (command, key or words)", ImGui::GetFontSize() * 16);
    auto shown = [&](const std::string& a, const std::string& b, const std::string& c) {
      return helpFilter_.PassFilter(a.c_str()) || helpFilter_.PassFilter(b.c_str()) || helpFilter_.PassFilter(c.c_str());
    };
    if (ImGui::BeginTable("actions", 3,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_Resizable)) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("Command");
      ImGui::TableSetupColumn("Shortcut");
      ImGui::TableSetupColumn("What it does");
      ImGui::TableHeadersRow();
      // In the menu bar's order, the commands with a key only last.
      const std::vector<std::string> menus = menuBarOrder(actions_.all());
      auto rank = [&](const Action& a) {
        const std::string top = a.menu.substr(0, a.menu.find('/'));
        return std::size_t(std::find(menus.begin(), menus.end(), top) - menus.begin());
      };
      std::vector<const Action*> listed;
      for (const Action& a : actions_.all()) listed.push_back(&a);
      std::stable_sort(listed.begin(), listed.end(),
                       [&](const Action* x, const Action* y) { return rank(*x) < rank(*y); });
      for (const Action* ap : listed) {
        const Action& a = *ap;
        std::string path = a.menu.empty() ? std::string("(key only)") : a.menu;
        for (std::size_t at; (at = path.find('/')) != std::string::npos;) path.replace(at, 1, " > ");
        path += " > " + a.label;
        if (!shown(path, a.shortcut.text(), a.help)) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(path.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.shortcut.text().c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", a.help.c_str());
      }
      // Every pane's mouse gestures (editor/gestures.h).
      for (const Gesture& g : paneGestures()) {
        if (!shown(g.pane, g.gesture, g.what)) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(g.pane);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", g.gesture);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", g.what);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace corbel::editor
