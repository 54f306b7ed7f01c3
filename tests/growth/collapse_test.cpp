// Collapsing staircases (Sec. 7.3.1): thousands of random rectilinear units, made as blobs of
// grid cells (independent of the ShapeTree), collapse to a rectangle and are rebuilt
// exactly from the canonical square by Face Split and Face Advance.
#include "growth/collapse.h"

#include "grid_oracle.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

namespace corbel::growth {
namespace {

using test::Cell;

std::set<Cell> randomBlob(std::mt19937_64& rng, int cells, int span) {
  std::set<Cell> s{{0, 0}};
  std::vector<Cell> list{{0, 0}};
  while (int(s.size()) < cells) {
    const Cell from = list[rng() % list.size()];
    const int d = int(rng() % 4);
    const Cell c{from.first + (d == 0) - (d == 1), from.second + (d == 2) - (d == 3)};
    if (std::abs(c.first) > span || std::abs(c.second) > span || s.count(c)) continue;
    s.insert(c);
    list.push_back(c);
  }
  return s;
}

TEST(CollapseStaircases, AnUShapeCollapsesInTwoSteps) {
  // A 6 × 4 block with a 2 × 3 notch from below: eight corners, two staircases each side.
  const std::vector<GridPoint> u{{0, 4}, {6, 4}, {6, 0}, {4, 0}, {4, 3}, {2, 3}, {2, 0}, {0, 0}};
  ASSERT_TRUE(simpleRectilinear(u));
  const auto trace = collapseStaircases(u);
  ASSERT_TRUE(trace);
  // Filling the notch is one collapse (a bump: both walls vanish); cutting an arm off first
  // takes two.
  EXPECT_GE(trace->steps.size(), 1u);
  EXPECT_LE(trace->steps.size(), 2u);
  std::string why;
  const ShapeTree t = rebuildFromCanonical(*trace, &why);
  EXPECT_EQ(canonicalCycle(t.outline()), canonicalCycle(u)) << why;
}

TEST(CollapseStaircases, EveryRandomRectilinearUnitReducesToTheSquareAndBack) {
  // Property (the spanning claim of Sec. 7.3.1): for every simple rectilinear unit, the
  // collapse ends in a rectangle; the canonical square grown by the reversed steps has the
  // unit's exact outline and area, every intermediate tree is valid, and undoing its whole
  // history gives back the 1 × 1 square.
  std::mt19937_64 rng(73);
  int shapes = 0, maxCorners = 0;
  while (shapes < 3000) {
    const std::set<Cell> blob = randomBlob(rng, 3 + int(rng() % 40), 7);
    const std::vector<GridPoint> outline = test::outlineOfCells(blob);
    if (outline.empty()) continue;
    ++shapes;
    maxCorners = std::max(maxCorners, int(outline.size()));
    ASSERT_TRUE(simpleRectilinear(outline));
    const auto trace = collapseStaircases(outline, {rng(), false});
    ASSERT_TRUE(trace) << "stuck on shape " << shapes;
    std::string why;
    ShapeTree t = rebuildFromCanonical(*trace, &why);
    ASSERT_EQ(canonicalCycle(t.outline()), canonicalCycle(outline)) << "shape " << shapes << ": " << why;
    ASSERT_EQ(t.area(), GridCoord(blob.size()));
    ASSERT_TRUE(t.valid(&why)) << why;
    EXPECT_EQ(test::cellsOf(t.boxes()), blob);
    while (t.undo()) {
    }
    EXPECT_EQ(t.outline(), (std::vector<GridPoint>{{trace->rectangle.x0, trace->rectangle.y0 + 1},
                                                   {trace->rectangle.x0 + 1, trace->rectangle.y0 + 1},
                                                   {trace->rectangle.x0 + 1, trace->rectangle.y0},
                                                   {trace->rectangle.x0, trace->rectangle.y0}}));
  }
  EXPECT_GE(maxCorners, 16);
}

TEST(CollapseStaircases, RemovingOnlyCutsTheUnitIntoRectangles) {
  // With removals only, each collapse cuts a rectangle off: the cut rectangles and the last
  // one tile the unit (the sea decomposition of Alg. 2 relies on this).
  std::mt19937_64 rng(74);
  int shapes = 0, stuck = 0;
  while (shapes < 1000) {
    const std::set<Cell> blob = randomBlob(rng, 3 + int(rng() % 30), 6);
    const std::vector<GridPoint> outline = test::outlineOfCells(blob);
    if (outline.empty()) continue;
    ++shapes;
    const auto trace = collapseStaircases(outline, {rng(), true});
    if (!trace) {
      ++stuck;
      continue;
    }
    std::vector<GridRect> parts{trace->rectangle};
    for (const CollapseStep& s : trace->steps) {
      EXPECT_GT(s.alpha, 0);
      parts.push_back(s.swept);
    }
    std::size_t total = 0;
    for (const GridRect& r : parts) total += std::size_t(r.area());
    EXPECT_EQ(total, blob.size());
    EXPECT_EQ(test::cellsOf(parts), blob);
  }
  RecordProperty("stuck", stuck);
  EXPECT_EQ(stuck, 0);
}

}  // namespace
}  // namespace corbel::growth
