#pragma once
// A generated form fitted into a region of the model (Sec. 7.3.3-7.3.4, Fig. 8.6): the form's
// rectangular cartogram (sub-units and sea) is laid in one of the eight orientations of the
// square, its bounding box mapped exactly onto the region (corners onto corners, lines in
// between proportionally, so ≺x and ≺z are kept), and sized (growth/sizing.h). With entrances
// (growth/entrances.h) the orientation is the one whose units lie nearest them along the region's
// sides, each entrance taken by a different unit (cheapest pairs first). After sizing, each taken entrance is realized
// (Sec. 7.3.3): its unit is made to open onto it over a door's width, by the cascading and
// staircase edge moves of realizeBySegments, keeping the entrances realized before it in place.
#include "growth/cartogram.h"
#include "growth/floorplan.h"
#include "growth/site.h"
#include "growth/sizing.h"
#include "growth/unit.h"

#include <string>
#include <vector>

namespace corbel::growth {

struct FitOptions {
  double z0 = 0, storeyHeight = 3.0;
  bool size = true;              // run the sizing heuristic after the fit
  int orientation = -1;          // 0 .. 7 to force one (bit 2: mirror x; bits 0-1: quarter turns); -1: choose
  bool realizeEntrances = true;  // move the layout's segments so each unit opens onto its entrance
  double doorWidth = 1.0;        // how much of the region's side a unit must share at its entrance (m)
  double roomWidth = 0;          // SizingOptions::roomWidth: kMinPartWidth in a grown model, 0 alone
};

// What became of one taken entrance.
struct EntranceFit {
  int unit = -1;            // the form's unit (index) that takes it
  int entrance = -1;        // index into the entrances given to fitForm
  int side = -1;            // the region's side it is on: 0 south (y0), 1 east (x1), 2 north (y1), 3 west (x0)
  double from = 0, to = 0;  // the door: the stretch of that side the unit must cover
  bool realized = false;    // the unit covers the door
  bool moved = false;       // segments were moved to make it so
  std::string why;          // when not realized
};

struct FittedForm {
  Layout layout;            // in region coordinates; tiles the region
  std::vector<Unit> units;  // id = form unit + 1, one storey from z0
  int orientation = 0;
  std::vector<int> entranceOf;  // per unit: the entrance it takes (-1: none)
  // Before realization (after sizing): Σ distance from each taken entrance to its unit, and Σ
  // cost, the distance along the region's side from each door to its unit's nearest stretch of
  // that side, a unit that does not reach the side costing the region's perimeter more. The
  // orientation and the assignment are chosen for the least cost.
  double entranceDistance = 0, entranceCost = 0;
  std::vector<EntranceFit> entranceFits;  // per taken entrance, in the order they were realized
  SizingResult sizing;
  double areaError = 0;  // the largest relative area error of a sub-unit rectangle at the end
};

// The orientation applied to a point (for tests: a quarter turn is (x, y) → (−y, x)).
Vec2 orient(int orientation, const Vec2& p);

// Throws InputError for an empty plan or a degenerate region.
FittedForm fitForm(const Floorplan& plan, const PlanRect& region, const std::vector<Vec2>& entrances = {},
                   const FitOptions& options = {});

// The growth rules (growth/constraints.h: envelope, clearance from cores and circulation, no
// overlap, rooms at least 3 m x 3 m, supports) that the fitted form's units break among the
// grown model's `units`, one sentence each; the form's units are named "form unit K" (K from
// 1), the model's "unit ID". Empty: the form may stand in the model.
std::vector<std::string> formViolations(const Site& site, const std::vector<Unit>& units, const FittedForm& form);

// The form to place among fitted ones: of those that obey the growth rules (fits[k]), the one
// that meets the most doors, then has the least area error (the first of equals); -1 if none.
int bestFit(const std::vector<FittedForm>& forms, const std::vector<bool>& fits);

}  // namespace corbel::growth
