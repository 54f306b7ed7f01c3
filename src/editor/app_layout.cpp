// The window's layout as the user shapes it: the splitters beside the side panels (drag to
// resize, double-click to hide or show), the toolbar over the 3D view, and the UI scale; all
// kept in the user's settings (editor/user_settings.h). The geometry is editor/layout.h.
#include "editor/app.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace corbel::editor {

void App::loadSettings() {
  settingsPath_ = (options_.stateDir.empty() ? defaultStateDir() : options_.stateDir) + "/settings.json";
  std::string problem;
  userSettings_ = loadUserSettings(settingsPath_, &problem);
  if (!problem.empty()) log(problem, true);
  float sx = 1, sy = 1;
  glfwGetWindowContentScale(window_, &sx, &sy);
  monitorScale_ = std::clamp(std::isfinite(sx) && sx > 0 ? sx : 1.0f, kMinUiScale, kMaxUiScale);
}

void App::saveSettings() {
  try {
    saveUserSettings(userSettings_, settingsPath_);
  } catch (const std::exception& e) {
    log(std::string("Settings not saved: ") + e.what(), true);
  }
}

float App::uiScale() const { return userSettings_.uiScale.value_or(monitorScale_); }

PanelSizes App::panelSizes() const {
  PanelSizes p = userSettings_.panels;
  p.scale = uiScale();
  return p;
}

void App::setUiScale(std::optional<float> scale) {
  if (scale) scale = std::clamp(std::round(*scale * 20.0f) / 20.0f, kMinUiScale, kMaxUiScale);
  userSettings_.uiScale = scale;
  saveSettings();
  log("UI scale " + std::to_string(int(std::lround(uiScale() * 100))) + " %" + (scale ? "" : " (the monitor's)"));
}

// Called before ImGui's frame begins: the font is loaded again at the scale's size (crisp,
// not stretched) and the style's sizes scaled from ImGui's own.
void App::applyUiScale() {
  const float scale = uiScale();
  if (scale == appliedScale_) return;
  static const ImGuiStyle base = [] {
    ImGuiStyle s = ImGui::GetStyle();
    s.WindowRounding = 0.0f;
    return s;
  }();
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  // DejaVu Sans (fonts-dejavu-core) has the glyphs the panels use: Latin-1 (degree, ², ×),
  // Greek (α, θ, μ), dashes and ellipsis, super- and subscripts (f_n⁻), arrows and the math
  // operators (≤, ≥, √, ∞); ImGui's built-in font is ASCII only, and a glyph outside these
  // ranges shows as "?".
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070,
                                   0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0x25A0, 0x25FF, 0};
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  bool loaded = false;
  if (FILE* f = std::fopen(font, "rb")) {
    std::fclose(f);
    loaded = io.Fonts->AddFontFromFileTTF(font, std::round(15.0f * scale), nullptr, ranges) != nullptr;
  }
  if (!loaded) {
    ImFontConfig config;
    config.SizePixels = std::round(13.0f * scale);
    io.Fonts->AddFontDefault(&config);
  }
  if (appliedScale_ != 0) {  // the first frame's texture is made by the backend itself
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  ImGui::GetStyle() = base;
  ImGui::GetStyle().ScaleAllSizes(scale);
  appliedScale_ = scale;
}

void App::togglePanel(bool left) {
  bool& shown = left ? userSettings_.panels.leftShown : userSettings_.panels.rightShown;
  shown = !shown;
  saveSettings();
}

// A splitter: a strip between a side panel and the view. Dragging it resizes the panel (a
// hidden one opens at its last width first); a double-click hides or shows it.
void App::drawSplitters(const Layout& l) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  auto splitter = [&](const char* id, const Rect& r, bool left) {
    if (r.w <= 0 || r.h <= 0) return;
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + r.x, vp->Pos.y + r.y));
    ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::InvisibleButton("##split", ImVec2(r.w, r.h));
    const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
    PanelSizes& p = userSettings_.panels;
    bool& shown = left ? p.leftShown : p.rightShown;
    float& width = left ? p.left : p.right;
    if (hot) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    // The drag is measured from where the press was, so a press and moves that arrive in one
    // frame resize by the whole way, not by a frame's delta.
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActivated()) splitterFrom_ = width;
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
      togglePanel(left);
    } else if (ImGui::IsItemActive() && io.MousePos.x != io.MouseClickedPos[0].x) {
      shown = true;
      const float w = draggedWidth(splitterFrom_, io.MousePos.x - io.MouseClickedPos[0].x, left, vp->Size.x, panelSizes());
      splitterMoved_ = splitterMoved_ || w != width;
      width = w;
    }
    if (ImGui::IsItemDeactivated() && splitterMoved_) {
      splitterMoved_ = false;
      saveSettings();
    }
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
      ImGui::SetTooltip("Drag to resize the %s panel; double-click to %s it", left ? "left" : "right",
                        shown ? "hide" : "show");
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a(vp->Pos.x + r.x, vp->Pos.y + r.y), b(a.x + r.w, a.y + r.h);
    dl->AddRectFilled(a, b, hot ? IM_COL32(90, 130, 200, 255) : IM_COL32(48, 50, 56, 255));
    // Three dots in the middle say it can be grabbed.
    for (int k = -1; k <= 1; ++k)
      dl->AddCircleFilled(ImVec2((a.x + b.x) / 2, (a.y + b.y) / 2 + k * 6 * uiScale()), 1.5f * uiScale(),
                          IM_COL32(160, 164, 172, 255));
    ImGui::End();
    ImGui::PopStyleVar(2);
  };
  splitter("##left splitter", l.leftSplitter, true);
  splitter("##right splitter", l.rightSplitter, false);
}

// The toolbar above the 3D view: the commands used most, each a button with its action's help
// and shortcut as a tooltip, and an Add menu with every kind of object.
void App::drawToolbar(const Layout& l) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + l.toolbar.x, vp->Pos.y + l.toolbar.y));
  ImGui::SetNextWindowSize(ImVec2(l.toolbar.w, l.toolbar.h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4 * uiScale(), 3 * uiScale()));
  ImGui::Begin("##toolbar", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  // The entries in order: an action's id and its button's text; "|" a gap; "add" the Add menu.
  // What does not fit the view's width goes, in order, into a ">>" menu at the end.
  struct Entry {
    const char* id;
    const char* text;
  };
  static constexpr Entry kEntries[] = {
      {"command.search", "Search"}, {"|", ""}, {"edit.undo", "Undo"}, {"edit.redo", "Redo"}, {"|", ""},
      {"add", "Add"}, {"|", ""}, {"view.frame", "Frame All"}, {"view.orthographic", "Ortho"}, {"view.top", "Top"},
      {"view.front", "Front"}, {"view.right", "Right"}, {"view.perspective", "Angled"}, {"|", ""},
      {"view.wireframe", "Wire"}, {"view.shadows", "Shadows"}, {"|", ""}, {"tool.push_pull", "Push/Pull"}, {"tool.measure", "Measure"}};
  const ImGuiStyle& style = ImGui::GetStyle();
  auto widthOf = [&](const Entry& e) {
    return std::string_view(e.id) == "|" ? ImGui::CalcTextSize("|").x : ImGui::CalcTextSize(e.text).x + 2 * style.FramePadding.x;
  };
  const float more = ImGui::CalcTextSize(">>").x + 2 * style.FramePadding.x + style.ItemSpacing.x;
  const float right = ImGui::GetWindowContentRegionMax().x;
  float total = 0;
  for (const Entry& e : kEntries) total += widthOf(e) + style.ItemSpacing.x;
  const bool allFit = ImGui::GetCursorPosX() + total - style.ItemSpacing.x <= right;
  std::vector<const Entry*> hidden;
  bool first = true;
  float x = ImGui::GetCursorPosX();
  auto tooltip = [&](const Action& a) {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    const std::string key = a.shortcut.text();
    ImGui::SetTooltip("%s%s%s%s\n%s", a.label.c_str(), key.empty() ? "" : " (", key.c_str(), key.empty() ? "" : ")",
                      a.help.c_str());
  };
  for (const Entry& e : kEntries) {
    const std::string_view id = e.id;
    if (!hidden.empty() || (!allFit && x + widthOf(e) > right - more)) {
      if (id != "|") hidden.push_back(&e);
      continue;
    }
    if (!first) ImGui::SameLine();
    first = false;
    if (id == "|") {
      ImGui::TextDisabled("|");
    } else if (id == "add") {
      if (ImGui::Button("Add")) ImGui::OpenPopup("##add");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Add an object of any kind (Object > Add)");
      if (ImGui::BeginPopup("##add")) {
        drawMenuItems("Object/Add");
        ImGui::EndPopup();
      }
    } else if (const Action* a = actions_.find(e.id)) {
      const bool on = a->checked && a->checked();
      if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      ImGui::BeginDisabled(!actions_.isEnabled(*a));
      if (ImGui::Button(e.text)) runAction(*a);
      ImGui::EndDisabled();
      if (on) ImGui::PopStyleColor();
      tooltip(*a);
    }
    x = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + style.ItemSpacing.x;
  }
  if (!hidden.empty()) {
    if (!first) ImGui::SameLine();
    if (ImGui::Button(">>")) ImGui::OpenPopup("##toolbar more");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The toolbar's commands that do not fit");
    if (ImGui::BeginPopup("##toolbar more")) {
      for (const Entry* e : hidden) {
        if (std::string_view(e->id) == "add") {
          if (ImGui::BeginMenu("Add")) {
            drawMenuItems("Object/Add");
            ImGui::EndMenu();
          }
        } else if (const Action* a = actions_.find(e->id)) {
          const std::string key = a->shortcut.text();
          if (ImGui::MenuItem(e->text, key.empty() ? nullptr : key.c_str(), a->checked && a->checked(),
                              actions_.isEnabled(*a)))
            runAction(*a);
          tooltip(*a);
        }
      }
      ImGui::EndPopup();
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace corbel::editor
