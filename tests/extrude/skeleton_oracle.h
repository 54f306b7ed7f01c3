#pragma once
// The independent oracle for equal angles: CGAL's straight skeleton lifted by tan φ.
#include "core/geometry.h"

#include <optional>
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

// Volume under one profile on every edge (points (w, z) from (0, 0), w never decreasing, as
// the random plans' profiles are): every edge then moves inward by the same w(z), so the
// active plan at height z is the straight skeleton's offset at time w(z), and a point whose
// skeleton time is t lies under the profile's height at w = t (the last segment going on).
// Integrated exactly over CGAL's skeleton faces, on each of which t is linear.
double cgalVolumeUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile);

// The highest point of that roof: the profile's height at the skeleton's latest time.
double cgalHeightUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile);

// The same for many plans, each computed in a forked child process. CGAL 5.5's skeleton now and
// then dereferences a null trisegment in MergeCoincidentNodes on the random run's plans, and
// not always on the same plan (it breaks ties between split events by their memory addresses;
// docs/extrude.md): a crash there would end the whole test. A child that dies leaves its plan
// without a height (nullopt) and the next child carries on after it; so does a plan CGAL
// refuses by an exception. Call it with no other thread running.
struct HeightQuery {
  std::vector<std::vector<Vec2>> loops;
  std::vector<Vec2> profile;
  bool dieForTest = false;  // the child aborts on this query (tests the isolation itself)
};
std::vector<std::optional<double>> cgalHeightsIsolated(const std::vector<HeightQuery>& queries);

}  // namespace corbel::extrude::test
