#include "core/scene_pick.h"

#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace corbel {

namespace {

// Möller and Trumbore's ray–triangle test: t of the hit, or a negative number.
double rayTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = OpenMesh::cross(d, e2);
  const double det = OpenMesh::dot(e1, p);
  if (std::abs(det) < 1e-300) return -1;
  const double inv = 1.0 / det;
  const Vec3 s = o - a;
  const double u = OpenMesh::dot(s, p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = OpenMesh::cross(s, e1);
  const double v = OpenMesh::dot(d, q) * inv;
  if (v < 0 || u + v > 1) return -1;
  return OpenMesh::dot(e2, q) * inv;
}

// Whether the ray meets the box [lo, hi] (slab test) before `tMax`.
bool rayBox(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi, double tMax) {
  double t0 = 0, t1 = tMax;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-300) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

std::optional<ScenePick> pickScene(const Scene& scene, const Vec3& origin, const Vec3& direction,
                                   const std::function<bool(ObjectId)>& visible) {
  const PolyMesh& mesh = scene.mesh();
  std::optional<ScenePick> best;
  double bestT = std::numeric_limits<double>::infinity();
  std::vector<Vec3> poly;
  for (const auto& [id, faces] : scene.facesByObject()) {
    if (visible && !visible(id)) continue;
    Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (auto f : faces)
      for (auto v : mesh.fv_range(f)) lo.minimize(mesh.point(v)), hi.maximize(mesh.point(v));
    if (faces.empty() || !rayBox(origin, direction, lo, hi, bestT)) continue;
    for (auto f : faces) {
      poly.clear();
      for (auto v : mesh.fv_range(f)) poly.push_back(mesh.point(v));
      for (const auto& tri : triangulatePolygon(poly)) {
        const double t = rayTriangle(origin, direction, poly[tri[0]], poly[tri[1]], poly[tri[2]]);
        if (t > 0 && t < bestT) {
          bestT = t;
          best = ScenePick{id, f, t};
        }
      }
    }
  }
  return best;
}

}  // namespace corbel
