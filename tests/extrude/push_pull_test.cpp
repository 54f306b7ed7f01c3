// Push/pull on a built extrusion (extrude/push_pull.h): the face a ray meets names the spec
// entry it comes from, and the edits give the plans, pitches, heights and anchor places
// computed by hand.
#include "core/error.h"
#include "extrude/push_pull.h"
#include "support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::extrude::test {
namespace {

namespace pp = corbel::extrude::pushpull;

// A 10 × 6 house: 3 m walls and a 45° hip roof on every edge (one shared profile).
ExtrusionSpec house() { return uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg)); }

void expectPoint(const Vec2& got, double x, double y) {
  EXPECT_NEAR(got[0], x, 1e-12);
  EXPECT_NEAR(got[1], y, 1e-12);
}

TEST(PushPull, AWallPushedOneAndAHalfMetresMakesTheRectangleTenBySevenAndAHalf) {
  // Edge 2 runs (10, 6) → (0, 6); its outward normal is +y.
  const ExtrusionSpec s = pp::pushEdge(house(), 0, 2, 1.5);
  expectPoint(s.loops[0].points[2], 10, 7.5);
  expectPoint(s.loops[0].points[3], 0, 7.5);
  expectPoint(s.loops[0].points[0], 0, 0);
  expectPoint(s.loops[0].points[1], 10, 0);
  EXPECT_NEAR(pp::edgeLength(s, 0, 1), 7.5, 1e-12);
  EXPECT_NEAR(measure(extrude(s).shell).baseArea, 75.0, 1e-9);
  // Pulled in by 1 m instead: 10 × 5.
  EXPECT_NEAR(measure(extrude(pp::pushEdge(house(), 0, 2, -1)).shell).baseArea, 50.0, 1e-9);
}

TEST(PushPull, SlantedNeighboursKeepTheirDirections) {
  // A trapezoid whose sides lean in by 2 m over 6 m: pushing the bottom edge 1 m out (−y)
  // slides its corners down the sides' lines, 1/3 m outward each.
  ExtrusionSpec s = uniformSpec({{Vec2(0, 0), Vec2(10, 0), Vec2(8, 6), Vec2(2, 6)}}, wallAndRoofProfile(3, 45 * kDeg));
  s = pp::pushEdge(s, 0, 0, 1);
  expectPoint(s.loops[0].points[0], -1.0 / 3, -1);
  expectPoint(s.loops[0].points[1], 10 + 1.0 / 3, -1);
  expectPoint(s.loops[0].points[2], 8, 6);
  // A neighbour along the edge's own line (a split wall) cannot guide the corner: it moves
  // straight out.
  ExtrusionSpec split = uniformSpec({{Vec2(0, 0), Vec2(5, 0), Vec2(10, 0), Vec2(10, 6), Vec2(0, 6)}}, hipProfile(45 * kDeg));
  split = pp::pushEdge(split, 0, 0, 1);
  expectPoint(split.loops[0].points[0], 0, -1);
  expectPoint(split.loops[0].points[1], 5, -1);
  EXPECT_THROW(pp::pushEdge(house(), 0, 7, 1), InputError);
  EXPECT_THROW(pp::pushEdge(house(), 0, 0, std::nan("")), InputError);
}

TEST(PushPull, ARoofTurnedFrom45To30DegreesHasTheRidgeHeightComputedByHand) {
  ExtrusionSpec s = house();
  EXPECT_NEAR(pp::segmentPitch(s.profiles[0], 0), 90, 1e-12);
  EXPECT_NEAR(pp::segmentPitch(s.profiles[0], 1), 45, 1e-12);
  EXPECT_NEAR(measure(extrude(s).shell).maxHeight, 3 + 3, 1e-9);  // half the 6 m depth at 45°
  s = pp::turnSegment(s, 0, 1, 30);
  EXPECT_NEAR(pp::segmentPitch(s.profiles[0], 1), 30, 1e-12);
  // Turned about its lower end (0, 3), keeping its length √2.
  expectPoint(s.profiles[0].points[1], 0, 3);
  expectPoint(s.profiles[0].points[2], std::sqrt(2.0) * std::cos(30 * kDeg), 3 + std::sqrt(2.0) * std::sin(30 * kDeg));
  // Every edge shares the profile: the ridge is 3 m in from the long sides, 3 tan 30° above the eaves.
  EXPECT_NEAR(measure(extrude(s).shell).maxHeight, 3 + 3 * std::tan(30 * kDeg), 1e-9);
}

TEST(PushPull, TurningAMiddleSegmentCarriesThePointsAboveIt) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, polyline("mansard", {Vec2(0, 0), Vec2(0, 3), Vec2(1, 5), Vec2(3, 6)}));
  // Segment 1 runs (0, 3) → (1, 5), length √5; at 90° it stands straight up from (0, 3).
  s = pp::turnSegment(s, 0, 1, 90);
  expectPoint(s.profiles[0].points[2], 0, 3 + std::sqrt(5.0));
  expectPoint(s.profiles[0].points[3], 2, 4 + std::sqrt(5.0));
  EXPECT_THROW(pp::turnSegment(s, 0, 1, 181), InputError) << "z would decrease";
  EXPECT_THROW(pp::turnSegment(s, 0, 2, 120), InputError) << "the last segment would lean outward";
  EXPECT_THROW(pp::turnSegment(s, 0, 2, 0), InputError) << "a level last segment never closes the roof";
  EXPECT_THROW(pp::turnSegment(s, 0, 3, 30), InputError) << "no such segment";
  EXPECT_THROW(pp::turnSegment(s, 1, 1, 30), InputError) << "no such profile";
}

TEST(PushPull, AnEdgeGivenItsOwnProfileTurnsAlone) {
  ExtrusionSpec s = house();
  EXPECT_EQ(pp::profileUsers(s, 0), 4);
  int own = -1;
  s = pp::ownProfile(s, 0, 1, &own);
  ASSERT_EQ(own, 1);
  EXPECT_EQ(s.profiles[1].name, "wall+roof 2");
  EXPECT_EQ(s.loops[0].profile, (std::vector<int>{0, 1, 0, 0}));
  s = pp::turnSegment(s, own, 1, 60);
  EXPECT_NEAR(pp::segmentPitch(s.profiles[0], 1), 45, 1e-12);
  EXPECT_NEAR(pp::segmentPitch(s.profiles[1], 1), 60, 1e-12);
  // The ridge of the long sides is unchanged: 3 m in at 45°.
  EXPECT_NEAR(measure(extrude(s).shell).maxHeight, 6, 1e-9);
}

TEST(PushPull, AnchorsSlideAlongTheirWalls) {
  ExtrusionSpec s = house();
  PlanStep dormer;
  dormer.name = "dormer";
  dormer.anchor = Anchor{0, 0, false, 0.5, 3.5};
  s.steps.push_back(dormer);
  s.anchors.emplace_back("door", Anchor{0, 0, false, 0.3, 0}, FeatureKind::Door);
  PlanStep chimney = dormer;
  chimney.name = "chimney";
  chimney.anchor = Anchor{0, 1, true, 3, 3};  // 3 m along the 6 m east wall
  s.steps.push_back(chimney);
  // 1 m along the 10 m south wall is a tenth of it.
  ExtrusionSpec t = pp::slideStep(s, 0, 1);
  EXPECT_NEAR(t.steps[0].anchor.along, 0.6, 1e-12);
  EXPECT_EQ(t.steps[0].anchor.height, 3.5);
  t = pp::slideFeature(t, 0, -2);
  EXPECT_NEAR(t.anchors[0].anchor.along, 0.1, 1e-12);
  t = pp::slideFeature(t, 0, -2);
  EXPECT_EQ(t.anchors[0].anchor.along, 0.0) << "stays on its wall";
  t = pp::slideStep(t, 1, 1.5);
  EXPECT_NEAR(t.steps[1].anchor.along, 4.5, 1e-12) << "an absolute anchor moves by metres";
  t = pp::slideStep(t, 1, 10);
  EXPECT_NEAR(t.steps[1].anchor.along, 6, 1e-12);
  EXPECT_THROW(pp::slideStep(s, 2, 1), InputError);
  EXPECT_THROW(pp::slideFeature(s, 1, 1), InputError);
}

// A row of dormers slides as one: every element moves by the same metres, so the spacing and
// the count stay, and the row stops where its last element meets the wall's end.
TEST(PushPull, ARepeatedRowSlidesAsAWhole) {
  ExtrusionSpec s = house();  // the south wall is 10 m
  PlanStep dormer;
  dormer.name = "dormer";
  dormer.anchor = Anchor{0, 0, false, 0.2, 3.5};
  dormer.repeat.kind = RepeatKind::Row;
  dormer.repeat.along = 0.6;  // first at 2 m, last at 6 m
  dormer.repeat.spacing = 2;
  s.steps.push_back(dormer);
  s.anchors.emplace_back("window", Anchor{0, 1, true, 1, 1}, FeatureKind::Window);
  s.anchors[0].repeat.kind = RepeatKind::Row;
  s.anchors[0].repeat.along = 3;  // 1 m to 3 m along the 6 m east wall
  s.anchors[0].repeat.spacing = 1;

  const auto places = [](const ExtrusionSpec& t, const Anchor& a, const Repeat& r) {
    std::vector<double> x;
    for (const Anchor& e : repeatAnchors(t, a, r)) x.push_back(e.along);
    return x;
  };
  const std::vector<double> before = places(s, s.steps[0].anchor, s.steps[0].repeat);
  ASSERT_EQ(before.size(), 3u);
  ExtrusionSpec t = pp::slideStep(s, 0, 1);  // 1 m is a tenth of the wall
  const std::vector<double> after = places(t, t.steps[0].anchor, t.steps[0].repeat);
  ASSERT_EQ(after.size(), before.size()) << "the count stays";
  for (std::size_t i = 0; i < after.size(); ++i) EXPECT_NEAR(after[i], before[i] + 0.1, 1e-12) << "element " << i;

  t = pp::slideStep(t, 0, 100);  // the last element stops at the wall's end, 3 m on
  EXPECT_NEAR(t.steps[0].repeat.along, 1.0, 1e-12);
  EXPECT_NEAR(t.steps[0].anchor.along, 0.6, 1e-12) << "the row keeps its length";
  t = pp::slideStep(t, 0, -100);
  EXPECT_NEAR(t.steps[0].anchor.along, 0.0, 1e-12);
  EXPECT_NEAR(t.steps[0].repeat.along, 0.4, 1e-12);

  t = pp::slideFeature(t, 0, 2);  // an absolute row moves by metres, up to the 6 m end
  EXPECT_NEAR(t.anchors[0].anchor.along, 3, 1e-12);
  EXPECT_NEAR(t.anchors[0].repeat.along, 5, 1e-12);
  t = pp::slideFeature(t, 0, 5);
  EXPECT_NEAR(t.anchors[0].anchor.along, 4, 1e-12);
  EXPECT_NEAR(t.anchors[0].repeat.along, 6, 1e-12);
  EXPECT_EQ(repeatAnchors(t, t.anchors[0].anchor, t.anchors[0].repeat).size(), 3u);
}

TEST(PushPull, TheRayNamesTheFacesSource) {
  ExtrusionSpec s = house();
  s.anchors.emplace_back("door", Anchor{0, 3, false, 0.5, 0}, FeatureKind::Door);  // west wall (0, 6) → (0, 0)
  const ExtrusionResult r = extrude(s);
  // Level, from the south, at the south wall's middle.
  pp::Target t = pp::pick(s, r, Vec3(5, -10, 1.5), Vec3(0, 1, 0));
  EXPECT_EQ(t.kind, pp::Kind::Wall);
  EXPECT_EQ(t.loop, 0);
  EXPECT_EQ(t.edge, 0);
  EXPECT_NEAR((t.hit - Vec3(5, 0, 1.5)).norm(), 0, 1e-9);
  EXPECT_NEAR((t.normal - Vec3(0, -1, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR(t.t, 10, 1e-9);
  // Straight down 1 m in from the south eaves: the south roof, segment 1, at 3 + 1 m.
  t = pp::pick(s, r, Vec3(5, 1, 20), Vec3(0, 0, -1));
  EXPECT_EQ(t.kind, pp::Kind::Roof);
  EXPECT_EQ(t.edge, 0);
  EXPECT_EQ(t.segment, 1);
  EXPECT_NEAR(t.hit[2], 4, 1e-9);
  // Down past the east eaves, 1 m from the east wall: the east roof.
  t = pp::pick(s, r, Vec3(9, 3, 20), Vec3(0, 0, -1));
  EXPECT_EQ(t.kind, pp::Kind::Roof);
  EXPECT_EQ(t.edge, 1);
  // From the west at the door's middle: the door stands out of the wall.
  t = pp::pick(s, r, Vec3(-10, 3, 1), Vec3(1, 0, 0));
  EXPECT_EQ(t.kind, pp::Kind::Feature);
  EXPECT_EQ(t.feature, 0);
  EXPECT_LT(t.hit[0], 0) << "on the door, in front of the wall";
  // From below: the base is no target; past the house, nothing.
  EXPECT_EQ(pp::pick(s, r, Vec3(5, 3, -5), Vec3(0, 0, 1)).kind, pp::Kind::None);
  EXPECT_EQ(pp::pick(s, r, Vec3(50, 3, -5), Vec3(0, 0, 1)).kind, pp::Kind::None);
}

TEST(PushPull, AStepsFacesNameTheStep) {
  ExtrusionSpec s = house();
  PlanStep chimney;
  chimney.name = "chimney";
  chimney.anchor = Anchor{0, 0, false, 0.5, 0};
  chimney.width = 2;
  chimney.depth = 1;  // 1 m out of the south wall, from the ground
  chimney.frontProfile = chimney.sideProfile = 0;
  s.steps.push_back(chimney);
  const ExtrusionResult r = extrude(s);
  // Level from the south at x = 5: the step's front, 1 m out of the wall.
  const pp::Target t = pp::pick(s, r, Vec3(5, -10, 1.5), Vec3(0, 1, 0));
  EXPECT_EQ(t.kind, pp::Kind::Step);
  EXPECT_EQ(t.step, 0);
  EXPECT_NEAR(t.hit[1], -1, 1e-9);
  // Beside it, the wall.
  EXPECT_EQ(pp::pick(s, r, Vec3(2, -10, 1.5), Vec3(0, 1, 0)).kind, pp::Kind::Wall);
}

}  // namespace
}  // namespace corbel::extrude::test
