// Dimensions in the plan and profile panes: labels beside the measured edges and segments, and
// the length typed for them (the numbers are editor/dimensions.h's).
#include "editor/extrusion_panes.h"

#include "editor/pane_drawing.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace corbel::editor {

namespace panes {

void dimensionLabel(ImDrawList* dl, ImVec2 a, ImVec2 b, const char* text, float side) {
  const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
  if (len < 1) return;
  // The right of a→b on screen (y down) is (−dy, dx).
  const ImVec2 n(-dy / len * side, dx / len * side);
  const ImU32 ink = IM_COL32(255, 236, 170, 255);
  for (const ImVec2& e : {a, b}) dl->AddLine(ImVec2(e.x + n.x * 4, e.y + n.y * 4), ImVec2(e.x + n.x * 12, e.y + n.y * 12), ink, 1.0f);
  const ImVec2 size = ImGui::CalcTextSize(text);
  // The label's centre 10 px beyond the edge plus half its extent across it; on the other side
  // where that leaves the pane, and kept inside it.
  const ImVec2 lo = dl->GetClipRectMin(), hi = dl->GetClipRectMax();
  const float reach = 10 + 0.5f * (std::abs(n.x) * size.x + std::abs(n.y) * size.y);
  ImVec2 c((a.x + b.x) / 2 + n.x * reach, (a.y + b.y) / 2 + n.y * reach);
  auto inside = [&](const ImVec2& q) {
    return q.x - size.x / 2 >= lo.x && q.x + size.x / 2 <= hi.x && q.y - size.y / 2 >= lo.y && q.y + size.y / 2 <= hi.y;
  };
  if (!inside(c)) c = ImVec2((a.x + b.x) / 2 - n.x * reach, (a.y + b.y) / 2 - n.y * reach);
  const ImVec2 tl(std::clamp(c.x - size.x / 2, lo.x + 3, std::max(lo.x + 3, hi.x - size.x - 3)),
                  std::clamp(c.y - size.y / 2, lo.y + 1, std::max(lo.y + 1, hi.y - size.y - 1)));
  dl->AddRectFilled(ImVec2(tl.x - 3, tl.y - 1), ImVec2(tl.x + size.x + 3, tl.y + size.y + 1), IM_COL32(20, 22, 26, 220), 3.0f);
  dl->AddText(tl, ink, text);
}

void typedBox(ImVec2 at, const std::string& text, const char* unit) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const std::string line = "Length: " + text + " " + unit + "  (Enter sets it, Esc drops it)";
  const ImVec2 size = ImGui::CalcTextSize(line.c_str());
  dl->AddRectFilled(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + size.x + 4, at.y + size.y + 3), IM_COL32(60, 52, 20, 235), 3.0f);
  dl->AddText(at, IM_COL32(255, 236, 170, 255), line.c_str());
}

}  // namespace panes

std::optional<double> ExtrusionPanes::typedLength(TypedValue& typed, bool target) {
  if (!target) {
    typed.clear();
    return std::nullopt;
  }
  if (!panes::keysHere()) return std::nullopt;
  for (const ImWchar c : ImGui::GetIO().InputQueueCharacters)
    if (c < 128) typed.type(static_cast<char>(c));
  if (panes::keyPressed(ImGuiKey_Backspace)) typed.backspace();
  if (panes::keyPressed(ImGuiKey_Escape)) typed.clear();
  if (panes::keyPressed(ImGuiKey_Enter) || panes::keyPressed(ImGuiKey_KeyPadEnter)) {
    const std::optional<double> v = typed.value();
    typed.clear();
    return v;
  }
  return std::nullopt;
}

}  // namespace corbel::editor
