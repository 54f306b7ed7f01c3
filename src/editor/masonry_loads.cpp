#include "editor/masonry_loads.h"

#include "core/error.h"

#include <cmath>
#include <limits>

namespace corbel::editor {
namespace {

// Whether q, on the plane of the polygon with normal n, lies inside it: even-odd crossings in
// the projection that drops n's largest axis.
bool insidePolygon(const std::vector<Vec3>& polygon, const Vec3& n, const Vec3& q) {
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[drop])) drop = k;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec3 &a = polygon[i], &b = polygon[j];
    if ((a[v] > q[v]) != (b[v] > q[v]) && q[u] < (b[u] - a[u]) * (q[v] - a[v]) / (b[v] - a[v]) + a[u]) inside = !inside;
  }
  return inside;
}

}  // namespace

std::optional<BlockHit> firstBlockHit(const MasonryView& view, const Vec3& origin, const Vec3& direction,
                                      bool fixedToo) {
  std::optional<BlockHit> best;
  for (std::size_t b = 0; b < view.blockFaces.size(); ++b) {
    if (!fixedToo && b < view.fixed.size() && view.fixed[b]) continue;
    for (std::size_t f = 0; f < view.blockFaces[b].size(); ++f) {
      const std::vector<Vec3>& face = view.blockFaces[b][f];
      if (face.size() < 3) continue;
      const Vec3 n = newellNormal(face);
      const double along = OpenMesh::dot(n, direction);
      if (along == 0 || !std::isfinite(along)) continue;
      const double t = OpenMesh::dot(n, face[0] - origin) / along;
      if (!(t >= 0) || (best && t >= best->distance)) continue;
      const Vec3 q = origin + direction * t;
      if (!insidePolygon(face, n, q)) continue;
      best = BlockHit{int(b), int(f), q, t};
    }
  }
  return best;
}

MasonryLoad loadAt(const MasonryView& view, const BlockHit& hit, LoadKind kind, double amount) {
  if (hit.block < 0 || std::size_t(hit.block) >= view.blockNames.size()) throw Error("no block was clicked");
  if (!std::isfinite(amount)) throw Error("the load must be a finite number");
  MasonryLoad l;
  l.block = view.blockNames[std::size_t(hit.block)];
  if (kind == LoadKind::Pressure) {
    l.face = hit.face;
    l.pressure = amount;
  } else {
    l.offset = hit.point - view.blockCentres[std::size_t(hit.block)];
    l.force = Vec3(0.0, 0.0, -kGravity * amount);
  }
  return l;
}

double loadMass(const MasonryLoad& load) { return load.face >= 0 ? 0.0 : -load.force[2] / kGravity; }

}  // namespace corbel::editor
