// The plan pane (Sec. 3, Fig. 4): the loops with their edges coloured by profile, drawn,
// selected, dragged and snapped; steps and features on their edges; the tracing image under it.
#include "editor/extrusion_panes.h"

#include "editor/dimensions.h"
#include "editor/pane_drawing.h"
#include "editor/pane_window.h"
#include "editor/plan_crossings.h"
#include "editor/widget_marks.h"
#include "extrude/edit.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <regex>

namespace corbel::editor {

namespace ed = extrude::edit;

using namespace panes;

namespace {

// Angle steps offered for angle snapping, degrees.
const float kAngleSteps[] = {5, 15, 30, 45};
const char* const kAngleStepLabels = "5\xc2\xb0\00015\xc2\xb0\00030\xc2\xb0\00045\xc2\xb0\0";

}  // namespace

void ExtrusionPanes::fit(const ExtrusionSpec& spec, const PlanBackground* background, float w, float h) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  auto grow = [&](const Vec2& p) {
    x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]);
    x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
  };
  for (const PlanLoop& l : spec.loops)
    for (const Vec2& p : l.points) grow(p);
  // Forced steps reach out of the plan: frame them too.
  for (const PlanStep& st : spec.steps) {
    const auto at = st.shape == StepShape::Forced ? anchorOnPlan(spec, st.anchor) : std::nullopt;
    if (!at) continue;
    const Vec2 d = *anchorDirection(spec, st.anchor);
    for (const Vec2& q : st.points) grow(*at + d * q[0] + Vec2(d[1], -d[0]) * q[1]);
  }
  // And the tracing image, once it is loaded.
  if (background && texture_ && background->image == texturePath_) {
    grow(background->origin);
    grow(background->origin + Vec2(textureW_, textureH_) * background->scale);
  }
  if (x0 > x1) return;
  cx_ = (x0 + x1) / 2;
  cy_ = (y0 + y1) / 2;
  zoom_ = std::clamp(0.8 * std::min(w / std::max(x1 - x0, 1e-3), h / std::max(y1 - y0, 1e-3)), 0.5, 2000.0);
  fitted_ = true;
}

void ExtrusionPanes::drawPlan(const PaneHost& host, const ExtrusionSpec& spec, float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Plan", nullptr, kPaneFlags);
  const DocObject* object = host.doc->find(host.object);
  // Toolbar.
  if (ImGui::Button("Fit")) fitted_ = false;
  ImGui::SameLine();
  ImGui::Checkbox("Snap", &snap_);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Snap corners to a %.2f m grid (hold Alt to drag freely)", grid_);
  ImGui::SameLine();
  ImGui::Checkbox("Angles", &snapAngles_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "With Snap: new edges turn to multiples of the angle step, or parallel or perpendicular to their "
        "neighbour when that is within half a step (hold Alt to draw freely)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(52);
  ImGui::Combo("##anglestep", &angleStep_, kAngleStepLabels);
  ImGui::SameLine();
  if (ImGui::Button(drawing_ && !forcedEdge_ ? "Cancel loop" : "Draw loop")) {
    drawing_ = !(drawing_ && !forcedEdge_);
    forcedEdge_.reset();
    drawn_.clear();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Click to place corners; click the first corner or press Enter to close. Inside another loop it becomes a "
        "hole.");
  ImGui::SameLine();
  if (ImGui::Button("Background…")) ImGui::OpenPopup("background");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("An image under the plan to trace from (saved with the object; never extruded)");
  if (ImGui::BeginPopup("background")) {
    if (object) backgroundFields(host, *object, spec);
    ImGui::EndPopup();
  }
  backgroundDialog_.draw();
  useChosenBackground(host, object, spec);
  ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x));
  const std::string current =
      spec.profiles.empty() ? "" : spec.profiles[std::min<std::size_t>(profile_, spec.profiles.size() - 1)].name;
  if (ImGui::BeginCombo("##assign", selectedEdges_.empty() ? "Select edges to assign a profile" : "Assign profile…")) {
    for (int i = 0; i < static_cast<int>(spec.profiles.size()); ++i) {
      ImGui::PushStyleColor(ImGuiCol_Text, profileColor(i));
      if (ImGui::Selectable(spec.profiles[i].name.c_str(), false) && !selectedEdges_.empty()) {
        const std::vector<ed::EdgeRef> edges(selectedEdges_.begin(), selectedEdges_.end());
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::setEdgeProfile(s, edges, i); },
            "Assign profile " + spec.profiles[i].name);
        profile_ = i;
      }
      marks::mark("plan: assign profile: " + spec.profiles[i].name);
      ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }
  marks::mark("plan: assign profile");
  (void)current;
  if (selectedEdges_.size() == 1) {
    if (ImGui::Button("Add step here")) ImGui::OpenPopup("step");
    marks::mark("plan: add step here");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "A natural step anchored on the selected edge: a dormer, a bay window or a buttress (Sec. 3.5)");
  }
  stepPopup(host);

  if (selectedEdges_.size() == 1) {
    ImGui::SameLine();
    if (ImGui::Button("Add feature here")) ImGui::OpenPopup("feature");
    marks::mark("plan: add feature here");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "A door, window, roof window or chimney pot at a mesh anchor on the selected edge (Sec. 3.4, Fig. 28)");
    ImGui::SameLine();
    if (ImGui::Button("Draw forced step") && !(drawing_ && forcedEdge_)) {
      drawing_ = true;
      forcedEdge_ = *selectedEdges_.begin();
      drawn_.clear();
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Click the corners of a polygon; closing it unions it with the plan at the chosen height, anchored on "
          "the selected edge where it is nearest (a forced step, Sec. 3.5)");
  }
  featurePopup(host, spec);
  if (forcedEdge_ && drawing_) {
    ImGui::TextColored(ImVec4(1.0f, 0.86f, 0.47f, 1.0f), "Forced step on loop %d edge %d:", forcedEdge_->first,
                       forcedEdge_->second);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::InputFloat("height (m)##forced", &forcedHeight_, 0.1f, 1.0f, "%.2f");
    forcedHeight_ = std::max(0.0f, forcedHeight_);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      drawing_ = false;
      forcedEdge_.reset();
      drawn_.clear();
    }
  }
  featureFields(host, spec);
  stepFields(host, spec);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float errH = host.error.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing() * 2;
  const ImVec2 size(std::max(avail.x, 10.0f), std::max(avail.y - errH, 10.0f));
  if (object && object->background) backgroundTexture(host, *object->background);  // may ask for a fit
  const bool pressed = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                       ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (autoFit_ && !pressed && (size.x != fittedW_ || size.y != fittedH_)) fitted_ = false;  // not under a drag
  if (!fitted_) {
    fit(spec, object && object->background ? &*object->background : nullptr, size.x, size.y);
    fittedW_ = size.x, fittedH_ = size.y;
    autoFit_ = true;
  }
  ImGui::InvisibleButton(
      "plan-canvas", size,
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  const ImGuiIO& io = ImGui::GetIO();
  auto toScreen = [&](const Vec2& p) {
    return ImVec2(float(origin.x + size.x / 2 + (p[0] - cx_) * zoom_),
                  float(origin.y + size.y / 2 - (p[1] - cy_) * zoom_));
  };
  auto toWorld = [&](ImVec2 s) {
    return Vec2(cx_ + (s.x - origin.x - size.x / 2) / zoom_, cy_ - (s.y - origin.y - size.y / 2) / zoom_);
  };
  auto snapped = [&](Vec2 p) {
    if (!snap_ || io.KeyAlt) return p;
    return Vec2(std::round(p[0] / grid_) * grid_, std::round(p[1] / grid_) * grid_);
  };
  // Angle snapping (extrude/edit.h): the guides it used are drawn over the plan this frame.
  std::vector<ed::SnapGuide> guides;
  const bool angles = snap_ && snapAngles_ && !io.KeyAlt;
  const double angleStep = kAngleSteps[std::clamp(angleStep_, 0, 3)];
  // The next point of a drawn polygon: its edge from the last point snaps to the axes or to
  // the previous edge (the first edge of a forced step: to its plan edge).
  auto drawnPoint = [&](const Vec2& pointer) {
    if (!angles || drawn_.empty()) return snapped(pointer);
    const Vec2 last(drawn_.back().first, drawn_.back().second);
    std::vector<Vec2> refs;
    if (drawn_.size() >= 2)
      refs.push_back(last - Vec2(drawn_[drawn_.size() - 2].first, drawn_[drawn_.size() - 2].second));
    else if (forcedEdge_ && forcedEdge_->first < static_cast<int>(spec.loops.size()) &&
             forcedEdge_->second < static_cast<int>(spec.loops[forcedEdge_->first].points.size())) {
      const auto& pts = spec.loops[forcedEdge_->first].points;
      refs.push_back(pts[(forcedEdge_->second + 1) % pts.size()] - pts[forcedEdge_->second]);
    }
    ed::AngleSnap a = ed::snapEdgeAngle(last, pointer, angleStep, refs, grid_);
    guides.insert(guides.end(), a.guides.begin(), a.guides.end());
    return a.point;
  };
  // A corner between corners `before` and `after` of a loop (dragged, or inserted into the
  // edge before `after`): both of its edges snap, each against the edge beyond its far corner.
  auto cornerPoint = [&](int li, int before, int after, const Vec2& pointer) {
    const Vec2 p = snapped(pointer);
    const auto& pts = spec.loops[li].points;
    const int n = static_cast<int>(pts.size());
    if (!angles || n < 3) return p;
    const Vec2 prev = pts[(before + n) % n], next = pts[after % n];
    const Vec2 refPrev = prev - pts[(before - 1 + 2 * n) % n], refNext = pts[(after + 1) % n] - next;
    ed::AngleSnap a = ed::snapCornerAngles(prev, next, pointer, angleStep, {refPrev}, {refNext});
    guides.insert(guides.end(), a.guides.begin(), a.guides.end());
    return a.guides.empty() ? p : a.point;
  };

  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 30, 34, 255));
  // The tracing image under everything, its lower-left corner at its origin.
  if (object && object->background && backgroundTexture(host, *object->background)) {
    const PlanBackground& b = *object->background;
    const ImVec2 tl = toScreen(Vec2(b.origin[0], b.origin[1] + textureH_ * b.scale));
    const ImVec2 br = toScreen(Vec2(b.origin[0] + textureW_ * b.scale, b.origin[1]));
    const int alpha = std::clamp(static_cast<int>(std::lround(b.opacity * 255)), 0, 255);
    dl->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)), tl, br, ImVec2(0, 0),
                 ImVec2(1, 1), IM_COL32(255, 255, 255, alpha));
  }
  // Grid: 1 m lines, 5 m lines stronger; coarser when zoomed out; see-through over an image.
  const ImU32 seeThrough = object && object->background && texture_ ? 0x70FFFFFF : 0xFFFFFFFF;
  const double step = zoom_ < 4 ? 10 : 1;
  const Vec2 lo = toWorld(ImVec2(origin.x, origin.y + size.y)), hi = toWorld(ImVec2(origin.x + size.x, origin.y));
  for (double gx = std::floor(lo[0] / step) * step; gx <= hi[0]; gx += step) {
    const bool major = std::fmod(std::abs(gx), 5 * step) < 1e-9;
    const ImVec2 a = toScreen(Vec2(gx, lo[1])), b = toScreen(Vec2(gx, hi[1]));
    dl->AddLine(a, b, (major ? IM_COL32(70, 74, 82, 255) : IM_COL32(45, 48, 54, 255)) & seeThrough);
  }
  for (double gy = std::floor(lo[1] / step) * step; gy <= hi[1]; gy += step) {
    const bool major = std::fmod(std::abs(gy), 5 * step) < 1e-9;
    const ImVec2 a = toScreen(Vec2(lo[0], gy)), b = toScreen(Vec2(hi[0], gy));
    dl->AddLine(a, b, (major ? IM_COL32(70, 74, 82, 255) : IM_COL32(45, 48, 54, 255)) & seeThrough);
  }
  // The kernel's complaint, if it names a point: "loops[i].points[j]".
  std::optional<std::pair<int, int>> faulty;
  std::smatch m;
  static const std::regex where(R"(loops\[(\d+)\]\.points\[(\d+)\])");
  if (std::regex_search(host.error, m, where)) faulty = std::make_pair(std::stoi(m[1]), std::stoi(m[2]));

  // Hit testing.
  const ImVec2 mouse = io.MousePos;
  std::optional<std::pair<int, int>> hotCorner, hotEdge;
  std::optional<int> hotFeature, hotStep;
  for (int k = 0; k < static_cast<int>(spec.anchors.size()); ++k)
    if (auto at = anchorOnPlan(spec, spec.anchors[k].anchor); at && dist(mouse, toScreen(*at)) < 7) hotFeature = k;
  if (!hotFeature)
    for (int k = 0; k < static_cast<int>(spec.steps.size()); ++k)
      if (auto at = anchorOnPlan(spec, spec.steps[k].anchor); at && dist(mouse, toScreen(*at)) < 7) hotStep = k;
  double best = hotFeature || hotStep ? 0 : 8;
  for (int li = 0; li < static_cast<int>(spec.loops.size()); ++li)
    for (int i = 0; i < static_cast<int>(spec.loops[li].points.size()); ++i) {
      const double d = dist(mouse, toScreen(spec.loops[li].points[i]));
      if (d < best) best = d, hotCorner = std::make_pair(li, i);
    }
  if (!hotCorner && !hotFeature && !hotStep) {
    best = 6;
    for (int li = 0; li < static_cast<int>(spec.loops.size()); ++li) {
      const auto& pts = spec.loops[li].points;
      for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
        const double d = distToSegment(mouse, toScreen(pts[i]), toScreen(pts[(i + 1) % pts.size()]));
        if (d < best) best = d, hotEdge = std::make_pair(li, i);
      }
    }
  }

  // Edges, coloured by profile; selected ones wide; the faulty one red and dashed-thick.
  for (int li = 0; li < static_cast<int>(spec.loops.size()); ++li) {
    const auto& l = spec.loops[li];
    for (int i = 0; i < static_cast<int>(l.points.size()); ++i) {
      const ImVec2 a = toScreen(l.points[i]), b = toScreen(l.points[(i + 1) % l.points.size()]);
      const bool sel = selectedEdges_.count({li, i}) > 0;
      const bool hot = hotEdge && *hotEdge == std::make_pair(li, i);
      dl->AddLine(a, b, profileColor(l.profile[i]), sel ? 5.0f : hot ? 3.5f : 2.0f);
      if (sel) dl->AddLine(a, b, IM_COL32(255, 255, 255, 160), 1.0f);
      // Direction tick at the middle: which side is inside.
      const ImVec2 mid((a.x + b.x) / 2, (a.y + b.y) / 2);
      const float dx = b.x - a.x, dy = b.y - a.y, len = std::max(1e-3f, std::sqrt(dx * dx + dy * dy));
      dl->AddLine(mid, ImVec2(mid.x + dy / len * 6, mid.y - dx / len * 6), profileColor(l.profile[i]), 1.5f);
    }
    if (li == 0) cornersOnScreen_.clear();
    cornersOnScreen_.emplace_back();
    for (int i = 0; i < static_cast<int>(l.points.size()); ++i) {
      const ImVec2 p = toScreen(l.points[i]);
      cornersOnScreen_.back().push_back({p.x, p.y});
      const bool isFaulty = faulty && faulty->first == li && faulty->second == i;
      const bool sel = selectedCorner_ && *selectedCorner_ == std::make_pair(li, i);
      const bool hot = hotCorner && *hotCorner == std::make_pair(li, i);
      const float r = hot || sel ? 5.0f : 3.5f;
      dl->AddRectFilled(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r),
                        isFaulty ? IM_COL32(255, 60, 60, 255)
                        : sel    ? IM_COL32(255, 255, 255, 255)
                                 : IM_COL32(210, 210, 210, 255));
      if (isFaulty) dl->AddCircle(p, 11, IM_COL32(255, 60, 60, 255), 20, 2.5f);
    }
  }
  // Where edges cross or touch (editor/plan_crossings.h): a red ring with a cross, so the
  // artist sees where the plan the kernel refuses goes wrong.
  {
    std::vector<std::vector<Vec2>> loops;
    for (const auto& l : spec.loops) loops.push_back(l.points);
    for (const PlanCrossing& c : planCrossings(loops)) {
      const ImVec2 p = toScreen(c.at);
      dl->AddCircle(p, 9, IM_COL32(255, 60, 60, 255), 20, 2.5f);
      dl->AddLine(ImVec2(p.x - 5, p.y - 5), ImVec2(p.x + 5, p.y + 5), IM_COL32(255, 60, 60, 255), 2.0f);
      dl->AddLine(ImVec2(p.x - 5, p.y + 5), ImVec2(p.x + 5, p.y - 5), IM_COL32(255, 60, 60, 255), 2.0f);
      if (dist(mouse, p) < 10)
        ImGui::SetTooltip("Edges %d and %d%s cross here: the plan cannot be built until they are apart", c.edgeA,
                          c.edgeB, c.loopA == c.loopB ? "" : " of two loops");
    }
  }
  // Anchors of steps: circles on their input edge (Fig. 4 j–n); a forced step's polygon as it
  // lies against its input edge; a repeat's elements as dots on a line to its last.
  for (int k = 0; k < static_cast<int>(spec.steps.size()); ++k) {
    const PlanStep& st = spec.steps[k];
    const auto at = anchorOnPlan(spec, st.anchor);
    if (!at) continue;
    const ImU32 col = IM_COL32(240, 80, 240, 255);
    if (st.shape == StepShape::Forced && st.points.size() >= 3) {
      const Vec2 d = *anchorDirection(spec, st.anchor);
      const Vec2 out(d[1], -d[0]);
      std::vector<ImVec2> poly;
      for (const Vec2& q : st.points) poly.push_back(toScreen(*at + d * q[0] + out * q[1]));
      dl->AddPolyline(poly.data(), static_cast<int>(poly.size()), (col & 0x00FFFFFF) | 0xB0000000, ImDrawFlags_Closed,
                      1.5f);
    }
    if (st.repeat.kind != RepeatKind::None) {
      const std::vector<Anchor> all = repeatAnchors(spec, st.anchor, st.repeat);
      if (auto last = anchorOnPlan(spec, all.back()))
        dl->AddLine(toScreen(*at), toScreen(*last), (col & 0x00FFFFFF) | 0x80000000, 1.5f);
      for (std::size_t i = 1; i < all.size() && i < 2000; ++i)
        if (auto q = anchorOnPlan(spec, all[i])) dl->AddCircleFilled(toScreen(*q), 3, col);
    }
    const bool sel = selectedStep_ && *selectedStep_ == k;
    if (sel || (hotStep && *hotStep == k)) dl->AddCircleFilled(toScreen(*at), 6, (col & 0x00FFFFFF) | 0x90000000, 16);
    dl->AddCircle(toScreen(*at), 6, col, 16, sel ? 3.0f : 2.0f);
  }
  // Mesh anchors (features): cyan circles; a repeat's elements as dots on a line to its last.
  for (int k = 0; k < static_cast<int>(spec.anchors.size()); ++k) {
    const MeshAnchor& m = spec.anchors[k];
    const auto at = anchorOnPlan(spec, m.anchor);
    if (!at) continue;
    const ImU32 col = IM_COL32(80, 220, 240, 255);
    if (m.repeat.kind != RepeatKind::None) {
      const std::vector<Anchor> all = repeatAnchors(spec, m.anchor, m.repeat);
      if (auto last = anchorOnPlan(spec, all.back()))
        dl->AddLine(toScreen(*at), toScreen(*last), (col & 0x00FFFFFF) | 0x80000000, 1.5f);
      for (std::size_t i = 1; i < all.size() && i < 2000; ++i)
        if (auto q = anchorOnPlan(spec, all[i])) dl->AddCircleFilled(toScreen(*q), 3, col);
    }
    const bool sel = selectedFeature_ && *selectedFeature_ == k;
    if (sel || (hotFeature && *hotFeature == k))
      dl->AddCircleFilled(toScreen(*at), 6, (col & 0x00FFFFFF) | 0x90000000, 16);
    dl->AddCircle(toScreen(*at), 6, col, 16, sel ? 3.0f : 2.0f);
  }
  // A loop (or a forced step's polygon) being drawn; its next point as it would be placed.
  std::optional<Vec2> nextDrawn;
  if (drawing_ && hovered) nextDrawn = drawnPoint(toWorld(mouse));
  if (drawing_) {
    const ImU32 col = forcedEdge_ ? IM_COL32(240, 120, 240, 255) : IM_COL32(255, 220, 120, 255);
    for (std::size_t i = 0; i < drawn_.size(); ++i) {
      const ImVec2 p = toScreen(Vec2(drawn_[i].first, drawn_[i].second));
      dl->AddCircleFilled(p, 4, col);
      if (i + 1 < drawn_.size())
        dl->AddLine(p, toScreen(Vec2(drawn_[i + 1].first, drawn_[i + 1].second)), col, 2.0f);
      else if (nextDrawn)
        dl->AddLine(p, toScreen(*nextDrawn), col, 2.0f);
    }
    if (nextDrawn) dl->AddCircle(toScreen(*nextDrawn), 4, col, 12, 1.5f);
  }
  // Calibration: the points clicked so far.
  if (calibrating_ == 1 || calibratePopup_) {
    const ImU32 col = IM_COL32(120, 255, 160, 255);
    dl->AddCircle(toScreen(calibrateA_), 5, col, 12, 2.0f);
    const Vec2 b = calibratePopup_ ? calibrateB_ : toWorld(mouse);
    dl->AddLine(toScreen(calibrateA_), toScreen(b), col, 1.5f);
    dl->AddCircle(toScreen(b), 5, col, 12, 2.0f);
  }
  // Dimensions: the length of each selected edge and of both edges at the selected or dragged
  // corner, outside the edge.
  {
    const auto corner = dragCorner_ ? dragCorner_ : selectedCorner_;
    std::set<std::pair<int, int>> measured = selectedEdges_;
    if (corner && corner->first < static_cast<int>(spec.loops.size()) &&
        corner->second < static_cast<int>(spec.loops[corner->first].points.size())) {
      const int n = static_cast<int>(spec.loops[corner->first].points.size());
      measured = {{corner->first, (corner->second + n - 1) % n}, {corner->first, corner->second}};
    }
    for (const auto& [li, ei] : measured) {
      if (li >= static_cast<int>(spec.loops.size()) || ei >= static_cast<int>(spec.loops[li].points.size())) continue;
      const auto& pts = spec.loops[li].points;
      char text[64];
      std::snprintf(text, sizeof text, "%.2f m", planEdgeLength(spec, li, ei));
      dimensionLabel(dl, toScreen(pts[ei]), toScreen(pts[(ei + 1) % pts.size()]), text, 1.0f);
    }
  }
  dl->PopClipRect();

  // Input.
  std::optional<std::pair<int, int>> lengthEdge;  // the edge a typed length goes to
  if (hovered) {
    if (io.MouseWheel != 0) {
      const Vec2 before = toWorld(mouse);
      zoom_ = std::clamp(zoom_ * std::pow(1.15, io.MouseWheel), 0.5, 2000.0);
      const Vec2 after = toWorld(mouse);
      cx_ += before[0] - after[0];
      cy_ += before[1] - after[1];
      autoFit_ = false;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
      cx_ -= io.MouseDelta.x / zoom_;
      cy_ += io.MouseDelta.y / zoom_;
      autoFit_ = false;
    }
  }
  if (calibrating_ > 0) {
    // Two free clicks (no snapping: they mark the image, not the plan).
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      if (calibrating_ == 2)
        calibrateA_ = toWorld(mouse);
      else
        calibrateB_ = toWorld(mouse);
      if (--calibrating_ == 0) {
        calibratePopup_ = true;
        calibrateDistance_ = float((calibrateB_ - calibrateA_).norm());
        ImGui::OpenPopup("calibrate");
      }
    } else if (keyPressed(ImGuiKey_Escape)) {
      calibrating_ = 0;
    }
  } else if (drawing_) {
    auto finishLoop = [&] {
      std::vector<Vec2> pts;
      for (auto [px, py] : drawn_) pts.emplace_back(px, py);
      if (forcedEdge_) {
        const auto [li, ei] = *forcedEdge_;
        const double height = forcedHeight_;
        const int front = profile_;
        const int index = static_cast<int>(spec.steps.size());
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::addForcedStep(s, li, ei, pts, height, front); },
            "Add forced step");
        pendingStep_ = index;  // the new one, once committed
      } else {
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::addLoop(s, pts, profile_); }, "Draw loop");
      }
      drawing_ = false;
      forcedEdge_.reset();
      drawn_.clear();
    };
    const bool enter = drawn_.size() >= 3 && keyPressed(ImGuiKey_Enter);
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      const bool closes = drawn_.size() >= 3 && dist(mouse, toScreen(Vec2(drawn_[0].first, drawn_[0].second))) < 8;
      const Vec2 p = nextDrawn ? *nextDrawn : snapped(toWorld(mouse));
      if (closes)
        finishLoop();
      else
        drawn_.emplace_back(p[0], p[1]);
    } else if (enter) {
      finishLoop();
    } else if (keyPressed(ImGuiKey_Escape)) {
      drawing_ = false;
      forcedEdge_.reset();
      drawn_.clear();
    }
  } else {
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && hotEdge) {
      const auto [li, ei] = *hotEdge;
      const Vec2 p = cornerPoint(li, ei, ei + 1, toWorld(mouse));
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::insertCorner(s, li, ei, p); }, "Insert corner");
      selectedCorner_ = std::make_pair(li, ei + 1);
    } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      if (hotFeature) {
        selectedFeature_ = hotFeature;
        dragFeature_ = hotFeature;
        selectedCorner_.reset();
        selectedStep_.reset();
      } else if (hotStep) {
        selectedStep_ = hotStep;
        selectedFeature_.reset();
        selectedCorner_.reset();
      } else if (hotCorner) {
        dragCorner_ = hotCorner;
        selectedCorner_ = hotCorner;
      } else if (hotEdge) {
        if (!io.KeyShift) selectedEdges_.clear();
        if (!selectedEdges_.erase(*hotEdge)) selectedEdges_.insert(*hotEdge);
        const auto& l = spec.loops[hotEdge->first];
        profile_ = l.profile[hotEdge->second];
        selectedCorner_.reset();
      } else {
        if (!io.KeyShift) selectedEdges_.clear();
        selectedCorner_.reset();
        boxFrom_ = std::make_pair(mouse.x, mouse.y);  // a drag from empty space selects by box
      }
    }
    // Box selection: every edge with both ends inside the box (Shift adds to the selection).
    if (boxFrom_) {
      const ImVec2 a(boxFrom_->first, boxFrom_->second);
      const ImVec2 lo(std::min(a.x, mouse.x), std::min(a.y, mouse.y)),
          hi(std::max(a.x, mouse.x), std::max(a.y, mouse.y));
      auto inBox = [&](const Vec2& p) {
        const ImVec2 q = toScreen(p);
        return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
      };
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        ImGui::GetWindowDrawList()->AddRect(lo, hi, IM_COL32(255, 255, 255, 160));
      } else {
        if (hi.x - lo.x > 3 || hi.y - lo.y > 3)
          for (int li = 0; li < static_cast<int>(spec.loops.size()); ++li)
            for (int i = 0; i < static_cast<int>(spec.loops[li].points.size()); ++i)
              if (inBox(spec.loops[li].points[i]) &&
                  inBox(spec.loops[li].points[(i + 1) % spec.loops[li].points.size()]))
                selectedEdges_.insert({li, i});
        boxFrom_.reset();
      }
    }
    if (dragCorner_ && ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
        ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
      const auto [li, ci] = *dragCorner_;
      const bool exists =
          li < static_cast<int>(spec.loops.size()) && ci < static_cast<int>(spec.loops[li].points.size());
      const Vec2 p = exists ? cornerPoint(li, ci - 1, ci + 1, toWorld(mouse)) : toWorld(mouse);
      if (exists && (spec.loops[li].points[ci] - p).norm() > 1e-12)
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::moveCorner(s, li, ci, p); }, "Move corner",
            "plan-corner-" + std::to_string(li) + "-" + std::to_string(ci));
    }
    if (dragCorner_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      dragCorner_.reset();
      host.endDrag();
    }
    // Dragging a feature's marker slides its anchor along its input edge: one undo step.
    if (dragFeature_ && *dragFeature_ < static_cast<int>(spec.anchors.size()) &&
        ImGui::IsMouseDown(ImGuiMouseButton_Left) && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 1.0f)) {
      const int k = *dragFeature_;
      Anchor a = spec.anchors[k].anchor;
      // The point of its wall under the pointer, in metres from the wall's start (on the grid
      // unless Alt is held).
      const WallRun run = wallRun(spec, a.loop, a.edge);
      double metres = nearestOnWall(spec, run, toWorld(mouse)).along;
      if (!io.KeyAlt) metres = std::round(metres / grid_) * grid_;
      const double along = a.absolute ? metres : std::clamp(metres / std::max(run.length, 1e-9), 0.0, 1.0);
      if (std::abs(along - a.along) > 1e-12) {
        a.along = along;
        apply(
            host, [&](const ExtrusionSpec& s) { return ed::moveMeshAnchor(s, k, a); }, "Move " + spec.anchors[k].name,
            "feature-anchor-" + std::to_string(k));
      }
    }
    if (dragFeature_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      dragFeature_.reset();
      host.endDrag();
    }
    // A typed length (editor/dimensions.h): with a corner dragged or selected, for the edge
    // arriving at it (the corner moves along where the edge points now); with one edge
    // selected, for that edge (its end corner moves). Enter sets it; typed during a drag it ends
    // the drag in the drag's undo step. While a number is being typed, Backspace edits it.
    const bool typing = !typedPlan_.text().empty();
    {
      const auto corner = dragCorner_ ? dragCorner_ : selectedCorner_;
      if (corner && corner->first < static_cast<int>(spec.loops.size()) &&
          corner->second < static_cast<int>(spec.loops[corner->first].points.size())) {
        const int n = static_cast<int>(spec.loops[corner->first].points.size());
        lengthEdge = std::make_pair(corner->first, (corner->second + n - 1) % n);
      } else if (!corner && selectedEdges_.size() == 1 && !selectedFeature_ && !selectedStep_) {
        lengthEdge = *selectedEdges_.begin();
      }
      if (const auto length = typedLength(typedPlan_, lengthEdge.has_value())) {
        const auto [li, ei] = *lengthEdge;
        const double l = *length;
        if (dragCorner_) {
          apply(
              host, [&](const ExtrusionSpec& s) { return setPlanEdgeLength(s, li, ei, l); }, "Move corner",
              "plan-corner-" + std::to_string(dragCorner_->first) + "-" + std::to_string(dragCorner_->second));
          dragCorner_.reset();
          host.endDrag();
        } else {
          apply(
              host, [&](const ExtrusionSpec& s) { return setPlanEdgeLength(s, li, ei, l); }, "Set edge length");
        }
      }
    }
    if (!typing && keysHere() && !selectedCorner_ && !selectedFeature_ && selectedStep_ &&
        (keyPressed(ImGuiKey_Delete) || keyPressed(ImGuiKey_Backspace))) {
      const int k = *selectedStep_;
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::deleteStep(s, k); }, "Delete step");
      selectedStep_.reset();
    }
    if (!typing && keysHere() && !selectedCorner_ && selectedFeature_ &&
        (keyPressed(ImGuiKey_Delete) || keyPressed(ImGuiKey_Backspace))) {
      const int k = *selectedFeature_;
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::deleteMeshAnchor(s, k); }, "Delete feature");
      selectedFeature_.reset();
    }
    if (!typing && keysHere() && selectedCorner_ &&
        (keyPressed(ImGuiKey_Delete) || keyPressed(ImGuiKey_Backspace))) {
      const auto [li, ci] = *selectedCorner_;
      std::vector<std::string> notes;  // what went with the corner's wall (undo brings it back)
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::deleteCorner(s, li, ci, &notes); }, "Delete corner");
      for (const std::string& n : notes) host.log(n + " (Undo restores it)", false);
      selectedCorner_.reset();
    }
  }
  // Guides of this frame's angle snapping: the snapped edges' lines across the pane.
  if (!guides.empty()) {
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    const double reach = (size.x + size.y) / zoom_;
    for (const ed::SnapGuide& g : guides) {
      const ImU32 col = g.kind == ed::SnapKind::Axis ? IM_COL32(120, 200, 255, 150) : IM_COL32(120, 255, 160, 170);
      dl->AddLine(toScreen(g.from - g.direction * reach), toScreen(g.from + g.direction * reach), col, 1.0f);
    }
    dl->PopClipRect();
  }
  calibratePopup(host, object);
  if (lengthEdge && !typedPlan_.text().empty())
    typedBox(ImVec2(origin.x + 6, origin.y + 5), typedPlan_.text(), "m");
  if (hovered) {
    const Vec2 p = toWorld(mouse);
    ImGui::SetTooltip("%.2f, %.2f m%s%s", p[0], p[1],
                      calibrating_ ? "\ncalibrating: click a point of the image whose distance to another you know"
                      : drawing_
                          ? "\nclick to place a corner; click the first one or press Enter to close, Esc to cancel"
                      : hotFeature ? "\na feature's anchor: drag along its edge, click to edit"
                      : hotStep    ? "\na step's anchor: click to edit its repeat, Delete to remove"
                      : hotCorner  ? "\ndrag to move, Delete to remove"
                      : hotEdge    ? "\nclick to select (Shift adds), double-click to add a corner"
                                   : "",
                      lengthEdge && !drawing_ && !calibrating_ ? "\ntype a length and Enter: the measured edge takes it"
                                                              : "");
  }
  if (!host.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
    ImGui::TextWrapped("%s (the last good shell stays in the preview)", host.error.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

}  // namespace corbel::editor
