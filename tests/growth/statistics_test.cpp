// Table 8.1's statistics on a hand-built configuration whose every figure is computed by hand.
#include "growth/statistics.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

TEST(Statistics, SwedishStandardTypesAndOccupants) {
  EXPECT_EQ(housingType(85.01), 'A');
  EXPECT_EQ(housingType(85.0), 'B');
  EXPECT_EQ(housingType(50.0), 'B');
  EXPECT_EQ(housingType(49.99), 'C');
  EXPECT_EQ(housingType(30.0), 'C');
  EXPECT_EQ(housingType(29.99), '-');
  EXPECT_EQ(occupantsOf('A'), 5);
  EXPECT_EQ(occupantsOf('B'), 3);
  EXPECT_EQ(occupantsOf('C'), 1);
  EXPECT_EQ(occupantsOf('-'), 0);
}

// U1 90 m² (A) on the ground; U2 60 m² (B) east of it; U3 40 m² (C) on U1's roof, which it
// uses as a garden; U4 25 m², two storeys high.
std::vector<Unit> handModel() {
  return {unitOf(1, {box(0, 0, 0, 10, 9, 3)}), unitOf(2, {box(20, 0, 0, 26, 10, 3)}),
          unitOf(3, {box(0, 0, 3, 5, 8, 6)}), unitOf(4, {box(30, 20, 0, 35, 25, 6)})};
}

TEST(Statistics, HandBuiltModel) {
  const Site site = test::openSite(40, 40, 2);
  const std::vector<Unit> units = handModel();
  std::vector<ViewBox> boxes;
  for (const Unit& u : units)
    for (const Box& p : u.parts) boxes.push_back({p, std::uint32_t(u.id)});
  ExactViewMapper mapper;
  const Statistics st = computeStatistics(site, units, mapper.render(boxes, site.bounds()));
  EXPECT_DOUBLE_EQ(st.siteArea, 1600);
  EXPECT_EQ(st.units, 4);
  EXPECT_EQ(st.typeA, 1);
  EXPECT_EQ(st.typeB, 1);
  EXPECT_EQ(st.typeC, 1);
  EXPECT_EQ(st.unclassified, 1);
  EXPECT_EQ(st.occupants, 5 + 3 + 1);
  EXPECT_DOUBLE_EQ(st.occupancyRatio, 9.0 / (1600 * 2));
  EXPECT_DOUBLE_EQ(st.averageFloorArea, (90 + 60 + 40 + 25) / 4.0);
  // Views by hand. U1: +x hidden by U2 (which covers y 0..9, z 0..3), -x 27, ±y 30 → 87,
  // three views. U2: -x only y 9..10 is clear of U1 (3), +x 30, ±y 18 → 69, four views.
  // U3: ±x 24, ±y 15 → 78. U4: 4 x 30 → 120.
  EXPECT_NEAR(st.perUnit[0].view, 87, 1e-9);
  EXPECT_NEAR(st.perUnit[1].view, 69, 1e-9);
  EXPECT_NEAR(st.perUnit[2].view, 78, 1e-9);
  EXPECT_NEAR(st.perUnit[3].view, 120, 1e-9);
  EXPECT_NEAR(st.averageView, (87 + 69 + 78 + 120) / 4.0, 1e-9);
  EXPECT_EQ(st.perUnit[0].views, 3);
  EXPECT_EQ(st.twoViews, 0);
  EXPECT_EQ(st.threeViews, 1);
  EXPECT_EQ(st.fourViews, 3);
  EXPECT_EQ(st.doubleVolume, 1);
  EXPECT_TRUE(st.perUnit[3].doubleVolume);
  // U1's roof outside U3 is 90 − 40 = 50 m² and meets U3 along x = 5 (8 m): U3's garden.
  EXPECT_EQ(st.outdoorSpace, 1);
  EXPECT_TRUE(st.perUnit[2].outdoorSpace);
}

TEST(Statistics, ARoofCoveredEverywhereOrOutOfReachIsNoGarden) {
  const Site site = test::openSite(40, 40, 3);
  // U2 covers all of U1's roof: nothing left open.
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 6, 6, 3)}), unitOf(2, {box(0, 0, 3, 6, 6, 6)})};
  EXPECT_FALSE(hasOutdoorSpace(site, units, 1));
  // U2 one storey higher than U1's roof: the roof is not at its floor.
  units = {unitOf(1, {box(0, 0, 0, 12, 6, 3)}), unitOf(2, {box(0, 0, 6, 6, 6, 9)})};
  EXPECT_FALSE(hasOutdoorSpace(site, units, 1));
  // At its floor, but the open roof touches it along 0.5 m only (a corner): no door.
  units = {unitOf(1, {box(0, 0, 0, 6, 6, 3)}), unitOf(2, {box(5.5, 6, 3, 9, 9, 6)})};
  EXPECT_FALSE(hasOutdoorSpace(site, units, 1));
  // Along 3 m with 30 m² open: a garden.
  units = {unitOf(1, {box(0, 0, 0, 6, 6, 3)}), unitOf(2, {box(3, 6, 3, 9, 9, 6)})};
  EXPECT_TRUE(hasOutdoorSpace(site, units, 1));
}

}  // namespace
}  // namespace corbel::growth
