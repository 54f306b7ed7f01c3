// The plan and profile panes as a pair: where each goes, what a new selection forgets, and how
// an edit of the spec is committed. Each pane's drawing and gestures are in its own file.
#include "editor/extrusion_panes.h"

#include "core/error.h"
#include "extrude/edit.h"

#include <imgui.h>

#include <cmath>

namespace corbel::editor {

namespace ed = extrude::edit;

void ExtrusionPanes::draw(const PaneHost& host, float x, float y, float w, float h) {
  const DocObject* o = host.doc->find(host.object);
  if (!o) return;
  const auto* spec = std::get_if<ExtrusionSpec>(&o->spec);
  if (!spec) return;
  if (profile_ >= static_cast<int>(spec->profiles.size())) profile_ = 0;
  const float planH = std::floor(h * 0.55f);
  drawPlan(host, *spec, x, y, w, planH);
  drawProfile(host, *spec, x, y + planH, w, h - planH);
}

void ExtrusionPanes::reset() {
  fitted_ = false;
  autoFit_ = true;
  selectedEdges_.clear();
  dragCorner_.reset();
  selectedCorner_.reset();
  boxFrom_.reset();
  drawing_ = false;
  drawn_.clear();
  profile_ = 0;
  dragPoint_.reset();
  selectedPoint_.reset();
  pickedSegment_.reset();
  selectedFeature_.reset();
  dragFeature_.reset();
  dragFeatureHeight_.reset();
  forcedEdge_.reset();
  selectedStep_.reset();
  pendingStep_.reset();
  pendingFeature_.reset();
  calibrating_ = 0;
  calibratePopup_ = false;
  chosenBackground_.reset();
  typedPlan_.clear();
  typedProfile_.clear();
}

void ExtrusionPanes::apply(const PaneHost& host, const std::function<ExtrusionSpec(const ExtrusionSpec&)>& change,
                           const std::string& label, const std::string& mergeKey) {
  Document d = *host.doc;
  DocObject* o = d.find(host.object);
  if (!o) return;
  auto* spec = std::get_if<ExtrusionSpec>(&o->spec);
  if (!spec) return;
  try {
    *spec = change(*spec);
  } catch (const InputError& e) {
    host.log(label + ": " + e.what(), true);
    return;
  }
  host.commit(std::move(d), label + " (" + o->name + ")", mergeKey);
}

}  // namespace corbel::editor
