#include "statics/arch.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

// Reverses faces whose Newell normal points towards the block's vertex average (an interior
// point of a convex block).
void orientOutward(Block& b) {
  Vec3 c(0.0);
  for (const Vec3& v : b.vertices) c += v;
  c /= double(b.vertices.size());
  for (auto& f : b.faces) {
    std::vector<Vec3> poly;
    Vec3 fc(0.0);
    for (int i : f) {
      poly.push_back(b.vertices[std::size_t(i)]);
      fc += b.vertices[std::size_t(i)];
    }
    fc /= double(f.size());
    if (dot(newellNormal(poly), fc - c) < 0) std::reverse(f.begin(), f.end());
  }
}

}  // namespace

Assembly semicircularArch(const ArchSpec& spec) {
  if (spec.blocks < 1 || spec.blocks > 100000) throw Error("arch: the number of voussoirs must be in 1..100000");
  if (!std::isfinite(spec.radius) || spec.radius <= 0) throw Error("arch: the radius must be a positive number");
  if (!std::isfinite(spec.thickness) || spec.thickness <= 0 || spec.thickness >= 2 * spec.radius)
    throw Error("arch: the thickness must be positive and less than the diameter");
  if (!std::isfinite(spec.depth) || spec.depth <= 0) throw Error("arch: the depth must be a positive number");
  if (!std::isfinite(spec.tiltDeg) || std::abs(spec.tiltDeg) >= 90) throw Error("arch: the tilt must be within ±90°");
  if (!std::isfinite(spec.density) || spec.density <= 0) throw Error("arch: the density must be a positive number");

  const int n = spec.blocks;
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2, h = spec.depth / 2;
  // Joint k: inner and outer points at both faces, computed once so neighbours share them.
  std::vector<std::array<Vec3, 4>> joints(std::size_t(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double th = std::numbers::pi * k / n;
    const double cs = k == 0 ? 1.0 : k == n ? -1.0 : std::cos(th);
    const double sn = (k == 0 || k == n) ? 0.0 : std::sin(th);
    joints[std::size_t(k)] = {Vec3(ri * cs, -h, ri * sn), Vec3(ro * cs, -h, ro * sn), Vec3(ro * cs, h, ro * sn),
                              Vec3(ri * cs, h, ri * sn)};
  }
  Assembly as;
  for (int i = 0; i < n; ++i) {
    Block b;
    b.name = "voussoir " + std::to_string(i);
    b.density = spec.density;
    for (const Vec3& v : joints[std::size_t(i)]) b.vertices.push_back(v);
    for (const Vec3& v : joints[std::size_t(i) + 1]) b.vertices.push_back(v);
    b.faces = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}, {0, 4, 5, 1}, {3, 2, 6, 7}};
    orientOutward(b);
    as.blocks.push_back(std::move(b));
  }
  const double span = ro + spec.thickness;
  as.blocks.push_back(boxBlock("ground", Vec3(-span, -2 * h, -spec.thickness), Vec3(span, 2 * h, 0.0), 1.0, true));
  const double tilt = spec.tiltDeg * std::numbers::pi / 180.0;
  as.gravity = Vec3(std::sin(tilt), 0.0, -std::cos(tilt));
  return as;
}

}  // namespace corbel::statics
