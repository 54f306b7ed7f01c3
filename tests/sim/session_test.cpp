// The collapse simulation against the statics kernel's verdicts and hand-computed physics
// (Whiting et al. 2009, Sec. 5): what the statics module finds standing with a margin stays
// put, what cannot stand falls, a shaken block slides as far as friction allows, a removed
// support lets what it carried drop, and runs repeat bitwise.
#include "sim/session.h"

#include "core/error.h"
#include "statics/analysis.h"
#include "statics/arch.h"
#include "statics/thresholds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace corbel::sim {
namespace {

constexpr double kStandsWithin = 1e-3;      // the "standing": no block moves 1 mm in 5 s
// Still: with the contact QP (the default) what is in equilibrium does not move; what is left is
// rounding (1e-16 to 1e-14 m on these cases), so a creep of a nanometre fails.
constexpr double kStill = 1e-9;
constexpr double kMiddleThird = 2.0 / 3.0;  // kern shrink leaving a rectangle's middle third (Sec. 3.4)

double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

statics::Block ground() { return statics::boxBlock("ground", Vec3(-5, -5, -1), Vec3(5, 5, 0), 1.0, true); }

// Cubes of side `a` stacked on the ground, cube k shifted by offsets[k] in x from the one below.
statics::Assembly stack(double a, const std::vector<double>& offsets) {
  statics::Assembly as;
  double x = 0;
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    x += offsets[k];
    as.blocks.push_back(statics::boxBlock("cube " + std::to_string(k), Vec3(x, 0, k * a), Vec3(x + a, a, (k + 1) * a)));
  }
  as.blocks.push_back(ground());
  return as;
}

statics::ArchSpec archOf(int blocks, double thickness) {
  statics::ArchSpec spec;
  spec.blocks = blocks;
  spec.thickness = thickness;
  return spec;
}

TEST(Session, BoxRestsWhereItWasBuilt) {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("box", Vec3(-0.2, -0.2, 0), Vec3(0.2, 0.2, 0.2)), ground()};
  Session s(as);
  s.runUntil(5.0);
  EXPECT_EQ(s.steps(), 1200);
  EXPECT_LT(s.maxDisplacement()[0], kStill);
  EXPECT_TRUE(s.fallenBlocks().empty());
}

// An arch the statics module finds standing even when every joint's force must pass through
// its middle third (kern shrink 2/3, the geometric factor of safety of Sec. 3.4) stays still.
TEST(Session, ArchThatStandsWithAMarginStaysStill) {
  statics::AnalysisOptions middleThird;
  middleThird.kernShrink = kMiddleThird;
  const double least = statics::minimumArchThickness(archOf(8, 0.2), middleThird, 1e-4);
  const statics::Assembly arch = statics::semicircularArch(archOf(8, 1.5 * least));
  ASSERT_TRUE(statics::checkFeasibility(arch, middleThird).feasible);
  Session s(arch);
  s.runUntil(5.0);
  EXPECT_LT(largest(s.maxDisplacement()), kStill);
  EXPECT_TRUE(s.fallenBlocks().empty());
}

// The oracle for the arch's least thickness is the statics kernel's LP bisection; at 80 % of
// it no force field in equilibrium exists, and the simulated arch comes down.
TEST(Session, ArchAtEightyPercentOfItsLeastThicknessCollapses) {
  const double least = statics::minimumArchThickness(archOf(20, 0.2), {}, 1e-4);
  EXPECT_NEAR(least, 0.107, 0.002);  // Milankovitch's 0.1075 for the continuous arch (Sec. 3.3)
  const statics::Assembly arch = statics::semicircularArch(archOf(20, 0.8 * least));
  ASSERT_FALSE(statics::checkFeasibility(arch).feasible);
  Session s(arch);
  s.runUntil(5.0);
  EXPECT_GE(s.fallenBlocks().size(), 10u) << "at least half the voussoirs out of place";
}

// Ochsendorf's tilting test (Sec. 3.3): the statics kernel's critical ground tilt for an arch
// (15.84° for t/R = 0.2 on 100 voussoirs) parts an arch that stays up from one that falls.
TEST(Session, ArchStaysBelowItsCriticalTiltAndFallsAboveIt) {
  const statics::ArchSpec spec = archOf(20, 0.2);
  const double critical = statics::criticalArchTilt(spec, {}, 1e-3);
  EXPECT_NEAR(critical, 15.8, 0.5);
  statics::ArchSpec tilted = spec;
  tilted.tiltDeg = critical - 6;
  Session below(statics::semicircularArch(tilted));
  below.runUntil(3.0);
  EXPECT_TRUE(below.fallenBlocks().empty());
  EXPECT_LT(largest(below.maxDisplacement()), kStill);
  tilted.tiltDeg = critical + 6;
  Session above(statics::semicircularArch(tilted));
  above.runUntil(3.0);
  EXPECT_GE(above.fallenBlocks().size(), 10u);
}

// Two cubes of side a: the top one tips when its centroid passes the lower cube's edge, at an
// overhang of a/2. Three cubes (the harmonic stack): the top may overhang the middle by a/2 and
// the top two the bottom by a/4, the pair's centroid then over the bottom's edge.
// Standing with a margin: every contact's resultant within its middle third (kern shrink 2/3),
// which for two cubes means an overhang of at most a/4.
TEST(Session, StackWithinItsTippingPointStands) {
  const double a = 0.3;
  statics::AnalysisOptions middleThird;
  middleThird.kernShrink = kMiddleThird;
  for (const auto& offsets : {std::vector<double>{0, 0.2 * a}, std::vector<double>{0, 0.1 * a, 0.15 * a}}) {
    const statics::Assembly as = stack(a, offsets);
    ASSERT_TRUE(statics::checkFeasibility(as, middleThird).feasible);
    Session s(as);
    s.runUntil(5.0);
    EXPECT_LT(largest(s.maxDisplacement()), kStill) << offsets.size() << " cubes";
  }
}

TEST(Session, StackPastItsTippingPointFalls) {
  const double a = 0.3;
  for (const auto& offsets : {std::vector<double>{0, 0.6 * a}, std::vector<double>{0, 0.3 * a, 0.45 * a}}) {
    const statics::Assembly as = stack(a, offsets);
    ASSERT_FALSE(statics::checkFeasibility(as).feasible);
    Session s(as);
    s.runUntil(5.0);
    const int top = int(offsets.size()) - 1;
    EXPECT_TRUE(s.fallen(top)) << offsets.size() << " cubes";
    EXPECT_GT(s.maxDisplacement()[top], a / 2);
  }
}

// A box on the ground when the ground jumps by V within Δ: in the ground's frame the box is
// thrown back at V/Δ minus friction μg for Δ, then slides to rest against μg. It slides
// (V/Δ − μg) Δ²/2 + (V − μgΔ)²/(2μg).
TEST(Session, ShakenBoxSlidesAsFarAsFrictionAllows) {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("box", Vec3(-0.2, -0.2, 0), Vec3(0.2, 0.2, 0.2)), ground()};
  const double v = 1.0, dt = kPaperShakeDuration, mu = 0.7, g = 9.81;
  Session s(as);
  s.shake(Vec3(v, 0, 0), dt);
  s.runUntil(1.0);
  const double expected = (v / dt - mu * g) * dt * dt / 2 + std::pow(v - mu * g * dt, 2) / (2 * mu * g);
  const double slid = -s.poses()[0].translation[0];
  EXPECT_NEAR(slid, expected, 0.02 * expected);
  EXPECT_NEAR(s.poses()[0].translation[2], 0, 1e-4);
}

// A box on a slope of θ (gravity turned by θ about y) with friction α = 0.7: Coulomb holds it
// below atan α = 35.0° and lets it slide above, with acceleration g (sin θ − α cos θ). Friction
// alone holds it along the slope, as it holds a vault's joints along the barrel's axis.
TEST(Session, FrictionHoldsABoxOnASlopeBelowItsAngleAndLetsItSlideAbove) {
  const double g = 9.81, mu = 0.7;
  auto onSlope = [&](double thetaDeg) {
    statics::Assembly as;
    as.blocks = {statics::boxBlock("box", Vec3(-0.2, -0.2, 0), Vec3(0.2, 0.2, 0.2)), ground()};
    const double t = thetaDeg * M_PI / 180;
    as.gravity = Vec3(std::sin(t), 0, -std::cos(t));
    return as;
  };
  Session held(onSlope(30));
  held.runUntil(5.0);
  EXPECT_LT(held.maxDisplacement()[0], kStill);
  const double theta = 40 * M_PI / 180;
  Session slides(onSlope(40));
  slides.runUntil(1.0);
  const double a = g * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR(slides.poses()[0].translation[0], a / 2, 0.01 * a / 2);  // ½ a t², t = 1 s
  // The contact QP's relaxed law would lift a sliding block by α·|v_t| a step (2.9 mm after 1 s
  // here) were the step's starting slip not added back; what is left is the slip the step
  // adds, α a h² (h the step): 12.7 µm.
  const double h = slides.settings().timeStep;
  EXPECT_GE(slides.poses()[0].translation[2], -kStill) << "not into the slope";
  EXPECT_LT(slides.poses()[0].translation[2], 1.5 * mu * a * h * h) << "on it";
}

// Froude similarity: a model a quarter the paper's width gets half its velocity and duration.
TEST(Session, PaperShakeScalesWithTheSquareRootOfTheSize) {
  statics::Assembly wide;
  wide.blocks = {statics::boxBlock("wall", Vec3(0, 0, 0), Vec3(10, 0.5, 2)), ground()};
  const ShakeSpec paper = paperShake(wide);
  EXPECT_NEAR(paper.velocity, 4.0, 1e-12);
  EXPECT_NEAR(paper.duration, 1.0 / 60, 1e-12);
  statics::Assembly narrow;
  narrow.blocks = {statics::boxBlock("pier", Vec3(0, 0, 0), Vec3(1, 2.5, 2)), ground()};
  EXPECT_NEAR(paperShake(narrow).velocity, 2.0, 1e-12) << "the ground is fixed and does not count";
  EXPECT_NEAR(paperShake(narrow).duration, 1.0 / 120, 1e-12);
}

// A box thrown off the edge of a 1 m thick ground slab lands on the floor under the slab.
TEST(Session, WhatLeavesTheGroundSlabLandsOnTheFloor) {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("box", Vec3(0.9, -0.1, 0), Vec3(1.1, 0.1, 0.2)),
               statics::boxBlock("slab", Vec3(-1, -1, -1), Vec3(1, 1, 0), 1.0, true)};
  Session s(as);
  s.shake(Vec3(-3, 0, 0));  // the ground jumps back: the box flies off towards +x
  s.runUntil(3.0);
  const Vec3 centre = s.poses()[0].apply(Vec3(1.0, 0, 0.1));
  EXPECT_GT(centre[0], 1.1) << "off the slab";
  EXPECT_NEAR(centre[2], -1.0 + 0.1, 2e-3) << "its centre a half-side above the floor";
  SimSettings noFloor;
  noFloor.floor = false;
  Session falling(as, noFloor);
  falling.shake(Vec3(-3, 0, 0));
  falling.runUntil(3.0);
  EXPECT_LT(falling.poses()[0].translation[2], -10.0) << "without the floor it falls on";
}

// Three cubes; without the middle one the top one falls onto the bottom one, a cube lower.
TEST(Session, RemovingASupportDropsWhatItCarried) {
  const double a = 0.3;
  Session s(stack(a, {0, 0, 0}));
  s.runUntil(0.5);
  s.removeBlock(s.blockIndex("cube 1"));
  s.runUntil(3.0);
  EXPECT_TRUE(s.removed(1));
  EXPECT_NEAR(s.poses()[2].translation[2], -a, 1e-3);
  EXPECT_LT(s.displacement()[0], kStandsWithin);
  EXPECT_TRUE(s.fallen(2));
}

// A pier broken along a 45° shear crack under a capstone: the wedges can hold each other only
// with friction above tan 45° = 1. The statics kernel, given the parts, says so both ways.
TEST(Session, BrokenPierHoldsOnlyWithFrictionAboveOne) {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("pier", Vec3(-0.15, -0.2, 0), Vec3(0.15, 0.2, 1.2)),
               statics::boxBlock("cap", Vec3(-0.3, -0.3, 1.2), Vec3(0.3, 0.3, 1.4)), ground()};
  for (double friction : {0.7, 1.5}) {
    SimSettings settings;
    settings.friction = friction;
    Session s(as, settings);
    const int first = s.breakBlock(0);
    EXPECT_TRUE(s.removed(0));
    EXPECT_TRUE(s.broken(0));
    ASSERT_EQ(s.pieces().size(), 2u);
    statics::Assembly cracked;
    cracked.blocks = {s.pieces()[first].shape, s.pieces()[first + 1].shape, as.blocks[1], as.blocks[2]};
    statics::AnalysisOptions options;
    options.friction = friction;
    const bool stands = statics::checkFeasibility(cracked, options).feasible;
    EXPECT_EQ(stands, friction > 1) << friction;
    s.runUntil(2.0);
    if (stands)
      EXPECT_LT(s.maxDisplacement()[1], kStill) << "the cap stays";
    else
      EXPECT_TRUE(s.fallen(1)) << "the cap comes down";
  }
  Session s(as);
  EXPECT_THROW(s.breakBlock(2), Error) << "the ground";
  s.breakBlock(0);
  EXPECT_THROW(s.breakBlock(0), Error) << "already broken";
}

// A load released from rest falls freely until it meets the block: at time t above the block
// its base is h − g t²/2 over the block's top (the integrator's first-order error is g·dt·t/2).
TEST(Session, DroppedLoadFallsFreelyThenRestsOnTheBlock) {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("pier", Vec3(-0.3, -0.3, 0), Vec3(0.3, 0.3, 1.0)), ground()};
  Session s(as);
  const double h = 0.8, g = 9.81, mass = 50;
  const int k = s.dropLoad(0, mass, h);
  const double side = std::cbrt(mass / s.settings().loadDensity);
  const double base0 = s.loads()[k].cube.vertices[0][2];
  EXPECT_NEAR(base0, 1.0 + h, 1e-12);
  s.runUntil(0.3);
  const double t = s.time();
  const double base = s.loadPoses()[k].apply(s.loads()[k].cube.vertices[0])[2];
  EXPECT_NEAR(base, 1.0 + h - g * t * t / 2, g * s.settings().timeStep * t);
  s.runUntil(2.0);
  const Vec3 centre = s.loadPoses()[k].apply(Vec3(0, 0, 1.0 + h + side / 2));
  EXPECT_NEAR(centre[2], 1.0 + side / 2, 1e-3);
  EXPECT_LT(s.maxDisplacement()[0], kStill) << "a 50 kg stone on a 864 kg pier";
}

std::vector<double> flatten(const Session& s) {
  std::vector<double> out;
  for (const auto* poses : {&s.poses(), &s.piecePoses(), &s.loadPoses()})
    for (const Pose& p : *poses) {
      out.insert(out.end(), p.rotation.begin(), p.rotation.end());
      for (int i = 0; i < 3; ++i) out.push_back(p.translation[i]);
    }
  return out;
}

// The same step and seed give bitwise-equal runs, in a new session or after reset(), with every
// perturbation in play.
TEST(Session, RunsAreBitwiseRepeatable) {
  const statics::Assembly arch = statics::semicircularArch(archOf(12, 0.15));
  for (bool random : {false, true}) {
    SimSettings settings;
    settings.randomOrder = random;
    settings.seed = 7;
    auto run = [&](Session& s) {
      s.shake(Vec3(1.5, 0.3, 0));
      s.runUntil(0.5);
      s.dropLoad(6, 20, 0.2);
      s.removeBlock(2);
      s.breakBlock(9);
      s.runUntil(1.5);
      return flatten(s);
    };
    Session a(arch, settings), b(arch, settings);
    const std::vector<double> first = run(a), second = run(b);
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(0, std::memcmp(first.data(), second.data(), first.size() * sizeof(double))) << "random order " << random;
    a.reset();
    EXPECT_EQ(a.time(), 0.0);
    EXPECT_FALSE(a.removed(2));
    EXPECT_TRUE(a.loads().empty());
    EXPECT_TRUE(a.pieces().empty());
    const std::vector<double> again = run(a);
    EXPECT_EQ(0, std::memcmp(first.data(), again.data(), first.size() * sizeof(double)));
    EXPECT_GT(largest(a.maxDisplacement()), 0.01) << "the perturbations did move it";
  }
}

TEST(Session, PlayStateTurnsWallTimeIntoSteps) {
  Session s(stack(0.3, {0}));
  EXPECT_EQ(s.advance(0.1), 0) << "paused";
  s.play();
  EXPECT_EQ(s.advance(0.1), 24);
  EXPECT_EQ(s.advance(0.5), 32) << "a slow frame is capped";
  s.pause();
  EXPECT_EQ(s.advance(0.1), 0);
  EXPECT_EQ(s.steps(), 56);
}

TEST(Session, BadRequestsSayWhatIsWrong) {
  Session s(stack(0.3, {0, 0}));
  try {
    s.blockIndex("keystone");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("keystone"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cube 0"), std::string::npos);
  }
  EXPECT_THROW(s.removeBlock(2), Error) << "the ground is fixed";
  EXPECT_THROW(s.removeBlock(7), Error);
  s.removeBlock(1);
  EXPECT_THROW(s.removeBlock(1), Error) << "already removed";
  EXPECT_THROW(s.dropLoad(0, -1, 0.5), Error);
  EXPECT_THROW(s.dropLoad(0, 10, -0.5), Error);
  EXPECT_THROW(s.dropLoad(1, 10, 0.5), Error) << "removed";
  EXPECT_THROW(s.shake(Vec3(1, 0, 0), 0), Error);
  SimSettings bad;
  bad.timeStep = -1;
  EXPECT_THROW(Session(stack(0.3, {0}), bad), Error);
  statics::Assembly inverted = stack(0.3, {0});
  for (auto& f : inverted.blocks[0].faces) std::reverse(f.begin(), f.end());
  EXPECT_THROW(Session{inverted}, Error);
}

}  // namespace
}  // namespace corbel::sim

namespace corbel::sim {
namespace {

// Bullet's bodies are convex hulls: an L-shaped block (its hull would fill the notch) is
// refused by name.
TEST(Session, NonConvexBlocksAreRefusedByName) {
  statics::Block l;
  l.name = "notched";
  // An L in (x, z): the top face's middle pushed down into a notch, 6 + 6 vertices.
  l.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0.5), Vec3(0.5, 0, 0.5), Vec3(0.5, 0, 1), Vec3(0, 0, 1),
                Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(1, 1, 0.5), Vec3(0.5, 1, 0.5), Vec3(0.5, 1, 1), Vec3(0, 1, 1)};
  l.faces = {{0, 1, 2, 3, 4, 5}, {11, 10, 9, 8, 7, 6}};
  for (int i = 0; i < 6; ++i) l.faces.push_back({(i + 1) % 6, i, 6 + i, 6 + (i + 1) % 6});
  statics::Assembly notched;
  notched.blocks = {l, ground()};
  try {
    Session s(notched);
    FAIL() << "a non-convex block was simulated";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("\"notched\" is not convex"), std::string::npos) << e.what();
  }
}

// A point load acts where it is: a unit cube of weight W pushed sideways at its top edge's
// middle by P tips over its far bottom edge when P·1 > W·½ (by hand; sliding needs P > 0.7 W).
// At 0.9 of that it stays where it is, as a block held by friction should; at 1.1 it falls.
// Applied at the centroid, the largest of these forces leaves it where it was.
TEST(Session, PointLoadsTipACubeAtTheHandComputedForce) {
  const double W = 2400 * 9.81;
  for (const auto& [factor, falls] : {std::pair{0.9, false}, {1.1, true}}) {
    statics::Assembly as = stack(1.0, {0.0});
    as.blocks[0].pointLoads.push_back({Vec3(0.0, 0.5, 1.0), Vec3(factor * W / 2, 0, 0)});
    Session s(as);
    s.runUntil(2.0);
    EXPECT_EQ(s.fallen(0), falls) << factor;
    if (falls)
      EXPECT_GT(s.maxDisplacement()[0], 0.5) << factor;
    else
      EXPECT_LT(s.maxDisplacement()[0], kStill) << factor;
  }
  statics::Assembly as = stack(1.0, {0.0});
  as.blocks[0].pointLoads.push_back({Vec3(0.5, 0.5, 0.5), Vec3(1.1 * W / 2, 0, 0)});
  Session s(as);
  s.runUntil(2.0);
  EXPECT_LT(s.maxDisplacement()[0], 1e-3);
}

}  // namespace
}  // namespace corbel::sim

namespace corbel::sim {
namespace {

// Bullet's sequential-impulse solver (Solver::SequentialImpulse, the alternative to the contact
// QP) with exact contacts (hull_contact.h): blocks meet through their own faces. A box on level
// ground and a cube on a cube are in equilibrium as built, their contacts the corners of the
// faces that touch: they rest where they are, to a micrometre. On a slope of 30° (below
// atan 0.7 = 35°) friction holds the box as still; on 40° it slides as Coulomb's law gives,
// ½ g (sin θ − α cos θ) t².
TEST(Session, ExactContactsHoldWhatIsInEquilibriumAndSlideAsCoulomb) {
  SimSettings exact;
  exact.solver = Solver::SequentialImpulse;
  exact.exactContacts = true;
  for (const statics::Assembly& as : {stack(0.4, {0}), stack(0.3, {0, 0})}) {
    Session s(as, exact);
    s.runUntil(5.0);
    EXPECT_LT(largest(s.maxDisplacement()), 1e-6) << as.blocks.size() - 1 << " cubes";
  }
  const double g = 9.81, mu = 0.7;
  auto onSlope = [&](double thetaDeg) {
    statics::Assembly as;
    as.blocks = {statics::boxBlock("box", Vec3(-0.2, -0.2, 0), Vec3(0.2, 0.2, 0.2)), ground()};
    const double t = thetaDeg * M_PI / 180;
    as.gravity = Vec3(std::sin(t), 0, -std::cos(t));
    return as;
  };
  Session held(onSlope(30), exact);
  held.runUntil(5.0);
  EXPECT_LT(held.maxDisplacement()[0], 1e-6);
  const double theta = 40 * M_PI / 180;
  Session slides(onSlope(40), exact);
  slides.runUntil(1.0);
  const double expected = g * (std::sin(theta) - mu * std::cos(theta)) / 2;
  EXPECT_NEAR(slides.poses()[0].translation[0], expected, 0.02 * expected);
  EXPECT_NEAR(slides.poses()[0].translation[2], 0, 1e-6) << "it slides on the slope, not into it";
}

// The arch of ArchThatStandsWithAMarginStaysStill, with Bullet's solver and exact contacts.
TEST(Session, ExactContactsKeepAnArchWithAMarginStill) {
  statics::AnalysisOptions middleThird;
  middleThird.kernShrink = kMiddleThird;
  const double least = statics::minimumArchThickness(archOf(8, 0.2), middleThird, 1e-4);
  SimSettings exact;
  exact.solver = Solver::SequentialImpulse;
  exact.exactContacts = true;
  Session s(statics::semicircularArch(archOf(8, 1.5 * least)), exact);
  s.runUntil(5.0);
  EXPECT_LT(largest(s.maxDisplacement()), kStandsWithin);
  EXPECT_TRUE(s.fallenBlocks().empty());
}

}  // namespace
}  // namespace corbel::sim
