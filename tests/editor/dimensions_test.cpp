// Dimensions of the plan and profile panes (editor/dimensions.h) against hand values: 3-4-5
// triangles, a 10 x 6 rectangle, a 45 degree roof segment.
#include "editor/dimensions.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace corbel::editor {
namespace {

// A 10 x 6 rectangle and a wall of 3 m under a 45 degree roof of 1 m run, then a 0.5 m ridge
// post (shorter than the moves below, so a point moved past an unmoved neighbour would be
// clamped).
ExtrusionSpec house() {
  ExtrusionSpec s;
  s.profiles.push_back({"hip", {Vec2(0, 0), Vec2(0, 3), Vec2(1, 4), Vec2(1, 4.5)}, {}});
  s.loops.push_back(PlanLoop({Vec2(0, 0), Vec2(10, 0), Vec2(10, 6), Vec2(0, 6)}, {0, 0, 0, 0}));
  return s;
}

TEST(Dimensions, PlanEdgeLengths) {
  const ExtrusionSpec s = house();
  EXPECT_DOUBLE_EQ(planEdgeLength(s, 0, 0), 10);
  EXPECT_DOUBLE_EQ(planEdgeLength(s, 0, 1), 6);
  EXPECT_DOUBLE_EQ(planEdgeLength(s, 0, 3), 6);  // the closing edge, (0, 6) to (0, 0)
  EXPECT_THROW(planEdgeLength(s, 0, 4), InputError);
  EXPECT_THROW(planEdgeLength(s, 1, 0), InputError);
}

// The end corner moves along the edge; the start and the other corners stay.
TEST(Dimensions, TypedEdgeLengthMovesTheEndCorner) {
  const ExtrusionSpec s = setPlanEdgeLength(house(), 0, 0, 12.5);
  const auto& p = s.loops[0].points;
  EXPECT_EQ(p[0], Vec2(0, 0));
  EXPECT_NEAR(p[1][0], 12.5, 1e-12);
  EXPECT_NEAR(p[1][1], 0, 1e-12);
  EXPECT_EQ(p[2], Vec2(10, 6));
  EXPECT_EQ(p[3], Vec2(0, 6));
  EXPECT_NEAR(planEdgeLength(s, 0, 0), 12.5, 1e-12);
  // The closing edge: its end is corner 0, moved up the y axis from (0, 6) towards (0, 0) by 2.
  const ExtrusionSpec t = setPlanEdgeLength(house(), 0, 3, 4);
  EXPECT_NEAR(t.loops[0].points[0][0], 0, 1e-12);
  EXPECT_NEAR(t.loops[0].points[0][1], 2, 1e-12);
}

// A slanted edge keeps its direction: (0, 0) -> (3, 4) is 5 long; at 10 it ends at (6, 8).
TEST(Dimensions, SlantedEdgeKeepsItsDirection) {
  ExtrusionSpec s = house();
  s.loops[0].points = {Vec2(0, 0), Vec2(3, 4), Vec2(-4, 3)};
  s.loops[0].profile = {0, 0, 0};
  EXPECT_DOUBLE_EQ(planEdgeLength(s, 0, 0), 5);
  const ExtrusionSpec t = setPlanEdgeLength(s, 0, 0, 10);
  EXPECT_NEAR(t.loops[0].points[1][0], 6, 1e-12);
  EXPECT_NEAR(t.loops[0].points[1][1], 8, 1e-12);
}

TEST(Dimensions, BadLengthsAreRefused) {
  for (double bad : {0.0, -2.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(setPlanEdgeLength(house(), 0, 0, bad), InputError) << bad;
    EXPECT_THROW(setProfileSegmentLength(house(), 0, 1, bad), InputError) << bad;
  }
  // No direction: a corner dragged back onto the one before it.
  ExtrusionSpec s = house();
  s.loops[0].points[1] = Vec2(0, 0);
  EXPECT_THROW(setPlanEdgeLength(s, 0, 0, 1), InputError);
}

TEST(Dimensions, ProfileSegmentLengthAndPitch) {
  const ExtrusionSpec s = house();
  EXPECT_DOUBLE_EQ(profileSegmentLength(s, 0, 0), 3);
  EXPECT_NEAR(profileSegmentLength(s, 0, 1), std::sqrt(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(profileSegmentPitch(s, 0, 0), 90);
  EXPECT_DOUBLE_EQ(profileSegmentPitch(s, 0, 1), 45);
  EXPECT_THROW(profileSegmentLength(s, 0, 3), InputError);
  EXPECT_THROW(profileSegmentPitch(s, 1, 0), InputError);
}

// Longer or shorter, the segment keeps its pitch and the points above it keep their offsets.
TEST(Dimensions, TypedSegmentLengthCarriesThePointsAbove) {
  // The roof segment from 1.414 to 2.828 m: its top at (2, 5), the post's top at (2, 5.5).
  const ExtrusionSpec up = setProfileSegmentLength(house(), 0, 1, 2 * std::sqrt(2.0));
  const auto& p = up.profiles[0].points;
  EXPECT_EQ(p[0], Vec2(0, 0));
  EXPECT_EQ(p[1], Vec2(0, 3));
  EXPECT_NEAR(p[2][0], 2, 1e-12);
  EXPECT_NEAR(p[2][1], 5, 1e-12);
  EXPECT_NEAR(p[3][0], 2, 1e-12);
  EXPECT_NEAR(p[3][1], 5.5, 1e-12);
  // The wall from 3 m to 0.5 m: everything above comes down 2.5 m.
  const ExtrusionSpec down = setProfileSegmentLength(house(), 0, 0, 0.5);
  const auto& q = down.profiles[0].points;
  EXPECT_EQ(q[1], Vec2(0, 0.5));
  EXPECT_EQ(q[2], Vec2(1, 1.5));
  EXPECT_EQ(q[3], Vec2(1, 2));
  EXPECT_NEAR(profileSegmentPitch(down, 0, 1), 45, 1e-12);
}

}  // namespace
}  // namespace corbel::editor
