#pragma once
// The independent oracle for equal angles: CGAL's straight skeleton lifted by tan φ.
#include "core/geometry.h"

#include <vector>

namespace corbel::extrude::test {

struct SkeletonRoof {
  double maxHeight = 0;  // tan φ × the latest event time
  double volume = 0;     // of the solid between the footprint and the lifted roof
  double roofArea = 0;
  std::size_t faces = 0;
};

// loops: outer counter-clockwise, holes clockwise (one outer loop with its holes).
SkeletonRoof cgalRoof(const std::vector<std::vector<Vec2>>& loops, double pitchRadians);

}  // namespace corbel::extrude::test
