// editor/push_pull.h: a push/pull drag turns pointer rays into the face's edit. The rays are
// aimed by hand at points whose value is known: a point 2 m out of a wall, a point seen from the
// roof's lower end at 30°, a point 1 m along a wall.
#include "core/error.h"
#include "editor/push_pull.h"
#include "extrude/extrude.h"
#include "extrude/spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace corbel::editor {
namespace {

namespace pp = extrude::pushpull;

constexpr double kDeg = std::numbers::pi / 180;

// A 10 × 6 house with 3 m walls and a 45° hip roof on every edge.
ExtrusionSpec house() {
  ExtrusionSpec s;
  s.profiles.push_back(extrude::wallAndRoofProfile(3, 45 * kDeg));
  PlanLoop l;
  l.points = {Vec2(0, 0), Vec2(10, 0), Vec2(10, 6), Vec2(0, 6)};
  l.profile.assign(4, 0);
  s.loops.push_back(l);
  return s;
}

// A ray from a camera at `eye` through `p`.
Ray through(const Vec3& eye, const Vec3& p) { return Ray{eye, (p - eye).normalized()}; }

TEST(PushPullDrag, AWallFollowsThePointerAlongItsNormal) {
  const ExtrusionSpec s = house();
  const Vec3 eye(20, -30, 12);
  const Ray start = through(eye, Vec3(5, 0, 1.5));
  const pp::Target t = pp::pick(s, extrude::extrude(s), start.origin, start.direction);
  ASSERT_EQ(t.kind, pp::Kind::Wall);
  PushPull d;
  d.begin(s, t, start);
  EXPECT_NEAR(d.value(), 0, 1e-9);
  // The pointer over the point 2 m out of the south wall (its outward normal is −y).
  d.pointer(through(eye, Vec3(5, -2, 1.5)));
  EXPECT_NEAR(d.value(), 2, 1e-9);
  EXPECT_NEAR(d.spec().loops[0].points[0][1], -2, 1e-9);
  EXPECT_EQ(d.label(), "Push wall");
  // Over a point 0.26 m in, snapped: 0.3 m in.
  d.pointer(through(eye, Vec3(5, 0.26, 1.5)));
  d.setSnap(true);
  EXPECT_NEAR(d.value(), -0.3, 1e-9);
  // Typed: exactly that, whatever the pointer says.
  for (char c : std::string("1.5")) EXPECT_TRUE(d.type(c));
  EXPECT_FALSE(d.type('x'));
  EXPECT_EQ(d.value(), 1.5);
  EXPECT_NEAR(d.spec().loops[0].points[1][1], -1.5, 1e-12);
  d.type('-');
  EXPECT_EQ(d.value(), -1.5);
  d.backspace();
  EXPECT_EQ(d.value(), -1.0);
}

TEST(PushPullDrag, ARoofTurnsAboutItsLowerEndToFollowThePointer) {
  const ExtrusionSpec s = house();
  const Vec3 eye(12, -30, 15);
  // The south roof 1 m up the slope from its eaves at (5, 0, 3).
  const Vec3 onRoof(5, std::sqrt(0.5), 3 + std::sqrt(0.5));
  const Ray start = through(eye, onRoof);
  const pp::Target t = pp::pick(s, extrude::extrude(s), start.origin, start.direction);
  ASSERT_EQ(t.kind, pp::Kind::Roof);
  PushPull d;
  d.begin(s, t, start);
  EXPECT_NEAR((d.pivot() - Vec3(5, 0, 3)).norm(), 0, 1e-9) << "the eaves under the pointer";
  EXPECT_NEAR(d.value(), 45, 1e-9);
  // The pointer over the point 2 m in from the eaves at 30° (in the plane x = 5, across the edge).
  d.pointer(through(eye, Vec3(5, 2 * std::cos(30 * kDeg), 3 + 2 * std::sin(30 * kDeg))));
  EXPECT_NEAR(d.value(), 30, 1e-9);
  ExtrusionSpec turned = d.spec();
  EXPECT_NEAR(pp::segmentPitch(turned.profiles[0], 1), 30, 1e-9);
  EXPECT_EQ(turned.profiles.size(), 1u) << "the shared profile turned for every edge";
  // Alt: this edge gets its own copy; the others keep 45°.
  d.setOwnCopy(true);
  turned = d.spec();
  ASSERT_EQ(turned.profiles.size(), 2u);
  EXPECT_EQ(turned.loops[0].profile, (std::vector<int>{1, 0, 0, 0}));
  EXPECT_NEAR(pp::segmentPitch(turned.profiles[0], 1), 45, 1e-9);
  EXPECT_NEAR(pp::segmentPitch(turned.profiles[1], 1), 30, 1e-9);
  // Past the vertical the last segment would lean out: the pointer's pitch stops at 90°.
  d.pointer(through(eye, Vec3(5, -1, 6)));
  EXPECT_NEAR(d.value(), 90, 1e-9);
  // A typed pitch is the new pitch; one the profile cannot take is refused with a reason.
  d.type('6');
  d.type('0');
  EXPECT_NEAR(pp::segmentPitch(d.spec().profiles[1], 1), 60, 1e-9);
  d.type('0');
  EXPECT_THROW(d.spec(), InputError);
}

TEST(PushPullDrag, AFeatureSlidesAlongItsWall) {
  ExtrusionSpec s = house();
  s.anchors.emplace_back("door", Anchor{0, 0, false, 0.5, 0}, FeatureKind::Door);
  const Vec3 eye(5, -30, 5);
  const Ray start = through(eye, Vec3(5, 0, 1));
  const pp::Target t = pp::pick(s, extrude::extrude(s), start.origin, start.direction);
  ASSERT_EQ(t.kind, pp::Kind::Feature);
  PushPull d;
  d.begin(s, t, start);
  // The pointer 1 m further along the south wall (+x) at the door's depth: a tenth of 10 m.
  d.pointer(through(eye, t.hit + Vec3(1, 0, 0)));
  EXPECT_NEAR(d.value(), 1, 1e-9);
  EXPECT_NEAR(d.spec().anchors[0].anchor.along, 0.6, 1e-9);
  EXPECT_EQ(d.label(), "Slide door");
}

}  // namespace
}  // namespace corbel::editor
