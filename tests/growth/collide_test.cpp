// Collide-and-extrude (Sec. 5.3, Fig. 5.3–5.4): the free region of a face by CGAL's polygon
// difference against hand-computed areas and columns, the interval twin against the CGAL result
// on random configurations, the splits they give, and the stair base's geometry by hand.
#include "growth/collide.h"
#include "growth/rng.h"
#include "growth/tolerances.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::growth {
namespace {

double freeArea(const std::vector<FreePolygon>& region) {
  double a = 0;
  for (const FreePolygon& p : region) a += p.area();
  return a;
}

std::vector<Interval> columnsOf(const FaceObstacles& f) {
  const std::vector<Interval> exact = freeColumns(f);
  EXPECT_EQ(exact, freeColumnsByIntervals(f)) << "the interval twin differs from the CGAL free region";
  return exact;
}

// A two-storey face 9 m wide; an obstacle over its upper right corner (3 × 3 m).
TEST(Collide, ObstacleOverACorner) {
  const FaceObstacles f{{0, 0, 9, 6}, {{6, 3, 12, 9}}};
  const auto region = freeRegion(f);
  ASSERT_EQ(region.size(), 1u);
  EXPECT_EQ(region[0].outer.size(), 6u);  // an L
  EXPECT_TRUE(region[0].holes.empty());
  EXPECT_DOUBLE_EQ(freeArea(region), 54 - 9);
  // The lower storey is free under the obstacle, but a split cuts the whole height.
  EXPECT_EQ(columnsOf(f), (std::vector<Interval>{{0, 6}}));
  EXPECT_EQ(collideSplits(f.face, columnsOf(f), 3), (std::vector<CollideSplit>{{6, false, {0, 6}}}));
}

// An obstacle over the middle of a 12 m face, the whole height, then only a band of it.
TEST(Collide, ObstacleInTheMiddle) {
  FaceObstacles f{{0, 0, 12, 3}, {{4, -1, 7, 5}}};
  auto region = freeRegion(f);
  EXPECT_EQ(region.size(), 2u);
  EXPECT_DOUBLE_EQ(freeArea(region), 36 - 9);
  const std::vector<Interval> columns = columnsOf(f);
  EXPECT_EQ(columns, (std::vector<Interval>{{0, 4}, {7, 12}}));
  // Both free pieces reach an end of the face: low first.
  EXPECT_EQ(collideSplits(f.face, columns, 3), (std::vector<CollideSplit>{{4, false, {0, 4}}, {7, true, {7, 12}}}));
  // Wider pieces needed: only the high one is wide enough (5 m), and 7 m is left below it.
  EXPECT_EQ(collideSplits(f.face, columns, 5), (std::vector<CollideSplit>{{7, true, {7, 12}}}));
  f.obstacles = {{4, 1, 7, 2}};  // a hole in the free region
  region = freeRegion(f);
  ASSERT_EQ(region.size(), 1u);
  EXPECT_EQ(region[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(freeArea(region), 36 - 3);
  EXPECT_EQ(columnsOf(f), columns);
}

TEST(Collide, ObstacleOverTheWholeFace) {
  const FaceObstacles f{{2, 0, 8, 3}, {{0, -1, 10, 4}}};
  EXPECT_TRUE(freeRegion(f).empty());
  EXPECT_TRUE(columnsOf(f).empty());
  EXPECT_TRUE(collideSplits(f.face, {}, 3).empty());
  // Nothing in the way: one column, and no split (the face is not colliding).
  const FaceObstacles open{{2, 0, 8, 3}, {}};
  EXPECT_DOUBLE_EQ(freeArea(freeRegion(open)), 18);
  EXPECT_EQ(columnsOf(open), (std::vector<Interval>{{2, 8}}));
  EXPECT_TRUE(collideSplits(open.face, columnsOf(open), 3).empty());
}

// Two obstacles on a 15 m face: free columns 0–2 (too narrow), 5–10 (between them) and 12–15.
TEST(Collide, TwoObstacles) {
  const FaceObstacles f{{0, 0, 15, 3}, {{2, 0, 5, 3}, {10, 0, 12, 3}}};
  EXPECT_EQ(freeRegion(f).size(), 3u);
  EXPECT_DOUBLE_EQ(freeArea(freeRegion(f)), 45 - 9 - 6);
  const std::vector<Interval> columns = columnsOf(f);
  EXPECT_EQ(columns, (std::vector<Interval>{{0, 2}, {5, 10}, {12, 15}}));
  // The wholly free end piece first; the middle column needs a split at either of its ends.
  EXPECT_EQ(collideSplits(f.face, columns, 3),
            (std::vector<CollideSplit>{{12, true, {12, 15}}, {10, false, {5, 10}}, {5, true, {5, 10}}}));
}

// Obstacles touching each other close the column between them; obstacles touching the face
// only along an edge (beside it, or above it) are not in the way.
TEST(Collide, TouchingEdges) {
  const FaceObstacles f{{0, 0, 12, 3}, {{3, 0, 6, 3}, {6, 0, 9, 3}, {12, 0, 14, 3}, {0, 3, 12, 6}, {-2, 0, 0, 3}}};
  EXPECT_EQ(freeRegion(f).size(), 2u);
  EXPECT_DOUBLE_EQ(freeArea(freeRegion(f)), 36 - 18);
  EXPECT_EQ(columnsOf(f), (std::vector<Interval>{{0, 3}, {9, 12}}));
  // Overlapping obstacles, and one that ends exactly at the face's edge.
  const FaceObstacles g{{0, 0, 12, 3}, {{2, 0, 6, 2}, {4, 1, 8, 3}, {10, 0, 12, 3}}};
  EXPECT_DOUBLE_EQ(freeArea(freeRegion(g)), 36 - (8 + 8 - 2) - 6);
  EXPECT_EQ(columnsOf(g), (std::vector<Interval>{{0, 2}, {8, 10}}));
}

// The interval twin against the CGAL free region on random faces and obstacles: coordinates on
// a 0.25 m grid (so edges often coincide and obstacles touch) and arbitrary doubles.
TEST(Collide, IntervalTwinAgreesWithTheCgalFreeRegion) {
  Rng rng(20261202);
  int splits = 0, partial = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool grid = trial % 2 == 0;
    auto coord = [&](double lo, double hi) {
      const double x = lo + rng.uniform() * (hi - lo);
      return grid ? std::round(x * 4) / 4 : x;
    };
    FaceObstacles f;
    const double w = grid ? 3 + 0.25 * rng.below(49) : 3 + 12 * rng.uniform();
    const double h = rng.below(2) ? 3 : 6;
    f.face = {0, 0, w, h};
    const int n = rng.below(6);
    for (int i = 0; i < n; ++i) {
      const double u0 = coord(-2, w + 1), v0 = rng.below(3) ? coord(-1, h) : (rng.below(2) ? 0 : 3);
      const double u1 = u0 + coord(0, 6), v1 = rng.below(2) ? h : v0 + coord(0, 4);
      f.obstacles.push_back({u0, v0, u1, v1});
    }
    const std::vector<Interval> exact = freeColumns(f), fast = freeColumnsByIntervals(f);
    ASSERT_EQ(exact, fast) << "trial " << trial;
    // The region's area against the rectangle difference of box.h (no CGAL).
    std::vector<Rect> left{f.face};
    for (const Rect& o : f.obstacles) left = subtract(left, o);
    ASSERT_NEAR(freeArea(freeRegion(f)), totalArea(left), 1e-9) << "trial " << trial;
    // Every free column lies in the free region: its area is covered by it exactly.
    for (const Interval& c : exact) {
      std::vector<Rect> column{{c.lo, 0, c.hi, h}};
      for (const Rect& o : f.obstacles) column = subtract(column, o);
      ASSERT_NEAR(totalArea(column), (c.hi - c.lo) * h, 1e-9) << "trial " << trial;
    }
    if (!exact.empty() && !(exact.size() == 1 && exact[0] == Interval{0, w})) ++partial;
    splits += int(collideSplits(f.face, exact, 3).size());
  }
  EXPECT_GT(partial, 1000);  // the cases that matter: faces partly blocked
  EXPECT_GT(splits, 500);
}

// Fig. 5.4 by hand: a one-storey part on storey 2 (z 6–9) whose +x face is 0.2 m short of a
// staircase of storey 0 (roof at z = 3).
TEST(Collide, StairBasePartCoversTheWholeTop) {
  const Box b{{0, 0, 6}, {6, 4, 9}};
  const Box stair{{6.2, 0.5, 0}, {10.2, 3.5, 3}};
  std::string why;
  const auto part = stairBasePart(b, Side::PosX, stair, 3, 0.3, &why);
  ASSERT_TRUE(part) << why;
  EXPECT_EQ(*part, (Box{{6, 0.5, 3}, {10.2, 3.5, 9}}));  // the top and the 0.2 m strip, two storeys
  // The same from the other side (-x face of a part beyond the staircase).
  const Box c{{10.5, 0, 6}, {15, 4, 9}};
  EXPECT_EQ(*stairBasePart(c, Side::NegX, stair, 3, 0.3), (Box{{6.2, 0.5, 3}, {10.5, 3.5, 9}}));
  // Refused: the roof at the part's own floor, the face 0.4 m short, the staircase beside the
  // face (0.8 m of it in front), a double-volume part, a floor face.
  EXPECT_FALSE(stairBasePart(Box{{0, 0, 3}, {6, 4, 6}}, Side::PosX, stair, 3, 0.3, &why));
  EXPECT_EQ(why, "the staircase's roof is not one storey below the part's floor");
  EXPECT_FALSE(stairBasePart(Box{{0, 0, 6}, {5.8, 4, 9}}, Side::PosX, stair, 3, 0.3, &why));
  EXPECT_EQ(why, "the face has not reached the staircase");
  EXPECT_FALSE(stairBasePart(Box{{0, 2.7, 6}, {6, 6.7, 9}}, Side::PosX, stair, 3, 0.3, &why));
  EXPECT_EQ(why, "the staircase faces the part along less than a door's width");
  EXPECT_FALSE(stairBasePart(Box{{0, 0, 6}, {6, 4, 12}}, Side::PosX, stair, 3, 0.3, &why));
  EXPECT_FALSE(stairBasePart(b, Side::Bottom, stair, 3, 0.3, &why));
  // Overlapping the staircase in plan already (the face went past its near side).
  EXPECT_FALSE(stairBasePart(Box{{0, 0, 6}, {7, 4, 9}}, Side::PosX, stair, 3, 0.3));
}

// Collide-and-extrude by hand (Fig. 5.3, Fig. 8.4), on cases worked by hand.
Box box(double x0, double y0, double z0, double x1, double y1, double z1) { return {{x0, y0, z0}, {x1, y1, z1}}; }

Unit oneRoom() {
  Unit u;
  u.id = 1;
  u.parts = {box(0, 0, 0, 10, 10, 3)};
  return u;
}

double unionVolume(const Unit& u) {
  double v = 0;
  for (const Box& p : u.parts) v += p.volume();
  return v;
}

void expectSound(const Unit& u, const std::vector<Box>& obstacles) {
  for (std::size_t i = 0; i < u.parts.size(); ++i) {
    for (std::size_t j = i + 1; j < u.parts.size(); ++j) EXPECT_FALSE(interiorsOverlap(u.parts[i], u.parts[j], kEps));
    for (const Box& o : obstacles) EXPECT_FALSE(interiorsOverlap(u.parts[i], o, kEps)) << "part " << i;
  }
}

TEST(CollideAndExtrude, EachStretchOfTheFaceAdvancesUntilItMeetsSomething) {
  // +x of a 10 × 10 room pushed 4 m; a block 2 m out covers y 0..4: that stretch stops at it.
  const std::vector<Box> obstacles{box(12, 0, 0, 20, 4, 3)};
  const auto e = collideAndExtrude(oneRoom(), 0, Side::PosX, 4, obstacles, 3);
  ASSERT_TRUE(e);
  ASSERT_EQ(e->unit.parts.size(), 2u);
  EXPECT_EQ(e->unit.parts[0], box(0, 0, 0, 12, 4, 3));
  EXPECT_EQ(e->unit.parts[1], box(0, 4, 0, 14, 10, 3));
  EXPECT_DOUBLE_EQ(e->added, (4 * 2 + 6 * 4) * 3.0);
  EXPECT_DOUBLE_EQ(unionVolume(e->unit), 300 + e->added);
  expectSound(e->unit, obstacles);
}

TEST(CollideAndExtrude, AStretchNarrowerThanARoomGoesWithTheNeighbourThatReachesLess) {
  // A 1 m post 1 m out at y 4..5 between the block (reach 2) and open ground (reach 4): the
  // post's stretch joins the block's, which then stops at the post.
  const std::vector<Box> obstacles{box(12, 0, 0, 20, 4, 3), box(11, 4, 0, 12, 5, 3)};
  const auto e = collideAndExtrude(oneRoom(), 0, Side::PosX, 4, obstacles, 3);
  ASSERT_TRUE(e);
  ASSERT_EQ(e->unit.parts.size(), 2u);
  EXPECT_EQ(e->unit.parts[0], box(0, 0, 0, 11, 5, 3));
  EXPECT_EQ(e->unit.parts[1], box(0, 5, 0, 14, 10, 3));
  EXPECT_DOUBLE_EQ(e->added, (5 * 1 + 5 * 4) * 3.0);
  expectSound(e->unit, obstacles);
}

TEST(CollideAndExtrude, WhatIsAboveTheStoreyOrBesideTheFaceDoesNotStopIt) {
  const std::vector<Box> obstacles{box(11, 0, 3, 20, 10, 6), box(11, 10, 0, 20, 14, 3), box(-5, 0, 0, -1, 10, 3)};
  const auto e = collideAndExtrude(oneRoom(), 0, Side::PosX, 4, obstacles, 3);
  ASSERT_TRUE(e);
  ASSERT_EQ(e->unit.parts.size(), 1u);
  EXPECT_EQ(e->unit.parts[0], box(0, 0, 0, 14, 10, 3));
  // -y the same way, 2 m: a part may grow on every side.
  const auto f = collideAndExtrude(e->unit, 0, Side::NegY, 2, obstacles, 3);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->unit.parts[0], box(0, -2, 0, 14, 10, 3));
}

TEST(CollideAndExtrude, TheUnitsOwnPartsAreInTheWayAndASideAgainstOneCannotMove) {
  Unit u = oneRoom();
  u.parts = {box(0, 0, 0, 4, 4, 3), box(0, 6, 0, 8, 10, 3), box(4, 0, 0, 8, 4, 3)};
  const auto e = collideAndExtrude(u, 0, Side::PosY, 5, {}, 3);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->unit.parts[0], box(0, 0, 0, 4, 6, 3)) << "stops at its own part 2 m out";
  std::string why;
  EXPECT_FALSE(collideAndExtrude(u, 0, Side::PosX, 1, {}, 3, &why)) << "its +x side is the third part's -x";
  EXPECT_NE(why.find("another part"), std::string::npos) << why;
}

TEST(CollideAndExtrude, PullsInKeepARoomAndFloorsAndBlockedFacesAreRefused) {
  const auto in = collideAndExtrude(oneRoom(), 0, Side::PosX, -2, {}, 3);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->unit.parts[0], box(0, 0, 0, 8, 10, 3));
  EXPECT_DOUBLE_EQ(in->added, -2 * 10 * 3.0);
  std::string why;
  EXPECT_FALSE(collideAndExtrude(oneRoom(), 0, Side::PosX, -8, {}, 3, &why));
  EXPECT_NE(why.find("deep"), std::string::npos) << why;
  EXPECT_FALSE(collideAndExtrude(oneRoom(), 0, Side::Top, 3, {}, 3, &why));
  EXPECT_NE(why.find("storeys"), std::string::npos) << why;
  EXPECT_FALSE(collideAndExtrude(oneRoom(), 0, Side::PosX, 2, {box(10, -1, 0, 12, 11, 3)}, 3, &why));
  EXPECT_NE(why.find("right at the face"), std::string::npos) << why;
  EXPECT_FALSE(collideAndExtrude(oneRoom(), 3, Side::PosX, 2, {}, 3, &why));
}

// A floor or ceiling moved by hand goes by whole storeys and keeps the growth's rules: parts of
// one or two storeys, a unit over at most two, nothing in the way, nothing under the ground.
TEST(MoveFloorOrCeiling, ARoomBecomesADoubleVolumeAndBackByWholeStoreys) {
  const auto up = moveFloorOrCeiling(oneRoom(), 0, Side::Top, 1, 3, {}, 0);
  ASSERT_TRUE(up);
  EXPECT_EQ(up->unit.parts[0], box(0, 0, 0, 10, 10, 6));
  EXPECT_DOUBLE_EQ(up->added, 10 * 10 * 3.0);
  EXPECT_DOUBLE_EQ(unionVolume(up->unit), 300 + up->added);
  // Back down by one storey: the room again, the volume given back.
  const auto down = moveFloorOrCeiling(up->unit, 0, Side::Top, -1, 3, {}, 0);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->unit.parts[0], oneRoom().parts[0]);
  EXPECT_DOUBLE_EQ(down->added, -300.0);
  // A room on the first floor (z 3..6) takes the storey below it.
  Unit high = oneRoom();
  high.parts[0] = box(0, 0, 3, 10, 10, 6);
  const auto floor = moveFloorOrCeiling(high, 0, Side::Bottom, 1, 3, {}, 0);
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->unit.parts[0], box(0, 0, 0, 10, 10, 6));
}

TEST(MoveFloorOrCeiling, WhatBreaksAGrowthRuleIsRefusedAndNothingMoves) {
  std::string why;
  auto refused = [&](const Unit& u, int part, Side s, int storeys, const std::vector<Box>& obstacles, const char* says) {
    why.clear();
    EXPECT_FALSE(moveFloorOrCeiling(u, part, s, storeys, 3, obstacles, 0, &why)) << says;
    EXPECT_NE(why.find(says), std::string::npos) << why;
  };
  refused(oneRoom(), 0, Side::Top, 2, {}, "one or two storeys");      // three storeys high
  refused(oneRoom(), 0, Side::Top, -1, {}, "one or two storeys");     // no height left
  refused(oneRoom(), 0, Side::Bottom, 1, {}, "below the ground");
  refused(oneRoom(), 0, Side::Top, 0, {}, "whole storeys");
  refused(oneRoom(), 0, Side::PosX, 1, {}, "a wall");
  // A neighbour's room over one corner of the ceiling stops the whole ceiling: no part is a
  // storey and a half, and a ceiling is not split.
  refused(oneRoom(), 0, Side::Top, 1, {box(8, 8, 3, 14, 14, 6)}, "above the ceiling");
  // Beside the ceiling (touching its edge) is not in the way.
  EXPECT_TRUE(moveFloorOrCeiling(oneRoom(), 0, Side::Top, 1, 3, {box(10, 0, 3, 14, 10, 6)}, 0));
  // A unit of a ground-floor room and a first-floor room beside it spans two storeys already:
  // the upper room cannot rise, the lower one can.
  Unit split = oneRoom();
  split.parts = {box(0, 0, 0, 5, 10, 3), box(5, 0, 3, 10, 10, 6)};
  refused(split, 1, Side::Top, 1, {}, "two storeys");
  EXPECT_TRUE(moveFloorOrCeiling(split, 0, Side::Top, 1, 3, {}, 0));
  // A ceiling under the unit's own room above cannot move.
  Unit stacked = oneRoom();
  stacked.parts = {box(0, 0, 0, 10, 10, 3), box(0, 0, 3, 10, 10, 6)};
  refused(stacked, 0, Side::Top, 1, {}, "meets another part");
}

}  // namespace
}  // namespace corbel::growth
