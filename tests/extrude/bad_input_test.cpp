// Bad plans and profiles get an InputError naming the loop, edge or point — never a crash,
// a hang or garbage.
#include "core/error.h"
#include "support.h"

#include <gtest/gtest.h>

#include <limits>

namespace corbel::extrude::test {
namespace {

std::string faultOf(const ExtrusionSpec& spec) {
  try {
    extrude(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<accepted>";
}

#define EXPECT_FAULT(spec, text) EXPECT_EQ(faultOf(spec), text)

TEST(BadInput, SelfIntersectingAndTouchingLoops) {
  const auto bowtie = uniformSpec({{Vec2(0, 0), Vec2(10, 0), Vec2(0, 6), Vec2(10, 6)}}, hipProfile(45 * kDeg));
  EXPECT_FAULT(bowtie, "loops[0] edge 1 and loops[0] edge 3 cross or touch: the loop intersects itself");
  // A hole touching the outer loop at a corner.
  const auto touching =
      uniformSpec({rectangle(10, 10), reversed({Vec2(0, 0), Vec2(4, 2), Vec2(2, 4)})}, hipProfile(45 * kDeg));
  EXPECT_EQ(faultOf(touching).find("cross or touch: loops must be disjoint") != std::string::npos, true)
      << faultOf(touching);
  // Two buildings overlapping.
  const auto overlap = uniformSpec({rectangle(10, 10), rectangle(10, 10, 5, 5)}, hipProfile(45 * kDeg));
  EXPECT_EQ(faultOf(overlap).find("loops must be disjoint") != std::string::npos, true) << faultOf(overlap);
}

TEST(BadInput, DegenerateEdgesAndOrientation) {
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(10, 0), Vec2(10, 0), Vec2(0, 6)}}, hipProfile(45 * kDeg)),
               "loops[0].points[2]: zero-length edge (repeats points[1])");
  EXPECT_FAULT(uniformSpec({reversed(rectangle(10, 6))}, hipProfile(45 * kDeg)),
               "loops[0]: an outer loop must run counter-clockwise (it runs clockwise)");
  EXPECT_FAULT(uniformSpec({rectangle(10, 10), rectangle(2, 2, 4, 4)}, hipProfile(45 * kDeg)),
               "loops[1]: a hole must run clockwise (it runs counter-clockwise)");
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(10, 0)}}, hipProfile(45 * kDeg)),
               "loops[0].points: a loop needs at least three corners");
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(10, 0), Vec2(5, 0), Vec2(5, 5)}}, hipProfile(45 * kDeg)),
               "loops[0].points[1]: the plan folds back on itself (a zero-width spike)");
}

TEST(BadInput, NonFiniteAndHugeCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(nan, 0), Vec2(0, 6)}}, hipProfile(45 * kDeg)),
               "loops[0].points[1]: coordinates must be finite");
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(10, 0), Vec2(0, inf)}}, hipProfile(45 * kDeg)),
               "loops[0].points[2]: coordinates must be finite");
  EXPECT_FAULT(uniformSpec({{Vec2(0, 0), Vec2(1e9, 0), Vec2(0, 6)}}, hipProfile(45 * kDeg)),
               "loops[0].points[1]: coordinates must be within 1e7 m");
}

TEST(BadInput, Profiles) {
  Profile down;
  down.points = {{0, 0}, {1, 2}, {2, 1}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, down),
               "profiles[0].points[2]: profiles must be vertically monotone (z may not decrease)");
  Profile outward;
  outward.points = {{0, 0}, {0, 3}, {-1, 4}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, outward),
               "profiles[0]: the last segment leans outward (angle < 0), so the roof could never close");
  Profile vertical;
  vertical.points = {{0, 0}, {0, 3}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, vertical),
               "loops[0]: no edge's profile ends leaning inward, so the roof cannot close");
  Profile one;
  one.points = {{0, 0}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, one), "profiles[0].points: a profile needs at least two points");
  Profile nan;
  nan.points = {{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, nan), "profiles[0].points[1]: coordinates must be finite");
  ExtrusionSpec missing = uniformSpec({rectangle(10, 6)}, hipProfile(45 * kDeg));
  missing.loops[0].profile[2] = 7;
  EXPECT_FAULT(missing, "loops[0].profile[2]: no profile number 7");
  ExtrusionSpec empty;
  EXPECT_FAULT(empty, "loops: a plan needs at least one loop");
  Profile flatStart;
  flatStart.points = {{0, 0}, {1, 0}, {2, 1}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, flatStart),
               "profiles[0].points[1]: a profile may not start with a horizontal segment (move the plan instead)");
  Profile flatEnd;
  flatEnd.points = {{0, 0}, {0, 1}, {1, 1}};
  EXPECT_FAULT(uniformSpec({rectangle(10, 6)}, flatEnd),
               "profiles[0].points[2]: a profile may not end with a horizontal segment");
}

// Each side of a square is two colinear edges, a gable (vertical for good) and a 45° hip. Volume
// maximising gives each side to its gable at the base (Sec. 4.8), so no edge of what is left
// ever rises: said as bad input naming the edges left, not capped into a shell of no volume.
// Minimising gives each side to its hip, and the roof is the pyramid: 10² × 5 / 3 m³ exactly,
// its roof area the footprint's over cos 45°.
TEST(BadInput, StraightRunsWhoseGablesWinByPriorityCannotClose) {
  ExtrusionSpec s;
  Profile gable;
  gable.name = "gable";
  gable.points = {{0, 0}, {0, 1}};
  s.profiles = {hipProfile(45 * kDeg), gable};
  s.loops = {{{Vec2(0, 0), Vec2(5, 0), Vec2(10, 0), Vec2(10, 5), Vec2(10, 10), Vec2(5, 10), Vec2(0, 10), Vec2(0, 5)},
              {1, 0, 1, 0, 1, 0, 1, 0}}};
  s.priority = Priority::MaximiseVolume;
  EXPECT_FAULT(s,
               "loops[0]: the roof cannot close: every edge left of this loop at its base is vertical for good "
               "(edges 0, 2, 4, 6), the sloped edges in line with them having given way by priority (Sec. 4.8), "
               "so nothing rises; give each straight run a sloped last segment, or let the sloped edges win "
               "(priority minimise_volume, or manual with their segments tagged high)");
  s.priority = Priority::MinimiseVolume;
  const ExtrusionResult r = extrude(s);
  EXPECT_TRUE(r.shell.warnings.empty());
  EXPECT_EQ(unpairedEdges(r.shell), 0u);
  const ShellMeasures m = measure(r.shell);
  EXPECT_NEAR(m.volume, 500.0 / 3.0, 1e-9 * 500.0 / 3.0);
  EXPECT_NEAR(m.roofArea, 100.0 * std::sqrt(2.0), 1e-9 * 100.0 * std::sqrt(2.0));
  EXPECT_NEAR(r.shell.maxHeight, 5.0, 1e-9 * 5.0);
}

TEST(BadInput, StepsAndAnchors) {
  const ExtrusionSpec house = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg));
  PlanStep ok;
  ok.anchor = {0, 0, false, 0.5, 3};
  ExtrusionSpec s = house;
  s.steps = {ok};
  s.steps[0].anchor.loop = 2;
  EXPECT_FAULT(s, "steps[0].anchor.loop: no loop number 2");
  s.steps = {ok};
  s.steps[0].anchor.edge = 4;
  EXPECT_FAULT(s, "steps[0].anchor.edge: loop 0 has no edge number 4");
  s.steps = {ok};
  s.steps[0].anchor.along = 1.5;
  EXPECT_FAULT(s, "steps[0].anchor.along: a relative anchor needs a fraction within [0, 1]");
  s.steps = {ok};
  s.steps[0].anchor.height = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FAULT(s, "steps[0].anchor.height: must be within [0, 1e5] m above the base");
  s.steps = {ok};
  s.steps[0].depth = 0;
  EXPECT_FAULT(s, "steps[0].depth: must be non-zero (negative for a recess)");
  s.steps = {ok};
  s.steps[0].shape = StepShape::Bay;
  s.steps[0].cant = 0.6;
  s.steps[0].width = 1;
  EXPECT_FAULT(s, "steps[0].cant: a bay's cant must be at least 0 and less than half its width");
  s.steps = {ok};
  s.steps[0].sideProfile = 3;
  EXPECT_FAULT(s, "steps[0]: no profile number 3");
  s.steps.clear();
  s.offsets = {{3.0, {{0, 0.0, 0.5, 0, 0}, {0, -0.1, -0.5, 0, 0}}, 0}};
  EXPECT_FAULT(s, "offsets[0].edges[1]: all offsets of one event must go the same way (all out, or all in)");
  s.offsets = {{3.0, {{0, 0.5, 0.2, 0, 0}}, 0}};
  EXPECT_FAULT(s, "offsets[0].edges[0]: the outside offset must lie beyond the inside one, on the same side of the edge");
  s.offsets = {{3.0, {}, 0}};
  EXPECT_FAULT(s, "offsets[0].edges: an offset event needs at least one edge");
  s.offsets = {{0.0, {{0, 0.0, 0.5, 0, 0}}, 0}};
  EXPECT_FAULT(s, "offsets[0].height: must be within (0, 1e5] m above the base");
  s.offsets = {{3.0, {{0, 0.0, 0.5, 0, 9}}, 0}};
  EXPECT_FAULT(s, "offsets[0].edges[0]: no profile number 9");
  s.offsets.clear();
  s.anchors = {{"door", {0, 0, true, -1e9, 0}}};
  EXPECT_EQ(faultOf(s), "<accepted>") << "an absolute anchor may lie beyond its edge (it is then not instanced)";
  s.anchors[0].anchor.height = -1;
  EXPECT_FAULT(s, "anchors[0].anchor.height: must be within [0, 1e5] m above the base");
}

}  // namespace
}  // namespace corbel::extrude::test
