// Masonry templates against independent oracles: analytic volumes, hand-counted contacts,
// hand-computed tipping angles, the validated semicircular arch.
#include "core/error.h"
#include "statics/arch.h"
#include "statics/builder.h"
#include "statics/buttress.h"
#include "statics/column.h"
#include "statics/dome.h"
#include "statics/equilibrium.h"
#include "statics/examples.h"
#include "statics/thresholds.h"
#include "statics/tolerances.h"
#include "statics/wall.h"
#include "statics/vault.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double totalVolume(const Assembly& as) {
  BBox box;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  const std::vector<BlockProperties> props = validateAssembly(as, lengthTolerance(box));  // every block validates
  double v = 0;
  for (std::size_t i = 0; i < as.blocks.size(); ++i)
    if (!as.blocks[i].fixed) v += props[i].volume;
  return v;
}

std::size_t contactCount(const Assembly& as) { return prepareEquilibrium(as, {}).contacts.interfaces.size(); }

Assembly onGround(std::vector<Block> blocks, double tiltDeg = 0) {
  StructureBuilder b;
  b.add("t", std::move(blocks));
  b.groundUnder(2.0);
  b.tilt(tiltDeg);
  return b.build();
}

bool stands(const Assembly& as) { return checkFeasibility(as).feasible; }

// The true pointed arch: each half is the annulus ρ ∓ t/2 about (∓d, 0) cut by x = 0; in polar
// coordinates about its centre its area is ∫ r·acos(d/r) dr over [ρ − t/2, ρ + t/2].
double pointedArchArea(const PointedArchSpec& s) {
  const double rho = s.radiusRatio * s.radius, d = rho - s.radius;
  auto F = [&](double r) { return 0.5 * r * r * std::acos(d / r) - 0.5 * d * std::sqrt(r * r - d * d); };
  return 2 * (F(rho + s.thickness / 2) - F(rho - s.thickness / 2));
}

TEST(Templates, PointedArchVolumeApproachesTheAnalyticAreaFromBelow) {
  PointedArchSpec s;
  s.radiusRatio = 2.0;
  s.thickness = 0.2;
  s.depth = 0.5;
  const double exact = pointedArchArea(s) * s.depth;
  double previousError = 0;
  for (int n : {20, 40, 80}) {
    s.blocks = n;
    const Assembly as = pointedArch(s);
    const double v = totalVolume(as);
    const double err = exact - v;
    EXPECT_GT(err, 0) << n;                 // chords cut inside the arcs
    EXPECT_LT(err, 0.01 * exact) << n;
    // The chords' loss shrinks with the joint angle; what is left is the crown block's
    // extrados chord, which spans the fixed angle between where intrados and extrados meet
    // the crown plane.
    if (previousError > 0) {
      EXPECT_LT(err, previousError) << n;
    }
    previousError = err;
    EXPECT_EQ(contactCount(as), std::size_t(n + 1)) << n;  // n − 1 joints, two springings
  }
}

// Radius ratio 1 is the semicircular arch: same blocks, same measure.
TEST(Templates, PointedArchWithRatioOneIsTheSemicircularArch) {
  PointedArchSpec p;
  p.blocks = 20;
  p.radiusRatio = 1.0;
  p.thickness = 0.06;
  ArchSpec s;
  s.blocks = 20;
  s.thickness = 0.06;
  const AnalysisResult a = analyse(pointedArch(p)), b = analyse(semicircularArch(s));
  EXPECT_GT(b.yNormalised, 1e-6);
  EXPECT_NEAR(a.yNormalised, b.yNormalised, 1e-8 * b.yNormalised);
  EXPECT_NEAR(totalVolume(pointedArch(p)), totalVolume(semicircularArch(s)), 1e-12);
}

// A pointed arch needs less thickness than a semicircular one: at t/R = 0.08 the equilateral
// arch stands and the semicircular (minimum 0.1075) does not.
TEST(Templates, EquilateralArchStandsWhereTheSemicircularOneFails) {
  PointedArchSpec p;
  p.blocks = 40;
  p.thickness = 0.08;
  EXPECT_TRUE(stands(pointedArch(p)));
  p.radiusRatio = 1.0;
  EXPECT_FALSE(stands(pointedArch(p)));
}

// A column of square drums (side b = 2a) tips on ground tilted past atan(b/H); sliding would
// need tan θ > α = 0.7, which b/H = 0.2 stays below.
TEST(Templates, ColumnVolumeContactsAndTippingTilt) {
  for (int sides : {4, 8}) {
    ColumnSpec c;
    c.drums = 5;
    c.sides = sides;
    c.radius = 0.3;
    c.height = 3.0;
    const Assembly as = onGround(columnBlocks(c));
    EXPECT_NEAR(totalVolume(as), c.height * 0.5 * sides * c.radius * c.radius * std::sin(2 * std::numbers::pi / sides), 1e-12);
    EXPECT_EQ(contactCount(as), std::size_t(c.drums));
    const double apothem = c.radius * std::cos(std::numbers::pi / sides);
    const double tip = std::atan(2 * apothem / c.height) / kDeg;
    EXPECT_TRUE(stands(onGround(columnBlocks(c), tip - 0.2))) << sides;
    EXPECT_FALSE(stands(onGround(columnBlocks(c), tip + 0.2))) << sides;
  }
}

TEST(Templates, ButtressVolumeContactsAndTippingTilt) {
  ButtressSpec s;
  s.height = 3.0;
  s.baseWidth = 1.2;
  s.topWidth = 0.6;
  s.depth = 0.8;
  s.courses = 6;
  // Widths interpolate linearly over the courses: their mean is (base + top)/2.
  EXPECT_NEAR(totalVolume(onGround(buttressBlocks(s))), s.depth * s.height * (s.baseWidth + s.topWidth) / 2, 1e-12);
  EXPECT_EQ(contactCount(onGround(buttressBlocks(s))), std::size_t(s.courses));
  // A pier (equal widths) of width b tips about its toe at tan θ = b/H (the base joint governs).
  s.baseWidth = s.topWidth = 0.9;
  const double tip = std::atan(s.baseWidth / s.height) / kDeg;
  EXPECT_TRUE(stands(onGround(buttressBlocks(s), tip - 0.2)));
  EXPECT_FALSE(stands(onGround(buttressBlocks(s), tip + 0.2)));
  const double found = bisectThreshold([&](double deg) { return stands(onGround(buttressBlocks(s), deg)); }, 0.0, 30.0, 1e-4);
  EXPECT_NEAR(found, tip, 1e-3);
}

// Running bond without openings, length m·b: even courses have m blocks, odd ones m + 1 (half
// blocks at the ends); each course has (blocks − 1) head joints, each pair of courses 2m bed
// contacts, and the first course m contacts with the ground.
TEST(Templates, WallOfCoursesHasTheHandCountedContacts) {
  WallSpec w;
  w.length = 3.0;
  w.blockLength = 0.5;
  w.courses = 5;
  w.height = 2.5;
  w.thickness = 0.3;
  const int m = 6;
  const Assembly as = onGround(wallBlocks(w));
  int heads = 0;
  for (int c = 0; c < w.courses; ++c) heads += (c % 2 ? m + 1 : m) - 1;
  EXPECT_EQ(int(as.blocks.size()) - 1, 3 * m + 2 * (m + 1));
  EXPECT_EQ(int(contactCount(as)), heads + (w.courses - 1) * 2 * m + m);
  EXPECT_NEAR(totalVolume(as), w.length * w.thickness * w.height, 1e-12);
  EXPECT_TRUE(stands(as));
}

TEST(Templates, WallWithWindowsHasTheOpeningsCutOutAndStands) {
  WallSpec w;
  w.length = 6.0;
  w.courses = 8;
  w.height = 4.0;
  w.windows = {{1.0, 1.0, 2, 6}, {3.5, 1.5, 0, 5}};  // a window and a door
  const Assembly as = onGround(wallBlocks(w));
  const double hc = w.height / w.courses;
  const double openings = (1.0 * 4 * hc + 1.5 * 5 * hc) * w.thickness;
  EXPECT_NEAR(totalVolume(as), w.length * w.thickness * w.height - openings, 1e-12);
  // No block lies in an opening: every block's centre is outside both.
  for (const Block& b : as.blocks) {
    if (b.fixed) continue;
    BBox box;
    for (const Vec3& v : b.vertices) box.add(v);
    const Vec3 c = box.center();
    for (const WindowSpec& o : w.windows)
      EXPECT_FALSE(c[0] > o.x && c[0] < o.x + o.width && c[2] > o.sill * hc && c[2] < o.head * hc) << b.name;
  }
  EXPECT_TRUE(stands(as));
  EXPECT_THROW(wallBlocks(WallSpec{6.0, 0.4, 4.0, 8, 0.5, {{5.5, 1.0, 1, 3}}, 2400.0}), Error);              // leaves the wall
  EXPECT_THROW(wallBlocks(WallSpec{6.0, 0.4, 4.0, 8, 0.5, {{1.0, 1.0, 1, 3}, {2.2, 1.0, 1, 3}}, 2400.0}), Error);  // overlap
  EXPECT_THROW(wallBlocks(WallSpec{6.0, 0.4, 4.0, 8, 0.5, {{1.0, 1.0, 3, 8}}, 2400.0}), Error);              // no lintel course
}

// Rings of voussoirs in stack bond: each ring is the semicircular arch (N − 1 joints, two
// springings), neighbouring rings touch voussoir to voussoir. The vault stands exactly when
// its arch does: on both sides of the arch's least thickness for N voussoirs (bisection).
TEST(Templates, BarrelVaultCountsVolumeAndStandsWithItsArch) {
  BarrelVaultSpec v;
  v.blocks = 12;
  v.rings = 4;
  v.radius = 1.0;
  v.thickness = 0.15;
  v.length = 2.0;
  const Assembly as = barrelVault(v);
  EXPECT_NEAR(totalVolume(as), v.length * v.blocks * v.radius * v.thickness * std::sin(std::numbers::pi / v.blocks), 1e-12);
  EXPECT_EQ(int(contactCount(as)), v.rings * (v.blocks + 1) + (v.rings - 1) * v.blocks);
  ArchSpec arch;
  arch.blocks = v.blocks;
  const double least = minimumArchThickness(arch, {}, 1e-5);
  v.thickness = least + 0.003;
  EXPECT_TRUE(stands(barrelVault(v)));
  v.thickness = least - 0.003;
  EXPECT_FALSE(stands(barrelVault(v)));
}

// A flyer of n voussoirs is a quarter of the chorded annulus: n R t sin(π/2n) of section, on a
// pier of height × width; its contacts are the n − 1 joints, the springing on the pier, the
// pier's courses (the top on the ground counted once). Its head, free of any wall, leans on
// nothing: alone it cantilevers off its pier and cannot stand; against a wall face it can.
TEST(Templates, FlyingButtressVolumeContactsAndTheWallItNeeds) {
  FlyingButtressSpec f;
  f.blocks = 5;
  f.radius = 1.2;
  f.thickness = 0.25;
  f.depth = 0.5;
  f.pierHeight = 1.5;
  f.pierWidth = 0.6;
  f.pierCourses = 3;
  const Assembly alone = onGround(flyingButtressBlocks(f));
  const double section = f.blocks * f.radius * f.thickness * std::sin(std::numbers::pi / (2 * f.blocks));
  EXPECT_NEAR(totalVolume(alone), (section + f.pierHeight * f.pierWidth) * f.depth, 1e-12);
  EXPECT_EQ(int(contactCount(alone)), (f.blocks - 1) + 1 + f.pierCourses);
  EXPECT_FALSE(stands(alone));
  // A fixed wall face at x = 0 behind the head: now the flyer is an arch between pier and wall.
  StructureBuilder b;
  b.add("flyer", flyingButtressBlocks(f));
  b.groundUnder(2.0);
  Assembly propped = b.build();
  propped.blocks.push_back(boxBlock("wall", Vec3(-1.0, -0.5, 0.0), Vec3(0.0, 1.0, 4.0), 1.0, true));
  EXPECT_EQ(int(contactCount(propped)), (f.blocks - 1) + 1 + f.pierCourses + 1);
  EXPECT_TRUE(stands(propped));
}

// The Bezier arch's centreline, written again here: the band of thickness t around a smooth
// curve has area t × its length exactly (the inner and outer offsets' curvature terms cancel),
// so the voussoirs' volume is that up to chords and the horizontal springing cuts.
double bezierLength(const BezierArchSpec& s) {
  auto point = [&](double u) {
    const double v = 1 - u;
    return Vec2(-s.radius * v * v * v + 3 * s.x1 * v * v * u + 3 * s.x2 * v * u * u + s.radius * u * u * u,
                3 * v * v * u + 3 * v * u * u);
  };
  double top = 0;
  for (int i = 0; i <= 100000; ++i) top = std::max(top, point(i / 100000.0)[1]);
  double length = 0;
  Vec2 prev = point(0);
  prev[1] *= s.height / top;
  for (int i = 1; i <= 100000; ++i) {
    Vec2 q = point(i / 100000.0);
    q[1] *= s.height / top;
    length += (q - prev).norm();
    prev = q;
  }
  return length;
}

TEST(Templates, BezierArchVolumeIsItsBandAndItsCrownItsHeight) {
  BezierArchSpec s;
  s.blocks = 64;
  s.x1 = -0.8;
  s.x2 = 0.3;
  s.height = 1.3;
  s.thickness = 0.05;
  const Assembly as = bezierArch(s);
  const double band = bezierLength(s) * s.thickness * s.depth;
  EXPECT_NEAR(totalVolume(as), band, 0.005 * band);
  EXPECT_EQ(contactCount(as), std::size_t(s.blocks + 1));
  double crown = 0;
  for (const ArchJoint& j : bezierJoints(s)) crown = std::max(crown, 0.5 * (j.inner[1] + j.outer[1]));
  EXPECT_NEAR(crown, s.height, 2e-3 * s.height);
}

// Mirroring the control points (x1, x2) → (−x2, −x1) mirrors the arch: the same measure.
TEST(Templates, BezierArchMirroredHasTheSameMeasure) {
  BezierArchSpec a;
  a.x1 = -1.2;
  a.x2 = 0.4;
  a.thickness = 0.05;
  BezierArchSpec b = a;
  b.x1 = -a.x2;
  b.x2 = -a.x1;
  const AnalysisResult ra = analyse(bezierArch(a)), rb = analyse(bezierArch(b));
  ASSERT_GT(ra.yNormalised, 1e-6);
  EXPECT_NEAR(ra.yNormalised, rb.yNormalised, 1e-7 * ra.yNormalised);
}

// The dome's blocks are inscribed in the spherical shell between the springing and the oculus,
// (2π/3)(ro³ − ri³) sin(90° − oculus): below it, and closer with more blocks. Contacts: each
// ring's meridional joints, the bed joints between rings, the springing ring on the ground.
TEST(Templates, DomeVolumeApproachesItsShellAndHasTheHandCountedContacts) {
  DomeSpec d;
  d.radius = 2.0;
  d.thickness = 0.2;
  d.oculusDeg = 10.0;
  const double ri = d.radius - d.thickness / 2, ro = d.radius + d.thickness / 2;
  const double shell = 2 * std::numbers::pi / 3 * (ro * ro * ro - ri * ri * ri) * std::sin((90 - d.oculusDeg) * kDeg);
  double previous = 0;
  for (int k : {1, 2, 4}) {
    d.rings = 4 * k;
    d.segments = 8 * k;
    const Assembly as = onGround(domeBlocks(d));
    const double v = totalVolume(as);
    EXPECT_LT(v, shell);
    EXPECT_GT(v, previous);
    previous = v;
    EXPECT_EQ(int(contactCount(as)), d.rings * d.segments + (d.rings - 1) * d.segments + d.segments);
  }
  EXPECT_GT(previous, 0.98 * shell);
}

// A drum's blocks are prisms on the ring between two regular n-gons, (n/2)(ro² − ri²) sin(2π/n)
// in plan. A window cuts, through each course it opens, a slab w wide across the segment
// between its inner and outer chords, w·t·cos(π/n) in plan, and splits the segment's block
// into two jambs; the block over it (its lintel) bears on both jambs, over the segment's
// plan less the opening. Mirror symmetry: the jambs are mirror images in the segment's plane.
TEST(Templates, DrumWindowsCutTheirOpeningsAndTheLintelsBearOnTheJambs) {
  DrumSpec d;
  d.courses = 5;
  d.segments = 16;
  d.radius = 3.0;
  d.thickness = 0.4;
  d.height = 5.0;
  d.bond = false;
  const double ri = d.radius - d.thickness / 2, ro = d.radius + d.thickness / 2, h = d.height / d.courses;
  const double ring = 8 * (ro * ro - ri * ri) * std::sin(2 * std::numbers::pi / 16);
  const double opening = d.thickness * std::cos(std::numbers::pi / 16);  // per metre of window width
  EXPECT_NEAR(totalVolume(onGround(drumBlocks(d))), ring * d.height, 1e-9);
  d.windowWidth = 0.7;
  d.windowSill = 1;
  d.windowHead = 4;
  const std::vector<Block> blocks = drumBlocks(d);
  const int windows = 8, openCourses = 3;
  EXPECT_EQ(blocks.size(), std::size_t(16 * 5 + windows * openCourses));
  const Assembly as = onGround(blocks);
  EXPECT_NEAR(totalVolume(as), ring * d.height - windows * openCourses * h * d.windowWidth * opening, 1e-9);
  // Segment 1 (the first window) in course 1: its jambs mirror each other in the plane at
  // angle 3π/16, and the gap between them is the window's width.
  const double mid = 3 * std::numbers::pi / 16;
  const Vec3 u(std::cos(mid), std::sin(mid), 0.0), v(-std::sin(mid), std::cos(mid), 0.0);
  const Block* jamb[2] = {nullptr, nullptr};
  for (const Block& b : as.blocks) {
    if (b.name == "t/course 1 block 1 jamb 0") jamb[0] = &b;
    if (b.name == "t/course 1 block 1 jamb 1") jamb[1] = &b;
  }
  ASSERT_TRUE(jamb[0] && jamb[1]);
  double inner0 = -1e9, inner1 = 1e9;
  for (const Vec3& p : jamb[0]->vertices) {
    inner0 = std::max(inner0, dot(p, v));
    const Vec3 mirrored = p - 2 * dot(p, v) * v;
    bool found = false;
    for (const Vec3& q : jamb[1]->vertices) found = found || (q - mirrored).norm() < 1e-12;
    EXPECT_TRUE(found) << p;
  }
  for (const Vec3& p : jamb[1]->vertices) inner1 = std::min(inner1, dot(p, v));
  EXPECT_NEAR(inner1 - inner0, d.windowWidth, 1e-12);
  // Course 4's block over the window touches the two jambs below it over its plan less the
  // opening; the neighbouring segments' blocks touch theirs over the whole plan.
  const std::vector<Interface> contacts = prepareEquilibrium(as, {}).contacts.interfaces;
  double lintel = 0, plain = 0;
  for (const Interface& f : contacts) {
    const std::string& a = as.blocks[std::size_t(f.a)].name;
    const std::string& b = as.blocks[std::size_t(f.b)].name;
    if ((a == "t/course 4 block 1") != (b == "t/course 4 block 1") &&
        (a.rfind("t/course 3 block 1 jamb", 0) == 0 || b.rfind("t/course 3 block 1 jamb", 0) == 0))
      lintel += f.area;
    if ((a == "t/course 4 block 2" && b == "t/course 3 block 2") ||
        (b == "t/course 4 block 2" && a == "t/course 3 block 2"))
      plain += f.area;
  }
  EXPECT_NEAR(plain, ring / 16, 1e-12);
  EXPECT_NEAR(lintel, ring / 16 - d.windowWidth * opening, 1e-12);
  EXPECT_TRUE(stands(as));
  d.windowWidth = 0.95 * 2 * ri * std::sin(std::numbers::pi / 16);  // jambs under 5 % of the inner chord
  EXPECT_THROW(drumBlocks(d), Error);
  d.windowWidth = 0.7;
  d.bond = true;
  EXPECT_THROW(drumBlocks(d), Error);
  d.bond = false;
  d.windowHead = 5;  // no course over the windows
  EXPECT_THROW(drumBlocks(d), Error);
}

// Heyman (The Stone Skeleton, 1995): a hemispherical masonry dome needs t/R ≥ 0.042. A dome
// of 10 rings × 16 voussoirs with a 2° oculus (nearly closed) stands from the same thickness.
TEST(Templates, HemisphericalDomeMinimumThicknessIsHeymans) {
  auto stands = [](double t) {
    DomeSpec d;
    d.radius = 1.0;
    d.thickness = t;
    d.rings = 10;
    d.segments = 16;
    d.oculusDeg = 2.0;
    return checkFeasibility(onGround(domeBlocks(d))).feasible;
  };
  EXPECT_NEAR(bisectThreshold(stands, 0.08, 0.01, 1e-3), 0.042, 0.002);
}

TEST(Templates, ExamplesHaveThePapersBlockCounts) {
  EXPECT_EQ(towerExample().build(towerExample().parameters).blocks.size(), 96u + 1);        // Fig. 11: 96 blocks
  EXPECT_EQ(barrelVaultExample().build(barrelVaultExample().parameters).blocks.size(), 140u + 1);  // Table 1: 140
  EXPECT_EQ(archOnColumnsExample().build(archOnColumnsExample().parameters).blocks.size(), 10u + 1);  // Table 1: 10
  // 60 vault blocks; per ring and side 4 wall courses, 5 flyer voussoirs, 3 pier courses.
  EXPECT_EQ(flyingButtressVaultExample().build(flyingButtressVaultExample().parameters).blocks.size(), 60u + 2 * 5 * 12 + 1);
  // Fig. 9 (Table 1: 486): 12 rings of 14 voussoirs, 7 piers of 6 courses a side, and 12 bays
  // of wall, each of the wall template's blocks for one bay with its window.
  {
    const ParametricModel c = chapelExample();
    WallSpec bay{3.0, 0.6, 6.0, 6, 0.75, {{0.75, 1.5, 1, 5}}, 2400.0};
    const std::size_t wall = wallBlocks(bay).size();
    EXPECT_EQ(c.build(c.parameters).blocks.size(), 12u * 14 + 2 * 7 * 6 + 12 * wall + 1);
    EXPECT_NEAR(double(c.build(c.parameters).blocks.size()), 486.0, 20.0);
  }
  // Fig. 1 (Table 1: 986): 26 rings of 12 voussoirs, 5 wall courses, 5 flyer voussoirs and 3
  // pier courses a side.
  EXPECT_EQ(abbeyExample().build(abbeyExample().parameters).blocks.size(), 26u * (12 + 2 * (5 + 5 + 3)) + 1);
  // Fig. 10 (c): 5 drum courses and 8 dome rings of 16, and 8 flyers of 5 voussoirs on 3
  // courses; 8 windows through 3 courses each add a jamb a course.
  EXPECT_EQ(mosqueExample().build(mosqueExample().parameters).blocks.size(),
            16u * 5 + 8 * 3 + 16 * 8 + 8 * (5 + 3) + 1);
  // Fig. 10 (a, d): no flyers; the hall's four walls (each the wall template, a + b = 6 m long,
  // 0.8 m thick, 4 courses of 1 m and a 1 m window) and 8 slabs under the drum.
  {
    const WallSpec wall{6.0, 0.8, 4.0, 4, 1.0, {{2.6 - 0.5, 1.0, 1, 3}}, 2400.0};
    EXPECT_EQ(mosqueHallExample().build(mosqueHallExample().parameters).blocks.size(),
              16u * 5 + 8 * 3 + 16 * 8 + 4 * wallBlocks(wall).size() + 8 + 1);
  }
  EXPECT_THROW(exampleByName("cathedral"), Error);
}

TEST(Templates, BadSpecsGetAClearError) {
  PointedArchSpec p;
  p.blocks = 7;
  EXPECT_THROW(pointedArch(p), Error);
  p.blocks = 8;
  p.radiusRatio = 0.5;
  EXPECT_THROW(pointedArch(p), Error);
  ColumnSpec c;
  c.sides = 2;
  EXPECT_THROW(columnBlocks(c), Error);
  ButtressSpec b;
  b.topWidth = -1;
  EXPECT_THROW(buttressBlocks(b), Error);
  BarrelVaultSpec v;
  v.rings = 0;
  EXPECT_THROW(barrelVaultBlocks(v), Error);
  DomeSpec d;
  d.oculusDeg = 90;
  EXPECT_THROW(domeBlocks(d), Error);
  FlyingButtressSpec f;
  f.pierWidth = 4 * f.radius;
  EXPECT_THROW(flyingButtressBlocks(f), Error);
}

}  // namespace
}  // namespace corbel::statics
