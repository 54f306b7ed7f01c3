#include "editor/face_snap.h"

#include <algorithm>
#include <cmath>

namespace corbel::editor {

std::vector<AxisFace> axisFaces(const Scene& scene, const std::vector<ObjectId>& objects) {
  std::vector<AxisFace> out;
  const PolyMesh& mesh = scene.mesh();
  for (ObjectId id : objects) {
    if (!scene.hasObject(id)) continue;
    for (PolyMesh::FaceHandle f : scene.faces(id)) {
      std::vector<Vec3> ps;
      for (auto v : mesh.fv_range(f)) ps.push_back(mesh.point(v));
      if (ps.size() < 3) continue;
      // Newell's normal: exact for a planar polygon, whatever its shape.
      Vec3 n(0, 0, 0);
      for (std::size_t i = 0; i < ps.size(); ++i) {
        const Vec3& a = ps[i];
        const Vec3& b = ps[(i + 1) % ps.size()];
        n += Vec3((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1]));
      }
      const double len = n.norm();
      if (!(len > 0)) continue;
      n /= len;
      for (int k = 0; k < 3; ++k) {
        if (std::abs(n[k]) < 1.0 - 1e-6) continue;
        AxisFace a;
        a.axis = k;
        a.side = n[k] > 0 ? 1 : -1;
        a.object = id;
        const int u = (k + 1) % 3, w = (k + 2) % 3;
        a.lo = {ps[0][u], ps[0][w]};
        a.hi = a.lo;
        double sum = 0;
        for (const Vec3& p : ps) {
          sum += p[k];
          a.lo = {std::min(a.lo[0], p[u]), std::min(a.lo[1], p[w])};
          a.hi = {std::max(a.hi[0], p[u]), std::max(a.hi[1], p[w])};
        }
        a.plane = sum / double(ps.size());
        out.push_back(a);
      }
    }
  }
  return out;
}

FaceSnapTargets::FaceSnapTargets(std::vector<AxisFace> faces) {
  for (AxisFace& f : faces) bySide_[f.axis * 2 + (f.side > 0 ? 1 : 0)].push_back(f);
  for (auto& v : bySide_) std::sort(v.begin(), v.end(), [](const AxisFace& a, const AxisFace& b) { return a.plane < b.plane; });
}

std::size_t FaceSnapTargets::size() const {
  std::size_t n = 0;
  for (const auto& v : bySide_) n += v.size();
  return n;
}

FaceSnap snapFaces(const std::vector<AxisFace>& moving, const FaceSnapTargets& targets, const Vec3& offset,
                   const std::array<bool, 3>& freeAxes, double tolerance) {
  FaceSnap out;
  if (!(tolerance > 0)) return out;
  std::array<double, 3> best{tolerance, tolerance, tolerance};
  for (const AxisFace& m : moving) {
    const int k = m.axis;
    if (!freeAxes[k]) continue;
    const int u = (k + 1) % 3, w = (k + 2) % 3;
    const double plane = m.plane + offset[k];
    const double lo0 = m.lo[0] + offset[u], hi0 = m.hi[0] + offset[u];
    const double lo1 = m.lo[1] + offset[w], hi1 = m.hi[1] + offset[w];
    // Facing: the target's normal is opposite (a top under a bottom, a side against a side).
    targets.within(k, -m.side, plane - best[k], plane + best[k], [&](const AxisFace& t) {
      const double gap = t.plane - plane;
      if (std::abs(gap) > best[k] || (out.onto[k] && std::abs(gap) == best[k])) return;
      // Overlap with positive area: faces that only share an edge or a corner do not bear.
      constexpr double kMinOverlap = 1e-9;  // m
      if (std::min(hi0, t.hi[0]) - std::max(lo0, t.lo[0]) <= kMinOverlap) return;
      if (std::min(hi1, t.hi[1]) - std::max(lo1, t.lo[1]) <= kMinOverlap) return;
      best[k] = std::abs(gap);
      out.delta[k] = gap;
      out.onto[k] = t.object;
    });
  }
  return out;
}

}  // namespace corbel::editor
