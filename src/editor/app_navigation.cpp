// The 3D view's navigation aids: the axis widget in its corner and bringing a new object into
// view. The camera math is editor/camera_views.h.
#include "editor/app.h"

#include "editor/camera_views.h"
#include "editor/plan_crossings.h"
#include "render/kifs_pass.h"

#include <imgui.h>

#include <cmath>

namespace corbel::editor {

// A circle in the view's top right corner with the six axis ends drawn as seen by the camera
// (the nearer ones last); a click on an end turns the view to look from it, orthographic.
void App::drawAxisWidget() {
  const float size = 2 * (kAxisWidgetRadius + kAxisKnobRadius + 2);
  const ImVec2 centre(view_.x() + view_.width() - kAxisWidgetInset, view_.y() + kAxisWidgetInset);
  if (view_.width() < 3 * kAxisWidgetInset || view_.height() < 3 * kAxisWidgetInset) return;
  ImGui::SetNextWindowPos(ImVec2(centre.x - size / 2, centre.y - size / 2));
  ImGui::SetNextWindowSize(ImVec2(size, size));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##axes", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::InvisibleButton("axes", ImVec2(size, size));
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const auto hot = ImGui::IsItemHovered() ? axisEndAt(view_.camera, mouse.x - centre.x, mouse.y - centre.y)
                                          : std::nullopt;
  if (hot && ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    render::applyPreset(view_.camera, presetOfAxis(*hot));
    view_.camera.orthographic = true;
    frameAll();
    log(std::string("View from ") + (hot->positive ? "+" : "-") + char('X' + hot->axis));
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", hot ? "Click: look from this axis (orthographic)"
                                : "Axes: X red, Y green, Z blue; click an end to look from it");
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddCircleFilled(centre, kAxisWidgetRadius + kAxisKnobRadius, IM_COL32(255, 255, 255, ImGui::IsItemHovered() ? 28 : 12));
  std::array<AxisEnd, 6> ends = axisEnds(view_.camera);
  std::sort(ends.begin(), ends.end(), [](const AxisEnd& a, const AxisEnd& b) { return a.depth < b.depth; });
  static const ImU32 colours[3] = {IM_COL32(230, 80, 80, 255), IM_COL32(120, 200, 80, 255), IM_COL32(80, 140, 240, 255)};
  for (const AxisEnd& e : ends) {
    const ImVec2 p(centre.x + e.dx, centre.y + e.dy);
    const ImU32 c = colours[e.axis];
    const bool isHot = hot && hot->axis == e.axis && hot->positive == e.positive;
    if (e.positive) {
      dl->AddLine(centre, p, c, 2.0f);
      dl->AddCircleFilled(p, kAxisKnobRadius, isHot ? IM_COL32(255, 255, 255, 255) : c);
      const char label[2] = {char('X' + e.axis), 0};
      const ImVec2 t = ImGui::CalcTextSize(label);
      dl->AddText(ImVec2(p.x - t.x / 2, p.y - t.y / 2), IM_COL32(20, 20, 20, 255), label);
    } else {
      dl->AddCircleFilled(p, kAxisKnobRadius, isHot ? IM_COL32(255, 255, 255, 200) : (c & 0x60FFFFFF));
      dl->AddCircle(p, kAxisKnobRadius, c, 0, 1.5f);
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

BBox App::objectBounds(ObjectId id) {
  // A ray-marched KIFS building has no faces in the Scene: its bounds are the march's.
  if (scene_.hasObject(id))
    if (const BBox b = scene_.bounds(id); !b.empty()) return b;
  return render::raymarchedKifs(history_.current(), [id](ObjectId o) { return o == id; }).bounds;
}

// Checked from the next frame on: the panel the new selection opens narrows the view first.
void App::reveal(ObjectId id) {
  reveal_.push_back(id);
  revealFrom_ = frame_ + 1;
}

// Objects added by the user come into view once built: the camera frames one that is not
// wholly in view (a failed or empty build is left where it is).
void App::revealAdded() {
  if (reveal_.empty() || !live_.current() || frame_ < revealFrom_) return;
  BBox box;
  for (ObjectId id : reveal_) box.add(objectBounds(id));
  reveal_.clear();
  if (box.empty() || boxInView(view_.camera, view_.aspect(), box)) return;
  view_.frame(box);
}

}  // namespace corbel::editor

namespace corbel::editor {

// Where a visible extrusion that failed to build has crossing edges: a red cross on its base
// and a post rising from it, drawn on top so a model in front does not hide it.
void App::drawErrorMarks(render::Overlay& onTop) {
  const render::Rgba red{1.0f, 0.2f, 0.2f, 1.0f};
  for (const DocObject& o : history_.current().objects) {
    const auto* e = std::get_if<ExtrusionSpec>(&o.spec);
    if (!e || !o.visible) continue;
    const auto st = sync_.status().find(o.id);
    if (st == sync_.status().end() || st->second.error.empty()) continue;
    std::vector<std::vector<Vec2>> loops;
    for (const auto& l : e->loops) loops.push_back(l.points);
    for (const PlanCrossing& c : planCrossings(loops)) {
      const double z = e->baseZ, r = std::max(0.3, 0.015 * view_.camera.distance);
      const Vec3 p(c.at[0], c.at[1], z);
      onTop.line(p + Vec3(-r, -r, 0), p + Vec3(r, r, 0), red);
      onTop.line(p + Vec3(-r, r, 0), p + Vec3(r, -r, 0), red);
      onTop.line(p, p + Vec3(0, 0, 4 * r), red);
    }
  }
}

}  // namespace corbel::editor
