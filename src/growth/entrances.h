#pragma once
// Seeds for form completion from a grown model (Ch. 7, Fig. 7.1 and 7.8): the completion engine
// takes N canonical units, "entrances to the units which has to belong to some particular unit
// in the floorplan after the completion process". In a region of a grown model (a void the
// growth left, Fig. 7.1) the entrances are where the grown units open onto it: per unit, the
// longest stretch of one of its faces on the chosen storey that lies in the region, faces into
// it and is free (no unit or obstacle right outside it).
#include "growth/box.h"
#include "growth/cartogram.h"
#include "growth/site.h"
#include "growth/unit.h"

#include <vector>

namespace corbel::growth {

struct Entrance {
  int unit = 0;            // the grown unit's id
  Vec2 at{0.0};            // the middle of the free stretch, on the face
  Side facing = Side::PosX;  // the face's outward normal: into the region
  double width = 0;        // the free stretch's length
};

struct EntranceOptions {
  int storey = 0;  // the storey whose faces count (a part counts when it spans its middle)
  double base = 0, storeyHeight = 3.0;
  double minWidth = 1.0;  // shorter free stretches are no entrance
  int maxCount = 12;      // the completion takes 1 .. 12 units: the widest entrances are kept
};

// The options for a storey of a site (its base and storey height), and the site's obstacles to
// entrances: its circulation and its cores' boxes. The editor's completion panel and
// `corbel-cli complete --from` read a grown model through these.
EntranceOptions storeyOptions(const Site& site, int storey);
std::vector<Box> entranceObstacles(const Site& site);
// The sides of a gap the completion looks for in a grown model (findGap), metres: at least two
// rooms of the growth's least width (kMinPartWidth, 3 m) and a metre between, so a form whose
// rooms stand two deep fits (a 6 m gap left every such form with a room under 3 m).
inline constexpr double kGapMinSide = 7, kGapMaxSide = 16;

// Ordered by unit id. Obstacles (cores, circulation) block a face like another unit does.
std::vector<Entrance> entrancesInRegion(const std::vector<Unit>& units, const PlanRect& region,
                                        const EntranceOptions& options = {}, const std::vector<Box>& obstacles = {});

// A gap to complete (Fig. 7.1: the completion "claims gaps (voids) in space for units"): on a
// 1 m grid over `bounds`, the rectangle free of every unit and obstacle on the storey, with both
// sides in [minSide, maxSide] m, that is most enclosed (the most grid cells right outside its
// sides are taken), then the largest. Returns false when there is none.
bool findGap(const std::vector<Unit>& units, const std::vector<Box>& obstacles, const PlanRect& bounds,
             const EntranceOptions& storey, double minSide, double maxSide, PlanRect& gap);

}  // namespace corbel::growth
