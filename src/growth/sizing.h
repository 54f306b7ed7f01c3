#pragma once
// Geometry sizing (Sec. 7.3.4, Fig. 7.19-7.20): the moving-segment heuristic (after van
// Kreveld and Speckmann) on a cartogram, toward sub-units of equal area.
//
// Targets: every sub-unit rectangle M = (bounding box area) / (number of sub-units), every sea
// rectangle a small m = seaShare·M. A segment here is a whole coordinate line of the
// cartogram (every rectangle side on it moves together); the outer lines stay on the region.
// Each pass visits the lines next to the worst-sized rectangles first and moves a line by ±δ
// when that lowers the maximum sub-unit error (ties: the sum of squared errors of all
// rectangles); δ halves after a pass with no move. A line never comes closer than minWidth to
// its neighbours, so no rectangle inverts and the arrangement (≺x, ≺z) is kept.
#include "growth/cartogram.h"
#include "growth/unit.h"

namespace corbel::growth {

struct SizingOptions {
  int maxPasses = 400;
  double minWidth = 0.5;
  double seaShare = 0.05;
};

struct SizingResult {
  double before = 0, after = 0;  // the maximum relative area error of a sub-unit
  int passes = 0;
  int moves = 0;
};

double maxAreaError(const Cartogram& c);
SizingResult sizeGeometry(Cartogram& c, const SizingOptions& options = {});

// Stretches the cartogram onto `region` (its outer lines onto the region's sides).
void fitToRegion(Cartogram& c, const PlanRect& region);

// The sized sub-units as growth units (id = unit index + 1), one storey from z0.
std::vector<Unit> sizedUnits(const Cartogram& c, int units, double z0, double storeyHeight);

}  // namespace corbel::growth
