// Roofs over grown units by the extrusion kernel (growth/roofs.h): the exposed tops against a
// count of 0.5 m cells, each roof's footprint, ridge, parapet and volume against hand formulas,
// every shell closed and 2-manifold; on a grown site, the footprints against the exposed area
// from pairwise rectangle overlaps.
#include "growth/roofs.h"

#include "core/scene.h"
#include "growth/engine.h"
#include "support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

const double kTan30 = std::tan(std::numbers::pi / 6);

// Newell's normal (length = twice the area) of a face.
Vec3 newell(const MeshData& m, const std::vector<int>& f) {
  Vec3 n(0.0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec3& p = m.points[f[i]];
    const Vec3& q = m.points[f[(i + 1) % f.size()]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

// Area of the horizontal faces at height z facing up (up) or down.
double horizontalArea(const MeshData& m, double z, bool up) {
  double a = 0;
  for (const auto& f : m.faces) {
    bool level = true;
    for (int v : f) level = level && std::abs(m.points[v][2] - z) < 1e-6;
    const Vec3 n = newell(m, f);
    if (level && (up ? n[2] > 0 : n[2] < 0)) a += std::abs(n[2]) / 2;
  }
  return a;
}

double top(const MeshData& m) {
  double z = -1e9;
  for (const Vec3& p : m.points) z = std::max(z, p[2]);
  return z;
}

ValidityReport validate(const MeshData& m) {
  Scene s;
  s.replaceObject(1, Kind::Shell, "roof", m);
  return s.validate(1);
}

// A: 6 × 4 and B: 4 × 4 side by side, tops at 3; C: a double volume beside B, top at 6; D on A,
// top at 6, strictly inside A's top (a hole in it); E: 4 × 3 apart, top at 3.
std::vector<Unit> composite() {
  return {unitOf(1, {box(0, 0, 0, 6, 4, 3)}), unitOf(2, {box(6, 0, 0, 10, 4, 3)}),
          unitOf(3, {box(10, 0, 0, 14, 4, 6)}), unitOf(4, {box(1, 1, 3, 5, 3.5, 6)}),
          unitOf(5, {box(20, 0, 0, 24, 3, 3)})};
}

// Exposed top area at z by 0.5 m cells: a cell centre under some part's top at z and under no
// box whose floor is at z.
double exposedByCells(const std::vector<Unit>& units, double z) {
  double area = 0;
  for (double x = 0.25; x < 30; x += 0.5)
    for (double y = 0.25; y < 10; y += 0.5) {
      bool top = false, covered = false;
      for (const Unit& u : units)
        for (const Box& b : u.parts) {
          const bool inside = b.lo[0] < x && x < b.hi[0] && b.lo[1] < y && y < b.hi[1];
          top = top || (inside && b.hi[2] == z);
          covered = covered || (inside && b.lo[2] == z);
        }
      if (top && !covered) area += 0.25;
    }
  return area;
}

TEST(Roofs, ExposedTopsAreTheUnionOfTopsLessWhatStandsOnThem) {
  const Site site = test::openSite(30, 10, 2);
  const auto units = composite();
  const auto regions = exposedTops(site, units);
  // Two regions at 3 m (A ∪ B with D's hole, E), two at 6 m (C, D).
  ASSERT_EQ(regions.size(), 4u);
  double at3 = 0, at6 = 0;
  int holes = 0;
  for (const RoofRegion& r : regions) {
    (r.z == 3 ? at3 : at6) += r.area();
    holes += int(r.loops.size()) - 1;
    EXPECT_TRUE(r.z == 3 || r.z == 6);
  }
  EXPECT_EQ(holes, 1);
  EXPECT_NEAR(at3, exposedByCells(units, 3), 1e-9);
  EXPECT_NEAR(at6, exposedByCells(units, 6), 1e-9);
  EXPECT_NEAR(at3, 24 + 16 - 10 + 12, 1e-9);  // by hand
  // A ∪ B is one loop of four corners (the shared side's corners are gone).
  EXPECT_EQ(regions[0].loops[0].size(), 4u);
}

TEST(Roofs, EveryProfileRoofsEachRegionWithAClosedShellOnItsFootprint) {
  const Site site = test::openSite(30, 10, 2);
  const auto units = composite();
  for (RoofProfile p : {RoofProfile::Flat, RoofProfile::Shed, RoofProfile::Gable, RoofProfile::Hip}) {
    SCOPED_TRACE(roofProfileName(p));
    RoofSettings s;
    s.profile = p;
    const Roofs roofs = buildRoofs(site, units, s);
    EXPECT_TRUE(roofs.warnings.empty()) << ::testing::PrintToString(roofs.warnings);
    ASSERT_EQ(roofs.shells.size(), 4u);
    double at3 = 0, at6 = 0;
    for (std::size_t i = 0; i < roofs.shells.size(); ++i) {
      const double z = roofs.regions[i].z;
      (z == 3 ? at3 : at6) += horizontalArea(roofs.shells[i], z, false);
      const ValidityReport r = validate(roofs.shells[i]);
      EXPECT_TRUE(r.closedManifold()) << i << ": " << ::testing::PrintToString(r.problems());
      EXPECT_EQ(r.components, 1u);
    }
    EXPECT_NEAR(at3, exposedByCells(units, 3), 1e-6);
    EXPECT_NEAR(at6, exposedByCells(units, 6), 1e-6);
  }
}

// One 8 × 5 unit, 3 m high.
Roofs single(RoofProfile p) {
  RoofSettings s;
  s.profile = p;
  return buildRoofs(test::openSite(30, 10, 1), {unitOf(1, {box(2, 2, 0, 10, 7, 3)})}, s);
}

TEST(Roofs, AFlatRoofLiesASlabAboveTheCeilingInsideA09mParapet) {
  const Roofs r = single(RoofProfile::Flat);
  ASSERT_EQ(r.shells.size(), 1u);
  const MeshData& m = r.shells[0];
  const RoofSettings s;
  EXPECT_DOUBLE_EQ(s.parapet, 0.9);
  EXPECT_NEAR(top(m) - (3 + s.slab), 0.9, 1e-9);  // the parapet above the roof surface
  const double t = s.parapetThickness;
  EXPECT_NEAR(horizontalArea(m, 3 + s.slab, true), (8 - 2 * t) * (5 - 2 * t), 1e-6);
  EXPECT_NEAR(horizontalArea(m, 3 + s.slab + 0.9, true), 40 - (8 - 2 * t) * (5 - 2 * t), 1e-6);  // coping
  const ValidityReport v = validate(m);
  EXPECT_TRUE(v.closedManifold());
  EXPECT_NEAR(v.volume, 40 * s.slab + (40 - (8 - 2 * t) * (5 - 2 * t)) * 0.9, 1e-6);
}

TEST(Roofs, AGablesRidgeIsHalfTheSpanTimesTheTangentOfThePitchAboveTheWallTop) {
  const Roofs r = single(RoofProfile::Gable);
  ASSERT_EQ(r.shells.size(), 1u);
  const double h = 2.5 * kTan30;
  EXPECT_NEAR(top(r.shells[0]), 3 + h, 1e-9);
  const ValidityReport v = validate(r.shells[0]);
  EXPECT_TRUE(v.closedManifold());
  EXPECT_NEAR(v.volume, 8 * 5 * h / 2, 1e-6);  // a triangular prism
}

TEST(Roofs, AHipHasTheGablesRidgeAndLosesAWedgeAtEachEnd) {
  const Roofs r = single(RoofProfile::Hip);
  ASSERT_EQ(r.shells.size(), 1u);
  const double h = 2.5 * kTan30;
  EXPECT_NEAR(top(r.shells[0]), 3 + h, 1e-9);
  // The prism less, per end, the prism's end half (W/2 · W · h / 2) plus the hip's half pyramid
  // (W · W/2 · h / 3): L W h / 2 − W² h / 6.
  EXPECT_NEAR(validate(r.shells[0]).volume, 8 * 5 * h / 2 - 25 * h / 6, 1e-6);
}

TEST(Roofs, AShedRisesAcrossTheShortSide) {
  const Roofs r = single(RoofProfile::Shed);
  ASSERT_EQ(r.shells.size(), 1u);
  const double h = 5 * kTan30;
  EXPECT_NEAR(top(r.shells[0]), 3 + h, 1e-9);
  // The high side is +y (the slope starts from the −y edge).
  for (const Vec3& p : r.shells[0].points) {
    if (p[2] > 3 + h - 1e-9) {
      EXPECT_NEAR(p[1], 7, 1e-9);
    }
  }
  EXPECT_NEAR(validate(r.shells[0]).volume, 8 * 5 * h / 2, 1e-6);
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Roofs, GrownSitesAreRoofedOverExactlyTheirExposedTops) {
  for (const auto& [file, count] : {std::pair{"growth-alpha.json", 72u}, std::pair{"growth-beta.json", 132u}}) {
  SCOPED_TRACE(file);
  const Site site = parseSite(readText(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + file));
  GrowthEngine engine(site, {});
  engine.run(100000);
  const auto& units = engine.units();
  ASSERT_EQ(units.size(), count);
  // The oracle: Σ tops less Σ pairwise overlaps with the boxes whose floor is at a top's height
  // (tops at one height are disjoint, and so are the floors standing on them).
  std::vector<Box> boxes;
  for (const Unit& u : units) boxes.insert(boxes.end(), u.parts.begin(), u.parts.end());
  std::vector<Box> standing = boxes;
  standing.insert(standing.end(), site.circulation.begin(), site.circulation.end());
  double exposed = 0;
  for (const Box& b : boxes) {
    exposed += b.footprintArea();
    for (const Box& o : standing)
      if (std::abs(o.lo[2] - b.hi[2]) < 1e-6)
        exposed -= overlapLength(b.lo[0], b.hi[0], o.lo[0], o.hi[0]) * overlapLength(b.lo[1], b.hi[1], o.lo[1], o.hi[1]);
  }
  for (RoofProfile p : {RoofProfile::Flat, RoofProfile::Gable, RoofProfile::Hip, RoofProfile::Shed}) {
    SCOPED_TRACE(roofProfileName(p));
    RoofSettings s;
    s.profile = p;
    const Roofs roofs = buildRoofs(site, units, s);
    EXPECT_TRUE(roofs.warnings.empty()) << roofs.warnings.size() << " " << ::testing::PrintToString(roofs.warnings);
    EXPECT_GT(roofs.regions.size(), 30u);  // units of five storeys: many roofs
    double area = 0, regions = 0;
    int open = 0;
    for (std::size_t i = 0; i < roofs.shells.size(); ++i) {
      regions += roofs.regions[i].area();
      area += horizontalArea(roofs.shells[i], roofs.regions[i].z, false);
      open += !validate(roofs.shells[i]).closedManifold();
    }
    EXPECT_NEAR(regions, exposed, 1e-6 * exposed);
    EXPECT_NEAR(area, exposed, 1e-6 * exposed);
    EXPECT_EQ(open, 0);
  }
  }
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// A ring closed only at a corner: bottom 6 × 2, right 2 × 4, top 2 × 2 and left 2 × 2, the top
// and left pieces meeting at (2, 4), so the enclosed 2 × 2 court touches the outside there.
TEST(Roofs, ARegionPinchedAtACornerIsCutThereIntoSimpleRegions) {
  const Site site = test::openSite(30, 10, 1);
  const std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 6, 2, 3)}), unitOf(2, {box(4, 2, 0, 6, 6, 3)}),
                                unitOf(3, {box(2, 4, 0, 4, 6, 3)}), unitOf(4, {box(0, 2, 0, 2, 4, 3)})};
  const auto regions = exposedTops(site, units);
  // Cut at x = 2: the rectangle 0–2 × 0–4 and the U of the rest.
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_NEAR(regions[0].area() + regions[1].area(), 12 + 8 + 4 + 4, 1e-9);
  for (const RoofRegion& r : regions) {
    EXPECT_EQ(r.loops.size(), 1u);
    std::vector<Vec2> corners = r.loops[0];
    std::sort(corners.begin(), corners.end(), [](const Vec2& a, const Vec2& b) { return std::pair(a[0], a[1]) < std::pair(b[0], b[1]); });
    EXPECT_EQ(std::adjacent_find(corners.begin(), corners.end()), corners.end());  // simple
  }
  for (RoofProfile p : {RoofProfile::Flat, RoofProfile::Shed, RoofProfile::Gable, RoofProfile::Hip}) {
    SCOPED_TRACE(roofProfileName(p));
    RoofSettings s;
    s.profile = p;
    const Roofs roofs = buildRoofs(site, units, s);
    EXPECT_TRUE(roofs.warnings.empty()) << ::testing::PrintToString(roofs.warnings);
    double area = 0;
    for (const MeshData& m : roofs.shells) {
      area += horizontalArea(m, 3, false);
      EXPECT_TRUE(validate(m).closedManifold());
    }
    EXPECT_NEAR(area, 28, 1e-6);
  }
}

}  // namespace
}  // namespace corbel::growth
