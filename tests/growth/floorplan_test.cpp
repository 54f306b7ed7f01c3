// Floorplans (Sec. 7.1): the update of Fig. 7.2-7.3 by hand, and random op sequences whose
// links are checked against unit-length boundary pieces shared by two units.
#include "growth/floorplan.h"

#include "grid_oracle.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

namespace corbel::growth {
namespace {

constexpr int kN = 0, kE = 1, kS = 2, kW = 3;

TEST(Floorplan, SplitAndAdvanceRelinkAsInFig73) {
  // Fig. 7.2: T1 (2 × 2) left of the taller T2 (2 × 4); b11 (T1 east) touches d21 (T2 west).
  Floorplan plan;
  ASSERT_EQ(plan.addUnit(ShapeTree::canonical({0, 0}, 2, 2)), 0);
  ASSERT_EQ(plan.addUnit(ShapeTree::canonical({2, 0}, 2, 4)), 1);
  ASSERT_EQ(plan.incidences().size(), 1u);
  EXPECT_EQ(plan.incidences()[0].a, (LeafRef{0, kE}));
  EXPECT_EQ(plan.incidences()[0].b, (LeafRef{1, kW}));
  // Fig. 7.3: d21 split at T1's height into d23 (lower), c22 (virtual) and d22 (upper); d22
  // advanced west by 1. The link (b11, d21) goes; (b11, d23) and (a11, c22) come; c22 and a21
  // get new weights.
  const SplitNodes s = plan.faceSplit(1, kW, 2);
  ASSERT_GE(s.first, 0);
  const int d23 = s.first, c22 = s.virtualNode, d22 = s.second;
  ASSERT_TRUE(plan.faceAdvance(1, d22, 1));
  EXPECT_EQ(plan.unit(1).node(c22).facing, Facing::South);
  EXPECT_EQ(plan.unit(1).node(c22).weight, 1);
  EXPECT_EQ(plan.unit(1).node(kN).weight, 3);  // a21
  const std::vector<Incidence> want{{{0, kN}, {1, c22}, 1, 2}, {{0, kE}, {1, d23}, 0, 2}};
  EXPECT_EQ(plan.incidences(), want);
  EXPECT_TRUE(plan.linksOf({1, d22}).empty());
  // Undo restores the single link.
  ASSERT_TRUE(plan.undo());
  ASSERT_TRUE(plan.undo());
  EXPECT_EQ(plan.incidences().size(), 1u);
  EXPECT_EQ(plan.incidences()[0].b, (LeafRef{1, kW}));
}

TEST(Floorplan, RefusesOverlapAndLeavesEverythingAsItWas) {
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 3, 3));
  plan.addUnit(ShapeTree::canonical({3, 0}, 3, 3));
  EXPECT_EQ(plan.addUnit(ShapeTree::canonical({2, 2}, 3, 3)), -1);
  const auto links = plan.incidences();
  std::string why;
  EXPECT_FALSE(plan.faceAdvance(0, kE, 1, &why));
  EXPECT_NE(why.find("overlap"), std::string::npos);
  EXPECT_EQ(plan.incidences(), links);
  EXPECT_EQ(plan.unit(0).area(), 9);
  EXPECT_EQ(plan.unit(0).historySize(), 0u);
}

TEST(Floorplan, RandomOperatorsKeepUnitsApartAndLinksExact) {
  // Property: after every accepted op, every unit is a simple rectilinear polygon tiled by
  // its boxes, no two units share a cell, and the recorded links are exactly the pairs of
  // leaves of different units that share unit boundary pieces with opposite facings, with
  // the shared length. Undo restores the links.
  std::mt19937_64 rng(87);
  int accepted = 0;
  for (int trial = 0; trial < 25; ++trial) {
    Floorplan plan;
    for (int i = 0; i < 4; ++i) plan.addUnit(ShapeTree::canonical({GridCoord(i % 2) * 6, GridCoord(i / 2) * 6}, 6, 6));
    std::vector<std::pair<std::size_t, decltype(test::recorded(plan))>> states{
        {plan.historySize(), test::recorded(plan)}};
    for (int step = 0; step < 60; ++step) {
      const int u = int(rng() % plan.units().size());
      const std::vector<int> leaves = plan.unit(u).leaves();
      const int leaf = leaves[rng() % leaves.size()];
      bool ok = false;
      if (rng() % 2) {
        const GridCoord w = plan.unit(u).node(leaf).weight;
        if (w >= 2) ok = plan.faceSplit(u, leaf, 1 + GridCoord(rng() % std::uint64_t(w - 1))).first >= 0;
      } else {
        const GridCoord alpha = GridCoord(rng() % 5) - 2;
        ok = alpha != 0 && plan.faceAdvance(u, leaf, alpha);
      }
      if (!ok) continue;
      ++accepted;
      std::string why;
      ASSERT_TRUE(plan.valid(&why)) << why;
      std::set<test::Cell> all;
      std::size_t total = 0;
      for (const ShapeTree& t : plan.units()) {
        const auto cells = test::cellsOf(t.outline());
        total += cells.size();
        all.insert(cells.begin(), cells.end());
      }
      EXPECT_EQ(all.size(), total) << "two units share a cell";
      ASSERT_EQ(test::recorded(plan), test::sharedPieces(plan));
      states.push_back({plan.historySize(), test::recorded(plan)});
    }
    for (std::size_t k = states.size(); k-- > 0;) {
      while (plan.historySize() > states[k].first) ASSERT_TRUE(plan.undo());
      EXPECT_EQ(test::recorded(plan), states[k].second);
    }
  }
  EXPECT_GT(accepted, 600);
}

TEST(Floorplan, ExtrudesBoxesToUnitsOfTheirStoreys) {
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({4, 0}, 4, 4));
  const SplitNodes s = plan.faceSplit(0, kN, 2);
  ASSERT_TRUE(plan.faceAdvance(0, s.second, 2));
  Extrusion how;
  how.cell = 0.5;
  how.storeyHeight = 3;
  how.storeys = {1, 2};  // the second unit is a double volume
  const std::vector<Unit> units = extrude(plan, how);
  ASSERT_EQ(units.size(), 2u);
  EXPECT_DOUBLE_EQ(units[0].floorArea(), (16 + 4) * 0.25);
  EXPECT_DOUBLE_EQ(units[0].volume(), (16 + 4) * 0.25 * 3);
  EXPECT_DOUBLE_EQ(units[1].volume(), 16 * 0.25 * 6);
  EXPECT_FALSE(unitMesh(units[0]).faces.empty());
}

}  // namespace
}  // namespace corbel::growth
