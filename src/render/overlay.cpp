#include "render/overlay.h"

#include "core/geometry.h"

#include <cmath>

namespace corbel::render {

void Overlay::placeSince(const Mark& mark, const Placement& placement) {
  if (placement.identity()) return;
  for (std::size_t i = mark.lines; i + 7 <= lines_.size(); i += 7) {
    const Vec3 p = placement.apply(Vec3(lines_[i], lines_[i + 1], lines_[i + 2]));
    for (int k = 0; k < 3; ++k) lines_[i + k] = float(p[k]);
  }
  for (std::size_t i = mark.triangles; i + 9 <= triangles_.size(); i += 9) {
    const Vec3 p = placement.apply(Vec3(triangles_[i], triangles_[i + 1], triangles_[i + 2]));
    const Vec3 n = placement.applyDirection(Vec3(triangles_[i + 3], triangles_[i + 4], triangles_[i + 5])).normalized();
    for (int k = 0; k < 3; ++k) triangles_[i + k] = float(p[k]), triangles_[i + 3 + k] = float(n[k]);
  }
}

void Overlay::clear() {
  lines_.clear();
  triangles_.clear();
}

void Overlay::line(const Vec3& a, const Vec3& b, const Rgba& c) {
  for (const Vec3* p : {&a, &b})
    lines_.insert(lines_.end(), {float((*p)[0]), float((*p)[1]), float((*p)[2]), c[0], c[1], c[2], c[3]});
}

void Overlay::arrow(const Vec3& from, const Vec3& to, const Rgba& c, double headFraction) {
  const Vec3 d = to - from;
  const double len = d.norm();
  if (!(len > 0)) return;
  const Vec3 axis = d / len;
  const double head = len * headFraction;
  const Vec3 base = to - axis * head;
  line(from, base, c);
  // Two vectors perpendicular to the axis.
  const Vec3 helper = std::abs(axis[2]) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
  const Vec3 u = OpenMesh::cross(axis, helper).normalized();
  const Vec3 v = OpenMesh::cross(axis, u);
  const double r = head * 0.35;
  const Vec3 ring[4] = {base + u * r, base + v * r, base - u * r, base - v * r};
  for (int i = 0; i < 4; ++i) {
    const Vec3& a = ring[i];
    const Vec3& b = ring[(i + 1) % 4];
    const Vec3 n = OpenMesh::cross(b - a, to - a).normalized();
    for (const Vec3* p : {&a, &b, &to})
      triangles_.insert(triangles_.end(), {float((*p)[0]), float((*p)[1]), float((*p)[2]), float(n[0]), float(n[1]),
                                           float(n[2]), c[0], c[1], c[2]});
  }
}

void Overlay::polygon(const std::vector<Vec3>& corners, const Rgba& c) {
  if (corners.size() < 3) return;
  Vec3 n = newellNormal(corners);
  if (!(n.norm() > 0)) return;
  n.normalize();
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    for (const Vec3* p : {&corners[0], &corners[i], &corners[i + 1]})
      triangles_.insert(triangles_.end(), {float((*p)[0]), float((*p)[1]), float((*p)[2]), float(n[0]), float(n[1]),
                                           float(n[2]), c[0], c[1], c[2]});
}

}  // namespace corbel::render
