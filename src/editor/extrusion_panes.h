#pragma once
// The plan pane and the profile pane of a procedural extrusion (Kelly & Wonka, Sec. 3, Fig. 4–5):
// 2D views drawn with ImGui's draw lists beside the 3D preview. Every change goes through the
// editing operations of extrude/edit.h and is committed to the document's history, so it is
// undoable and the preview re-extrudes from the new spec. One class, its parts in files of
// their own: extrusion_panes.cpp (the pair, committing), plan_pane.cpp, profile_pane.cpp,
// plan_anchors.cpp (steps and features), plan_background.cpp (the tracing image),
// pane_dimensions.cpp (lengths shown and typed) and extrusion_pick.cpp (a click in the 3D view).
#include "core/document.h"
#include "core/geometry.h"
#include "editor/file_dialog.h"
#include "editor/typed_value.h"

#include <array>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>

struct ImVec2;

namespace corbel::editor {

struct PaneHost {
  const Document* doc = nullptr;
  ObjectId object = 0;
  std::string error;  // the kernel's message for the object ("" = its shell is current)
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void()> endDrag;  // closes the current merge (a drag ended)
  std::function<void(const std::string&, bool)> log;
};

class ExtrusionPanes {
 public:
  // Draws both panes in the rectangle (pos, size), plan above profile.
  void draw(const PaneHost& host, float x, float y, float w, float h);
  void reset();  // another object was selected
  // A click in the 3D view: the face of the object's shell under the ray (re-extruded, so its
  // provenance is exact) selects its plan edge and profile segment. Returns a description, or
  // "" when the ray misses.
  std::string pick(const ExtrusionSpec& spec, const Vec3& origin, const Vec3& direction);
  // Selects plan edge (loop, edge) and shows its profile, lighting `segment` (after a push/pull
  // on that edge's face: an edge given its own profile shows that copy).
  void showEdge(const ExtrusionSpec& spec, int loop, int edge, std::optional<int> segment);
  int shownProfile() const { return profile_; }  // the profile pane's profile (an index)
  const std::set<std::pair<int, int>>& selectedEdges() const { return selectedEdges_; }  // (loop, edge)
  // Where the plan pane drew each corner last frame (window pixels, loop by loop): for tests
  // that click them (the test log, editor/test_log.h).
  const std::vector<std::vector<std::array<float, 2>>>& cornersOnScreen() const { return cornersOnScreen_; }
  // Where the profile pane drew the shown profile's points last frame (window pixels).
  const std::vector<std::array<float, 2>>& profilePointsOnScreen() const { return profilePointsOnScreen_; }

 private:
  void drawPlan(const PaneHost& host, const ExtrusionSpec& spec, float x, float y, float w, float h);
  void drawProfile(const PaneHost& host, const ExtrusionSpec& spec, float x, float y, float w, float h);
  void apply(const PaneHost& host, const std::function<ExtrusionSpec(const ExtrusionSpec&)>& change,
             const std::string& label, const std::string& mergeKey = {});
  void fit(const ExtrusionSpec& spec, const PlanBackground* background, float w, float h);  // plan, forced steps, image
  // Commits the object's plan background (nullopt removes it); not a spec change.
  void setBackground(const PaneHost& host, std::optional<PlanBackground> b, const std::string& label,
                     const std::string& mergeKey = {});
  void backgroundFields(const PaneHost& host, const DocObject& object, const ExtrusionSpec& spec);
  // Loads the background's image into a texture when its path changed; false when it has none
  // or it cannot be read (logged once per path).
  bool backgroundTexture(const PaneHost& host, const PlanBackground& b);
  void stepFields(const PaneHost& host, const ExtrusionSpec& spec);
  void stepPopup(const PaneHost& host);
  void featurePopup(const PaneHost& host, const ExtrusionSpec& spec);
  void useChosenBackground(const PaneHost& host, const DocObject* object, const ExtrusionSpec& spec);
  void calibratePopup(const PaneHost& host, const DocObject* object);
  // pane_dimensions.cpp: the characters, Backspace, Esc and Enter of this frame for a typed
  // length while the pane has keys and `target` (something takes a length); the value on Enter.
  // Without a target the text is dropped.
  std::optional<double> typedLength(TypedValue& typed, bool target);

  // Plan view: world (m) ↔ pane pixels.
  double cx_ = 0, cy_ = 0, zoom_ = 20;  // centre, pixels per metre
  bool fitted_ = false;
  // Until the user zooms or pans, the plan is fitted again whenever its canvas changes size (a
  // feature's fields above it take room), so no edge goes out of sight.
  bool autoFit_ = true;
  float fittedW_ = 0, fittedH_ = 0;
  bool snap_ = true;
  double grid_ = 0.25;
  bool snapAngles_ = true;  // with snap_: edges turn to multiples of angleStep_ or to a neighbour
  int angleStep_ = 1;       // index into the pane's angle steps (5, 15, 30, 45 degrees)
  std::set<std::pair<int, int>> selectedEdges_;
  std::optional<std::pair<int, int>> dragCorner_, selectedCorner_;
  std::optional<std::pair<float, float>> boxFrom_;  // where a box selection started (pixels)
  bool drawing_ = false;
  std::vector<std::pair<double, double>> drawn_;
  // Drawing a forced step (Sec. 3.5) for this edge instead of a loop.
  std::optional<std::pair<int, int>> forcedEdge_;
  float forcedHeight_ = 0.0f;
  std::optional<int> selectedStep_;
  // A step or feature just added: selected from the next frame on, when the spec holds it.
  std::optional<int> pendingStep_, pendingFeature_;

  // Background image for tracing: the texture of the image at texturePath_ (0 = none).
  unsigned texture_ = 0;
  int textureW_ = 0, textureH_ = 0;
  std::string texturePath_, textureError_;
  FileDialog backgroundDialog_;
  std::optional<std::string> chosenBackground_;  // picked in the dialog, committed next frame
  // Calibrating the background: two clicked plan points, then their true distance.
  int calibrating_ = 0;  // points still to click (0: not calibrating)
  Vec2 calibrateA_{0, 0}, calibrateB_{0, 0};
  float calibrateDistance_ = 1.0f;
  bool calibratePopup_ = false;

  // Profile view.
  int profile_ = 0;
  double pzoom_ = 30, pw0_ = -1, pz0_ = -0.5;  // pixels per metre, lower-left corner in (w, z)
  std::optional<int> dragPoint_, selectedPoint_, pickedSegment_;
  float overhangHeight_ = 3.0f, overhangDepth_ = 0.4f;
  // "Add step" on the selected edge: a natural step at an anchor (Sec. 3.4–3.5).
  float stepFraction_ = 0.5f, stepHeight_ = 3.0f, stepWidth_ = 1.6f, stepDepth_ = 0.3f, stepCant_ = 0.4f;
  int stepShape_ = 0;  // 0 dormer, 1 bay, 2 buttress
  // "Add feature here" and the selected mesh anchor with its feature (Sec. 3.4, 3.6, Fig. 28).
  int featureKind_ = 1;  // 0 door, 1 window, 2 roof window, 3 chimney pot
  float featureFraction_ = 0.5f, featureHeight_ = 1.0f;
  float featureSize_[3] = {1.2f, 1.4f, 0.12f};
  std::optional<int> selectedFeature_, dragFeature_, dragFeatureHeight_;
  void featureFields(const PaneHost& host, const ExtrusionSpec& spec);
  std::vector<std::vector<std::array<float, 2>>> cornersOnScreen_;
  std::vector<std::array<float, 2>> profilePointsOnScreen_;
  // A length being typed (SketchUp's measurements box): in the plan pane for an edge, in the
  // profile pane for a segment.
  TypedValue typedPlan_, typedProfile_;
};

}  // namespace corbel::editor
