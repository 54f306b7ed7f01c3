// Small assemblies whose thresholds are computed by hand: stacks, tipping, sliding, the kern.
#include "core/error.h"
#include "statics/analysis.h"
#include "statics/builder.h"
#include "statics/examples.h"
#include "statics/thresholds.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Ground (x ≤ 0 ends at a table edge when `edge`), a unit cube at x ∈ [v, v+1] on it and a
// unit cube at x ∈ [u, u+1] on that.
Assembly stack(double v, double u, bool edge = false) {
  Assembly as;
  as.blocks.push_back(boxBlock("ground", Vec3(-3, -1, -1), Vec3(edge ? 0.0 : 3.0, 2, 0), 1.0, true));
  as.blocks.push_back(boxBlock("bottom", Vec3(v, 0, 0), Vec3(v + 1, 1, 1)));
  as.blocks.push_back(boxBlock("top", Vec3(u, 0, 1), Vec3(u + 1, 1, 2)));
  return as;
}

bool stands(const Assembly& as, const AnalysisOptions& o = {}) { return checkFeasibility(as, o).feasible; }

TEST(BlockStatics, AStraightStackStandsWithoutTensionAndInEquilibrium) {
  const AnalysisResult r = analyse(stack(0, 0));
  EXPECT_EQ(r.status, SolveStatus::Optimal);
  EXPECT_TRUE(r.feasible);
  EXPECT_LE(r.yNormalised, 1e-12);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
  ASSERT_EQ(r.interfaces.size(), 2u);
  // Each interface carries the weight above it, straight down through the centre.
  const double cube = 2400 * 9.81;
  for (const InterfaceForces& f : r.interfaces) {
    const double above = f.a == 0 ? 2 * cube : cube;  // the ground (block 0) carries both cubes
    EXPECT_NEAR(std::abs(f.normalForce), above, 1e-6 * above);
    EXPECT_NEAR(f.tangentialForce, 0, 1e-6 * above);
    EXPECT_NEAR(f.centreOfPressure[0], 0.5, 1e-6);
    EXPECT_NEAR(f.centreOfPressure[1], 0.5, 1e-6);
  }
  EXPECT_TRUE(stands(stack(0, 0)));
}

// The top cube tips once its centroid passes the bottom cube's edge: offset 1/2.
TEST(BlockStatics, OverhangTipsAtHalfABlock) {
  EXPECT_TRUE(stands(stack(0, 0.49)));
  EXPECT_FALSE(stands(stack(0, 0.51)));
  const double d = bisectThreshold([](double u) { return stands(stack(0, u)); }, 0.0, 0.9, 1e-7);
  EXPECT_NEAR(d, 0.5, 1e-6);
  const AnalysisResult r = analyse(stack(0, 0.51));
  EXPECT_FALSE(r.feasible);
  EXPECT_GT(r.yNormalised, 1e-8);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
}

// Two cubes over a table edge (the harmonic stack): with the top at the bottom's tipping
// offset 1/2, the pair's centroid v + 3/4 must stay over the table, so v ≤ −3/4.
TEST(BlockStatics, HarmonicStackOverATableEdge) {
  EXPECT_TRUE(stands(stack(-0.76, -0.76 + 0.5, true)));
  EXPECT_FALSE(stands(stack(-0.74, -0.74 + 0.5, true)));
  const double v = bisectThreshold([](double b) { return stands(stack(b, b + 0.5, true)); }, -0.9, -0.6, 1e-7);
  EXPECT_NEAR(v, -0.75, 1e-6);
}

// A block on ground tilted by θ slides when tan θ > α (a cube tips only at 45°).
TEST(BlockStatics, BlockOnAnInclineSlidesAtTheFrictionAngle) {
  for (double alpha : {0.7, 0.4}) {
    AnalysisOptions o;
    o.friction = alpha;
    auto onIncline = [&](double deg) {
      Assembly as;
      as.blocks.push_back(boxBlock("ground", Vec3(-2, -2, -1), Vec3(3, 3, 0), 1.0, true));
      as.blocks.push_back(boxBlock("block", Vec3(0, 0, 0), Vec3(1, 1, 1)));
      as.gravity = Vec3(std::sin(deg * kDeg), 0, -std::cos(deg * kDeg));
      return as;
    };
    const double slide = bisectThreshold([&](double deg) { return stands(onIncline(deg), o); }, 0.0, 44.0, 1e-6);
    EXPECT_NEAR(slide, std::atan(alpha) / kDeg, 1e-4) << "alpha " << alpha;
    // The conservative pyramid (α/√2) slides earlier.
    AnalysisOptions c = o;
    c.conservativeFriction = true;
    const double early = bisectThreshold([&](double deg) { return stands(onIncline(deg), c); }, 0.0, 44.0, 1e-6);
    EXPECT_NEAR(early, std::atan(alpha / std::sqrt(2.0)) / kDeg, 1e-4) << "alpha " << alpha;
    // Past the friction angle the QP holds the block by tension-free friction only if it can't:
    // the measure is positive and equilibrium still holds.
    const AnalysisResult r = analyse(onIncline(slide + 1), o);
    EXPECT_FALSE(r.feasible);
    EXPECT_LE(r.equilibriumResidual, 1e-8);
  }
}

// On a plane tilted by θ towards the direction ψ (in the frame of the contact's square edges)
// a block needs friction tan θ · N along ψ from the friction polygon scaled by N, so it slides
// once tan θ passes the polygon's radius along ψ: the square pyramid |f_t1|, |f_t2| ≤ α f_n
// reaches α / max(|cos ψ|, |sin ψ|) (α√2 in its corners at 45°), the octagon with sides
// touching the friction circle α / cos(ψ − the nearest side's normal) (α at 45°, α/cos 22.5°
// at 22.5°). α = 0.5 keeps every threshold below tipping (atan √2 along a diagonal).
TEST(BlockStatics, EightSidedPyramidSlidesCloserToTheCone) {
  auto slideAngle = [](int sides, double psiDeg) {
    AnalysisOptions o;
    o.friction = 0.5;
    o.frictionSides = sides;
    const double psi = psiDeg * kDeg;
    auto tilted = [&](double deg) {
      Assembly as;
      as.blocks.push_back(boxBlock("ground", Vec3(-2, -2, -1), Vec3(3, 3, 0), 1.0, true));
      as.blocks.push_back(boxBlock("block", Vec3(0, 0, 0), Vec3(1, 1, 1)));
      const double t = deg * kDeg;
      as.gravity = Vec3(std::sin(t) * std::cos(psi), std::sin(t) * std::sin(psi), -std::cos(t));
      return as;
    };
    return bisectThreshold([&](double deg) { return stands(tilted(deg), o); }, 0.0, 50.0, 1e-6);
  };
  const double a = 0.5;
  EXPECT_NEAR(slideAngle(4, 0.0), std::atan(a) / kDeg, 1e-4);
  EXPECT_NEAR(slideAngle(8, 0.0), std::atan(a) / kDeg, 1e-4);
  EXPECT_NEAR(slideAngle(4, 45.0), std::atan(a * std::sqrt(2.0)) / kDeg, 1e-4);
  EXPECT_NEAR(slideAngle(8, 45.0), std::atan(a) / kDeg, 1e-4);
  EXPECT_NEAR(slideAngle(8, 22.5), std::atan(a / std::cos(22.5 * kDeg)) / kDeg, 1e-4);
  EXPECT_NEAR(slideAngle(4, 22.5), std::atan(a / std::cos(22.5 * kDeg)) / kDeg, 1e-4);
  AnalysisOptions bad;
  bad.frictionSides = 6;
  EXPECT_THROW(analyse(stack(0, 0), bad), Error);
}

// Kern shrink s scales the contact [u, 1] about its centre; the top's centroid u + 1/2 reaches
// the shrunk edge at u = (1 − s)/(2 − s).
TEST(BlockStatics, KernShrinkTurnsAJustFeasibleOverhangInfeasible) {
  AnalysisOptions kern;
  kern.kernShrink = 0.1;
  EXPECT_TRUE(stands(stack(0, 0.49)));
  EXPECT_FALSE(stands(stack(0, 0.49), kern));
  const double u = bisectThreshold([&](double x) { return stands(stack(0, x), kern); }, 0.0, 0.9, 1e-7);
  EXPECT_NEAR(u, 0.9 / 1.9, 1e-6);
  EXPECT_FALSE(analyse(stack(0, 0.49), kern).feasible);
}

// The kern margin of the same overhang (largestKernMargin): the top cube at offset u rests on
// [u, 1], half-width (1 − u)/2 shrunk to (1 − u)(1 − s)/2 about its centre (1 + u)/2, with
// its weight at u + 1/2, u/2 from that centre: it stands while s ≤ 1 − u/(1 − u) (the
// ground's contact, 1 − u, allows more). By hand 0.75 at u = 0.2 and 0 at u = 1/2; past
// 1/2 none (−1); a straight stack stands at the largest kern searched.
TEST(BlockStatics, KernMarginOfAnOverhangIsTheHandComputedOne) {
  const double m = largestKernMargin(stack(0, 0.2), {}, 1e-4);
  EXPECT_LE(m, 0.75);
  EXPECT_GE(m, 0.75 - 1e-4);  // the bracket's standing end, 1e-4 wide
  EXPECT_LT(largestKernMargin(stack(0, 0.5 - 1e-3), {}, 1e-2), 1e-2);
  EXPECT_EQ(largestKernMargin(stack(0, 0.6)), -1.0);
  EXPECT_EQ(largestKernMargin(stack(0, 0)), kMaxKernMargin);
  EXPECT_THROW(largestKernMargin(stack(0, 0.2), {}, 0.0), Error);
}

// The centre of pressure against the contact polygon: top cube at offset 0.3 rests on
// [0.3, 1] (centroid 0.65) with its weight at 0.8: gauge 0.15/0.35; the ground carries both
// cubes' centroid 0.65 on [0, 1] (centroid 0.5): gauge 0.15/0.5. A straight stack: 0.
TEST(BlockStatics, PressureGaugePlacesTheResultantInTheContact) {
  const AnalysisResult r = analyse(stack(0, 0.3));
  ASSERT_EQ(r.interfaces.size(), 2u);
  for (const InterfaceForces& f : r.interfaces) {
    const double expected = f.a == 1 ? 0.15 / 0.35 : 0.15 / 0.5;
    EXPECT_NEAR(f.pressureGauge, expected, 1e-6) << f.a << "-" << f.b;
  }
  EXPECT_TRUE(r.tensionSites.empty());
  for (const InterfaceForces& f : analyse(stack(0, 0)).interfaces) EXPECT_NEAR(f.pressureGauge, 0.0, 1e-6);
}

// Past tipping the top cube (weight Wc at x = 1.2) on the contact [0.7, 1] needs tension T at
// the edge x = 0.7: moments about x = 1 give 0.3 T = 0.2 Wc, T = 2/3 Wc, shared by the two
// corners there (symmetry in y). So y = 2 (Wc/3)² and y/W² = 1/18 with W = 2 Wc, and the
// tension sites are those two corners.
TEST(BlockStatics, TensionSitesOfATippedOverhangAreHandComputed) {
  const AnalysisResult r = analyse(stack(0, 0.7));
  ASSERT_EQ(r.status, SolveStatus::Optimal);
  EXPECT_NEAR(r.yNormalised, 1.0 / 18.0, 1e-7);
  const double cube = 2400 * 9.81;
  ASSERT_EQ(r.tensionSites.size(), 2u);
  for (const TensionSite& t : r.tensionSites) {
    EXPECT_NEAR(t.point[0], 0.7, 1e-9);
    EXPECT_NEAR(t.point[2], 1.0, 1e-9);
    EXPECT_NEAR(t.tension, cube / 3, 1e-5 * cube);
    const InterfaceForces& f = r.interfaces[std::size_t(t.interface)];
    EXPECT_EQ(f.a, 1);
    EXPECT_EQ(f.b, 2);
    EXPECT_NEAR(f.vertices[std::size_t(t.vertex)].tension, t.tension, 1e-9);
  }
}

// A time cap returns the best iterate with its own status (any real solve takes over 1 ns).
TEST(BlockStatics, SolverTimeCapStopsWithItsStatus) {
  AnalysisOptions o;
  o.solver.maxSeconds = 1e-9;
  const AnalysisResult r = analyse(stack(0, 0.7), o);
  EXPECT_EQ(r.status, SolveStatus::TimeLimit);
  EXPECT_FALSE(r.feasible);
  EXPECT_EQ(toString(r.status), "time limit");
}

// A running-bond wall of half-metre blocks, 0.4 m thick, on the ground.
Assembly runningBondWall(double length, int courses, double height) {
  WallSpec w;
  w.blockLength = 0.5;
  w.length = length;
  w.courses = courses;
  w.height = height;
  w.thickness = 0.4;
  StructureBuilder b;
  b.add("wall", wallBlocks(w));
  b.groundUnder(1.0);
  return b.build();
}

// The early exit on a certified small objective (IpmOptions::objectiveExitBelow,
// docs/statics.md): on a standing wall it must stop sooner than the full tolerances, with y
// within its reported bound of the fully converged y (the oracle: the same QP with the exit
// off) and in equilibrium; on a model that does not stand (y/W² = 1/18 for the tipped
// overhang) it must not fire, so the result is the same bit for bit.
TEST(BlockStatics, EarlyExitStopsSoonerWithinItsCertifiedBound) {
  const Assembly wall = runningBondWall(5, 10, 2.5);
  AnalysisOptions off;
  off.solver.objectiveExitBelow = 0;
  const AnalysisResult full = analyse(wall, off), early = analyse(wall);
  ASSERT_EQ(full.status, SolveStatus::Optimal);
  ASSERT_EQ(early.status, SolveStatus::Optimal);
  EXPECT_LT(early.iterations, full.iterations);
  EXPECT_TRUE(early.feasible);
  EXPECT_LE(early.yNormalised, AnalysisOptions{}.solver.objectiveExitBelow);
  EXPECT_EQ(early.gap, early.yNormalised);
  // Each is within its own gap of the optimum, so of each other within the sum.
  EXPECT_LE(std::abs(early.yNormalised - full.yNormalised), early.gap + full.gap);
  EXPECT_LE(early.yNormalised, full.yNormalised);
  EXPECT_LE(early.equilibriumResidual, 1e-8);
  for (const InterfaceForces& f : early.interfaces)
    for (const VertexForce& v : f.vertices) EXPECT_GE(v.compression, 0);

  const AnalysisResult tippedFull = analyse(stack(0, 0.7), off), tipped = analyse(stack(0, 0.7));
  EXPECT_EQ(tipped.iterations, tippedFull.iterations);
  EXPECT_EQ(tipped.yNormalised, tippedFull.yNormalised);
  EXPECT_NEAR(tipped.yNormalised, 1.0 / 18, 1e-7);
}

// The least-squares start (IpmOptions::feasibilityCorrections, docs/statics.md): on a running-
// bond wall under its own weight the equilibrium field of least norm is compression within the
// pyramid, so the solve must end at iteration 0 with that certificate. Checked independently of
// the solver: the LP phase-1 agrees that the wall stands, the ground carries the whole weight,
// and every vertex force is compressive and inside the pyramid. On the tipped overhang the
// start fails, and the iterates, so the result, must be those of the solve without it, bit for
// bit.
TEST(BlockStatics, LeastSquaresStartCertifiesAStandingWallBeforeAnyIteration) {
  const Assembly wall = runningBondWall(8, 16, 4);
  ASSERT_GT(wall.blocks.size(), 250u);
  AnalysisOptions off;
  off.solver.feasibilityCorrections = 0;
  const AnalysisResult r = analyse(wall), without = analyse(wall, off);
  ASSERT_EQ(r.status, SolveStatus::Optimal);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_GT(without.iterations, 3);
  EXPECT_TRUE(r.feasible);
  EXPECT_TRUE(without.feasible);
  EXPECT_TRUE(checkFeasibility(wall).feasible);
  EXPECT_LE(r.yNormalised, AnalysisOptions{}.solver.objectiveExitBelow);
  EXPECT_LE(r.equilibriumResidual, 1e-8);
  const double W = r.totalWeight, alpha = AnalysisOptions{}.friction;
  Vec3 fromGround(0.0);
  for (const InterfaceForces& f : r.interfaces) {
    const bool aFixed = wall.blocks[std::size_t(f.a)].fixed, bFixed = wall.blocks[std::size_t(f.b)].fixed;
    if (bFixed) fromGround -= f.resultant;  // the resultant acts on b; a (the wall) gets its opposite
    if (aFixed) fromGround += f.resultant;
    for (const VertexForce& v : f.vertices) {
      EXPECT_GE(v.compression, 0);
      EXPECT_LE(v.tension, 1e-6 * W);
      EXPECT_LE(std::abs(v.t1), alpha * v.compression + 1e-12 * W);
      EXPECT_LE(std::abs(v.t2), alpha * v.compression + 1e-12 * W);
    }
  }
  const Vec3 up = -wall.gravity / wall.gravity.norm();
  EXPECT_NEAR(dot(fromGround, up), W, 1e-8 * W);
  EXPECT_NEAR((fromGround - up * dot(fromGround, up)).norm(), 0, 1e-8 * W);

  const AnalysisResult tipped = analyse(stack(0, 0.7)), tippedWithout = analyse(stack(0, 0.7), off);
  EXPECT_EQ(tipped.iterations, tippedWithout.iterations);
  EXPECT_EQ(tipped.yNormalised, tippedWithout.yNormalised);
  EXPECT_NEAR(tipped.yNormalised, 1.0 / 18, 1e-7);
}

// The strongly infeasible examples (docs/statics.md, "The polish"): the iterations stop short
// of their tolerances there. Without the polish the best iterate is `reduced accuracy`, y_ipm
// with a gap g (y* ∈ [y_ipm − g, y_ipm]); the polish must end `optimal` with its y inside that
// bracket, in equilibrium, and with a duality gap at the solver's relative tolerance.
TEST(BlockStatics, StronglyInfeasibleExamplesArePolishedToOptimalInsideTheIterationsBracket) {
  AnalysisOptions unpolished;
  unpolished.solver.polish = false;
  for (const ParametricModel& m : {towerExample(), barrelVaultExample(), flyingButtressVaultExample()}) {
    const Assembly a = m.build(m.parameters);
    const AnalysisResult r = analyse(a), ipm = analyse(a, unpolished);
    EXPECT_EQ(ipm.status, SolveStatus::ReducedAccuracy) << m.name << ": " << toString(ipm.status);
    EXPECT_LE(ipm.gap, 1e-3 * ipm.yNormalised) << m.name;
    ASSERT_EQ(r.status, SolveStatus::Optimal) << m.name << ": " << toString(r.status);
    EXPECT_LE(r.equilibriumResidual, 1e-10) << m.name;
    EXPECT_FALSE(r.feasible) << m.name;
    EXPECT_GT(r.yNormalised, 1e-6) << m.name;
    EXPECT_LE(r.gap, 1e-10 * r.yNormalised) << m.name;
    EXPECT_LE(r.yNormalised, ipm.yNormalised * (1 + 1e-12)) << m.name;
    EXPECT_GE(r.yNormalised, ipm.yNormalised - ipm.gap) << m.name;
    std::printf("%s: polished y/W² %.12e, iterate %.12e (gap %.1e)\n", m.name.c_str(), r.yNormalised, ipm.yNormalised,
                ipm.gap);
  }
}

TEST(BlockStatics, ContactPolygonIsTheOverlapOfTheFaces) {
  const AnalysisResult r = analyse(stack(0, 0.3));
  ASSERT_EQ(r.interfaces.size(), 2u);
  for (const InterfaceForces& f : r.interfaces)
    if (f.a == 1 && f.b == 2) {
      EXPECT_NEAR(f.area, 0.7, 1e-12);
      EXPECT_EQ(f.vertices.size(), 4u);
    }
}

TEST(BlockStatics, BadInputGetsAClearError) {
  auto message = [](const Assembly& as) {
    try {
      analyse(as);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Assembly nan = stack(0, 0);
  nan.blocks[2].vertices[3][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(nan).find("\"top\": vertex 3 is not a finite point"), std::string::npos) << message(nan);

  Assembly floating = stack(0, 0);
  floating.blocks.push_back(boxBlock("cloud", Vec3(5, 5, 5), Vec3(6, 6, 6)));
  EXPECT_NE(message(floating).find("\"cloud\" floats"), std::string::npos) << message(floating);

  // The top cube beside the bottom one's top face: they share only the edge x = 1.
  const Assembly edge = stack(0, 1.0);
  EXPECT_NE(message(edge).find("\"top\" floats"), std::string::npos) << message(edge);
  EXPECT_NE(message(edge).find("zero-area contact"), std::string::npos) << message(edge);

  Assembly inverted = stack(0, 0);
  for (auto& f : inverted.blocks[1].faces) std::reverse(f.begin(), f.end());
  EXPECT_NE(message(inverted).find("\"bottom\": faces point inwards"), std::string::npos) << message(inverted);

  Assembly dense = stack(0, 0);
  dense.blocks[1].density = -1;
  EXPECT_NE(message(dense).find("density"), std::string::npos);

  AnalysisOptions bad;
  bad.friction = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(analyse(stack(0, 0), bad), Error);
  bad = {};
  bad.kernShrink = 1.0;
  EXPECT_THROW(checkFeasibility(stack(0, 0), bad), Error);
}

}  // namespace
}  // namespace corbel::statics
