#pragma once
// Statistics on space use of a grown model (Table 8.1).
//
// - occupants by the Swedish standard (Ch. 8): Type A (floor area > 85 m²) houses five,
//   Type B (50–85 m²) three, Type C (30–50 m²) one; smaller units house nobody;
// - occupancy ratio: occupants per m² of envelope floor (site area × storeys), which is how
//   Table 8.1's figures come out (Alpha: 213 / (90 m × 50 m × 5) = 0.0095);
// - views: a unit has a view in a direction when at least kMinViewArea of it is seen that
//   way; "two views" and "three views" count units with exactly two and three;
// - double volume: a part two storeys high;
// - outdoor space: another unit's roof at the unit's floor level, open above over at least
//   kMinGardenArea and meeting one of the unit's parts along an unbroken stretch of at least
//   kMinDoorWidth (a door).
#include "growth/site.h"
#include "growth/unit.h"
#include "growth/view_map.h"

#include <array>
#include <vector>

namespace corbel::growth {

// 'A', 'B', 'C', or '-' below 30 m².
char housingType(double floorArea);
int occupantsOf(char type);

struct UnitStatistics {
  int id = 0;
  double floorArea = 0;
  double volume = 0;
  double view = 0;
  std::array<double, 4> viewByDirection{};  // by ViewDirection
  int views = 0;                            // directions with a view
  char type = '-';
  bool doubleVolume = false;
  bool outdoorSpace = false;
};

struct Statistics {
  double siteArea = 0;
  int storeys = 0;
  int units = 0;
  int occupants = 0;
  double occupancyRatio = 0;
  int typeA = 0, typeB = 0, typeC = 0, unclassified = 0;
  double averageView = 0;
  int twoViews = 0, threeViews = 0, fourViews = 0;
  double averageFloorArea = 0;
  int doubleVolume = 0;
  int outdoorSpace = 0;
  std::vector<UnitStatistics> perUnit;
};

bool hasOutdoorSpace(const Site& site, const std::vector<Unit>& units, std::size_t unit);
Statistics computeStatistics(const Site& site, const std::vector<Unit>& units, const ViewMaps& views);

}  // namespace corbel::growth
