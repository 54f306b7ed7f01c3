// kifs/facings.h: a KIFS facade lies on every wall of the mass it follows. The oracles are
// McGraw's fold itself and hand geometry: on a wall that faces along a fold axis, the id across
// the wall is the same all along it and the id along it repeats with the facade period w; a
// rectangle turned by 30° is the box turned by 30°.
#include "kifs/facings.h"

#include "core/document.h"
#include "kifs/follow.h"
#include "kifs/kernel.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <iostream>
#include <random>
#include <set>

namespace corbel::kifs {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

glm::dvec2 rotated(const glm::dvec2& p, double deg) {
  const double c = std::cos(deg * kDeg), s = std::sin(deg * kDeg);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// The `box` preset with bays: its folds' r (0 in the preset, where every point has ids 3, 3)
// set to kifs/params.h's defaults, so the ids change along a wall.
KifsParams boxWithBays() {
  KifsParams p = preset("box");
  p.facade.r = {0.25, 0.125, 0.4};
  return p;
}

// That building following a hand-made shell (world space, the mass unplaced).
Building following(const TriangleSoup& soup, int resolution, int iterations = 0) {
  KifsParams look = boxWithBays();
  if (iterations > 0) look.iterations = iterations;
  KifsSpec k = specOf(look, "box");
  k.mass.footprint = "object";
  k.mass.object = "Mass";
  k.mass.resolution = resolution;
  DocObject mass;
  mass.name = "Mass";
  const KifsParams params = paramsOf(k);
  return Building(params, bakeFollowedMass(mass, soup, params));
}

// A plan with one wall at 30° to the others: A (0, 0), B (20, 0), C (20, 10) and
// D (0, 10 + 20 tan 30°). CD is the longest wall (20 / cos 30° = 23.1 m); its outward normal
// is at 60°, so it turns by −30° onto the y axis; the other three turn by 0.
std::vector<glm::dvec2> slantedPlan() {
  return {{0, 0}, {20, 0}, {20, 10}, {0, 10 + 20 * std::tan(30 * kDeg)}};
}

TEST(KifsFacings, ATurnedRectangleHasOneFacingThatTurnsTheFrame) {
  std::vector<glm::dvec2> plan;
  for (const glm::dvec2& p : std::vector<glm::dvec2>{{-6, -6}, {6, -6}, {6, 6}, {-6, 6}}) plan.push_back(rotated(p, 30));
  const Facings f = facingsOf(test::prism(plan, 22.8), glm::dvec3(0.0), glm::dvec2(1, 0), 6.0);
  EXPECT_NEAR(f.main, 30 * kDeg, 1e-12);
  EXPECT_TRUE(f.turns.empty());
  EXPECT_TRUE(f.walls.empty());
  // Seen from a frame already turned by 10°, the walls turn by 20° more.
  EXPECT_NEAR(facingsOf(test::prism(plan, 22.8), glm::dvec3(0.0), glm::dvec2(std::cos(10 * kDeg), std::sin(10 * kDeg)), 6.0).main,
              20 * kDeg, 1e-12);
  // An axis-aligned box turns by exactly nothing.
  EXPECT_EQ(facingsOf(test::prism({{-6, -6}, {6, -6}, {6, 6}, {-6, 6}}, 22.8), glm::dvec3(0.0), glm::dvec2(1, 0), 6.0).main, 0.0);
}

// The box preset's own box (12 × 12 × 22.8 m) turned by 30° as geometry: at the turned image
// of a point the follower has the preset's ids and storey, and its distances within one cell
// diagonal (the bake's error), as OnTheBoxItIsTheBoxPresetWithinOneCell has unturned.
TEST(KifsFacings, OnATurnedBoxTheFacadeIsTheBoxPresetsTurned) {
  std::vector<glm::dvec2> plan;
  for (const glm::dvec2& p : std::vector<glm::dvec2>{{-6, -6}, {6, -6}, {6, 6}, {-6, 6}}) plan.push_back(rotated(p, 30));
  const Building follow = following(test::prism(plan, 22.8), 40);
  const Building ref(boxWithBays());
  const double diagonal = std::sqrt(3.0) * follow.mass()->cell;
  std::mt19937_64 rng(5);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec3 p = test::uniformIn(rng, {-9, -9, 7.2}, {9, 9, 26});
    const double storey = std::fmod(p.z, 3.0);
    if (storey < 1e-9 || storey > 3.0 - 1e-9) continue;
    const glm::dvec2 q = rotated({p.x, p.y}, 30);
    const Aabb grid = follow.mass()->grid();  // beyond it the bake's bound is the shell box's, which the turn widens
    if (q.x < grid.lo.x || q.y < grid.lo.y || p.z < grid.lo.z || q.x > grid.hi.x || q.y > grid.hi.y || p.z > grid.hi.z)
      continue;
    const Sample f = follow.evaluate({q.x, q.y, p.z}), r = ref.evaluate(p);
    ++compared;
    EXPECT_EQ(f.idX, r.idX) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(f.idZ, r.idZ) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(f.floor, r.floor);
    EXPECT_NEAR(f.surface, r.surface, diagonal + 1e-4);
  }
  EXPECT_GT(compared, 3000);
}

TEST(KifsFacings, AWallAt30DegreesIsAFacingOfItsOwn) {
  const Facings f = facingsOf(test::prism(slantedPlan(), 12), glm::dvec3(0.0), glm::dvec2(1, 0), 6.0);
  EXPECT_NEAR(f.main, -30 * kDeg, 1e-12);  // the longest wall's
  ASSERT_EQ(f.turns.size(), 2u);
  EXPECT_NEAR(f.turns[0], 0.0, 1e-12);
  EXPECT_NEAR(f.turns[1], 30 * kDeg, 1e-12);
  ASSERT_EQ(f.walls.size(), 4u);
  EXPECT_EQ(f.walls[0].facing, 0);  // CD
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(f.walls[i].facing, 1);
}

// A wall shorter than the facade period cannot hold a bay: a 2 m chamfer at 45° on a 20 × 10 m
// plan is a facing of its own only when shorter walls count.
TEST(KifsFacings, AWallShorterThanOneBayTakesTheFacingAroundIt) {
  const double cut = std::sqrt(2.0);  // the chamfer's legs: 2 m along the diagonal
  const TriangleSoup plan = test::prism({{0, 0}, {20, 0}, {20, 10 - cut}, {20 - cut, 10}, {0, 10}}, 9);
  const Facings bays = facingsOf(plan, glm::dvec3(0.0), glm::dvec2(1, 0), 6.0);
  EXPECT_EQ(bays.main, 0.0);
  EXPECT_TRUE(bays.turns.empty());
  const Facings every = facingsOf(plan, glm::dvec3(0.0), glm::dvec2(1, 0), 1.0);
  ASSERT_EQ(every.turns.size(), 2u);
  EXPECT_NEAR(std::abs(every.turns[1]), 45 * kDeg, 1e-12);
}

// Along every wall of the slanted plan, 0.3 m inside it and mid-storey: the id across the wall
// is one value all along, and the id along it repeats every w = 6 m. Folding in the frame's axes
// instead, the 30° wall would change both ids and repeat every w / cos 30° along it.
TEST(KifsFacings, OnEveryWallTheBaysRunAlongTheWall) {
  const std::vector<glm::dvec2> plan = slantedPlan();
  const Building b = following(test::prism(plan, 12), 48);
  const double w = b.params().facade.period;
  ASSERT_EQ(w, 6.0);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const glm::dvec2 a = plan[i], c = plan[(i + 1) % plan.size()];
    const double length = glm::length(c - a);
    const glm::dvec2 along = (c - a) / length, inward(-along.y, along.x);
    auto at = [&](double s) {
      const glm::dvec2 p = a + s * along + 0.3 * inward;
      return b.evaluate({p.x, p.y, 4.5});
    };
    std::set<int> across, alongIds;
    int repeats = 0, samples = 0;
    for (int k = 0; k < 400; ++k) {
      const double s = 1.0 + u(rng) * (length - 2.0 - w);  // a metre from the corners' seams
      const Sample x = at(s), y = at(s + w);
      // Which id runs across depends on the axis the wall faces along after its turn.
      const bool facesZ = std::abs(std::cos(std::atan2(inward.y, inward.x) - (i == 2 ? -30 * kDeg : 0.0))) < 0.5;
      const int acrossId = facesZ ? x.idZ : x.idX, alongId = facesZ ? x.idX : x.idZ;
      across.insert(acrossId);
      alongIds.insert(alongId);
      repeats += (facesZ ? y.idX : y.idZ) == alongId;
      ++samples;
    }
    EXPECT_EQ(across.size(), 1u) << "wall " << i;
    if (length - 2.0 - w > 6.0) {  // a period's span sampled
      EXPECT_GE(alongIds.size(), 2u) << "wall " << i;
    }
    EXPECT_EQ(repeats, samples) << "wall " << i;
  }
}

// facingAt's gaps: every point nearer than `gap` to a point takes that point's facing, and
// every point nearer than `beyond` takes one of the two nearest facings.
TEST(KifsFacings, NoPointWithinTheGapTakesAnotherFacing) {
  const Building b = following(test::prism(slantedPlan(), 12), 16);
  const MassField& m = *b.mass();
  ASSERT_FALSE(m.walls.empty());
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int nearSeam = 0;
  for (int i = 0; i < 3000; ++i) {
    const glm::dvec3 p = m.toFrame(test::uniformIn(rng, {-5, -5, 0}, {25, 27, 1}));
    const MassField::FacingAt at = m.facingAt({p.x, p.y});
    ASSERT_GE(at.gap, 0.0);
    ASSERT_NE(at.other, at.facing);
    nearSeam += at.gap < 0.5;
    for (int k = 0; k < 20; ++k) {
      const double angle = 2 * std::numbers::pi * u(rng), r = at.gap * (0.9 + 0.0999 * u(rng));
      const glm::dvec2 q(p.x + r * std::cos(angle), p.y + r * std::sin(angle));
      ASSERT_EQ(m.facingAt(q).facing, at.facing) << p.x << " " << p.y << " gap " << at.gap;
    }
  }
  EXPECT_GT(nearSeam, 30);
}

// The bound steps across seams but never into the fractal beyond them: from points in the walls
// near the corners where the facings meet, no point within the bound is in the fractal's solid
// (the estimate negative where the inner shell is not: max(d_o, d_KIFS) < 0 in that point's own
// facing). The points are in the fractal's holes in the walls, where the bound is the
// fractal's cell, not d_o's or d_i's. One iteration of Algorithm 1 keeps its estimate close to
// the true distance, so a bound that ignored the seams would reach across them (with the cap
// taken out, this test fails).
TEST(KifsFacings, TheBoundNeverReachesTheFractalAcrossASeam) {
  const std::vector<glm::dvec2> plan = slantedPlan();
  const Building b = following(test::prism(plan, 12), 48, 1);
  const MassField& m = *b.mass();
  const double shell = b.params().mass.shell;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int tested = 0, acrossSeams = 0;
  for (const glm::dvec2& corner : {plan[2], plan[3]}) {  // C and D, where the 30° wall meets the others
    for (int i = 0; i < 6000; ++i) {
      const glm::dvec3 p = test::uniformIn(rng, {corner.x - 2, corner.y - 2, 0.5}, {corner.x + 2, corner.y + 2, 11.5});
      const Sample at = b.evaluate(p);
      if (!(m.distance(p) < 0) || m.distance(p) + shell < 0 || at.surface < 0) continue;  // in a hole in the wall
      const double bound = at.bound;
      const int facing = m.facingAt(glm::dvec2(m.toFrame(p))).facing;
      ++tested;
      for (int k = 0; k < 20; ++k) {
        const glm::dvec3 q = p + 0.99 * bound * u(rng) * test::unitVector(rng);
        const bool across = m.facingAt(glm::dvec2(m.toFrame(q))).facing != facing;
        acrossSeams += across;
        const bool inFractal = b.evaluate(q).surface < 0 && m.distance(q) + shell >= 0;
        ASSERT_FALSE(inFractal) << "from " << p.x << " " << p.y << " " << p.z << " bound " << bound
                                << (across ? " across a seam" : "");
      }
    }
  }
  std::cout << tested << " points in holes, " << acrossSeams << " of their neighbours across a seam\n";
  EXPECT_GT(tested, 300);
  EXPECT_GT(acrossSeams, 200);
}

}  // namespace
}  // namespace corbel::kifs
