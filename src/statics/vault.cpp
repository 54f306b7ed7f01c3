#include "statics/vault.h"

#include "core/error.h"
#include "statics/arch.h"

#include <cmath>
#include <string>

namespace corbel::statics {

std::vector<Block> barrelVaultBlocks(const BarrelVaultSpec& spec) {
  if (spec.rings < 1 || spec.rings > 10000) throw Error("barrel vault: the number of rings must be in 1..10000");
  if (!std::isfinite(spec.length) || spec.length <= 0) throw Error("barrel vault: the length must be a positive number");
  ArchSpec ring;
  ring.blocks = spec.blocks;
  ring.radius = spec.radius;
  ring.thickness = spec.thickness;
  ring.depth = spec.length / spec.rings;
  ring.density = spec.density;
  const std::vector<ArchJoint> joints = semicircularJoints(ring);
  std::vector<Block> out;
  for (int r = 0; r < spec.rings; ++r) {
    const double y0 = spec.length * r / spec.rings, y1 = spec.length * (r + 1) / spec.rings;
    for (Block& b : voussoirs(joints, y0, y1, spec.density)) {
      b.name = "ring " + std::to_string(r) + " " + b.name;
      out.push_back(std::move(b));
    }
  }
  return out;
}

Assembly barrelVault(const BarrelVaultSpec& spec) {
  Assembly as;
  as.blocks = barrelVaultBlocks(spec);
  const double reach = spec.radius + 1.5 * spec.thickness;
  as.blocks.push_back(boxBlock("ground", Vec3(-reach, -0.5, -spec.thickness), Vec3(reach, spec.length + 0.5, 0.0), 1.0, true));
  return as;
}

}  // namespace corbel::statics
