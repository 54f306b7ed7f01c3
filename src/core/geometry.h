#pragma once
// Small geometry vocabulary shared by every kernel: points in meters, Z up, right-handed.
#include <OpenMesh/Core/Geometry/VectorT.hh>

#include <array>
#include <limits>
#include <vector>

namespace corbel {

using Vec3 = OpenMesh::Vec3d;
using Vec2 = OpenMesh::Vec2d;

// Axis-aligned bounding box; empty() until a point is added.
struct BBox {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  bool empty() const { return !(lo[0] <= hi[0]); }
  void add(const Vec3& p) {
    lo.minimize(p);
    hi.maximize(p);
  }
  void add(const BBox& b) {
    if (!b.empty()) {
      add(b.lo);
      add(b.hi);
    }
  }
  Vec3 center() const { return (lo + hi) * 0.5; }
  Vec3 size() const { return empty() ? Vec3(0.0) : hi - lo; }
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
};

// Newell's normal of a polygon (length = twice its area); robust for non-convex polygons.
Vec3 newellNormal(const std::vector<Vec3>& polygon);

// Triangulation of a simple planar polygon (any orientation): ear clipping, then Lawson's flips
// to the polygon's constrained Delaunay triangulation in its own plane. Returns index triples
// into `polygon`. No triangle is a sliver (a corner within 1e-7 of the polygon's size of its
// opposite side, in space) while another ear is left: a polygon planar only to rounding would
// fold there across the faces it meets. Degenerate or self-touching input still yields n-2
// triangles (the clipping falls back to the best remaining ear), so rendering never loses a face.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec3>& polygon);

}  // namespace corbel
