#include "statics/buttress.h"

#include "core/error.h"

#include <cmath>
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

}  // namespace corbel::statics
