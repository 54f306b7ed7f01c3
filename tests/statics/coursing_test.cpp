// Coursed stone walls (statics/coursing.h) against independent oracles: the wall's volume by
// hand (ring area = perimeter·t − t²·Σ cot(φ/2), openings subtracted), a point-by-point check
// that the blocks tile it, the overturning load of a free-standing wall by hand (W·t / 2h), and
// the existing wall template (wall.h) for a straight wall with openings; buttresses: the stepped
// walls' volume and tiling by hand, and the moment a pier adds against a head load.
#include "core/error.h"
#include "statics/analysis.h"
#include "statics/arch.h"
#include "statics/builder.h"
#include "statics/coursing.h"
#include "statics/interfaces.h"
#include "statics/shapes.h"
#include "statics/thresholds.h"
#include "statics/tolerances.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

// Inside the regular N-gon inscribed in the circle of radius r about c, above its diameter
// (the opening under a semicircular arch of N chord voussoirs): in the sector of angle π/N
// holding p, nearer c than that sector's chord.
bool underArch(const Vec2& p, const Vec2& c, double r, int n) {
  const Vec2 q = p - c;
  if (q[1] <= 0) return false;
  const double step = std::numbers::pi / n;
  const double phi = std::atan2(q[1], q[0]);
  const double midAngle = (std::floor(phi / step) + 0.5) * step;
  return q[0] * std::cos(midAngle) + q[1] * std::sin(midAngle) < r * std::cos(step / 2);
}

std::vector<const Block*> voussoirsOf(const CoursedWalls& w) {
  std::vector<const Block*> v;
  for (const Block& b : w.blocks)
    if (b.name.find("voussoir") != std::string::npos) v.push_back(&b);
  return v;
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

// A straight free-standing wall `length` long, 3 m high and 0.3 m thick, in 0.5 m courses of
// 0.6 m blocks.
CoursingSpec freeWall(double length) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(length, 0)};
  s.closed = false;
  s.height = 3.0;
  s.courseHeight = 0.5;
  s.blockLength = 0.6;
  s.thickness = 0.3;
  return s;
}

// A free-standing wall of weight W, thickness t and height h overturns about its outer foot
// when a horizontal load P at its head exceeds W·t / (2h): its weight's moment about that edge
// is W·t/2, the load's P·h (and the same at every bed joint above, for the share of each).
TEST(Coursing, FreeStandingWallTipsAtTheHandComputedHeadLoad) {
  const CoursingSpec s = freeWall(4.0);
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

// Wind of pressure p on the face of a free-standing wall (length L, height h, thickness t,
// weight W) pushes p·L·h at mid-height. About the leeward foot its moment p·L·h²/2 overturns the
// weight's W·t/2 once p passes W·t / (L·h²): the hand moment of the head-load case above with
// the resultant at h/2 (and the base joint governs: above height z the ratio grows as h/(h − z)).
TEST(Coursing, WindTipsAFreeStandingWallAtTheHandComputedPressure) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(4, 0)};  // the outer face at y = 0 faces −y
  s.closed = false;
  s.height = 3.0;
  s.courseHeight = 0.5;
  s.blockLength = 0.6;
  s.thickness = 0.3;
  const double W = s.density * 9.81 * 4.0 * 0.3 * 3.0;
  const double critical = W * s.thickness / (4.0 * s.height * s.height);
  auto windy = [&](double p, const Vec2& towards) {
    CoursedWalls w = courseWalls(s);
    loadWind(s, w, p, towards);
    return w;
  };
  for (const auto& [factor, expectStands] : {std::pair{0.98, true}, {1.02, false}})
    EXPECT_EQ(checkFeasibility(onGround(windy(factor * critical, Vec2(0, 1)).blocks)).feasible, expectStands) << factor;
  // The whole face takes p × its area; a wind along the wall, or onto its other side (not an
  // outer face), takes nothing.
  auto total = [](const CoursedWalls& w) {
    Vec3 f(0.0);
    for (const Block& b : w.blocks)
      for (const PointLoad& l : b.pointLoads) f += l.force;
    return f;
  };
  EXPECT_NEAR(total(windy(100, Vec2(0, 1)))[1], 100 * 12.0, 1e-9);
  EXPECT_NEAR(total(windy(100, Vec2(0, 2)))[0], 0.0, 1e-12);
  EXPECT_NEAR(total(windy(100, Vec2(1, 1)))[1], 100 * 12.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(total(windy(100, Vec2(1, 0))).norm(), 0.0);
  EXPECT_EQ(total(windy(100, Vec2(0, -1))).norm(), 0.0);
  // An opening takes its area out of the face.
  s.openings = {{"window", 0, 1.0, 2.0, 0.5, 1.0, OpeningHead::SemicircularArch}};
  const CoursedWalls arched = windy(100, Vec2(0, 1));
  const int n = int(voussoirsOf(arched).size());
  EXPECT_NEAR(total(arched)[1], 100 * (12.0 - 0.5 - 0.5 * n * 0.25 * std::sin(std::numbers::pi / n)), 1e-9);
  EXPECT_THROW(windy(-1, Vec2(0, 1)), Error);
  EXPECT_THROW(windy(1, Vec2(0, 0)), Error);
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

// A rectangular house with a semicircular-arched window in its long wall and a door under a
// lintel: the blocks fill the ring of walls less the openings, each opening a rectangle up to
// the springing and, above it, the N-gon inscribed in the intrados circle (N = the voussoirs).
// Springing at 1.6 m the arch's courses end below the wall head; at 2.0 m they reach it, and
// the top course's spandrels carry their share of the head.
TEST(Coursing, SemicircularArchBlocksTileTheWall) {
  for (const double springing : {1.6, 2.0}) {
    SCOPED_TRACE(springing);
    CoursingSpec s = house();
    s.openings = {{"door", 0, 0.9, 1.7, 0.0, 2.0, OpeningHead::Lintel},
                  {"arched", 0, 3.0, 4.2, springing - 0.8, springing, OpeningHead::SemicircularArch}};
    const CoursedWalls w = courseWalls(s);
    const std::vector<const Block*> vs = voussoirsOf(w);
    const int n = int(vs.size());
    ASSERT_GE(n, 5);
    EXPECT_EQ(n % 2, 1);
    const double r = 0.6;
    const Vec2 centre(3.6, springing);
    const double polygon = 0.5 * n * r * r * std::sin(std::numbers::pi / n);
    const double expected = 9.0 * 3.2 - (0.8 * 2.0 + 1.2 * 0.8 + polygon) * 0.5;
    EXPECT_NEAR(volumeOf(w.blocks), expected, 1e-9);
    std::vector<BBox> boxes;
    for (const Block& b : w.blocks) {
      BBox box;
      for (const Vec3& v : b.vertices) box.add(v);
      boxes.push_back(box);
    }
    int wrong = 0, samples = 0;
    for (double x = -0.2 + 0.0137; x < 6.2; x += 0.0431)
      for (double y = -0.2 + 0.0091; y < 4.2; y += 0.0993)
        for (double z = 0.0113; z < 3.2; z += 0.0377) {
          const bool inRing = x > 0 && x < 6 && y > 0 && y < 4 && !(x > 0.5 && x < 5.5 && y > 0.5 && y < 3.5);
          const bool front = y < 0.5;
          const bool inDoor = front && x > 0.9 && x < 1.7 && z < 2.0;
          const bool inArched = front && ((x > 3.0 && x < 4.2 && z > springing - 0.8 && z < springing) ||
                                          underArch(Vec2(x, z), centre, r, n));
          const Vec3 p(x, y, z);
          int count = 0;
          for (std::size_t i = 0; i < w.blocks.size(); ++i)
            if (within(boxes[i], p) && inside(w.blocks[i], p)) ++count;
          wrong += count != ((inRing && !inDoor && !inArched) ? 1 : 0);
          ++samples;
        }
    EXPECT_EQ(wrong, 0) << "of " << samples << " samples";
    std::vector<double> covered(4, 0.0);
    for (const HeadSpan& h : w.heads) covered[std::size_t(h.edge)] += h.to - h.from;
    EXPECT_NEAR(covered[0], 6.0, 1e-12);
    EXPECT_NEAR(covered[1], 4.0, 1e-12);
    const Assembly as = onGround(w.blocks);
    EXPECT_TRUE(checkFeasibility(as).feasible);
    EXPECT_TRUE(analyse(as).feasible);
  }
}

// The arch over an opening is the arch template's (arch.h) block for block: N voussoirs of
// centreline radius R = r + d/2 and thickness d, d the ring's depth. So on its springings alone
// it stands exactly where the template does: above the template's least thickness for N, found
// by bisection (about 0.11 R for N near 11), and not below it.
TEST(Coursing, SemicircularArchIsTheArchTemplateAndStandsWhereItDoes) {
  auto wallWith = [](double depth) {
    CoursingSpec s;
    s.plan = {Vec2(0, 0), Vec2(6, 0)};
    s.closed = false;
    s.height = 4.0;
    s.courseHeight = 0.4;
    s.blockLength = 0.8;
    s.thickness = 0.4;
    WallOpening o{"arched", 0, 2.0, 4.0, 0.0, 1.6, OpeningHead::SemicircularArch};
    o.archDepth = depth;
    s.openings = {o};
    return s;
  };
  const double ri = 1.0, springing = 1.6;
  auto ringAlone = [&](const CoursedWalls& w) {
    std::vector<Block> blocks;
    for (const Block* b : voussoirsOf(w)) blocks.push_back(*b);
    blocks.push_back(boxBlock("ground", Vec3(0, -1, springing - 1), Vec3(6, 1, springing), 1.0, true));
    Assembly as;
    as.blocks = std::move(blocks);
    return as;
  };
  // The template's least t/R for the voussoir count the wall gives a ring near that ratio.
  const CoursedWalls probe = courseWalls(wallWith(0.12));
  const int n = int(voussoirsOf(probe).size());
  ArchSpec unit;
  unit.blocks = n;
  unit.radius = 1.0;
  const double least = minimumArchThickness(unit, {}, 1e-5);
  EXPECT_GT(least, 0.09);
  EXPECT_LT(least, 0.13);
  for (const auto& [factor, stands] : {std::pair{0.95, false}, {1.05, true}}) {
    const double ratio = factor * least;  // d / (ri + d/2)
    const double depth = ratio * ri / (1 - ratio / 2);
    const CoursingSpec s = wallWith(depth);
    const CoursedWalls w = courseWalls(s);
    const std::vector<const Block*> vs = voussoirsOf(w);
    ASSERT_EQ(int(vs.size()), n) << factor;
    ArchSpec t = unit;
    t.radius = ri + depth / 2;
    t.thickness = depth;
    t.depth = s.thickness;
    const std::vector<Block> expected = placed(semicircularArchBlocks(t), Vec3(3.0, s.thickness / 2, springing));
    for (std::size_t k = 0; k < vs.size(); ++k) {
      ASSERT_EQ(vs[k]->vertices.size(), expected[k].vertices.size());
      double far = 0;
      for (const Vec3& v : vs[k]->vertices) {
        double nearest = 1e9;
        for (const Vec3& e : expected[k].vertices) nearest = std::min(nearest, (v - e).norm());
        far = std::max(far, nearest);
      }
      EXPECT_LT(far, 1e-12) << vs[k]->name;
    }
    EXPECT_EQ(checkFeasibility(ringAlone(w)).feasible, stands) << factor;
    // In its wall, under the spandrels and the courses above, it stands either way.
    EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible) << factor;
  }
}

// Buttresses against the house's walls: a pier 0.8 m long, 0.6 m deep and as high as the walls
// on the front (edge 0, x in [4, 4.8], outside y < 0) and one 1 m long, 0.4 m deep and 2 m high
// on the back (edge 2 runs from (6, 4) to (0, 4): u in [2, 3] is x in [3, 4], outside y > 4).
CoursingSpec buttressedHouse() {
  CoursingSpec s = house();
  s.buttresses = {{"front", 0, 4.0, 4.8, 0.6, 3.2}, {"back", 2, 2.0, 3.0, 0.4, 2.0}};
  return s;
}

// The stepped plan's walls by hand: the ring and openings of BlocksTileTheWallsOfARectangularHouse
// plus each pier's plan area × its height; sampled point by point like that test.
TEST(Coursing, ButtressesTileTheSteppedWalls) {
  const CoursingSpec s = buttressedHouse();
  const CoursedWalls w = courseWalls(s);
  ASSERT_EQ(w.courses, 8);
  const double expected = 9.0 * 3.2 - (1.0 * 2.0 + 1.0 * 1.2) * 0.5 + 0.8 * 0.6 * 3.2 + 1.0 * 0.4 * 2.0;
  EXPECT_NEAR(volumeOf(w.blocks), expected, 1e-9);
  std::vector<BBox> boxes;
  for (const Block& b : w.blocks) {
    BBox box;
    for (const Vec3& v : b.vertices) box.add(v);
    boxes.push_back(box);
  }
  int wrong = 0, samples = 0;
  for (double x = -0.2 + 0.0137; x < 6.2; x += 0.0731)
    for (double y = -0.8 + 0.0091; y < 4.6; y += 0.0693)
      for (double z = 0.0113; z < 3.2; z += 0.0977) {
        const bool inRing = x > 0 && x < 6 && y > 0 && y < 4 && !(x > 0.5 && x < 5.5 && y > 0.5 && y < 3.5);
        const bool inDoor = y < 0.5 && x > 2 && x < 3 && z < 2.0;
        const bool inWindow = x > 5.5 && y > 1.5 && y < 2.5 && z > 0.8 && z < 2.0;
        const bool inFront = x > 4 && x < 4.8 && y > -0.6 && y < 0;
        const bool inBack = x > 3 && x < 4 && y > 4 && y < 4.4 && z < 2.0;
        const Vec3 p(x, y, z);
        int count = 0;
        for (std::size_t i = 0; i < w.blocks.size(); ++i)
          if (within(boxes[i], p) && inside(w.blocks[i], p)) ++count;
        wrong += count != (((inRing && !inDoor && !inWindow) || inFront || inBack) ? 1 : 0);
        ++samples;
      }
  EXPECT_EQ(wrong, 0) << "of " << samples << " samples";

  // Bonded: through-stones (wall and pier one block) on even courses, 4 for the front pier's 8
  // courses and 3 for the back one's 5, and on the head course (7) over the front pier, which
  // reaches it; the piers' own blocks on the other odd ones (3 and 2), each against a wall block
  // over a vertical interface.
  int through = 0, own = 0;
  for (const Block& b : w.blocks) {
    through += b.name.find("through") != std::string::npos;
    own += b.name.find(" buttress ") != std::string::npos;
  }
  EXPECT_EQ(through, (4 + 1) + 3);
  EXPECT_EQ(own, 3 + 2);
  Assembly as;
  as.blocks = w.blocks;
  BBox box;
  for (const BBox& b : boxes) box.add(b.lo), box.add(b.hi);
  const std::vector<BlockProperties> props = validateAssembly(as, lengthTolerance(box));
  const Contacts c = findContacts(as, props, lengthTolerance(box), 0.0);
  for (std::size_t i = 0; i < w.blocks.size(); ++i) {
    if (w.blocks[i].name.find(" buttress ") == std::string::npos) continue;
    double againstWall = 0;
    for (const Interface& f : c.interfaces) {
      const int other = f.a == int(i) ? f.b : f.b == int(i) ? f.a : -1;
      if (other < 0 || std::abs(f.normal[2]) > 1e-9) continue;
      const std::string& name = w.blocks[std::size_t(other)].name;
      if (name.find("buttress") == std::string::npos && name.find("through") == std::string::npos) againstWall += f.area;
    }
    // The whole face against the wall: pier length × course height.
    const double length = w.blocks[i].name.find("front") != std::string::npos ? 0.8 : 1.0;
    EXPECT_NEAR(againstWall, length * 0.4, 1e-9) << w.blocks[i].name;
  }
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// A free-standing wall (length L, thickness t, height h, weight W) under a horizontal load P at
// its head tips about its outer foot once P·h > W·t/2; here P = W·t/h, twice that. A pier of
// depth d, as long as the wall and as high (weight W_b = W·d/t), moves the pivot to its own
// outer foot: the rigid wall and pier resist W·(d + t/2) + W_b·d/2 (in N·m, t = 0.3 m, so
// P·h = 0.3 W). For d = 0.1 m that is 0.25 W + 0.017 W = 0.267 W, short of it: rotating the
// whole about the pier's foot is a mechanism, so it falls whatever the LP. For d = 0.3 m it is
// 0.45 W + 0.15 W = 0.6 W, over 1.5 × 0.3 W; each bed joint above carries the same ratio
// (weight and load moment both scale with the height above it), so it stands by the LP.
TEST(Coursing, ButtressHoldsAWallTheHeadLoadOverturns) {
  const CoursingSpec s = freeWall(2.4);
  const double L = 2.4, W = s.density * 9.81 * L * s.thickness * s.height;
  const double P = W * s.thickness / s.height;  // twice the free wall's W·t / (2h)
  auto stands = [&](double depth) {
    CoursingSpec b = s;
    if (depth > 0) b.buttresses = {{"pier", 0, 0.0, L, depth, s.height}};
    CoursedWalls w = courseWalls(b);
    loadWallHeads(b, w, {{0.0, P / L}});
    return checkFeasibility(onGround(w.blocks)).feasible;
  };
  auto resisting = [&](double d) { return W * (d + s.thickness / 2) + W * d / s.thickness * d / 2; };
  EXPECT_GT(P * s.height, W * s.thickness / 2);
  EXPECT_FALSE(stands(0.0));
  EXPECT_LT(resisting(0.1), P * s.height);
  EXPECT_FALSE(stands(0.1));
  EXPECT_GE(resisting(0.3), 1.5 * P * s.height);
  EXPECT_TRUE(stands(0.3));

  // A pier 0.8 m long in the middle of the wall: the same mechanism about its foot needs
  // W·(d + t/2) + W_b·d/2 ≥ P·h (W_b = W·(0.8 / L)·d/t), so d = 0.1 m falls; the hand moment is
  // only necessary here, since the wall's 0.8 m ends beyond the pier must be held by the bond
  // (the LP finds them turning off at d = 0.3 m, 1.67 times over the moment); at d = 0.6 m,
  // three times over, the LP finds the bonded pier holds the whole wall.
  auto middle = [&](double depth) {
    CoursingSpec b = s;
    b.buttresses = {{"pier", 0, 0.8, 1.6, depth, s.height}};
    CoursedWalls w = courseWalls(b);
    loadWallHeads(b, w, {{0.0, P / L}});
    return checkFeasibility(onGround(w.blocks)).feasible;
  };
  auto resistingMiddle = [&](double d) { return W * (d + s.thickness / 2) + W * (0.8 / L) * d / s.thickness * d / 2; };
  EXPECT_LT(resistingMiddle(0.1), P * s.height);
  EXPECT_FALSE(middle(0.1));
  EXPECT_GE(resistingMiddle(0.6), 3 * P * s.height);
  EXPECT_TRUE(middle(0.6));
}

// Inside a simple polygon (crossing number).
bool inPolygon(const std::vector<Vec2>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) in = !in;
  }
  return in;
}

// Two convex blocks share no volume when some axis separates them (the separating axis
// theorem: for polyhedra, a face normal of either or the cross product of an edge of each):
// their projections on it overlap by at most `tol`.
bool disjoint(const Block& a, const Block& b, double tol) {
  auto normals = [](const Block& k) {
    std::vector<Vec3> out;
    for (const auto& f : k.faces) {
      std::vector<Vec3> poly;
      for (int i : f) poly.push_back(k.vertices[std::size_t(i)]);
      out.push_back(newellNormal(poly).normalized());
    }
    return out;
  };
  auto edges = [](const Block& k) {
    std::vector<Vec3> out;
    for (const auto& f : k.faces)
      for (std::size_t i = 0; i < f.size(); ++i)
        out.push_back((k.vertices[std::size_t(f[(i + 1) % f.size()])] - k.vertices[std::size_t(f[i])]).normalized());
    return out;
  };
  std::vector<Vec3> axes = normals(a);
  for (const Vec3& n : normals(b)) axes.push_back(n);
  for (const Vec3& u : edges(a))
    for (const Vec3& v : edges(b)) {
      const Vec3 c = cross(u, v);
      if (c.norm() > 1e-6) axes.push_back(c.normalized());
    }
  for (const Vec3& n : axes) {
    double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
    for (const Vec3& v : a.vertices) loA = std::min(loA, dot(n, v)), hiA = std::max(hiA, dot(n, v));
    for (const Vec3& v : b.vertices) loB = std::min(loB, dot(n, v)), hiB = std::max(hiB, dot(n, v));
    if (hiA <= loB + tol || hiB <= loA + tol) return true;
  }
  return false;
}

// Pairs of blocks that share volume.
int overlappingPairs(const std::vector<Block>& blocks) {
  std::vector<BBox> boxes;
  for (const Block& b : blocks) {
    BBox box;
    for (const Vec3& v : b.vertices) box.add(v);
    boxes.push_back(box);
  }
  int pairs = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    for (std::size_t j = i + 1; j < blocks.size(); ++j) {
      bool apart = false;
      for (int k = 0; k < 3; ++k)
        apart = apart || boxes[i].hi[k] <= boxes[j].lo[k] + 1e-9 || boxes[j].hi[k] <= boxes[i].lo[k] + 1e-9;
      if (!apart && !disjoint(blocks[i], blocks[j], 1e-9)) ++pairs;
    }
  return pairs;
}

// Sample points over the box [lo, hi] that lie in no block or in several, against `solid`.
template <class Solid>
int wronglyCovered(const std::vector<Block>& blocks, const Vec3& lo, const Vec3& hi, Solid solid) {
  std::vector<BBox> boxes;
  for (const Block& b : blocks) {
    BBox box;
    for (const Vec3& v : b.vertices) box.add(v);
    boxes.push_back(box);
  }
  int wrong = 0;
  for (double x = lo[0] + 0.0137; x < hi[0]; x += 0.0731)
    for (double y = lo[1] + 0.0091; y < hi[1]; y += 0.0693)
      for (double z = lo[2] + 0.0113; z < hi[2]; z += 0.0977) {
        const Vec3 p(x, y, z);
        int count = 0;
        for (std::size_t i = 0; i < blocks.size(); ++i)
          if (within(boxes[i], p) && inside(blocks[i], p)) ++count;
        wrong += count != (solid(p) ? 1 : 0);
      }
  return wrong;
}

// A ring of walls of thickness t inside a plan of perimeter P whose corners turn by τ_i (left
// positive) has the area P·t − t²·Σ tan(τ_i / 2): each corner's interior angle is π − τ_i, and
// the inner face's miter takes t²·cot((π − τ_i)/2) there; a reflex corner (τ < 0) gives it back.
double ringArea(const std::vector<Vec2>& plan, double t) {
  double perimeter = 0, corners = 0;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Vec2 a = plan[(i + plan.size() - 1) % plan.size()], b = plan[i], c = plan[(i + 1) % plan.size()];
    const Vec2 u = b - a, v = c - b;
    perimeter += v.norm();
    corners += std::tan(std::atan2(u[0] * v[1] - u[1] * v[0], dot(u, v)) / 2);
  }
  return perimeter * t - t * t * corners;
}

// An L-shaped plan: one reflex corner at (3, 3), turning by −90°. Its ring by hand: perimeter
// 24 m, five convex corners and one reflex: 24·0.5 − 0.25·(5 − 1) = 11 m², over 2 m.
TEST(Coursing, LShapedPlanTilesItsWallsAndBondsTheReflexCorner) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(6, 0), Vec2(6, 3), Vec2(3, 3), Vec2(3, 6), Vec2(0, 6)};
  s.height = 2.0;
  s.courseHeight = 0.4;
  s.blockLength = 0.8;
  s.thickness = 0.5;
  s.openings = {{"door", 3, 1.0, 2.0, 0.0, 1.2, OpeningHead::Lintel}};  // on the wall at y = 3 → 6, x = 3
  const CoursedWalls w = courseWalls(s);
  ASSERT_EQ(w.courses, 5);
  EXPECT_NEAR(ringArea(s.plan, 0.5), 11.0, 1e-12);
  EXPECT_NEAR(volumeOf(w.blocks), 11.0 * 2.0 - 1.0 * 1.2 * 0.5, 1e-9);
  const std::vector<Vec2> inner = {Vec2(0.5, 0.5), Vec2(5.5, 0.5), Vec2(5.5, 2.5),
                                   Vec2(2.5, 2.5), Vec2(2.5, 5.5), Vec2(0.5, 5.5)};
  EXPECT_EQ(wronglyCovered(w.blocks, Vec3(-0.2, -0.2, 0.0), Vec3(6.2, 6.2, 2.0),
                           [&](const Vec3& p) {
                             const bool door = p[0] > 2.5 && p[0] < 3 && p[1] > 4 && p[1] < 5 && p[2] < 1.2;
                             return inPolygon(s.plan, p[0], p[1]) && !inPolygon(inner, p[0], p[1]) && !door;
                           }),
            0);
  EXPECT_EQ(overlappingPairs(w.blocks), 0);
  // Bonded: the square between the outer corner (3, 3) and the inner one (2.5, 2.5) belongs to
  // the incoming wall (edge 2, from (6, 3)) on even courses and to the outgoing one (edge 3) on
  // odd ones, and the block holding it runs on past the corner along its own wall.
  for (int c = 0; c < w.courses; ++c) {
    const Vec3 p(2.75, 2.75, 0.4 * c + 0.2);
    int holders = 0;
    for (const Block& b : w.blocks) {
      if (!inside(b, p)) continue;
      ++holders;
      EXPECT_EQ(b.name.rfind(c % 2 == 0 ? "wall 2 " : "wall 3 ", 0), 0u) << b.name << " course " << c;
      EXPECT_TRUE(inside(b, c % 2 == 0 ? Vec3(3.1, 2.75, p[2]) : Vec3(2.75, 3.1, p[2]))) << b.name;
    }
    EXPECT_EQ(holders, 1);
  }
  std::vector<double> covered(6, 0.0);
  for (const HeadSpan& h : w.heads) covered[std::size_t(h.edge)] += h.to - h.from;
  for (int e = 0; e < 6; ++e)
    EXPECT_NEAR(covered[std::size_t(e)], (s.plan[std::size_t(e + 1) % 6] - s.plan[std::size_t(e)]).norm(), 1e-12);
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// The 6 × 4 m house with a bay on its front wall: the wall opened from x = 1.5 to 4.5 and the
// bay's cheeks and front 1 m out (reflex corners at (1.5, 0) and (4.5, 0)), a window in the
// bay's front and a door in the back wall. By hand: perimeter 22 m, six convex corners, two
// reflex: 22·0.5 − 0.25·(6 − 2) = 10 m² over 3.2 m, less the window 1 × 1.2 m and the door
// 1 × 2 m.
TEST(Coursing, BayTilesTheSteppedWalls) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(1.5, 0), Vec2(1.5, -1), Vec2(4.5, -1), Vec2(4.5, 0), Vec2(6, 0), Vec2(6, 4), Vec2(0, 4)};
  s.height = 3.2;
  s.courseHeight = 0.4;
  s.blockLength = 0.8;
  s.thickness = 0.5;
  s.openings = {{"window", 2, 1.0, 2.0, 0.8, 2.0, OpeningHead::Lintel}, {"door", 6, 2.0, 3.0, 0.0, 2.0, OpeningHead::FlatArch}};
  const CoursedWalls w = courseWalls(s);
  ASSERT_EQ(w.courses, 8);
  EXPECT_NEAR(ringArea(s.plan, 0.5), 10.0, 1e-12);
  EXPECT_NEAR(volumeOf(w.blocks), 10.0 * 3.2 - (1.0 * 1.2 + 1.0 * 2.0) * 0.5, 1e-9);
  const std::vector<Vec2> inner = {Vec2(0.5, 0.5), Vec2(2.0, 0.5), Vec2(2.0, -0.5), Vec2(4.0, -0.5),
                                   Vec2(4.0, 0.5), Vec2(5.5, 0.5), Vec2(5.5, 3.5), Vec2(0.5, 3.5)};
  EXPECT_EQ(wronglyCovered(w.blocks, Vec3(-0.2, -1.2, 0.0), Vec3(6.2, 4.2, 3.2),
                           [&](const Vec3& p) {
                             const bool window = p[1] < -0.5 && p[0] > 2.5 && p[0] < 3.5 && p[2] > 0.8 && p[2] < 2.0;
                             const bool door = p[1] > 3.5 && p[0] > 3 && p[0] < 4 && p[2] < 2.0;
                             return inPolygon(s.plan, p[0], p[1]) && !inPolygon(inner, p[0], p[1]) && !window && !door;
                           }),
            0);
  EXPECT_EQ(overlappingPairs(w.blocks), 0);
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// A canted bay (cheeks from (2, 0) to (2.5, −1) and (3.5, −1) to (4, 0)) and a recess notched
// into the back wall: every corner's miter by hand (ringArea), blocks convex by construction
// (halfspaceBlock / prismBlock) and disjoint.
TEST(Coursing, CantedBayAndRecessHaveTheRingVolume) {
  CoursingSpec s;
  s.plan = {Vec2(0, 0), Vec2(2, 0), Vec2(2.5, -1), Vec2(3.5, -1), Vec2(4, 0), Vec2(6, 0), Vec2(6, 5),
            Vec2(4, 5), Vec2(4, 3.8), Vec2(2, 3.8), Vec2(2, 5), Vec2(0, 5)};
  s.height = 2.4;
  s.courseHeight = 0.4;
  s.blockLength = 0.8;
  s.thickness = 0.4;
  const CoursedWalls w = courseWalls(s);
  // Perimeter: 2 + 2·√1.25 + 1 + 2 + 5 + 2 + 1.2 + 2 + 1.2 + 2 + 5; the cheeks' turns cancel
  // (tan is odd), leaving the four house corners and the recess's four (two each way): Σ = 4.
  const double perimeter = 22.4 + 2 * std::sqrt(1.25) + 1.0;
  EXPECT_NEAR(ringArea(s.plan, 0.4), perimeter * 0.4 - 0.16 * 4, 1e-12);
  EXPECT_NEAR(volumeOf(w.blocks), (perimeter * 0.4 - 0.16 * 4) * 2.4, 1e-9);
  EXPECT_EQ(overlappingPairs(w.blocks), 0);
  EXPECT_TRUE(checkFeasibility(onGround(w.blocks)).feasible);
}

// A free-standing wall (L = 2.4 m, t = 0.3 m, h = 3 m, weight W) with a return at each end
// turning back towards its outer side (reflex corners at (0, 0) and (L, 0)), pushed outwards at
// its head by P = 3·W·t/(2h), three times what tips it alone. Whole, it can only turn about the
// returns' outer feet (y = −R): its weight resists W·(R + t/2) plus, for each return with its
// corner square (t × (R + t) in plan, weight W_r), W_r·(R + t)/2; P·h overturns. For R = 0.15 m
// that is short of P·h, so it falls whatever the bond; for R = 1.2 m it is five times over, and
// the returns, bonded at the reflex corners, hold it by the LP.
TEST(Coursing, ReturnsAtReflexCornersHoldAWallTheHeadLoadOverturns) {
  const double L = 2.4, t = 0.3, h = 3.0, rho = 2400 * 9.81;
  const double W = rho * L * t * h, P = 3 * W * t / (2 * h);
  auto resisting = [&](double R) { return W * (R + t / 2) + 2 * rho * t * (R + t) * h * (R + t) / 2; };
  auto stands = [&](double R) {
    CoursingSpec s = freeWall(L);
    s.plan = {Vec2(0, -R), Vec2(0, 0), Vec2(L, 0), Vec2(L, -R)};
    CoursedWalls w = courseWalls(s);
    EXPECT_NEAR(volumeOf(w.blocks), (L * t + 2 * t * (R + t)) * h, 1e-9);
    EXPECT_EQ(overlappingPairs(w.blocks), 0);
    loadWallHeads(s, w, {{0.0, 0.0}, {0.0, P / L}, {0.0, 0.0}});
    return checkFeasibility(onGround(w.blocks)).feasible;
  };
  EXPECT_LT(resisting(0.15), P * h);
  EXPECT_FALSE(stands(0.15));
  EXPECT_GE(resisting(1.2), 5 * P * h);
  EXPECT_TRUE(stands(1.2));
}

// Two bands laid one on the other are the walls coursed at once: the house's door and window
// (heads in course 5) cut through the lower band open to its head (throughHead) and go on in
// the upper one from below its foot; split at course 5 the upper band holds only their heads
// (top 0). The upper band numbers its courses on (firstCourse), so the bond goes on. Identity:
// block by block (by name), the same vertices.
TEST(Coursing, TwoBandsAreTheWallsCoursedAtOnce) {
  const CoursingSpec whole = house();
  const CoursedWalls once = courseWalls(whole);
  for (int kb : {3, 5}) {
    const double zb = kb * 0.4;
    CoursingSpec lower = whole, upper = whole;
    lower.height = zb;
    upper.base = zb;
    upper.height = 3.2 - zb;
    upper.firstCourse = kb;
    for (std::size_t k = 0; k < whole.openings.size(); ++k) {
      lower.openings[k].throughHead = true;
      upper.openings[k].bottom = -zb;
      upper.openings[k].top = 5 * 0.4 - zb;
    }
    std::vector<Block> both = courseWalls(lower).blocks;
    for (const Block& b : courseWalls(upper).blocks) both.push_back(b);
    ASSERT_EQ(both.size(), once.blocks.size()) << kb;
    auto sorted = [](const Block& b) {
      std::vector<std::array<double, 3>> v;
      for (const Vec3& p : b.vertices) v.push_back({std::round(p[0] * 1e9), std::round(p[1] * 1e9), std::round(p[2] * 1e9)});
      std::sort(v.begin(), v.end());
      return v;
    };
    int differ = 0;
    for (const Block& b : both) {
      const auto it = std::find_if(once.blocks.begin(), once.blocks.end(), [&](const Block& o) { return o.name == b.name; });
      differ += it == once.blocks.end() || sorted(*it) != sorted(b);
    }
    EXPECT_EQ(differ, 0) << kb;
  }
}

TEST(Coursing, RefusesWhatCannotBeCoursed) {
  CoursingSpec s = house();
  s.plan = {Vec2(0, 0), Vec2(6, 0), Vec2(6, 4), Vec2(3, 0.5), Vec2(0, 4)};  // turns right by more than 90° at (3, 0.5)
  s.openings.clear();
  EXPECT_THROW(courseWalls(s), Error);
  s.plan = {Vec2(0, 0), Vec2(2, 0), Vec2(2, -1), Vec2(4, -1), Vec2(4, 0), Vec2(6, 0), Vec2(6, 4), Vec2(0, 4)};
  s.openings = {{"at the corner", 4, 0.5, 1.0, 0.0, 1.2, OpeningHead::Lintel}};  // its lintel within b/4 of the reflex corner
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
  s = house();
  s.openings[1].head = OpeningHead::SemicircularArch;  // 1 m span from 2 m: rises past 3.2 m
  s.openings[1].top = 2.4;
  EXPECT_THROW(courseWalls(s), Error);
  s = house();
  s.openings[1] = {"wide", 1, 0.8, 3.2, 0.0, 0.8, OpeningHead::SemicircularArch};  // zone into a corner
  EXPECT_THROW(courseWalls(s), Error);  s = buttressedHouse();
  s.buttresses[0].from = 0.2;  // into the corner's square
  EXPECT_THROW(courseWalls(s), Error);
  s = buttressedHouse();
  s.buttresses[0].from = 3.0;  // on the door's lintel
  EXPECT_THROW(courseWalls(s), Error);
  s = buttressedHouse();
  s.buttresses.push_back({"overlap", 0, 4.5, 5.0, 0.3, 1.0});
  EXPECT_THROW(courseWalls(s), Error);
  s = buttressedHouse();
  s.buttresses[1].depth = 0;
  EXPECT_THROW(courseWalls(s), Error);
}

}  // namespace
}  // namespace corbel::statics
