#pragma once
// The tape measure of the 3D view (M): click a point, click another, read the distance between
// them and its run along x, y and z. A point is taken where the pointer's ray meets the scene:
// it snaps to a corner of the face under the pointer, then to an edge's midpoint, then onto an
// edge, when one lies within a few pixels; else it is the face's own point, and where the ray
// meets no face, the ground (z = 0). No GL: the view draws what this holds.
#include "core/scene.h"
#include "editor/viewport.h"

#include <functional>
#include <optional>
#include <string>

namespace corbel::editor {

struct TapePoint {
  enum class Snap { Ground, Face, Edge, Midpoint, Corner };
  Vec3 at{0.0, 0.0, 0.0};
  Snap snap = Snap::Ground;
  ObjectId object = 0;  // 0 on the ground
};

// Where the tape's end lands for `ray`: see above. `tolerance(p)` is how far (m) from the hit
// point p a corner or an edge may lie and still take the point (a few pixels at p's depth);
// `visible` filters the objects (null: all). nullopt when the ray meets neither a face nor the
// ground in front of it.
std::optional<TapePoint> tapePoint(const Scene& scene, const Ray& ray, const std::function<double(const Vec3&)>& tolerance,
                                   const std::function<bool(ObjectId)>& visible = nullptr);

// The name of a snap, for the tooltip: "corner", "midpoint", "on edge", "on face", "on ground".
const char* snapName(TapePoint::Snap s);

class TapeMeasure {
 public:
  // A click: the first sets the start, the second ends the measurement; the next begins anew.
  void click(const TapePoint& p);
  // The point under the pointer (nullopt: none), followed by the free end while measuring.
  void hover(std::optional<TapePoint> p) { hover_ = std::move(p); }
  void clear();

  bool measuring() const { return start_ && !end_; }  // the start is set, the end follows the pointer
  bool done() const { return start_ && end_; }
  const std::optional<TapePoint>& start() const { return start_; }
  // The end: fixed after the second click, else the pointer's point.
  const std::optional<TapePoint>& end() const { return end_ ? end_ : hover_; }
  const std::optional<TapePoint>& hovered() const { return hover_; }
  // Start to end (nullopt without both).
  std::optional<Vec3> span() const;
  // "4.250 m  (x 3.000, y 3.000, z 0.250)"; "" without both ends.
  std::string describe() const;
  // The axis the span runs along (0, 1, 2) when it is parallel to one within 0.01°, else -1:
  // the view draws it in that axis's colour.
  int axis() const;

 private:
  std::optional<TapePoint> start_, end_, hover_;
};

}  // namespace corbel::editor
