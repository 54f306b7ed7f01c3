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

// Every answer below comes from CGAL's skeleton built in a forked child process. CGAL 5.5's
// skeleton now and then reads freed memory or dereferences a null trisegment in
// MergeCoincidentNodes, and not always on the same plan (it breaks ties between split events by
// their memory addresses; docs/extrude.md); under valgrind it has also looped for good. In a
// child, a crash or a hang (past a time limit) costs one try, not the test run: the plan is then
// tried turned a quarter and a half turn about the origin (exact in floating point, the same
// heights and volume, CGAL's nodes made in another order), and only after three failures has no
// answer. The single-plan functions
// throw, naming the plan's size, when it has none.

// loops: outer counter-clockwise, holes clockwise (one outer loop with its holes).
SkeletonRoof cgalRoof(const std::vector<std::vector<Vec2>>& loops, double pitchRadians);

// Under one profile on every edge (points (w, z) from (0, 0), w never decreasing, as the random
// plans' profiles are): every edge then moves inward by the same w(z), so the active plan at
// height z is the straight skeleton's offset at time w(z), and a point whose skeleton time is t
// lies under the profile's height at w = t (the last segment going on). The volume is
// integrated exactly over CGAL's skeleton faces, on each of which t is linear; the height is the
// profile's at the skeleton's latest time.
struct UnderProfile {
  double height = 0;
  double volume = 0;
};
UnderProfile cgalUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile);
double cgalVolumeUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile);
double cgalHeightUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile);

// The same for many plans, one child going through them from where the last one stopped (forking
// once per plan would cost more than the skeletons). A plan without an answer is nullopt. Call
// it with no other thread running.
inline constexpr double kSkeletonSecondsPerQuery = 120;  // natively milliseconds; valgrind: ×50
struct SkeletonQuery {
  std::vector<std::vector<Vec2>> loops;
  std::vector<Vec2> profile;
  bool dieForTest = false;       // the child aborts on this query, every try (tests the isolation)
  bool hangForTest = false;      // the child waits for good on it (tests the time limit)
  bool dieFirstForTest = false;  // the child aborts on the first try only (tests the next try)
};
std::vector<std::optional<UnderProfile>> cgalUnderProfileIsolated(const std::vector<SkeletonQuery>& queries,
                                                                  double secondsPerQuery = kSkeletonSecondsPerQuery);

}  // namespace corbel::extrude::test
