// Angle snapping of the plan pane (extrude/edit.h): hand-computed directions and points.
#include "extrude/edit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace corbel::extrude::test {
namespace {

namespace ed = corbel::extrude::edit;

constexpr double kRad = std::numbers::pi / 180;
Vec2 polar(double r, double deg) { return Vec2(r * std::cos(deg * kRad), r * std::sin(deg * kRad)); }
double degrees(const Vec2& d) { return std::atan2(d[1], d[0]) / kRad; }

TEST(PlanSnap, AnEdgeAt47DegreesGoesTo45OnTheProjectedRay) {
  const Vec2 from(2, 1);
  const ed::AngleSnap s = ed::snapEdgeAngle(from, from + polar(10, 47), 15, {});
  ASSERT_EQ(s.guides.size(), 1u);
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Axis);
  EXPECT_NEAR(degrees(s.guides[0].direction), 45, 1e-12);
  // The pointer's projection: 10 cos 2° along the 45° ray.
  const Vec2 expected = from + polar(10 * std::cos(2 * kRad), 45);
  EXPECT_NEAR((s.point - expected).norm(), 0, 1e-12);
  EXPECT_EQ(s.guides[0].from, from);
}

TEST(PlanSnap, ANeighbourWithinHalfAStepWinsOverTheAxes) {
  // Neighbour at 37°: 35° is 2° from parallel (and 5° from the 30° axis multiple).
  const Vec2 ref = polar(1, 37);
  ed::AngleSnap s = ed::snapEdgeAngle(Vec2(0, 0), polar(4, 35), 15, {ref});
  ASSERT_EQ(s.guides.size(), 1u);
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Parallel);
  EXPECT_NEAR((s.point - polar(4 * std::cos(2 * kRad), 37)).norm(), 0, 1e-12);
  // 125° is 2° from perpendicular to it (127°).
  s = ed::snapEdgeAngle(Vec2(0, 0), polar(4, 125), 15, {ref});
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Perpendicular);
  EXPECT_NEAR((s.point - polar(4 * std::cos(2 * kRad), 127)).norm(), 0, 1e-12);
  // Antiparallel counts as parallel: 219° → 217°.
  s = ed::snapEdgeAngle(Vec2(0, 0), polar(4, 219), 15, {ref});
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Parallel);
  EXPECT_NEAR((s.point - polar(4 * std::cos(2 * kRad), 217)).norm(), 0, 1e-12);
  // 50° is 13° from the neighbour, more than half of 15°: the 45° axis multiple.
  s = ed::snapEdgeAngle(Vec2(0, 0), polar(4, 50), 15, {ref});
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Axis);
  EXPECT_NEAR((s.point - polar(4 * std::cos(5 * kRad), 45)).norm(), 0, 1e-12);
  // A 30° neighbour, pointer at 33°: parallel to it (which is also on the 15° grid).
  s = ed::snapEdgeAngle(Vec2(1, 1), Vec2(1, 1) + polar(6, 33), 15, {polar(2, 30)});
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Parallel);
  EXPECT_NEAR((s.point - (Vec2(1, 1) + polar(6 * std::cos(3 * kRad), 30))).norm(), 0, 1e-12);
}

TEST(PlanSnap, AxisDirectionsAreExactAndLengthsRoundToTheGrid) {
  // atan(0.2 / 3.1) = 3.7°: along x; length 3.1 rounds to 3.0 on a 0.25 m step.
  ed::AngleSnap s = ed::snapEdgeAngle(Vec2(1, 2), Vec2(4.1, 2.2), 15, {}, 0.25);
  EXPECT_EQ(s.point, Vec2(4, 2)) << "exact, no rounding residue from cos and sin";
  s = ed::snapEdgeAngle(Vec2(1, 2), Vec2(0.8, -3), 15, {});  // 92.3° below: straight down
  EXPECT_EQ(s.point, Vec2(1, -3));
  // A length under half a step still keeps one step.
  s = ed::snapEdgeAngle(Vec2(0, 0), Vec2(0.1, 0), 15, {}, 0.25);
  EXPECT_EQ(s.point, Vec2(0.25, 0));
}

TEST(PlanSnap, NothingToSnapLeavesThePointAlone) {
  const Vec2 p(3, 4);
  for (double step : {0.0, -15.0, 91.0, std::nan("")}) {
    const ed::AngleSnap s = ed::snapEdgeAngle(Vec2(0, 0), p, step, {});
    EXPECT_EQ(s.point, p) << step;
    EXPECT_TRUE(s.guides.empty());
  }
  const ed::AngleSnap s = ed::snapEdgeAngle(p, p, 15, {});
  EXPECT_EQ(s.point, p);
  EXPECT_TRUE(s.guides.empty());
  // A zero or non-finite reference is skipped: the axes still apply.
  const ed::AngleSnap z = ed::snapEdgeAngle(Vec2(0, 0), polar(2, 88), 15, {Vec2(0, 0), Vec2(std::nan(""), 1)});
  EXPECT_EQ(z.point, Vec2(0, 2 * std::cos(2 * kRad)));
}

TEST(PlanSnap, ADraggedRectangleCornerStaysSquare) {
  // Corner 2 of the 10 × 6 rectangle dragged to (10.3, 6.2): the edge from (10, 0) is
  // perpendicular to the edge before it, the edge from (0, 6) perpendicular to the edge after
  // it, so they meet at (10, 6).
  const ed::AngleSnap s = ed::snapCornerAngles(Vec2(10, 0), Vec2(0, 6), Vec2(10.3, 6.2), 15, {Vec2(10, 0)}, {Vec2(0, -6)});
  EXPECT_EQ(s.point, Vec2(10, 6));
  ASSERT_EQ(s.guides.size(), 2u);
  EXPECT_EQ(s.guides[0].kind, ed::SnapKind::Perpendicular);
  EXPECT_EQ(s.guides[1].kind, ed::SnapKind::Perpendicular);
}

TEST(PlanSnap, ACornerMeetsTwoSnappedLines) {
  // From (0, 0) at 46° (→ 45°) and from (10, 0) at 136.4° (→ 135°): the lines y = x and
  // y = 10 − x meet at (5, 5).
  const Vec2 to(5.1, 5.3);
  EXPECT_NEAR(degrees(to), 46.1, 0.1);
  const ed::AngleSnap s = ed::snapCornerAngles(Vec2(0, 0), Vec2(10, 0), to, 15, {}, {});
  ASSERT_EQ(s.guides.size(), 2u);
  EXPECT_NEAR((s.point - Vec2(5, 5)).norm(), 0, 1e-12);
}

TEST(PlanSnap, ACornerOnAStraightEdgeSnapsOntoIt) {
  // Inserting a corner near the edge (0, 0)–(10, 0): both halves snap along x, the two lines
  // are one, so only the pointer is projected onto it.
  const ed::AngleSnap s = ed::snapCornerAngles(Vec2(0, 0), Vec2(10, 0), Vec2(4, 0.3), 15, {}, {});
  ASSERT_EQ(s.guides.size(), 1u);
  EXPECT_EQ(s.point, Vec2(4, 0));
}

TEST(PlanSnap, CloseToAStraightAngleBothEdgesStillSnap) {
  // From (0, 0) towards (5, 0.7) is 7.97°, over half a step from 0°: 15°. From (10, 0) it is
  // 172.03°: 165°. The lines meet at (5, 5 tan 15°), 0.64 m from the pointer: kept.
  const ed::AngleSnap s = ed::snapCornerAngles(Vec2(0, 0), Vec2(10, 0), Vec2(5, 0.7), 15, {}, {});
  ASSERT_EQ(s.guides.size(), 2u);
  EXPECT_NEAR((s.point - Vec2(5, 5 * std::tan(15 * kRad))).norm(), 0, 1e-12);
}

TEST(PlanSnap, LinesMeetingBehindACornerFallBackToTheNearerSnap) {
  // prev (0, 0), next (1, 0), pointer (10, 1.3): from prev 7.4° → 0° (the line y = 0); from
  // next 8.2° → 15°. They meet at next itself, not in front of it, so one edge snaps: y = 0
  // would move the pointer 1.3 m, the 15° ray from next only 1.07 m.
  const Vec2 next(1, 0), to(10, 1.3);
  const ed::AngleSnap s = ed::snapCornerAngles(Vec2(0, 0), next, to, 15, {}, {});
  ASSERT_EQ(s.guides.size(), 1u);
  EXPECT_EQ(s.guides[0].from, next);
  const Vec2 dir = polar(1, 15);
  const Vec2 expected = next + dir * ((to - next)[0] * dir[0] + (to - next)[1] * dir[1]);
  EXPECT_NEAR((s.point - expected).norm(), 0, 1e-12);
  EXPECT_NEAR((s.point - to).norm(), 1.07, 0.01);
}

}  // namespace
}  // namespace corbel::extrude::test
