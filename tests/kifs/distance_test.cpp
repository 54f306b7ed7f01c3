// Specifications of kifs/distance.h: Algorithm 1 is the Menger sponge for the paper's
// parameters, it is 1-Lipschitz, the bailout never changes its sign nor makes it larger, the
// building's bound never reaches into the solid, and the folds of Algorithm 2 and Eq. 4 give
// the paper's ids and storeys.
#include "core/error.h"
#include "kifs/distance.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace corbel::kifs::test {
namespace {

// The 20 sub-cubes the Menger sponge keeps, as digit triples in {0, 1, 2}: at most one 1.
std::vector<std::array<int, 3>> keptCubes(bool kept) {
  std::vector<std::array<int, 3>> out;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        if (((a == 1) + (b == 1) + (c == 1) <= 1) == kept) out.push_back({a, b, c});
  return out;
}

KifsParams mengerParams(int iterations) {
  KifsParams p;
  p.centre = {1, 1, 1};
  p.scale = 3;
  p.iterations = iterations;
  return p;
}

// Fig. 1a: s = 3, c = (1, 1, 1), R1 = R2 = I is the Menger sponge of [−1, 1]³. Every point of
// the level-N sponge (N = M + 1 folds) is inside; the centre of every cube removed at a level
// up to N − 2 is outside. The paper's literal line 13 (z < h ⇒ z −= 2h) fails both.
TEST(KifsDistance, MengerParametersGiveTheMengerSponge) {
  const int M = 4, N = M + 1;
  const Building b(mengerParams(M));
  const auto kept = keptCubes(true), removed = keptCubes(false);
  ASSERT_EQ(kept.size(), 20u);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> pickKept(0, 19), pickRemoved(0, 6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 3000; ++trial) {
    // A point of the level-N sponge: N kept digits, then anywhere in that cube.
    glm::dvec3 lo(-1.0);
    double side = 2.0;
    for (int level = 0; level < N; ++level) {
      side /= 3.0;
      const auto& d = kept[pickKept(rng)];
      lo += side * glm::dvec3(d[0], d[1], d[2]);
    }
    const glm::dvec3 inside = lo + side * glm::dvec3(u(rng), u(rng), u(rng));
    EXPECT_LE(b.kifs(inside), 0.0) << "level-" << N << " sponge point " << inside.x << "," << inside.y << "," << inside.z;

    // The centre of a cube removed at level L ≤ N − 2.
    const int L = 1 + trial % (N - 2);
    lo = glm::dvec3(-1.0);
    side = 2.0;
    for (int level = 0; level < L; ++level) {
      side /= 3.0;
      const auto& d = level + 1 < L ? kept[pickKept(rng)] : removed[pickRemoved(rng)];
      lo += side * glm::dvec3(d[0], d[1], d[2]);
    }
    const glm::dvec3 centre = lo + 0.5 * side;
    EXPECT_GT(b.kifs(centre), 0.0) << "centre of a cube removed at level " << L;
  }
}

// Every fold is 1-Lipschitz and the scale is s, so without a bailout (|T^{M+1} p| − ρ)/s^{M+1}
// is 1-Lipschitz, also with R1 ≠ I (which needs the continuous form of line 13).
TEST(KifsDistance, AlgorithmOneIsOneLipschitz) {
  for (int variant = 0; variant < 3; ++variant) {
    KifsParams p;
    p.bailout = 1e300;
    if (variant == 1) p.r1 = {0, 180.0 / 25.0, 0};  // Fig. 2b
    if (variant == 2) p.r1 = {10, 45, 5}, p.r2 = {0, 22.5, 0}, p.centre = {1.1, 0.7, 0.5}, p.scale = 2.6;
    const Building b(p);
    std::mt19937_64 rng(11 + variant);
    std::uniform_real_distribution<double> logLen(-6.0, 0.3);
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
      const glm::dvec3 a = uniformIn(rng, glm::dvec3(-1.5), glm::dvec3(1.5));
      const glm::dvec3 c = a + std::pow(10.0, logLen(rng)) * unitVector(rng);
      const double ratio = std::abs(b.kifs(a) - b.kifs(c)) / glm::length(a - c);
      worst = std::max(worst, ratio);
    }
    EXPECT_LE(worst, 1.0 + 1e-6) << "variant " << variant;
  }
}

// A bailout of at least ρ² keeps the solid and the sign, and only lowers the estimate outside.
TEST(KifsDistance, BailoutKeepsTheSignAndLowersTheEstimate) {
  for (double bailout : {4.0, 10.0, 1000.0}) {
    KifsParams p, exact;
    p.bailout = bailout;
    exact.bailout = 1e300;
    const Building b(p), e(exact);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 20000; ++i) {
      const glm::dvec3 q = uniformIn(rng, glm::dvec3(-3.0), glm::dvec3(3.0));
      const double db = b.kifs(q), de = e.kifs(q);
      if (de <= 0) {
        EXPECT_DOUBLE_EQ(db, de);
      } else {
        EXPECT_GT(db, 0.0) << "bailout " << bailout;
        EXPECT_LE(db, de * (1 + 1e-12)) << "bailout " << bailout;
      }
    }
  }
}

// The sphere tracer's premise: around any point, no point of the solid lies closer than the
// bound. Checked by sampling each ball densely (inside and on its sphere), for every preset
// and for points both far and near the surface. Facade-id and floor boundaries, where the
// folded coordinates jump, are where a bound without the cell-boundary caps fails this.
TEST(KifsDistance, BoundNeverReachesIntoTheSolid) {
  for (const std::string& name : buildingPresets()) {
    const Building b(preset(name));
    const Aabb box = b.worldBounds();
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0), near(-2.5, 0.0);
    int tested = 0;
    for (int i = 0; tested < 1000 && i < 100000; ++i) {
      glm::dvec3 p = uniformIn(rng, box.lo, box.hi);
      if (i % 2 == 1) {  // near the surface: from a solid point, a short way out
        if (b.evaluate(p).surface > 0) continue;
        p += std::pow(10.0, near(rng)) * unitVector(rng);
      }
      const double r = b.evaluate(p).bound;
      if (r <= 0) continue;
      ++tested;
      for (int k = 0; k < 1000; ++k) {
        const double radius = (k % 3 == 0 ? 1.0 : std::cbrt(u(rng))) * r * (1 - 1e-9);
        const glm::dvec3 q = p + radius * unitVector(rng);
        ASSERT_GT(b.evaluate(q).surface, 0.0) << name << ": bound " << r << " at (" << p.x << ", " << p.y << ", "
                                              << p.z << ") reaches the solid at distance " << radius;
      }
    }
    EXPECT_EQ(tested, 1000) << name;
  }
}

// The bound and the estimate describe the same solid: one is ≤ 0 exactly when the other is.
TEST(KifsDistance, BoundAndSurfaceShareTheSolid) {
  for (const std::string& name : buildingPresets()) {
    const Building b(preset(name));
    std::mt19937_64 rng(9);
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
      const Sample s = b.evaluate(uniformIn(rng, b.worldBounds().lo, b.worldBounds().hi));
      EXPECT_EQ(s.bound <= 0, s.surface <= 0) << name;
      EXPECT_LE(s.bound, s.surface + 1e-12) << name;
      inside += s.surface <= 0;
    }
    EXPECT_GT(inside, 0) << name << ": the preset is empty";
  }
}

// Eq. 1-3 against the closest point of each box (clamping): exact outside, negative inside.
TEST(KifsDistance, MassModelIsTheDistanceToTheUnionOfItsBoxes) {
  for (Footprint f : {Footprint::Box, Footprint::T, Footprint::H}) {
    MassModel m;
    m.footprint = f;
    m.halfWidth = 10, m.halfDepth = 7, m.wing = 2.5, m.height = 12;
    // The boxes written out independently (lo, hi) in building coordinates, y up.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes;
    if (f == Footprint::Box) boxes = {{{-10, 0, -7}, {10, 12, 7}}};
    if (f == Footprint::T) boxes = {{{-10, 0, 2}, {10, 12, 7}}, {{-2.5, 0, -7}, {2.5, 12, 7}}};
    if (f == Footprint::H)
      boxes = {{{-10, 0, -7}, {-5, 12, 7}}, {{5, 0, -7}, {10, 12, 7}}, {{-10, 0, -2.5}, {10, 12, 2.5}}};
    std::mt19937_64 rng(1);
    for (int i = 0; i < 5000; ++i) {
      const glm::dvec3 p = uniformIn(rng, glm::dvec3(-14, -3, -11), glm::dvec3(14, 16, 11));
      double oracle = 1e300;
      bool in = false;
      for (const auto& [lo, hi] : boxes) {
        oracle = std::min(oracle, glm::length(p - glm::clamp(p, lo, hi)));
        in = in || (glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi)));
      }
      const double d = massModelDistance(m, p, 0.0);
      if (in) EXPECT_LT(d, 0.0);
      else EXPECT_NEAR(d, oracle, 1e-12);
    }
  }
}

// Algorithm 2 with Fig. 6's r = (0.25, 0.125, 0.4), values worked by hand at three places of a
// period, and the symmetry and continuity of the triangle wave.
TEST(KifsDistance, FacadeFoldGivesThePapersIds) {
  Facade fc;
  fc.period = 4.0;
  fc.r = {0.25, 0.125, 0.4};
  struct Case {
    double u, f;
    int id;
  };
  for (const Case& c : {Case{0.1, 0.05, 2}, Case{0.5, 0.0, 0}, Case{0.3, 0.1, 0}}) {
    const FacadeFold r = facadeFold(c.u * fc.period + 3 * fc.period, fc);
    EXPECT_NEAR(r.f, c.f, 1e-12) << "u = " << c.u;
    EXPECT_EQ(r.id, c.id) << "u = " << c.u;
  }
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> x(-20, 20);
  for (int i = 0; i < 2000; ++i) {
    const double a = x(rng);
    const FacadeFold l = facadeFold(a, fc), m = facadeFold(-a, fc), p = facadeFold(a + fc.period, fc);
    EXPECT_NEAR(l.f, m.f, 1e-9);  // mirror symmetry
    EXPECT_EQ(l.id, m.id);
    EXPECT_NEAR(l.f, p.f, 1e-9);  // periodic
    EXPECT_NEAR(facadeFold(a + 1e-9, fc).f, l.f, 1e-8);  // continuous (a sawtooth is not)
  }
  EXPECT_NEAR(facadeFold(-1e-12, fc).f, facadeFold(1e-12, fc).f, 1e-9);  // across a period boundary
}

// Eq. 4 with Fig. 4's parameters: six storeys of h = 1/3 on y ∈ [0, 2].
TEST(KifsDistance, FloorsAreTheStoreysOfEquationFour) {
  KifsParams p;
  p.floors = {1.0 / 3.0, 0.0, 1.0};
  p.mass.height = 2.0, p.mass.shell = 0.1, p.mass.halfWidth = p.mass.halfDepth = 1.0;
  const Building b(p);
  for (int k = 0; k < 6; ++k)
    for (double frac : {0.1, 0.5, 0.9}) EXPECT_EQ(b.evaluate({0.3, 0.2, (k + frac) / 3.0}).floor, k);
}

// Bad parameters are refused with the field's name, never a crash or a hang.
TEST(KifsDistance, BadParametersNameTheField) {
  auto expectRefused = [](const std::string& field, auto&& edit) {
    KifsParams p;
    edit(p);
    try {
      Building b(p);
      ADD_FAILURE() << field << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("kifs." + field), std::string::npos) << e.what();
    }
  };
  const double nan = std::nan("");
  expectRefused("iterations", [](KifsParams& p) { p.iterations = -1; });
  expectRefused("iterations", [](KifsParams& p) { p.iterations = 1000000; });
  expectRefused("scale", [&](KifsParams& p) { p.scale = nan; });
  expectRefused("scale", [](KifsParams& p) { p.scale = 1.0; });
  expectRefused("scale", [](KifsParams& p) { p.scale = 0.5; });
  expectRefused("centre[1]", [&](KifsParams& p) { p.centre.y = nan; });
  expectRefused("r2.y", [](KifsParams& p) { p.r2.yDeg = INFINITY; });
  expectRefused("bailout", [](KifsParams& p) { p.bailout = 1.5; });  // the paper's literal value
  expectRefused("bailout", [&](KifsParams& p) { p.bailout = nan; });
  expectRefused("mass.height", [](KifsParams& p) { p.mass.height = 0; });
  expectRefused("mass.shell", [](KifsParams& p) { p.mass.shell = 100; });
  expectRefused("mass.wing", [](KifsParams& p) { p.mass.footprint = Footprint::H, p.mass.wing = 50; });
  expectRefused("facade.period", [](KifsParams& p) { p.facade.period = 0; });
  expectRefused("facade.a1", [&](KifsParams& p) { p.facade.a1 = nan; });
  expectRefused("floors.height", [](KifsParams& p) { p.floors.height = -1; });
  expectRefused("floors.sy", [](KifsParams& p) { p.floors.sy = 0; });
  expectRefused("curvilinear.sTheta", [](KifsParams& p) { p.curvilinear.enabled = true, p.curvilinear.sTheta = 0; });
  expectRefused("curvilinear.cR", [](KifsParams& p) { p.curvilinear.enabled = true, p.curvilinear.cR = 100; });
  expectRefused("trace.maxSteps", [](KifsParams& p) { p.trace.maxSteps = 0; });
  expectRefused("trace.lipschitz", [](KifsParams& p) { p.trace.lipschitz = 1.5; });
  expectRefused("trace.overRelax", [](KifsParams& p) { p.trace.overRelax = 2.5; });
  expectRefused("trace.hitFactor", [&](KifsParams& p) { p.trace.hitFactor = nan; });
}

TEST(KifsDistance, UnknownPresetListsTheNames) {
  try {
    preset("gothic");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("box"), std::string::npos) << e.what();
  }
  for (const auto& n : presetNames()) EXPECT_NO_THROW(Building{preset(n)}) << n;
}

// The polar preset closes into a ring of whole facade periods (2π s_θ = 12 periods), so it
// has the 12-fold symmetry of a rotation by one period about the ring's axis, and nothing
// jumps where atan2 wraps from π to −π: the bound and the estimate at a point equal those at
// the point turned by 30°, including pairs on either side of the wrap.
TEST(KifsDistance, ClosedRingHasNoSeamWhereTheAngleWraps) {
  const KifsParams p = preset("polar");
  const Building b(p);
  ASSERT_TRUE(b.closedRing());
  const double step = p.facade.period / p.curvilinear.sTheta;  // one period in angle
  ASSERT_NEAR(2 * std::numbers::pi / step, 12.0, 1e-12);
  const double y0 = p.curvilinear.z0;
  int straddling = 0;
  for (int i = 0; i < 400; ++i) {
    const double r = 7.0 + 6.0 * ((i * 37) % 101) / 100.0, h = 0.5 + 29.0 * ((i * 53) % 97) / 96.0;
    // Angles crowd the wrap: half the samples lie within one step of π.
    const double a = i % 2 ? std::numbers::pi - step * ((i * 17) % 89) / 88.0 : -std::numbers::pi + 2 * std::numbers::pi * i / 400.0;
    const double a2 = a + step;  // past π for the crowded half: atan2 gives a2 − 2π there
    straddling += a2 > std::numbers::pi;
    const glm::dvec3 p1(r * std::cos(a), y0 + r * std::sin(a), h), p2(r * std::cos(a2), y0 + r * std::sin(a2), h);
    const Sample s1 = b.evaluate(p1), s2 = b.evaluate(p2);
    EXPECT_NEAR(s1.bound, s2.bound, 1e-9) << "r " << r << " angle " << a;
    EXPECT_NEAR(s1.surface, s2.surface, 1e-9) << "r " << r << " angle " << a;
  }
  EXPECT_GT(straddling, 150);
}

}  // namespace
}  // namespace corbel::kifs::test
