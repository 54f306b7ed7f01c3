#pragma once
// A roof carried on piers: where a wall has buttresses up to its head, a builder sets the
// roof's principal rafters (or trusses) over them, and a wall plate spanning from pier to pier
// carries the common rafters between, so the roof's weight and thrust come down on the wall
// head over the piers, not along it.
#include "statics/coursing.h"

#include <vector>

namespace corbel::statics {

// The stretch of one edge's roof that one pier carries.
struct PierShare {
  int edge = -1;
  int buttress = -1;            // index in spec.buttresses
  double from = 0.0, to = 0.0;  // m along the edge's outer face: the roof over it bears on the pier
};

// The piers of `spec` that reach its wall head (their top snapped to the same course joints as
// courseWalls, `courses` courses in all) and the roof each carries: on an edge with piers at
// centres c1 < c2 < … < cn, pier k carries the roof from midway between c(k−1) and ck to midway
// between ck and c(k+1), the first from the edge's start, the last to its end, so together they
// carry the whole edge. Edges without such piers have no share.
std::vector<PierShare> pierShares(const CoursingSpec& spec, int courses);

// As loadWallHeads, but an edge with piers up to its head takes its load on them: pier k's
// share (to − from) × the edge's load per metre, on the top-course blocks over the pier (each
// in proportion to how much of the pier's length its head span covers), at the middle of that
// overlap on the wall's centre line. Edges without piers are loaded along their head as
// loadWallHeads does. The loads' sum is the same either way.
void loadHeadsOnPiers(const CoursingSpec& spec, CoursedWalls& walls, const std::vector<HeadLoad>& perEdge);

}  // namespace corbel::statics
