#include "statics/buttress.h"

#include "core/error.h"
#include "statics/arch.h"
#include "statics/shapes.h"

#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {

std::vector<Block> buttressBlocks(const ButtressSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (spec.courses < 1 || spec.courses > 10000) throw Error("buttress: the number of courses must be in 1..10000");
  if (!positive(spec.height)) throw Error("buttress: the height must be a positive number");
  if (!positive(spec.baseWidth) || !positive(spec.topWidth)) throw Error("buttress: the widths must be positive numbers");
  if (!positive(spec.depth)) throw Error("buttress: the depth must be a positive number");
  if (!positive(spec.density)) throw Error("buttress: the density must be a positive number");
  std::vector<Block> out;
  for (int i = 0; i < spec.courses; ++i) {
    const double f = spec.courses == 1 ? 0.0 : double(i) / (spec.courses - 1);
    const double w = spec.baseWidth + (spec.topWidth - spec.baseWidth) * f;
    const double z0 = spec.height * i / spec.courses, z1 = spec.height * (i + 1) / spec.courses;
    out.push_back(boxBlock("course " + std::to_string(i), Vec3(0.0, 0.0, z0), Vec3(w, spec.depth, z1), spec.density));
  }
  return out;
}

std::vector<Block> flyingButtressBlocks(const FlyingButtressSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (spec.blocks < 1 || spec.blocks > 10000) throw Error("flying buttress: the number of voussoirs must be in 1..10000");
  if (!positive(spec.radius) || !positive(spec.thickness) || spec.thickness >= 2 * spec.radius)
    throw Error("flying buttress: radius and thickness must be positive, the thickness below the diameter");
  if (!positive(spec.depth) || !positive(spec.pierHeight) || !positive(spec.pierWidth) || !positive(spec.density))
    throw Error("flying buttress: depth, pier height, pier width and density must be positive numbers");
  if (spec.pierWidth / 2 >= spec.radius) throw Error("flying buttress: the pier would reach the wall (pier width ≥ 2 × radius)");
  const int n = spec.blocks;
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2, zc = spec.pierHeight;
  std::vector<ArchJoint> joints(std::size_t(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double phi = std::numbers::pi / 2 * k / n;
    const double cs = k == 0 ? 1.0 : k == n ? 0.0 : std::cos(phi), sn = k == 0 ? 0.0 : k == n ? 1.0 : std::sin(phi);
    joints[std::size_t(k)] = {Vec2(ri * cs, zc + ri * sn), Vec2(ro * cs, zc + ro * sn)};
  }
  std::vector<Block> out = voussoirs(joints, 0.0, spec.depth, spec.density);
  ButtressSpec pier{spec.pierHeight, spec.pierWidth, spec.pierWidth, spec.depth, spec.pierCourses, spec.density};
  for (Block& b : placed(buttressBlocks(pier), Vec3(spec.radius - spec.pierWidth / 2, 0.0, 0.0), "pier")) out.push_back(b);
  return out;
}

}  // namespace corbel::statics
