#pragma once
// Geometry sizing (Sec. 7.3.4, Fig. 7.19-7.20): the moving-segment heuristic (after van
// Kreveld and Speckmann) on a realized cartogram, toward sub-units of equal area.
//
// Targets: every sub-unit rectangle M = (bounding box area) / (number of sub-unit
// rectangles), every sea rectangle a small m = seaShare·M. A segment is a maximal run of
// collinear rectangle sides inside the box; moving it moves every side on it. Each pass
// visits the segments next to the worst-sized rectangles first and moves one by ±δ when that
// lowers the largest sub-unit error |A − M| / M (ties: the sum of squared errors of all
// rectangles; with a room width, the rooms' shortfall from it first); δ halves after a pass with no move. A segment keeps every rectangle next to
// it at least minWidth wide and never slides past a corner on the segments its ends lie on,
// so no rectangle inverts and the order of corners along every segment, hence ≺x and ≺z,
// is kept.
#include "growth/cartogram.h"
#include "growth/unit.h"

namespace corbel::growth {

// Rectangles with their own coordinates, and the unit of each (-1: sea).
struct Layout {
  std::vector<PlanRect> rects;
  std::vector<int> unit;
  static Layout of(const Cartogram& c);
  int subUnits() const;
};

struct SizingOptions {
  int maxPasses = 400;
  double minWidth = 0.5;
  double seaShare = 0.05;
  // The least width of a room (a sub-unit rectangle) where the form is to obey the growth
  // rules (kMinPartWidth); 0: none. Moves that widen a narrower room come before any other
  // (the sum of the rooms' shortfalls is compared first), and none makes a room narrower.
  double roomWidth = 0;
};

struct SizingResult {
  double before = 0, after = 0;  // the largest relative area error of a sub-unit rectangle
  int passes = 0;
  int moves = 0;
  int segments = 0;  // movable segments
};

// Cascading and staircase edge moves (Sec. 7.3.3, Fig. 7.16-7.18): each corresponded
// corner is brought to its target by moving the segments it lies on; a segment that would
// squeeze a neighbouring rectangle below minWidth pushes the segment beyond it (cascading), and
// one whose end would slide past a corner on the segment it ends on pushes that corner's
// segment (staircase), on to the box, which does not move. Refused (unchanged) when the
// targets are not realizable or the pushes reach the box.
bool realizeBySegments(Layout& l, const std::vector<Correspondence>& targets, double minWidth,
                       std::string* why = nullptr);

double maxAreaError(const Layout& l);
// How much narrower than `roomWidth` the sub-unit rectangles are, summed (0: none is).
double roomShortfall(const Layout& l, double roomWidth);
SizingResult sizeGeometry(Layout& l, const SizingOptions& options = {});

// Stretches the cartogram onto `region` (its outer lines onto the region's sides).
void fitToRegion(Cartogram& c, const PlanRect& region);

// The sized sub-units as growth units (id = unit index + 1), one storey from z0.
std::vector<Unit> sizedUnits(const Layout& l, int units, double z0, double storeyHeight);

}  // namespace corbel::growth
