#pragma once
// Moving and turning the selected objects in the 3D view, Blender's G and R as a state machine
// (no GL, no ImGui): the pointer drags, X/Y/Z constrains to an axis, digits typed meanwhile give
// the exact value (3.5 Enter), Ctrl snaps (0.5 m grid, 15°), a left click or Enter confirms,
// Escape or a right click puts everything back. A move lays the moving objects' faces on other
// objects' facing faces within a few pixels (face_snap.h) unless a value is typed, Ctrl snaps
// to the grid, or the face snap is switched off (Alt held). What it computes is each object's placement;
// the App commits them (one undo step per transform).
#include "core/document.h"
#include "editor/face_snap.h"
#include "editor/typed_value.h"
#include "editor/viewport.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace corbel::editor {

inline constexpr double kMoveSnap = 0.5;     // m
inline constexpr double kRotateSnap = 15.0;  // degrees
inline constexpr float kFaceSnapPixels = 10;  // how near, on screen, a face snaps onto another

class Transform {
 public:
  enum class Mode { None, Move, Rotate };
  // Free: on the ground; X, Y, Z: along an axis; XZ, YZ: on the vertical plane through the
  // pivot across y or across x (the gizmo's upright squares).
  enum class Axis { Free, X, Y, Z, XZ, YZ };

  // Starts on `objects` (their placements now) about `pivot` with the pointer's ray `ray`.
  void begin(Mode mode, const std::map<ObjectId, Placement>& objects, const Vec3& pivot, const Ray& ray);
  bool active() const { return mode_ != Mode::None; }
  Mode mode() const { return mode_; }
  Axis axis() const { return axis_; }
  const Vec3& pivot() const { return pivot_; }

  void pointer(const Ray& ray);            // the pointer moved
  void setAxis(Axis axis);                 // X, Y, Z, XZ, YZ; the same one again frees it
  void setSnap(bool snap) { snap_ = snap; }
  // The faces a move may snap: the moving objects' (placed where the move began) and the
  // others', and how near (m) a face must come.
  void setFaceSnap(std::vector<AxisFace> moving, std::shared_ptr<const FaceSnapTargets> targets, double tolerance);
  void setFaceSnapOn(bool on) { faceSnapOn_ = on; }
  // What the face snap does to the move now (nothing when it is off or finds no face).
  FaceSnap faceSnap() const;
  // A typed character of the value ('0'-'9', '.', '-'); false if it is none of those.
  bool type(char c) { return typed_.type(c); }
  void backspace() { typed_.backspace(); }
  const std::string& typed() const { return typed_.text(); }
  void end() { mode_ = Mode::None; }

  // The move (m) or turn (degrees) now: the typed value when there is one, else the pointer's.
  Vec3 offset() const;
  double angle() const;
  // Each object's placement now.
  std::map<ObjectId, Placement> placements() const;
  // One line for the status bar: "Move X 3.5 m (typed)".
  std::string describe() const;

 private:
  std::optional<Vec3> planeHit(const Ray& ray) const;
  Vec3 pointerOffset() const;  // the move before the face snap
  Mode mode_ = Mode::None;
  Axis axis_ = Axis::Free;
  bool snap_ = false;
  std::map<ObjectId, Placement> start_;
  Vec3 pivot_{0, 0, 0};
  Ray startRay_, ray_;
  Vec3 viewDir_{0, 0, -1};
  TypedValue typed_;
  std::vector<AxisFace> movingFaces_;
  std::shared_ptr<const FaceSnapTargets> targets_;
  double faceTolerance_ = 0;
  bool faceSnapOn_ = true;
};

}  // namespace corbel::editor
