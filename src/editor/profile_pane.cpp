// The profile pane (Sec. 3.2, Fig. 5): one profile's points in (w, z), dragged, inserted and
// tagged; the heights of steps and features beside the plan edge; overhangs and the library.
#include "editor/extrusion_panes.h"

#include "editor/dimensions.h"
#include "editor/fields.h"
#include "editor/pane_drawing.h"
#include "editor/pane_window.h"
#include "editor/widget_marks.h"
#include "extrude/edit.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace corbel::editor {

namespace ed = extrude::edit;

using namespace panes;

void ExtrusionPanes::drawProfile(const PaneHost& host, const ExtrusionSpec& spec, float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Profile", nullptr, kPaneFlags);
  if (spec.profiles.empty()) {
    ImGui::End();
    return;
  }
  profile_ = std::clamp(profile_, 0, static_cast<int>(spec.profiles.size()) - 1);
  ImGui::SetNextItemWidth(150);
  if (ImGui::BeginCombo("##profile", spec.profiles[profile_].name.c_str())) {
    for (int i = 0; i < static_cast<int>(spec.profiles.size()); ++i) {
      ImGui::PushStyleColor(ImGuiCol_Text, profileColor(i));
      if (ImGui::Selectable(spec.profiles[i].name.c_str(), i == profile_)) {
        profile_ = i;
        selectedPoint_.reset();
        pickedSegment_.reset();
      }
      ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  if (ImGui::BeginCombo("##library", "New from library")) {
    for (const Profile& p : ed::profileLibrary()) {
      if (ImGui::Selectable(p.name.c_str())) {
        int index = 0;
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::addProfile(s, p, &index); }, "Add profile " + p.name);
        profile_ = static_cast<int>(spec.profiles.size());  // the new one, once committed
      }
      marks::mark("profile: library: " + p.name);
    }
    ImGui::EndCombo();
  }
  marks::mark("profile: library");
  ImGui::SameLine();
  if (ImGui::Button("Add overhang")) ImGui::OpenPopup("overhang");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Insert a horizontal overhang into every profile at one height (Sec. 3.3)");
  if (ImGui::BeginPopup("overhang")) {
    ImGui::InputFloat("Height (m)", &overhangHeight_, 0.1f, 1.0f, "%.2f");
    ImGui::InputFloat("Depth (m)", &overhangDepth_, 0.05f, 0.5f, "%.2f");
    if (ImGui::Button("Add to every profile")) {
      const double hh = overhangHeight_, dd = overhangDepth_;
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::addOverhang(s, hh, dd); }, "Add overhang");
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  // A profile just taken from the library is in the next frame's spec, not in this one.
  if (profile_ >= static_cast<int>(spec.profiles.size())) {
    ImGui::End();
    return;
  }
  const Profile& p = spec.profiles[profile_];
  if (selectedPoint_ && *selectedPoint_ >= static_cast<int>(p.points.size())) selectedPoint_.reset();
  if (selectedPoint_) {
    const int i = *selectedPoint_;
    const float was[2] = {float(p.points[i][0]), float(p.points[i][1])};
    float wz[2];
    ImGui::SetNextItemWidth(160);
    if (commitFloats("w, z (m)", was, wz, 2))
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::moveProfilePoint(s, profile_, i, Vec2(wz[0], wz[1])); },
          "Set profile point");
    if (i > 0) {
      ImGui::SameLine();
      const std::string was = static_cast<std::size_t>(i - 1) < p.tags.size() ? p.tags[i - 1] : "";
      ImGui::SetNextItemWidth(110);
      if (std::string t; commitText("tag below", was, t, 63)) {
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::setSegmentTag(s, profile_, i - 1, t); }, "Set tag");
      }
    }
  }

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 10.0f),
                    std::max(ImGui::GetContentRegionAvail().y, 10.0f));
  ImGui::InvisibleButton("profile-canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  // Fit the profile (and its continuation) once per profile shown.
  double wMin = 0, wMax = 1, zMax = 1;
  for (const Vec2& q : p.points) wMin = std::min(wMin, q[0]), wMax = std::max(wMax, q[0]), zMax = std::max(zMax, q[1]);
  pzoom_ = std::clamp(0.8 * std::min(size.x / (wMax - wMin + 2), size.y / (zMax + 1)), 2.0, 400.0);
  pw0_ = wMin - 1;
  pz0_ = -0.5;
  auto toScreen = [&](const Vec2& q) {
    return ImVec2(float(origin.x + (q[0] - pw0_) * pzoom_), float(origin.y + size.y - (q[1] - pz0_) * pzoom_));
  };
  auto toProfile = [&](ImVec2 s) {
    return Vec2(pw0_ + (s.x - origin.x) / pzoom_, pz0_ + (origin.y + size.y - s.y) / pzoom_);
  };
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 30, 34, 255));
  for (double gz = 0; gz <= zMax + 1; gz += 1)
    dl->AddLine(toScreen(Vec2(pw0_, gz)), toScreen(Vec2(pw0_ + size.x / pzoom_, gz)), IM_COL32(45, 48, 54, 255));
  for (double gw = std::floor(pw0_); gw <= pw0_ + size.x / pzoom_; gw += 1)
    dl->AddLine(toScreen(Vec2(gw, pz0_)), toScreen(Vec2(gw, zMax + 1)), IM_COL32(45, 48, 54, 255));
  // The plan edge (w = 0) and the ground.
  dl->AddLine(toScreen(Vec2(0, pz0_)), toScreen(Vec2(0, zMax + 1)), IM_COL32(90, 95, 105, 255), 1.5f);
  dl->AddLine(toScreen(Vec2(pw0_, 0)), toScreen(Vec2(pw0_ + size.x / pzoom_, 0)), IM_COL32(90, 95, 105, 255), 1.5f);
  dl->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(150, 150, 160, 255),
              "z up; w inward (right) from the plan edge");

  std::optional<int> hotPoint, hotSegment;
  double best = 8;
  for (int i = 0; i < static_cast<int>(p.points.size()); ++i) {
    const double d = dist(io.MousePos, toScreen(p.points[i]));
    if (d < best) best = d, hotPoint = i;
  }
  if (!hotPoint) {
    best = 6;
    for (int i = 0; i + 1 < static_cast<int>(p.points.size()); ++i) {
      const double d = distToSegment(io.MousePos, toScreen(p.points[i]), toScreen(p.points[i + 1]));
      if (d < best) best = d, hotSegment = i;
    }
  }
  const ImU32 col = profileColor(profile_);
  for (int i = 0; i + 1 < static_cast<int>(p.points.size()); ++i) {
    const ImVec2 a = toScreen(p.points[i]), b = toScreen(p.points[i + 1]);
    const bool picked = pickedSegment_ && *pickedSegment_ == i;
    if (picked) dl->AddLine(a, b, IM_COL32(255, 255, 255, 200), 8.0f);
    dl->AddLine(a, b, col, hotSegment && *hotSegment == i ? 4.0f : 2.5f);
    // Tags as small triangles beside their segment.
    if (static_cast<std::size_t>(i) < p.tags.size() && !p.tags[i].empty()) {
      const ImVec2 mid((a.x + b.x) / 2 + 8, (a.y + b.y) / 2);
      dl->AddTriangleFilled(ImVec2(mid.x, mid.y - 4), ImVec2(mid.x, mid.y + 4), ImVec2(mid.x + 7, mid.y),
                            IM_COL32(240, 200, 80, 255));
      dl->AddText(ImVec2(mid.x + 10, mid.y - 7), IM_COL32(200, 200, 200, 255), p.tags[i].c_str());
    }
  }
  // The last segment carries on upward: dotted continuation.
  if (p.points.size() >= 2) {
    const Vec2 a = p.points[p.points.size() - 2], b = p.points.back();
    const Vec2 c = b + (b - a) / std::max((b - a).norm(), 1e-9) * 1.5;
    dl->AddLine(toScreen(b), toScreen(c), (col & 0x00FFFFFF) | 0x60000000, 1.5f);
  }
  // Anchor heights of steps (Sec. 3.4), and of features (cyan, beside the plan edge: drag up
  // or down to move the anchor's height).
  for (const PlanStep& st : spec.steps)
    dl->AddCircle(toScreen(Vec2(0, st.anchor.height)), 5, IM_COL32(240, 80, 240, 255), 12, 2.0f);
  std::optional<int> hotFeature;
  auto featureMarker = [&](int k) {
    const ImVec2 q = toScreen(Vec2(0, spec.anchors[k].anchor.height));
    return ImVec2(q.x - 12, q.y);
  };
  for (int k = 0; k < static_cast<int>(spec.anchors.size()); ++k) {
    const ImVec2 q = featureMarker(k);
    if (dist(io.MousePos, q) < 7) hotFeature = k;
    const bool sel = selectedFeature_ && *selectedFeature_ == k;
    if (sel) dl->AddCircleFilled(q, 5, IM_COL32(80, 220, 240, 150), 12);
    dl->AddCircle(q, 5, IM_COL32(80, 220, 240, 255), 12, sel ? 3.0f : 2.0f);
    if (spec.anchors[k].repeat.kind == RepeatKind::Grid) {
      const ImVec2 top = featureMarker(k), last(top.x, toScreen(Vec2(0, spec.anchors[k].repeat.height)).y);
      dl->AddLine(top, last, IM_COL32(80, 220, 240, 128), 1.5f);
      dl->AddCircleFilled(last, 3, IM_COL32(80, 220, 240, 255));
    }
  }
  if (hotFeature) hotPoint.reset(), hotSegment.reset();
  profilePointsOnScreen_.clear();
  for (int i = 0; i < static_cast<int>(p.points.size()); ++i) {
    const ImVec2 q = toScreen(p.points[i]);
    profilePointsOnScreen_.push_back({q.x, q.y});
    const bool sel = selectedPoint_ && *selectedPoint_ == i;
    const float r = (hotPoint && *hotPoint == i) || sel ? 5.0f : 3.5f;
    dl->AddRectFilled(ImVec2(q.x - r, q.y - r), ImVec2(q.x + r, q.y + r),
                      sel ? IM_COL32(255, 255, 255, 255) : IM_COL32(210, 210, 210, 255));
  }
  // Dimensions: length and pitch of the picked segment, or of both segments at the selected or
  // dragged point; the segment a typed length goes to is the one below the point.
  std::optional<int> lengthSegment;
  {
    const int last = static_cast<int>(p.points.size()) - 1;
    const auto point = dragPoint_ ? dragPoint_ : selectedPoint_;
    std::set<int> measured;
    if (point && *point <= last) {
      if (*point > 0) measured.insert(*point - 1), lengthSegment = *point - 1;
      if (*point < last) measured.insert(*point);
    } else if (pickedSegment_ && *pickedSegment_ < last) {
      measured.insert(*pickedSegment_);
      lengthSegment = pickedSegment_;
    }
    for (int s : measured) {
      char text[64];
      std::snprintf(text, sizeof text, "%.2f m, %.1f\xc2\xb0", profileSegmentLength(spec, profile_, s),
                    profileSegmentPitch(spec, profile_, s));
      dimensionLabel(dl, toScreen(p.points[s]), toScreen(p.points[s + 1]), text, -1.0f);
    }
  }
  dl->PopClipRect();

  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && hotSegment) {
    const int s = *hotSegment;
    const Vec2 at = toProfile(io.MousePos);
    apply(
        host, [&](const ExtrusionSpec& sp) { return ed::insertProfilePoint(sp, profile_, s, at); },
        "Insert profile point");
    selectedPoint_ = s + 1;
  } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && hotFeature) {
    selectedFeature_ = hotFeature;
    dragFeatureHeight_ = hotFeature;
  } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    selectedPoint_ = hotPoint;
    dragPoint_ = hotPoint;
    pickedSegment_ = hotPoint ? std::nullopt : hotSegment;  // a click on a segment measures it
  }
  if (dragFeatureHeight_ && *dragFeatureHeight_ < static_cast<int>(spec.anchors.size()) &&
      ImGui::IsMouseDown(ImGuiMouseButton_Left) && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
    const int k = *dragFeatureHeight_;
    Anchor a = spec.anchors[k].anchor;
    double z = std::max(0.0, toProfile(io.MousePos)[1]);
    if (!io.KeyAlt) z = std::round(z * 20) / 20;
    if (std::abs(z - a.height) > 1e-12) {
      a.height = z;
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::moveMeshAnchor(s, k, a); }, "Move " + spec.anchors[k].name,
          "feature-height-" + std::to_string(k));
    }
  }
  if (dragFeatureHeight_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    dragFeatureHeight_.reset();
    host.endDrag();
  }
  if (dragPoint_ && ImGui::IsMouseDown(ImGuiMouseButton_Left) && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f) &&
      *dragPoint_ > 0) {
    const int i = *dragPoint_;
    Vec2 at = toProfile(io.MousePos);
    if (!io.KeyAlt) at = Vec2(std::round(at[0] * 10) / 10, std::round(at[1] * 10) / 10);
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::moveProfilePoint(s, profile_, i, at); }, "Move profile point",
        "profile-" + std::to_string(profile_) + "-" + std::to_string(i));
  }
  if (dragPoint_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    dragPoint_.reset();
    host.endDrag();
  }
  // A typed length for the measured segment (editor/dimensions.h): the points above it move
  // with its upper end. Typed during a drag it ends the drag in the drag's undo step.
  const bool typing = !typedProfile_.text().empty();
  if (const auto length = typedLength(typedProfile_, lengthSegment.has_value())) {
    const int s = *lengthSegment;
    const double l = *length;
    if (dragPoint_) {
      apply(
          host, [&](const ExtrusionSpec& sp) { return setProfileSegmentLength(sp, profile_, s, l); },
          "Move profile point", "profile-" + std::to_string(profile_) + "-" + std::to_string(*dragPoint_));
      dragPoint_.reset();
      host.endDrag();
    } else {
      apply(
          host, [&](const ExtrusionSpec& sp) { return setProfileSegmentLength(sp, profile_, s, l); },
          "Set segment length");
    }
  }
  if (lengthSegment && !typedProfile_.text().empty())
    typedBox(ImVec2(origin.x + 6, origin.y + size.y - ImGui::GetTextLineHeight() - 8), typedProfile_.text(), "m");
  if (!typing && keysHere() && selectedPoint_ && (keyPressed(ImGuiKey_Delete) || keyPressed(ImGuiKey_Backspace))) {
    const int i = *selectedPoint_;
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::deleteProfilePoint(s, profile_, i); }, "Delete profile point");
    selectedPoint_.reset();
  }
  if (hovered) {
    const Vec2 q = toProfile(io.MousePos);
    ImGui::SetTooltip("w %.2f, z %.2f m%s", q[0], q[1],
                      hotPoint     ? "\ndrag (z stays between its neighbours), Delete to remove"
                      : hotSegment ? "\nclick to measure (type a length and Enter), double-click to add a point"
                                   : "");
  }
  ImGui::End();
}

}  // namespace corbel::editor
