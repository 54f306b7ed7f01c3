#pragma once
// The signed area of a closed polygon by the shoelace formula: positive when its corners run
// counter-clockwise. Shared by the kernels that orient and measure plan loops.
#include "core/geometry.h"

#include <vector>

namespace corbel {

inline double signedArea(const std::vector<Vec2>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 &p = loop[i], &q = loop[(i + 1) % loop.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

}  // namespace corbel
