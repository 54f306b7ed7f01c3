// Coursed stone walls (statics/coursing.h) against independent oracles: the wall's volume by
// hand (ring area = perimeter·t − t²·Σ cot(φ/2), openings subtracted), a point-by-point check
// that the blocks tile it, the overturning load of a free-standing wall by hand (W·t / 2h), and
// the existing wall template (wall.h) for a straight wall with openings.
#include "core/error.h"
#include "statics/analysis.h"
#include "statics/builder.h"
#include "statics/coursing.h"
#include "statics/shapes.h"
#include "statics/tolerances.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::statics {
namespace {

Assembly onGround(std::vector<Block> blocks) {
  StructureBuilder b;
  b.add("", std::move(blocks));
  b.groundUnder(1.0);
  return b.build();
}

double volumeOf(const std::vector<Block>& blocks) {
  Assembly as;
  as.blocks = blocks;
  BBox box;
  for (const Block& b : blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  double v = 0;
  for (const BlockProperties& p : validateAssembly(as, lengthTolerance(box))) v += p.volume;
  return v;
}

bool within(const BBox& b, const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.lo[k] || p[k] > b.hi[k]) return false;
  return true;
}

// Inside a convex block: behind every face's plane.
bool inside(const Block& b, const Vec3& p) {
  for (const auto& f : b.faces) {
    std::vector<Vec3> poly;
    for (int i : f) poly.push_back(b.vertices[std::size_t(i)]);
    if (dot(p - poly[0], newellNormal(poly).normalized()) > 0) return false;
  }
  return true;
}

CoursingSpec house() {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(6, 0), Vec2(6, 4), Vec2(0, 4)};
  s.height = 3.2;
  s.courseHeight = 0.4;
  s.blockLength = 0.8;
  s.thickness = 0.5;
  // A door (courses 0-4, lintel in 5) and a window under a flat arch (courses 2-4, arch in 5).
  s.openings = {{"door", 0, 2.0, 3.0, 0.0, 2.0, OpeningHead::Lintel},
                {"window", 1, 1.5, 2.5, 0.8, 2.0, OpeningHead::FlatArch}};
  return s;
}

TEST(Coursing, BlocksTileTheWallsOfARectangularHouse) {
  const CoursingSpec s = house();
  const CoursedWalls w = courseWalls(s);
  EXPECT_EQ(w.courses, 8);
  // Ring: perimeter·t − t²·Σ cot(45°) = 20·0.5 − 4·0.25 = 9 m²; openings 1 × 2 and 1 × 1.2 m.
  const double expected = 9.0 * 3.2 - (1.0 * 2.0 + 1.0 * 1.2) * 0.5;
  EXPECT_NEAR(volumeOf(w.blocks), expected, 1e-9);
  // Every sample point of the walls lies in exactly one block, every other point in none.
  int wrong = 0, samples = 0;
  std::vector<BBox> boxes;
  for (const Block& b : w.blocks) {
    BBox box;
    for (const Vec3& v : b.vertices) box.add(v);
    boxes.push_back(box);
  }
  for (double x = -0.2 + 0.0137; x < 6.2; x += 0.0731)
    for (double y = -0.2 + 0.0091; y < 4.2; y += 0.0693)
      for (double z = 0.0113; z < 3.2; z += 0.0977) {
        const bool inRing = x > 0 && x < 6 && y > 0 && y < 4 && !(x > 0.5 && x < 5.5 && y > 0.5 && y < 3.5);
        const bool inDoor = y < 0.5 && x > 2 && x < 3 && z < 2.0;
        const bool inWindow = x > 5.5 && y > 1.5 && y < 2.5 && z > 0.8 && z < 2.0;
        const Vec3 p(x, y, z);
        int count = 0;
        for (std::size_t i = 0; i < w.blocks.size(); ++i)
          if (within(boxes[i], p) && inside(w.blocks[i], p)) ++count;
        wrong += count != ((inRing && !inDoor && !inWindow) ? 1 : 0);
        ++samples;
      }
  EXPECT_EQ(wrong, 0) << "of " << samples << " samples";
  // Each edge's head is covered once by the top course's spans.
  std::vector<double> covered(4, 0.0);
  for (const HeadSpan& h : w.heads) covered[std::size_t(h.edge)] += h.to - h.from;
  EXPECT_NEAR(covered[0], 6.0, 1e-12);
  EXPECT_NEAR(covered[1], 4.0, 1e-12);
  EXPECT_NEAR(covered[2], 6.0, 1e-12);
  EXPECT_NEAR(covered[3], 4.0, 1e-12);
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

TEST(Coursing, HexagonalPlanHasTheRingVolumeAndBondedCorners) {
  CoursingSpec s;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3;
    s.plan.emplace_back(3 * std::cos(a), 3 * std::sin(a));
  }
  s.height = 2.0;
  s.courseHeight = 0.5;
  s.thickness = 0.6;
  const CoursedWalls w = courseWalls(s);
  // Perimeter 18; each corner's interior angle 120°, cot 60° = 1/√3.
  const double ring = 18 * 0.6 - 0.36 * 6 / std::sqrt(3.0);
  EXPECT_NEAR(volumeOf(w.blocks), ring * 2.0, 1e-9);
  // Bonded: the blocks holding a corner square alternate between the two walls from course to
  // course, so no vertical joint runs through two courses at a corner.
  int cornerBlocks = 0;
  for (const Block& b : w.blocks) cornerBlocks += b.vertices.size() == 10;
  EXPECT_EQ(cornerBlocks, 6 * w.courses);
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// A free-standing wall of weight W, thickness t and height h overturns about its outer foot
// when a horizontal load P at its head exceeds W·t / (2h): its weight's moment about that edge
// is W·t/2, the load's P·h (and the same at every bed joint above, for the share of each).
TEST(Coursing, FreeStandingWallTipsAtTheHandComputedHeadLoad) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(4, 0)};
  s.closed = false;
  s.height = 3.0;
  s.courseHeight = 0.5;
  s.blockLength = 0.6;
  s.thickness = 0.3;
  const double W = s.density * 9.81 * 4.0 * 0.3 * 3.0;
  const double critical = W * s.thickness / (2 * s.height);
  for (const auto& [factor, expectStands] : {std::pair{0.98, true}, {1.02, false}}) {
    CoursedWalls w = courseWalls(s);
    loadWallHeads(s, w, {{0.0, factor * critical / 4.0}});
    const Assembly as = onGround(w.blocks);
    EXPECT_EQ(checkFeasibility(as).feasible, expectStands) << factor;
  }
  // The same load downwards (no thrust) leaves it standing.
  CoursedWalls w = courseWalls(s);
  loadWallHeads(s, w, {{5 * W / 4.0, 0.0}});
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// A straight open wall with a window and a door is the wall template's wall, block for block.
TEST(Coursing, StraightWallWithLintelsIsTheWallTemplate) {
  WallSpec t;
  t.length = 6.0;
  t.thickness = 0.4;
  t.height = 4.0;
  t.courses = 8;
  t.blockLength = 0.5;
  t.windows = {{1.0, 1.0, 2, 6}, {3.5, 1.5, 0, 5}};
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(6, 0)};
  s.closed = false;
  s.height = 4.0;
  s.courseHeight = 0.5;
  s.blockLength = 0.5;
  s.thickness = 0.4;
  s.openings = {{"window", 0, 1.0, 2.0, 1.0, 3.0, OpeningHead::Lintel}, {"door", 0, 3.5, 5.0, 0.0, 2.5, OpeningHead::Lintel}};
  const std::vector<Block> a = wallBlocks(t);
  const std::vector<Block> b = courseWalls(s).blocks;
  ASSERT_EQ(a.size(), b.size());
  auto boxOf = [](const Block& k) {
    BBox box;
    for (const Vec3& v : k.vertices) box.add(v);
    return box;
  };
  for (const Block& k : a) {
    const BBox ka = boxOf(k);
    const bool found = std::any_of(b.begin(), b.end(), [&](const Block& m) {
      const BBox kb = boxOf(m);
      return (ka.lo - kb.lo).norm() < 1e-12 && (ka.hi - kb.hi).norm() < 1e-12 && m.vertices.size() == 8;
    });
    EXPECT_TRUE(found) << k.name;
  }
  // The same analysis: turned so the thickness runs along x and tilted past atan(t/h) = 5.7°
  // until neither stands, the same measure.
  StructureBuilder ba, bb;
  ba.add("", rotatedZ(a, std::numbers::pi / 2)).groundUnder(1.0).tilt(8);
  bb.add("", rotatedZ(b, std::numbers::pi / 2)).groundUnder(1.0).tilt(8);
  const AnalysisResult ra = analyse(ba.build()), rb = analyse(bb.build());
  EXPECT_FALSE(ra.feasible);
  EXPECT_NEAR(ra.totalWeight, rb.totalWeight, 1e-9 * ra.totalWeight);
  EXPECT_NEAR(rb.yNormalised, ra.yNormalised, 1e-6 * ra.yNormalised);
}

TEST(Coursing, RefusesWhatCannotBeCoursed) {
  CoursingSpec s = house();
  s.plan = {Vec2(0, 0), Vec2(6, 0), Vec2(6, 4), Vec2(3, 2), Vec2(0, 4)};  // reflex corner at (3, 2)
  s.openings.clear();
  EXPECT_THROW(courseWalls(s), Error);
  s = house();
  s.openings[0].from = 0.2;  // into the corner's square
  EXPECT_THROW(courseWalls(s), Error);
  s = house();
  s.openings[0].top = 3.2;  // no course above for its lintel
  EXPECT_THROW(courseWalls(s), Error);
  s = house();
  s.openings.push_back({"overlap", 0, 2.5, 3.5, 0.0, 2.0, OpeningHead::Lintel});
  EXPECT_THROW(courseWalls(s), Error);
  s = house();
  s.thickness = -1;
  EXPECT_THROW(courseWalls(s), Error);
}

}  // namespace
}  // namespace corbel::statics
