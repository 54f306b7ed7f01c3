// The rectangular cartogram (Sec. 7.3.2-7.3.3): Alg. 1 against hand-drawn outlines and a
// raster of the union, the sea decomposition as an exact tiling of the bounding box, and
// realization keeping ≺x and ≺z for every pair of corners.
#include "growth/cartogram.h"

#include "grid_oracle.h"
#include "growth/collapse.h"
#include "growth/completion.h"

#include <gtest/gtest.h>

#include <random>

namespace corbel::growth {
namespace {

std::set<test::Cell> unionCells(const Floorplan& plan) {
  std::set<test::Cell> all;
  for (const ShapeTree& t : plan.units())
    for (const auto& c : test::cellsOf(t.boxes())) all.insert(c);
  return all;
}

std::vector<Form> someForms(int seeds, std::uint64_t seed, int count) {
  return generateForms(test::formRequest(seeds, Fraction::of(3, 10), Fraction::of(4, 10), count, seed)).forms;
}

TEST(BoundaryPath, TwoSquaresOfEqualHeight) {
  // A = [0,4]², B = [4,8]×[0,4]: the outline is the 8 × 4 rectangle. A's east edge starts
  // inside its link with B (StartCovered), B's west edge has its link behind (ContactsBehind),
  // the outer edges have none (NoIncidence).
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({4, 0}, 4, 4));
  const BoundaryTrace t = traceBoundary(plan);
  EXPECT_EQ(canonicalCycle(t.corners), canonicalCycle({{0, 4}, {8, 4}, {8, 0}, {0, 0}}));
  EXPECT_GT(t.cases[int(TraceCase::NoIncidence)], 0);
  EXPECT_GT(t.cases[int(TraceCase::StartCovered)], 0);
  EXPECT_GT(t.cases[int(TraceCase::ContactsBehind)], 0);
}

TEST(BoundaryPath, AContactAheadCutsTheEdge) {
  // B = [4,8]×[−2,2] lower than A = [0,4]²: walking A's east edge down from (4,4), the link
  // with B begins at (4,2) (ContactAhead): the path turns onto B there.
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({4, -2}, 4, 4));
  const BoundaryTrace t = traceBoundary(plan);
  EXPECT_EQ(canonicalCycle(t.corners),
            canonicalCycle({{0, 4}, {4, 4}, {4, 2}, {8, 2}, {8, -2}, {4, -2}, {4, 0}, {0, 0}}));
  EXPECT_GT(t.cases[int(TraceCase::ContactAhead)], 0);
  // The four extremal paths: top (y = 4) to right (x = 8), and so on round.
  const auto& c = t.corners;
  EXPECT_EQ(c[std::size_t(t.paths[0].first)], (GridPoint{4, 4}));
  EXPECT_EQ(c[std::size_t(t.paths[0].second)], (GridPoint{8, 2}));
  EXPECT_EQ(c[std::size_t(t.paths[2].first)], (GridPoint{4, -2}));
  EXPECT_EQ(c[std::size_t(t.paths[2].second)], (GridPoint{0, 0}));
}

TEST(BoundaryPath, GeneratedFormsTraceTheOuterBoundaryOfTheirUnion) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    for (const Form& f : someForms(4 + int(seed % 3), seed, 3)) {
      const auto oracle = test::outlineOfCells(unionCells(f.plan), true);
      if (oracle.empty()) continue;  // units meeting at a single corner: no simple outline
      const BoundaryTrace t = traceBoundary(f.plan);
      EXPECT_EQ(canonicalCycle(t.corners), canonicalCycle(oracle));
      ++checked;
    }
  EXPECT_GT(checked, 10);
}

TEST(SeaRegion, SeaAndSubUnitsTileTheBoundingBox) {
  // Property: the sea rectangles are disjoint, miss every unit, and with the sub-units cover
  // the bounding box cell for cell; a courtyard (sea enclosed by units) is sea too.
  std::vector<Floorplan> plans;
  Floorplan ring;
  ring.addUnit(ShapeTree::canonical({0, 0}, 6, 2));
  ring.addUnit(ShapeTree::canonical({4, 2}, 2, 4));
  ring.addUnit(ShapeTree::canonical({0, 4}, 4, 2));
  ring.addUnit(ShapeTree::canonical({0, 2}, 2, 2));
  plans.push_back(ring);
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    for (Form& f : someForms(5, seed, 3)) plans.push_back(std::move(f.plan));
  int collapsedOnly = 0;
  for (const Floorplan& plan : plans) {
    std::size_t fallback = 0;
    const std::vector<GridRect> sea = seaRectangles(plan, traceBoundary(plan), &fallback);
    // Without a courtyard, collapsing the pockets' steps (Alg. 2) cuts all the sea.
    if (!test::outlineOfCells(unionCells(plan)).empty()) {
      EXPECT_EQ(fallback, 0u);
      ++collapsedOnly;
    }
    const GridRect b = plan.bounds();
    std::size_t total = 0;
    for (const GridRect& r : sea) total += std::size_t(r.area());
    const auto seaCells = test::cellsOf(sea), units = unionCells(plan);
    EXPECT_EQ(seaCells.size(), total) << "sea rectangles overlap";
    for (const auto& c : seaCells) EXPECT_FALSE(units.count(c));
    EXPECT_EQ(seaCells.size() + units.size(), std::size_t(b.area()));
  }
  EXPECT_GT(collapsedOnly, 10);
  const auto ringSea = seaRectangles(ring, traceBoundary(ring));
  EXPECT_EQ(test::cellsOf(ringSea), (std::set<test::Cell>{{2, 2}, {2, 3}, {3, 2}, {3, 3}}));
}

TEST(SeaRegion, AnEmptyFloorplanHasNoSeaAndNoCartogram) {
  const Floorplan none;
  EXPECT_TRUE(traceBoundary(none).corners.empty());
  EXPECT_TRUE(seaRectangles(none, traceBoundary(none)).empty());
  EXPECT_TRUE(Cartogram::of(none).rects.empty());
}

TEST(Relations, SideBySideRectanglesByHand) {
  // A = [0,1]², B = [1,2]×[0,1]; corners 0 SW, 1 SE, 2 NE, 3 NW.
  const std::vector<PlanRect> r{{0, 0, 1, 1}, {1, 0, 2, 1}};
  const Relations rel = relationsOf(r);
  auto at = [](int rect, int corner) { return std::size_t(4 * rect + corner); };
  EXPECT_TRUE(rel.x[at(0, 0)][at(1, 1)]);   // A.SW ≺x B.SE
  EXPECT_TRUE(rel.x[at(0, 3)][at(1, 1)]);   // A.NW ≺x B.SE: up or down is free
  EXPECT_FALSE(rel.x[at(1, 0)][at(0, 1)]);  // the same point: not comparable
  EXPECT_FALSE(rel.x[at(1, 1)][at(0, 0)]);
  EXPECT_TRUE(rel.z[at(0, 0)][at(1, 2)]);   // A.SW ≺z B.NE
  EXPECT_FALSE(rel.z[at(0, 0)][at(1, 1)]);  // same height
}

TEST(Relations, RealizationKeepsBothRelationsForAllCornerPairs) {
  // Property: targets made by a random increasing remap of the lines are realizable; the
  // realized cartogram puts each corner on its target, keeps every rectangle non-empty and
  // has the same ≺x and ≺z as before for every pair of corners. Swapping two comparable
  // corners' targets is refused and changes nothing.
  std::mt19937_64 rng(31);
  int realized = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    for (const Form& f : someForms(4, seed, 2)) {
      Cartogram c = Cartogram::of(f.plan);
      const Relations before = relationsOf(c.geometry());
      std::vector<double> nx = c.xs, ny = c.ys;
      double acc = 0;
      for (double& x : nx) x = (acc += 0.5 + double(rng() % 100) / 20.0);
      acc = 0;
      for (double& y : ny) y = (acc += 0.5 + double(rng() % 100) / 20.0);
      std::vector<Correspondence> targets;
      for (int k = 0; k < 6; ++k) {
        const CornerRef corner{int(rng() % c.rects.size()), int(rng() % 4)};
        const Cartogram::Rect& r = c.rects[std::size_t(corner.rect)];
        const int ix = corner.corner == 0 || corner.corner == 3 ? r.x0 : r.x1, iy = corner.corner <= 1 ? r.y0 : r.y1;
        targets.push_back({corner, nx[std::size_t(ix)], ny[std::size_t(iy)]});
      }
      std::string why;
      ASSERT_TRUE(realize(c, targets, &why)) << why;
      ++realized;
      const std::vector<PlanRect> g = c.geometry();
      for (const Correspondence& t : targets) {
        const auto p = cornerAt(g, t.corner);
        EXPECT_DOUBLE_EQ(p[0], t.x);
        EXPECT_DOUBLE_EQ(p[1], t.y);
      }
      for (const PlanRect& r : g) EXPECT_GT(r.area(), 0);
      EXPECT_EQ(relationsOf(g), before);
      // A rectangle's SW and NE corners are comparable both ways; exchanging their targets is
      // not realizable.
      Cartogram same = c;
      const std::vector<Correspondence> swapped{{{0, 0}, g[0].x1, g[0].y1}, {{0, 2}, g[0].x0, g[0].y0}};
      EXPECT_FALSE(realizable(same, swapped));
      EXPECT_FALSE(realize(same, swapped, &why));
      EXPECT_EQ(same.xs, c.xs);
    }
  EXPECT_GE(realized, 8);
}

}  // namespace
}  // namespace corbel::growth
