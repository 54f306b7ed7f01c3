#pragma once
// Where an object stands in the scene: a translation, a turn about the vertical (z) axis and a
// uniform scale, applied after its kernel built it in its own frame. A kind's own coordinates
// (box.origin, extrusion.base, plan corners, a town's local frame) stay its geometry; the
// placement moves that geometry as a whole: p ↦ translation + Rz(rotation)·(scale·p).
#include "core/geometry.h"
#include "core/mesh_data.h"

#include <optional>
#include <string>

namespace corbel {

struct Placement {
  Vec3 translation{0.0, 0.0, 0.0};  // m
  double rotation_deg = 0.0;        // about z, counter-clockwise seen from above
  double scale = 1.0;               // uniform, > 0

  bool identity() const { return *this == Placement{}; }
  // The placed position of a point of the object's own frame, and back.
  Vec3 apply(const Vec3& p) const;
  Vec3 unapply(const Vec3& p) const;
  // The same for a direction (no translation).
  Vec3 applyDirection(const Vec3& d) const;
  Vec3 unapplyDirection(const Vec3& d) const;
  bool operator==(const Placement&) const = default;
};

// cos and sin of an angle in degrees, exact at multiples of 90° (so a quarter turn moves a
// corner onto a corner without rounding).
std::pair<double, double> cosSinDegrees(double degrees);

// Every point of the soup moved by the placement (faces keep their order: a placement is a
// rotation and a positive scale, so outward stays outward).
void applyPlacement(MeshData& mesh, const Placement& placement);

// The placement's values: translation within ±1e7 m, a finite rotation, a scale in
// [1e-4, 1e4]. An error text naming the field ("scale: ...") or nullopt.
std::optional<std::string> checkPlacement(const Placement& placement);

}  // namespace corbel
