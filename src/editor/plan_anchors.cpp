// Steps and features anchored on plan edges (Sec. 3.4–3.6, Fig. 28): the popups that add
// them and the fields of the selected one (size, repeat, delete).
#include "editor/extrusion_panes.h"

#include "core/error.h"
#include "editor/fields.h"
#include "editor/widget_marks.h"
#include "extrude/edit.h"

#include <imgui.h>

#include <algorithm>

namespace corbel::editor {

namespace ed = extrude::edit;

namespace {

const FeatureKind kFeatureKinds[] = {FeatureKind::Door, FeatureKind::Window, FeatureKind::RoofWindow,
                                     FeatureKind::ChimneyPot};
const char* const kFeatureLabels = "door\0window\0roof window\0chimney pot\0";

}  // namespace

// The repeat fields of a feature or a step (Sec. 3.6): none, a row or a grid up to a last
// place; true when the user changed them. `id` keeps two sets of fields apart.
static bool repeatFields(Repeat& rep, const Anchor& anchor, const std::string& id) {
  int kind = static_cast<int>(rep.kind);
  ImGui::SetNextItemWidth(90);
  bool changed = marks::combo(("Repeat" + id).c_str(), &kind, "none\0row\0grid\0", id.empty() ? "feature: repeat" : "step: repeat");
  if (changed && rep.kind == RepeatKind::None) {
    // A new repeat runs to the far end of the edge (relative) or 4 m on (absolute).
    rep.along = anchor.absolute ? anchor.along + 4 : (anchor.along < 0.5 ? 0.9 : 0.1);
    rep.height = anchor.height + 3;
  }
  rep.kind = static_cast<RepeatKind>(kind);
  if (rep.kind == RepeatKind::None) return changed;
  const float was[2] = {float(rep.along), float(rep.spacing)};
  float v[2];
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140);
  if (commitFloats(((anchor.absolute ? "last at, spacing" : "last fraction, spacing") + id).c_str(), was, v, 2)) {
    rep.along = v[0];
    rep.spacing = v[1];
    changed = true;
  }
  if (rep.kind == RepeatKind::Grid) {
    const float was2[2] = {float(rep.height), float(rep.rowSpacing)};
    float g[2];
    ImGui::SetNextItemWidth(140);
    if (commitFloats(("last row height, row spacing" + id).c_str(), was2, g, 2)) {
      rep.height = g[0];
      rep.rowSpacing = g[1];
      changed = true;
    }
  }
  return changed;
}

// Size, repeat and deletion of the selected feature anchor; each field commits when edited.
void ExtrusionPanes::featureFields(const PaneHost& host, const ExtrusionSpec& spec) {
  if (pendingFeature_ && *pendingFeature_ < static_cast<int>(spec.anchors.size())) {
    selectedFeature_ = pendingFeature_;
    pendingFeature_.reset();
  }
  if (!selectedFeature_ || *selectedFeature_ >= static_cast<int>(spec.anchors.size())) {
    selectedFeature_.reset();
    return;
  }
  const int k = *selectedFeature_;
  const MeshAnchor& m = spec.anchors[k];
  ImGui::Separator();
  ImGui::Text("Feature \"%s\": %s", m.name.c_str(), featureName(m.feature));
  if (m.feature != FeatureKind::None) {
    const float was[3] = {float(m.size.width), float(m.size.height), float(m.size.depth)};
    float size[3];
    ImGui::SetNextItemWidth(220);
    if (commitFloats("W, H, D (m)", was, size, 3)) {
      const FeatureSize fs{size[0], size[1], size[2]};
      apply(
          host, [&](const ExtrusionSpec& s) { return ed::setFeatureSize(s, k, fs); }, "Resize " + m.name);
    }
  }
  Repeat rep = m.repeat;
  const bool changed = repeatFields(rep, m.anchor, "");
  if (changed)
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::setFeatureRepeat(s, k, rep); }, "Repeat " + m.name);
  ImGui::SameLine();
  if (ImGui::Button("Delete feature")) {
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::deleteMeshAnchor(s, k); }, "Delete " + m.name);
    selectedFeature_.reset();
  }
}

// Name, repeat and deletion of the selected step (Sec. 3.5–3.6); each field commits when edited.
void ExtrusionPanes::stepFields(const PaneHost& host, const ExtrusionSpec& spec) {
  if (pendingStep_ && *pendingStep_ < static_cast<int>(spec.steps.size())) {
    selectedStep_ = pendingStep_;
    pendingStep_.reset();
  }
  if (!selectedStep_ || *selectedStep_ >= static_cast<int>(spec.steps.size())) {
    selectedStep_.reset();
    return;
  }
  const int k = *selectedStep_;
  const PlanStep& st = spec.steps[k];
  ImGui::Separator();
  const char* shape = st.shape == StepShape::Forced ? "forced" : st.shape == StepShape::Bay ? "bay" : "rectangle";
  ImGui::Text("Step \"%s\": %s at %.2f m", st.name.c_str(), shape, st.anchor.height);
  ImGui::SameLine();
  if (ImGui::SmallButton("Delete step")) {
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::deleteStep(s, k); }, "Delete step");
    selectedStep_.reset();
    return;
  }
  Repeat rep = st.repeat;
  const bool changed = repeatFields(rep, st.anchor, "##step");
  if (rep.kind != RepeatKind::None) {
    const RepeatGrid grid = repeatGrid(spec, st.anchor, st.repeat);
    if (st.repeat.kind != RepeatKind::None) ImGui::TextDisabled("%zu x %zu steps", grid.columns, grid.rows);
  }
  if (changed)
    apply(
        host, [&](const ExtrusionSpec& s) { return ed::setStepRepeat(s, k, rep); }, "Repeat " + st.name);
}

// The "Add step here" popup: a dormer, bay window or buttress on the selected edge, its
// profiles taken from the library once.
void ExtrusionPanes::stepPopup(const PaneHost& host) {
if (ImGui::BeginPopup("step")) {
  marks::combo("Kind", &stepShape_, "dormer\0bay window\0buttress\0", "add step: kind");
  ImGui::SliderFloat("Along the edge", &stepFraction_, 0.0f, 1.0f, "%.2f");
  marks::mark("add step: along");
  ImGui::InputFloat("Height (m)", &stepHeight_, 0.1f, 1.0f, "%.2f");
  marks::mark("add step: height");
  ImGui::InputFloat("Width (m)", &stepWidth_, 0.1f, 1.0f, "%.2f");
  ImGui::InputFloat("Depth out (m)", &stepDepth_, 0.05f, 0.5f, "%.2f");
  if (stepShape_ == 1) ImGui::InputFloat("Cant (m)", &stepCant_, 0.05f, 0.5f, "%.2f");
  const bool add = ImGui::Button("Add");
  marks::mark("add step: add");
  if (add && !selectedEdges_.empty()) {
    const auto [li, ei] = *selectedEdges_.begin();
    const int shape = stepShape_;
    PlanStep st;
    st.name = shape == 0 ? "dormer" : shape == 1 ? "bay window" : "buttress";
    st.anchor = {li, ei, false, stepFraction_, shape == 0 ? stepHeight_ : 0.0};
    st.width = stepWidth_;
    st.depth = stepDepth_;
    st.cant = stepCant_;
    st.shape = shape == 1 ? StepShape::Bay : StepShape::Rectangle;
    apply(
        host,
        [&](const ExtrusionSpec& s0) {
          // The step's profiles come from the library, added once.
          ExtrusionSpec s = s0;
          auto use = [&](const std::string& name) {
            for (int i = 0; i < static_cast<int>(s.profiles.size()); ++i)
              if (s.profiles[i].name == name) return i;
            for (const Profile& p : ed::profileLibrary())
              if (p.name == name) {
                int index = 0;
                s = ed::addProfile(s, p, &index);
                return index;
              }
            throw InputError("profile", "no library profile " + name);
          };
          if (shape == 0) {
            st.frontProfile = use("dormer front");
            st.sideProfile = use("dormer side");
          } else if (shape == 1) {
            st.frontProfile = st.sideProfile = use("bay");
          } else {
            st.frontProfile = use("buttress");
            st.sideProfile = use("vertical wall");
          }
          ExtrusionSpec added = ed::addStep(s, st);
          pendingStep_ = static_cast<int>(added.steps.size()) - 1;  // selected once committed
          selectedFeature_.reset();
          return added;
        },
        "Add " + st.name);
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}
}

// The "Add feature here" popup: a door, window, roof window or chimney pot on the selected edge.
void ExtrusionPanes::featurePopup(const PaneHost& host, const ExtrusionSpec& /*spec*/) {
if (ImGui::BeginPopup("feature")) {
  if (marks::combo("Kind", &featureKind_, kFeatureLabels, "add feature: kind")) {
    const FeatureSize d = defaultFeatureSize(kFeatureKinds[featureKind_]);
    featureSize_[0] = float(d.width), featureSize_[1] = float(d.height), featureSize_[2] = float(d.depth);
  }
  ImGui::SliderFloat("Along the edge", &featureFraction_, 0.0f, 1.0f, "%.2f");
  marks::mark("add feature: along");
  ImGui::InputFloat("Height (m)", &featureHeight_, 0.1f, 1.0f, "%.2f");
  marks::mark("add feature: height");
  ImGui::InputFloat3("W, H, D (m)", featureSize_, "%.2f");
  const bool add = ImGui::Button("Add");
  marks::mark("add feature: add");
  if (add && !selectedEdges_.empty()) {
    const auto [li, ei] = *selectedEdges_.begin();
    const FeatureKind kind = kFeatureKinds[featureKind_];
    std::string label = featureName(kind);
    std::replace(label.begin(), label.end(), '_', ' ');
    const MeshAnchor m(label, {li, ei, false, featureFraction_, std::max(0.0f, featureHeight_)}, kind,
                       {featureSize_[0], featureSize_[1], featureSize_[2]});
    apply(
        host,
        [&](const ExtrusionSpec& s) {
          ExtrusionSpec added = ed::addMeshAnchor(s, m);
          pendingFeature_ = static_cast<int>(added.anchors.size()) - 1;  // selected once committed
          selectedStep_.reset();
          return added;
        },
        "Add " + label);
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}
}

}  // namespace corbel::editor
