// ShapeTree (Ch. 6): the tree operations of Fig. 6.5-6.6 against hand-drawn outlines, and
// random op sequences against an independent raster of the outline and the boxes.
#include "growth/shapetree.h"

#include "grid_oracle.h"

#include <gtest/gtest.h>

#include <random>

namespace corbel::growth {
namespace {

using test::cellsOf;

constexpr int kN = 0, kE = 1, kS = 2, kW = 3;  // the four top-level nodes of a canonical unit

TEST(ShapeTree, CanonicalUnitIsFourLabelledLeaves) {
  // Fig. 6.1: a square; leaves a, b, c, d clockwise with their lengths as weights.
  const ShapeTree t = ShapeTree::canonical({0, 0}, 5, 3);
  ASSERT_EQ(t.leaves(), (std::vector<int>{kN, kE, kS, kW}));
  EXPECT_EQ(facingLetter(t.node(kN).facing), 'a');
  EXPECT_EQ(facingLetter(t.node(kW).facing), 'd');
  EXPECT_EQ(t.node(kN).weight, 5);
  EXPECT_EQ(t.node(kE).weight, 3);
  EXPECT_EQ(t.outline(), (std::vector<GridPoint>{{0, 3}, {5, 3}, {5, 0}, {0, 0}}));
  EXPECT_EQ(t.area(), 15);
  EXPECT_EQ(t.faceCount(), 4);
  EXPECT_TRUE(t.valid());
}

TEST(ShapeTree, SplitThenAdvanceMakesTheLShapeOfFig64) {
  // A 4 × 4 square; its east edge runs from (4,4) down to (4,0). Split it 2 from its start:
  // b1 (upper), a virtual node, b2 (lower) - Fig. 6.5.
  ShapeTree t = ShapeTree::canonical({0, 0}, 4, 4);
  const SplitNodes s = t.faceSplit(kE, 2);
  ASSERT_GE(s.first, 0);
  EXPECT_EQ(t.node(kE).children, (std::vector<int>{s.first, s.virtualNode, s.second}));
  EXPECT_TRUE(t.node(s.virtualNode).isVirtual());
  EXPECT_EQ(t.faceCount(), 5);        // the two pieces are faces, the virtual node is not
  EXPECT_EQ(t.outline().size(), 4u);  // geometry unchanged
  // Advance b2 east by 3 (Fig. 6.6): the virtual node becomes a north-facing step of length 3
  // and the next edge (south) grows by 3.
  ASSERT_TRUE(t.faceAdvance(s.second, 3));
  EXPECT_FALSE(t.node(s.virtualNode).isVirtual());
  EXPECT_EQ(t.node(s.virtualNode).facing, Facing::North);
  EXPECT_EQ(t.node(s.virtualNode).weight, 3);
  EXPECT_EQ(t.node(kS).weight, 7);
  EXPECT_EQ(t.outline(), (std::vector<GridPoint>{{0, 4}, {4, 4}, {4, 2}, {7, 2}, {7, 0}, {0, 0}}));
  EXPECT_EQ(t.area(), 16 + 6);
  EXPECT_EQ(t.boxes(), (std::vector<GridRect>{{0, 0, 4, 4}, {4, 0, 7, 2}}));
  EXPECT_EQ(t.faceCount(), 6);
  EXPECT_TRUE(t.valid());
  // The same face advancing again extends its box instead of adding one.
  ASSERT_TRUE(t.faceAdvance(s.second, 1));
  EXPECT_EQ(t.boxes(), (std::vector<GridRect>{{0, 0, 4, 4}, {4, 0, 8, 2}}));
}

TEST(ShapeTree, UndoWalksTheHistoryBack) {
  ShapeTree t = ShapeTree::canonical({0, 0}, 6, 6);
  const auto square = t.outline();
  const SplitNodes s = t.faceSplit(kN, 2);
  ASSERT_TRUE(t.faceAdvance(s.second, 2));
  const SplitNodes s2 = t.faceSplit(s.second, 1);
  ASSERT_TRUE(t.faceAdvance(s2.first, -1));
  EXPECT_EQ(t.historySize(), 4u);
  ASSERT_TRUE(t.undo());
  EXPECT_EQ(t.outline(), (std::vector<GridPoint>{{0, 6}, {2, 6}, {2, 8}, {6, 8}, {6, 0}, {0, 0}}));
  while (t.undo()) {
  }
  EXPECT_EQ(t.outline(), square);
  EXPECT_EQ(t.nodes().size(), 4u);
  EXPECT_EQ(t.boxes().size(), 1u);
}

TEST(ShapeTree, RefusesSplitsOffTheEdgeAndAdvancesThatBreakTheOutline) {
  ShapeTree t = ShapeTree::canonical({0, 0}, 4, 4);
  std::string why;
  EXPECT_LT(t.faceSplit(kE, 0, &why).first, 0);
  EXPECT_LT(t.faceSplit(kE, 4, &why).first, 0);
  const SplitNodes s = t.faceSplit(kE, 2);
  EXPECT_LT(t.faceSplit(kE, 1, &why).first, 0);  // no longer a leaf
  // Retreating b2 by 5 would turn the 4-long south edge inside out.
  EXPECT_FALSE(t.faceAdvance(s.second, -5, &why));
  EXPECT_NE(why.find("negative"), std::string::npos);
  // A U: the south edge notched from below; then pushing one arm through the other.
  ShapeTree u = ShapeTree::canonical({0, 0}, 6, 4);
  const SplitNodes a = u.faceSplit(kS, 2);        // south runs west: (6,0) → (4,0) | (4,0) → (0,0)
  const SplitNodes b = u.faceSplit(a.second, 2);  // (4,0) → (2,0) | (2,0) → (0,0)
  ASSERT_TRUE(u.faceAdvance(b.first, -3));        // a 2 × 3 notch
  EXPECT_EQ(u.area(), 24 - 6);
  const auto before = u.outline();
  // The notch's west wall (the second split's virtual node, now an east-facing edge at x=2)
  // pushed east by 3 would pass the east wall at x=4.
  EXPECT_FALSE(u.faceAdvance(b.virtualNode, 3, &why));
  EXPECT_EQ(u.outline(), before);
  EXPECT_TRUE(u.valid());
}

TEST(ShapeTree, ComponentsAreSubtreesClosedByTheNextLeaf) {
  // Sec. 6.5 / Fig. 6.7: the subtree at a split node lists its pieces; the next leaf from
  // the left (c) completes the component's outline.
  ShapeTree t = ShapeTree::canonical({0, 0}, 4, 4);
  const SplitNodes s = t.faceSplit(kE, 2);
  ASSERT_TRUE(t.faceAdvance(s.second, 3));
  const ShapeComponent c = t.component(kE);
  EXPECT_EQ(c.leaves, (std::vector<int>{s.first, s.virtualNode, s.second}));
  EXPECT_EQ(c.closing, kS);
  EXPECT_EQ(t.component(s.first).closing, s.virtualNode);
}

TEST(ShapeTree, SplitCountsCapSubtrees) {
  // Eq. 6.1: a cap on a subtree's splits, and children's caps within their parent's.
  ShapeTree t = ShapeTree::canonical({0, 0}, 12, 12);
  ASSERT_TRUE(t.setSplitLimit(kN, 2));
  const SplitNodes s = t.faceSplit(kN, 6);
  ASSERT_GE(s.first, 0);
  EXPECT_EQ(t.splitCount(kN), 1);
  ASSERT_GE(t.faceSplit(s.first, 3).first, 0);
  std::string why;
  EXPECT_LT(t.faceSplit(s.second, 3, &why).first, 0);  // a third split under a
  EXPECT_NE(why.find("Eq. 6.1"), std::string::npos);
  EXPECT_GE(t.faceSplit(kE, 6).first, 0);      // other subtrees are free
  EXPECT_FALSE(t.setSplitLimit(kN, 1));        // it already has two
  EXPECT_FALSE(t.setSplitLimit(s.second, 3));  // more than the parent's 2
  EXPECT_TRUE(t.setSplitLimit(s.second, 0));
  EXPECT_TRUE(t.undo());
  EXPECT_TRUE(t.undo());
  EXPECT_GE(t.faceSplit(s.first, 2).first, 0);  // undo gave the split back
  EXPECT_EQ(t.node(s.second).splitLimit, 0);    // and kept the caps
  EXPECT_LT(t.faceSplit(s.second, 2).first, 0);
}

TEST(ShapeTree, RandomOperatorsKeepARectilinearOutlineTiledByItsBoxes) {
  // Property: after every accepted op the outline is simple and rectilinear, labels agree,
  // the boxes rasterise to exactly the cells inside the outline, and an advance changes the
  // area by α × the edge's length; a refused op changes nothing; undo restores exactly.
  std::mt19937_64 rng(8);
  int accepted = 0;
  for (int trial = 0; trial < 60; ++trial) {
    ShapeTree t = ShapeTree::canonical({0, 0}, 8 + GridCoord(rng() % 8), 8 + GridCoord(rng() % 8));
    std::vector<std::pair<std::size_t, std::vector<GridPoint>>> states{{0, t.outline()}};
    for (int step = 0; step < 40; ++step) {
      const std::vector<int> leaves = t.leaves();
      const int leaf = leaves[rng() % leaves.size()];
      const auto before = t.outline();
      const GridCoord area = t.area();
      if (rng() % 2) {
        const GridCoord w = t.node(leaf).weight;
        if (w < 2) continue;
        const SplitNodes s = t.faceSplit(leaf, 1 + GridCoord(rng() % std::uint64_t(w - 1)));
        ASSERT_GE(s.first, 0);
        EXPECT_EQ(t.outline(), before);
      } else {
        const GridCoord alpha = GridCoord(rng() % 7) - 3;
        if (alpha == 0) continue;
        const GridCoord len = t.node(leaf).weight;
        if (!t.faceAdvance(leaf, alpha)) {
          EXPECT_EQ(t.outline(), before);
          continue;
        }
        EXPECT_EQ(t.area(), area + alpha * len);
      }
      ++accepted;
      std::string why;
      ASSERT_TRUE(t.valid(&why)) << why;
      const auto out = t.outline();
      ASSERT_TRUE(simpleRectilinear(out, &why)) << why;
      EXPECT_EQ(cellsOf(out), cellsOf(t.boxes()));
      EXPECT_EQ(GridCoord(cellsOf(out).size()), t.area());
      states.push_back({t.historySize(), out});
    }
    for (std::size_t k = states.size(); k-- > 0;) {
      while (t.historySize() > states[k].first) ASSERT_TRUE(t.undo());
      EXPECT_EQ(t.outline(), states[k].second);
    }
    EXPECT_EQ(t.historySize(), 0u);
  }
  EXPECT_GT(accepted, 1000);
}

}  // namespace
}  // namespace corbel::growth
