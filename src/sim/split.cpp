#include "sim/split.h"

#include "core/error.h"
#include "sim/mass_properties.h"

#include <algorithm>
#include <cmath>

namespace corbel::sim {
namespace {

// Collects a part's vertices, merging points closer than `tolerance`.
struct PartBuilder {
  statics::Block block;
  double tolerance = 0;
  int index(const Vec3& p) {
    for (std::size_t i = 0; i < block.vertices.size(); ++i)
      if ((block.vertices[i] - p).norm() <= tolerance) return int(i);
    block.vertices.push_back(p);
    return int(block.vertices.size()) - 1;
  }
  void face(const std::vector<Vec3>& loop) {
    std::vector<int> f;
    for (const Vec3& p : loop) {
      const int i = index(p);
      if (f.empty() || (f.back() != i && f.front() != i)) f.push_back(i);
    }
    if (f.size() >= 3) block.faces.push_back(std::move(f));
  }
};

// The part of a convex polygon where side(x) ≤ 0 (Sutherland–Hodgman against one plane).
std::vector<Vec3> clip(const std::vector<Vec3>& polygon, const Vec3& point, const Vec3& normal, double sign,
                       std::vector<Vec3>& onPlane) {
  std::vector<Vec3> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % n];
    const double da = sign * dot(a - point, normal), db = sign * dot(b - point, normal);
    if (da <= 0) out.push_back(a);
    if (da == 0) onPlane.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const Vec3 x = a + (b - a) * (da / (da - db));
      out.push_back(x);
      onPlane.push_back(x);
    }
  }
  return out;
}

statics::Block part(const statics::Block& block, const Vec3& point, const Vec3& normal, double sign, double tolerance,
                    const char* suffix) {
  PartBuilder b;
  b.tolerance = tolerance;
  b.block.name = block.name + suffix;
  b.block.density = block.density;
  b.block.fixed = block.fixed;
  std::vector<Vec3> cut;
  for (const auto& f : block.faces) {
    std::vector<Vec3> loop;
    for (int i : f) loop.push_back(block.vertices[i]);
    b.face(clip(loop, point, normal, sign, cut));
  }
  // The cut face: the points on the plane in angular order, counter-clockwise seen from outside,
  // where outside is along sign·normal.
  Vec3 centre(0.0);
  for (const Vec3& p : cut) centre += p;
  if (cut.empty()) return b.block;
  centre /= double(cut.size());
  const Vec3 out = normal * sign;
  Vec3 u = cut[0] - centre;
  for (const Vec3& p : cut)
    if ((p - centre).norm() > u.norm()) u = p - centre;
  u.normalize();
  const Vec3 v = cross(out, u);
  std::sort(cut.begin(), cut.end(), [&](const Vec3& p, const Vec3& q) {
    return std::atan2(dot(p - centre, v), dot(p - centre, u)) < std::atan2(dot(q - centre, v), dot(q - centre, u));
  });
  b.face(cut);
  return b.block;
}

}  // namespace

std::array<statics::Block, 2> splitBlock(const statics::Block& block, const Vec3& point, const Vec3& normal) {
  if (!(normal.norm() > 0)) throw Error("break: the cutting plane of block \"" + block.name + "\" has no normal");
  const Vec3 n = normal / normal.norm();
  BBox box;
  for (const Vec3& p : block.vertices) box.add(p);
  const double tolerance = 1e-9 * std::max(box.diagonal(), 1e-300);
  std::array<statics::Block, 2> parts = {part(block, point, n, 1.0, tolerance, " (part 1)"),
                                         part(block, point, n, -1.0, tolerance, " (part 2)")};
  for (const statics::Block& p : parts) {
    if (p.faces.size() < 4) throw Error("break: the plane does not cut block \"" + block.name + "\" in two");
    massProperties(p);  // throws when a part encloses no volume
  }
  return parts;
}

Vec3 shearCrackNormal(const statics::Block& block) {
  const MassProperties m = massProperties(block);
  // The smallest moment is about the longest direction, the largest about the shortest.
  return (m.principalAxes[0] + m.principalAxes[2]) / std::sqrt(2.0);
}

}  // namespace corbel::sim
