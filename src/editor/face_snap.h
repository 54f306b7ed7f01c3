#pragma once
// Face snapping for moves: while objects are dragged, a face of theirs that comes within a few
// pixels of a facing face of another object is laid on it, their planes made one. Masonry
// objects placed by hand then touch exactly, and "All masonry objects together" finds their
// contacts (an arch's springing on a column's top) without a contact tolerance. SketchUp and
// Blender's face snapping do the same for the same reason. Only faces whose normal lies along
// x, y or z take part: blocks, walls, slabs and floors, which is where objects meet. No GL.
#include "core/scene.h"

#include <array>
#include <optional>
#include <vector>

namespace corbel::editor {

// A face whose outward normal is ±x, ±y or ±z.
struct AxisFace {
  int axis = 0;               // 0, 1, 2: the normal's axis
  int side = 1;               // +1: the normal points along +axis; −1: along −axis
  double plane = 0;           // the face's coordinate on that axis
  std::array<double, 2> lo{}, hi{};  // its extent on axes (axis + 1) % 3 and (axis + 2) % 3
  ObjectId object = 0;
};

// The axis faces of those objects in the Scene (placed, world coordinates). A face counts when
// its unit normal is within 1e-6 of an axis; its plane is the mean of its corners' coordinates.
std::vector<AxisFace> axisFaces(const Scene& scene, const std::vector<ObjectId>& objects);

// The faces to snap onto, sorted for range queries by plane.
class FaceSnapTargets {
 public:
  explicit FaceSnapTargets(std::vector<AxisFace> faces);
  // Faces of that axis and side whose plane lies in [lo, hi].
  template <class F>
  void within(int axis, int side, double lo, double hi, F&& visit) const;
  std::size_t size() const;

 private:
  std::array<std::vector<AxisFace>, 6> bySide_;  // index axis * 2 + (side > 0)
};

struct FaceSnap {
  Vec3 delta{0.0, 0.0, 0.0};                   // added to the move
  std::array<std::optional<ObjectId>, 3> onto;  // per axis, the object snapped onto
  bool any() const { return onto[0] || onto[1] || onto[2]; }
};

// The change to `offset` that lays a moving face on a facing one: per free axis, of the moving
// faces moved by `offset` and the target faces opposite them (normals facing each other) whose
// planes are within `tolerance` and whose extents overlap with positive area, the nearest pair.
FaceSnap snapFaces(const std::vector<AxisFace>& moving, const FaceSnapTargets& targets, const Vec3& offset,
                   const std::array<bool, 3>& freeAxes, double tolerance);

template <class F>
void FaceSnapTargets::within(int axis, int side, double lo, double hi, F&& visit) const {
  const std::vector<AxisFace>& v = bySide_[axis * 2 + (side > 0 ? 1 : 0)];
  auto it = std::lower_bound(v.begin(), v.end(), lo, [](const AxisFace& f, double x) { return f.plane < x; });
  for (; it != v.end() && it->plane <= hi; ++it) visit(*it);
}

}  // namespace corbel::editor
