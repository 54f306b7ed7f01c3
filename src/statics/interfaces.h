#pragma once
// Contact interfaces between blocks (Whiting et al. 2009, Sec. 2 "Adjacencies", Sec. 3.4).
#include "statics/model.h"

#include <string>
#include <vector>

namespace corbel::statics {

// A planar contact between blocks a and b. `normal` points from a into b; `t1` runs along an
// edge of the contact polygon and t2 = normal × t1. `polygon` is the contact polygon (simple,
// counter-clockwise about the normal; convex where both faces are); `points` are where the vertex forces act: the
// polygon scaled about its area centroid by (1 − kern shrink), Sec. 3.4.
struct Interface {
  int a = -1, b = -1;
  int faceA = -1, faceB = -1;  // the touching faces of a and b
  Vec3 normal{0.0}, t1{0.0}, t2{0.0};
  std::vector<Vec3> polygon;
  std::vector<Vec3> points;
  Vec3 centroid{0.0};
  double area = 0;
};

// Two blocks whose faces touch in a common plane over no area (along an edge or at a point).
struct ZeroAreaContact {
  int a = -1, b = -1;
};

struct Contacts {
  std::vector<Interface> interfaces;
  std::vector<ZeroAreaContact> zeroArea;
};

// Sutherland–Hodgman clip of `subject` by the convex counter-clockwise polygon `clip`, in a
// plane. Points within `tol` of a clip line count as inside, so identical faces clip to
// themselves; the result has no repeated points and no points on their neighbours' line
// (`simplified`), and is empty when fewer than 3 are left.
std::vector<Vec2> clipConvex(std::vector<Vec2> subject, const std::vector<Vec2>& clip, double tol);
std::vector<Vec2> simplified(std::vector<Vec2> subject, double tol);

// Whether two bounding boxes overlap or come within `tol` of each other on every axis.
bool boxesTouch(const BBox& a, const BBox& b, double tol);

// Finds every contact between coplanar, opposite faces of two blocks (at least one of them
// free) whose planes are within `tolerance`, with bounding boxes as the spatial filter. The
// contact polygon is the intersection of the two faces in the plane of a's face: a clip
// where both are convex, CGAL's exact Boolean intersection otherwise (one interface per
// connected piece, its outer boundary; slivers below `tolerance` × the blocks' size dropped). `kernShrink` in [0, 1)
// moves every force point towards the polygon centroid. Interfaces come sorted by (a, b, faceA, faceB), so the same
// model gives the same order whatever the spatial filter visits first (the parameter search relies on it).
Contacts findContacts(const Assembly& assembly, const std::vector<BlockProperties>& props, double tolerance,
                      double kernShrink);

}  // namespace corbel::statics
