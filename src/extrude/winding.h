#pragma once
// The winding rule over an active plan that overlaps itself (Sec. 4.4, "post inter-chain
// intersections"): where the corners an event made leave loops that cross one another, the
// plan's valid region is where the loops wind around a point at least once. Its boundary is
// the new active plan; each piece of it lies on one edge of the old plan, so it keeps that
// edge's direction plane and profile. What the old plan covered more than once (winding ≥ 2)
// or the wrong way round (winding ≤ −1, a loop turned inside out) is closed by flat caps, so
// the faces that ended there stay closed.
#include "core/geometry.h"

#include <utility>
#include <vector>

namespace corbel::extrude {

struct WindingEdge {
  Vec2 start;      // it ends where the next edge of its loop starts
  int source = -1; // the old plan's edge it lies on: a flat index over the input loops
};

struct WindingCap {
  int level = 0;  // ≥ 2: covers where the winding number is at least this, facing up;
                  // ≤ −1: where it is at most this, facing down
  // Directed boundary pieces, counter-clockwise seen from the side the cap faces; pieces
  // inside the region come in both directions and cancel when traced.
  std::vector<std::pair<Vec2, Vec2>> pieces;
};

struct WindingResult {
  // The boundary of the region of winding number ≥ 1, the region on each edge's left (outer
  // loops counter-clockwise, holes clockwise); consecutive pieces of one old edge are one edge.
  std::vector<std::vector<WindingEdge>> loops;
  std::vector<WindingCap> caps;
  int minWinding = 0, maxWinding = 0;
};

// Loop l's edge i runs from loops[l][i] to loops[l][(i + 1) % size]; zero-length edges are
// ignored. Exact (CGAL's arrangement over an exact kernel); the output points are rounded.
WindingResult windingRule(const std::vector<std::vector<Vec2>>& loops);

// Area of a cap (or any set of directed pieces that close): the shoelace sum of its pieces.
double piecesArea(const std::vector<std::pair<Vec2, Vec2>>& pieces);

}  // namespace corbel::extrude
