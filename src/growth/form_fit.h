#pragma once
// A generated form fitted into a region of the model (Sec. 7.3.3-7.3.4, Fig. 8.6): the form's
// rectangular cartogram (sub-units and sea) is laid in one of the eight orientations of the
// square, its bounding box mapped exactly onto the region (corners onto corners, lines in
// between proportionally, so ≺x and ≺z are kept), and sized (growth/sizing.h). With entrances
// (growth/entrances.h) the orientation is the one whose units lie nearest them, each entrance
// taken by a different unit (nearest pairs first).
#include "growth/cartogram.h"
#include "growth/floorplan.h"
#include "growth/sizing.h"
#include "growth/unit.h"

#include <vector>

namespace corbel::growth {

struct FitOptions {
  double z0 = 0, storeyHeight = 3.0;
  bool size = true;    // run the sizing heuristic after the fit
  int orientation = -1;  // 0 .. 7 to force one (bit 2: mirror x; bits 0-1: quarter turns); -1: choose
};

struct FittedForm {
  Layout layout;            // in region coordinates; tiles the region
  std::vector<Unit> units;  // id = form unit + 1, one storey from z0
  int orientation = 0;
  std::vector<int> entranceOf;  // per unit: the entrance it takes (-1: none)
  double entranceDistance = 0;  // Σ distance from each taken entrance to its unit
  SizingResult sizing;
};

// The orientation applied to a point (for tests: a quarter turn is (x, y) → (−y, x)).
Vec2 orient(int orientation, const Vec2& p);

// Throws InputError for an empty plan or a degenerate region.
FittedForm fitForm(const Floorplan& plan, const PlanRect& region, const std::vector<Vec2>& entrances = {},
                   const FitOptions& options = {});

}  // namespace corbel::growth
