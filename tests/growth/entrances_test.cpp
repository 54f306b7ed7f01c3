// growth/entrances.h: the seeds of a completion taken from a grown model lie in the region, on a
// face of their unit, and open onto free space in the region (Ch. 7, Fig. 7.1 and 7.8).
#include "growth/entrances.h"

#include "growth/kernel.h"
#include "support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

// Two units either side of a 6 m × 6 m gap and one across its top.
std::vector<Unit> gapModel() {
  return {unitOf(1, {box(0, 0, 0, 4, 4, 3)}), unitOf(2, {box(10, 0, 0, 14, 4, 3)}),
          unitOf(3, {box(4, 6, 0, 10, 9, 3)})};
}

TEST(Entrances, EveryUnitOpeningOntoTheRegionGivesOneAtTheMiddleOfItsFreeFace) {
  const auto e = entrancesInRegion(gapModel(), {4, 0, 10, 6});
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].unit, 1);
  EXPECT_EQ(e[0].facing, Side::PosX);
  EXPECT_DOUBLE_EQ(e[0].at[0], 4);
  EXPECT_DOUBLE_EQ(e[0].at[1], 2);
  EXPECT_DOUBLE_EQ(e[0].width, 4);
  EXPECT_EQ(e[1].unit, 2);
  EXPECT_EQ(e[1].facing, Side::NegX);
  EXPECT_DOUBLE_EQ(e[1].at[0], 10);
  EXPECT_DOUBLE_EQ(e[1].at[1], 2);
  EXPECT_EQ(e[2].unit, 3);
  EXPECT_EQ(e[2].facing, Side::NegY);
  EXPECT_DOUBLE_EQ(e[2].at[0], 7);
  EXPECT_DOUBLE_EQ(e[2].at[1], 6);
  EXPECT_DOUBLE_EQ(e[2].width, 6);
}

TEST(Entrances, AnObstacleOrAnotherUnitRightOutsideAFaceClosesThatStretch) {
  // A staircase against the lower half of unit 1's east face: the free stretch is its upper half.
  auto e = entrancesInRegion(gapModel(), {4, 0, 10, 6}, {}, {box(4, 0, 0, 5, 2, 3)});
  ASSERT_EQ(e.size(), 3u);
  EXPECT_DOUBLE_EQ(e[0].at[1], 3);
  EXPECT_DOUBLE_EQ(e[0].width, 2);
  // A unit filling the whole gap leaves no entrance but its own faces toward the others... which
  // touch them: none is free.
  std::vector<Unit> full = gapModel();
  full.push_back(unitOf(4, {box(4, 0, 0, 10, 6, 3)}));
  EXPECT_TRUE(entrancesInRegion(full, {4, 0, 10, 6}).empty());
}

TEST(Entrances, FacesPointingOutOfTheRegionOrOnAnotherStoreyDoNotCount) {
  // West of unit 1, its west face (x = 0, the region's east side) faces into the region.
  const auto west = entrancesInRegion(gapModel(), {-6, 0, 0, 4});
  ASSERT_EQ(west.size(), 1u);
  EXPECT_EQ(west[0].facing, Side::NegX);
  // Unit 1's own box as the region: all its faces lie on the region's sides, facing out.
  EXPECT_TRUE(entrancesInRegion(gapModel(), {0, 0, 4, 4}).empty());
  EntranceOptions up;
  up.storey = 1;
  EXPECT_TRUE(entrancesInRegion(gapModel(), {4, 0, 10, 6}, up).empty());
}

TEST(Entrances, AtMostMaxCountAndTheWidestAreKept) {
  EntranceOptions two;
  two.maxCount = 2;
  const auto e = entrancesInRegion(gapModel(), {4, 0, 10, 6}, two);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].unit, 1);  // width 4 (ties with unit 2: the first stays)
  EXPECT_EQ(e[1].unit, 3);  // width 6
}

std::string alphaSite() {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Entrances, SeedsOfAGrownModelLieInTheRegionAtUnitFacesOpeningOntoFreeSpace) {
  const GrownModel m = grow(GrowthSpec{alphaSite(), 1, 20});
  const PlanRect region{36, 13, 54, 38};
  std::vector<Box> obstacles = m.site.circulation;
  for (std::size_t i = 0; i < m.site.cores.size(); ++i) obstacles.push_back(m.site.coreBox(i));
  EntranceOptions o;
  o.storeyHeight = m.site.storeyHeight;
  o.base = m.site.base;
  const auto es = entrancesInRegion(m.units, region, o, obstacles);
  ASSERT_FALSE(es.empty());
  EXPECT_LE(es.size(), 12u);
  std::set<int> ids;
  const double zMid = m.site.base + 0.5 * m.site.storeyHeight;
  auto solidAt = [&](double x, double y) {
    for (const Unit& u : m.units)
      for (const Box& b : u.parts)
        if (b.lo[2] < zMid && b.hi[2] > zMid && x > b.lo[0] && x < b.hi[0] && y > b.lo[1] && y < b.hi[1]) return true;
    for (const Box& b : obstacles)
      if (b.lo[2] < zMid && b.hi[2] > zMid && x > b.lo[0] && x < b.hi[0] && y > b.lo[1] && y < b.hi[1]) return true;
    return false;
  };
  for (const Entrance& e : es) {
    SCOPED_TRACE(e.unit);
    EXPECT_TRUE(ids.insert(e.unit).second) << "one entrance per unit";
    EXPECT_GE(e.width, o.minWidth);
    EXPECT_GE(e.at[0], region.x0);
    EXPECT_LE(e.at[0], region.x1);
    EXPECT_GE(e.at[1], region.y0);
    EXPECT_LE(e.at[1], region.y1);
    // On a side of a part of its unit on the ground storey.
    const int a = sideAxis(e.facing), t = 1 - a;
    bool onFace = false;
    for (const Unit& u : m.units)
      if (u.id == e.unit)
        for (const Box& b : u.parts)
          onFace |= b.lo[2] < zMid && b.hi[2] > zMid && sideCoord(b, e.facing) == e.at[a] && e.at[t] >= b.lo[t] &&
                    e.at[t] <= b.hi[t];
    EXPECT_TRUE(onFace);
    // Just outside it: inside the region and free.
    Vec2 out = e.at;
    out[a] += 0.01 * sideSign(e.facing);
    EXPECT_GT(out[0], region.x0);
    EXPECT_LT(out[0], region.x1);
    EXPECT_FALSE(solidAt(out[0], out[1]));
    // and just inside it: the unit.
    Vec2 in = e.at;
    in[a] -= 0.01 * sideSign(e.facing);
    EXPECT_TRUE(solidAt(in[0], in[1]));
  }
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

TEST(Entrances, TheGapFoundIsFreeWithinBoundsAndMeetsTheUnitsAroundIt) {
  // The 6 m × 6 m gap of gapModel() with unit faces at whole meters, and a unit whose face is at 10.5.
  std::vector<Unit> units{test::unitOf(1, {test::box(0, 0, 0, 4, 6, 3)}), test::unitOf(2, {test::box(10.5, 0, 0, 14, 6, 3)}),
                          test::unitOf(3, {test::box(0, 6, 0, 14, 9, 3)})};
  PlanRect gap;
  ASSERT_TRUE(findGap(units, {}, {0, 0, 14, 9}, {}, 3, 8, gap));
  // The most enclosed free rectangle is the notch between the three, its east side moved onto 10.5.
  EXPECT_DOUBLE_EQ(gap.x0, 4);
  EXPECT_DOUBLE_EQ(gap.x1, 10.5);
  EXPECT_DOUBLE_EQ(gap.y1, 6);
  EXPECT_DOUBLE_EQ(gap.y0, 0);
  const auto e = entrancesInRegion(units, gap);
  EXPECT_EQ(e.size(), 3u);  // every unit opens onto it
  PlanRect none;
  EXPECT_FALSE(findGap({test::unitOf(1, {test::box(0, 0, 0, 14, 9, 3)})}, {}, {0, 0, 14, 9}, {}, 3, 8, none));
}

}  // namespace
}  // namespace corbel::growth
