#pragma once
// Collide-and-extrude (Sec. 5.3, Fig. 5.3–5.4).
//
// A face of a growing part, in its own plane, is the rectangle [u0, u1] × [v0, v1]: u runs
// along the face (x for a ±y face, y for a ±x face) and v is z. What an advance of the face
// would run into (other units' parts, cores and circulation with their clearance zones) is
// projected onto that plane and clipped to the face. The free region is the face minus the
// obstacles, computed with CGAL's polygon Boolean difference on an exact kernel
// (`freeRegion`). A split cuts the whole part, full height, so the pieces that can extrude past
// the obstacles are the free *columns*: the stretches of u whose whole height is free
// (`freeColumns`). `freeColumnsByIntervals` gets the same stretches from the obstacles' u
// extents alone (a column is blocked exactly when some obstacle of positive height covers it);
// the engine uses it by default because it is much faster, and the tests hold it to the CGAL
// result. `collideSplits` turns free columns into the splits that free a piece.
//
// Fig. 5.4's stair base: `stairBasePart` is the part a unit adds when a face of its part has
// reached an external staircase whose roof lies one storey below the part's floor.
#include "growth/box.h"
#include "growth/unit.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::growth {

// A face in its plane and the obstacles' footprints on that plane (any size; they are
// clipped to the face).
struct FaceObstacles {
  Rect face;
  std::vector<Rect> obstacles;
};

// One polygon with holes of the free region, corners counter-clockwise (holes clockwise).
struct FreePolygon {
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
  double area() const;
};

// An open stretch [lo, hi] of u with lo < hi.
struct Interval {
  double lo = 0, hi = 0;
  bool operator==(const Interval&) const = default;
};

// face − ∪ obstacles by CGAL's Polygon_set_2 difference (exact predicates and constructions).
std::vector<FreePolygon> freeRegion(const FaceObstacles& f);

// The maximal stretches of u over which the whole height of the face is free, from the CGAL
// free region (its corners' coordinates cut the face into cells; a cell is free when its centre
// lies inside the region). Sorted, disjoint, not touching.
std::vector<Interval> freeColumns(const FaceObstacles& f);
// The same from the obstacles' u extents (an obstacle of positive height and width on the face
// blocks its u extent), without CGAL.
std::vector<Interval> freeColumnsByIntervals(const FaceObstacles& f);

// A split of the part at u = at whose free piece (low: u < at, high: u > at) starts a free
// column at least `least` wide. When the column ends before the face does, the free piece is
// still blocked beyond it and a second split at the column's far end frees it.
struct CollideSplit {
  double at = 0;
  bool freeHigh = false;
  Interval column;
  bool operator==(const CollideSplit&) const = default;
};

// Every split that frees a column of at least `least`, both pieces at least `least` wide;
// columns reaching an end of the face (a wholly free piece) first, then low before high.
// Nothing when the face is wholly free or wholly blocked.
std::vector<CollideSplit> collideSplits(const Rect& face, const std::vector<Interval>& columns, double least);

// Collide-and-extrude by hand (Fig. 5.3, Fig. 8.4): the vertical side s of part `part` of u
// pushed out by d > 0 past whatever it meets. Along the face each stretch advances until it meets
// an obstacle (the nearest of `obstacles` and the unit's own other parts whose box enters the
// swept region), at most d; the part is split where the reach changes, so every piece stays a
// box and the unit gains exactly the swept region up to the obstacles. A stretch narrower than
// `least` goes with the neighbour that reaches less, so no piece is narrower than `least` unless
// the face is. d < 0 pulls the side in (the part keeps at least `least` of depth). Without a
// change (`why` says why): a floor or ceiling side (moveFloorOrCeiling moves those), a side that meets another part of the unit,
// an obstacle right at the face along its whole width, a pull past `least`.
struct Extruded {
  Unit unit;
  double added = 0;  // volume gained (negative: lost)
};
std::optional<Extruded> collideAndExtrude(const Unit& u, int part, Side s, double d, const std::vector<Box>& obstacles,
                                          double least, std::string* why = nullptr);

// A floor or ceiling moved by hand: side s (Bottom or Top) of part `part` of u moved out by
// `storeys` whole storeys of `storeyHeight` (negative: in), so that a room becomes a double
// volume or one again (Sec. 5.3: parts are one or two storeys high, a unit spans at most two).
// The whole face moves or nothing does: unlike a wall it is not split, since a part of one and
// a half storeys is no room. Without a change (`why` says why): a vertical side, no storeys, a
// side that meets another part of the unit, a part that would not be one or two whole storeys
// high, a unit that would span more than two storeys, a floor below `ground`, or something
// (another part, an obstacle) in the swept region.
std::optional<Extruded> moveFloorOrCeiling(const Unit& u, int part, Side s, int storeys, double storeyHeight,
                                           const std::vector<Box>& obstacles, double ground, std::string* why = nullptr);

// Fig. 5.4: a unit may take the whole top of an external staircase as a part whose floor is
// the staircase's roof, when side s of its one-storey part b has reached the staircase: the
// staircase lies in front of the face at most `reach` (α) beyond it, faces it along at least a
// door's width, and its roof is one storey below b's floor. The part covers the staircase's top
// and the strip between it and the face, from the roof up to b's ceiling: two storeys, the
// lower one on the staircase's roof, with the unit's internal stair up to its second level
// (b's storey). Without a reason (`why`) when the rule does not apply.
std::optional<Box> stairBasePart(const Box& b, Side s, const Box& staircase, double storeyHeight, double reach,
                                 std::string* why = nullptr);

}  // namespace corbel::growth
