#include "statics/column.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {

std::vector<Block> columnBlocks(const ColumnSpec& spec) {
  if (spec.drums < 1 || spec.drums > 10000) throw Error("column: the number of drums must be in 1..10000");
  if (spec.sides < 3 || spec.sides > 256) throw Error("column: the number of sides must be in 3..256");
  if (!std::isfinite(spec.radius) || spec.radius <= 0) throw Error("column: the radius must be a positive number");
  if (!std::isfinite(spec.height) || spec.height <= 0) throw Error("column: the height must be a positive number");
  if (!std::isfinite(spec.density) || spec.density <= 0) throw Error("column: the density must be a positive number");
  // Corners at half-steps of angle, so the side between the last and first corner faces +x.
  std::vector<Vec3> section;
  for (int i = 0; i < spec.sides; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.5) / spec.sides;
    section.emplace_back(spec.radius * std::cos(a), spec.radius * std::sin(a), 0.0);
  }
  std::vector<Block> out;
  for (int d = 0; d < spec.drums; ++d) {
    const double z0 = spec.height * d / spec.drums, z1 = spec.height * (d + 1) / spec.drums;
    std::vector<Vec3> base = section;
    for (Vec3& p : base) p[2] = z0;
    out.push_back(prismBlock("drum " + std::to_string(d), base, Vec3(0.0, 0.0, z1 - z0), spec.density));
  }
  return out;
}

}  // namespace corbel::statics
