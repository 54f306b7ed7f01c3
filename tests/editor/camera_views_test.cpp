// editor/camera_views.h and the camera's orthographic projection: framing, zoom towards the
// pointer and the axis widget held to hand computations.
#include "editor/camera_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace corbel::editor {
namespace {

const double kTan20 = std::tan(20.0 * std::numbers::pi / 180.0);  // half the default 40° field of view

BBox boxOf(Vec3 lo, Vec3 hi) {
  BBox b;
  b.add(lo);
  b.add(hi);
  return b;
}

// Where a world point lands in normalised device coordinates.
glm::dvec3 ndc(const render::OrbitCamera& c, double aspect, Vec3 p) {
  const glm::dvec4 q = c.projection(aspect) * c.view() * glm::dvec4(p[0], p[1], p[2], 1.0);
  return glm::dvec3(q) / q.w;
}

TEST(CameraViews, OrthographicTopViewFramesTheBoxByItsWidestSide) {
  // Looking down on 10 × 4 × 3 m at aspect 2: right is +X, up is +Y. Half width 5 needs a half
  // height of 2.5 (aspect 2), half depth 2 needs 2; heights do not count. Distance = 1.08 · 2.5 / tan 20°.
  render::OrbitCamera c;
  render::applyPreset(c, render::CameraPreset::Top);
  c.orthographic = true;
  c.frame(boxOf(Vec3(0, 0, 0), Vec3(10, 4, 3)), 2.0);
  EXPECT_NEAR(c.target[0], 5.0, 1e-12);
  EXPECT_NEAR(c.target[1], 2.0, 1e-12);
  EXPECT_NEAR(c.distance, 1.08 * 2.5 / kTan20, 1e-9);
  EXPECT_NEAR(c.halfHeight(), 2.7, 1e-9);
  // The corner (10, 4) at x = 5 / (2 · 2.7), y = 2 / 2.7, whatever its height.
  for (double z : {0.0, 3.0, 500.0}) {
    const glm::dvec3 p = ndc(c, 2.0, Vec3(10, 4, z));
    EXPECT_NEAR(p.x, 5.0 / 5.4, 1e-9);
    EXPECT_NEAR(p.y, 2.0 / 2.7, 1e-9);
    EXPECT_LT(std::abs(p.z), 1.0);  // zoomed in, nothing within a kilometre above the eye is cut off
  }
}

TEST(CameraViews, PerspectiveFrontViewFramesTheNearFaceToo) {
  // A 2 m cube from the front (along +Y): the near face (1 m nearer) fills the height at
  // d = 1 + 1 / tan 20°, and framing keeps 8 % more.
  render::OrbitCamera c;
  render::applyPreset(c, render::CameraPreset::Front);
  c.frame(boxOf(Vec3(-1, -1, -1), Vec3(1, 1, 1)), 1.0);
  EXPECT_NEAR(c.distance, 1.08 * (1.0 + 1.0 / kTan20), 1e-9);
  EXPECT_TRUE(boxInView(c, 1.0, boxOf(Vec3(-1, -1, -1), Vec3(1, 1, 1))));
  EXPECT_FALSE(boxInView(c, 1.0, boxOf(Vec3(100, 0, 0), Vec3(101, 1, 1))));
  EXPECT_FALSE(boxInView(c, 1.0, boxOf(Vec3(0, -50, 0), Vec3(1, -49, 1))));  // behind the eye
}

TEST(CameraViews, TheSixSidesLookAlongTheirAxes) {
  const struct {
    render::CameraPreset preset;
    Vec3 forward;  // eye → target
  } sides[] = {{render::CameraPreset::Front, {0, 1, 0}},  {render::CameraPreset::Back, {0, -1, 0}},
               {render::CameraPreset::Right, {-1, 0, 0}}, {render::CameraPreset::Left, {1, 0, 0}},
               {render::CameraPreset::Top, {0, 0, -1}},   {render::CameraPreset::Bottom, {0, 0, 1}}};
  for (const auto& s : sides) {
    render::OrbitCamera c;
    render::applyPreset(c, s.preset);
    const Vec3 f = (c.target - c.eye()) / c.distance;
    EXPECT_NEAR((f - s.forward).norm(), 0.0, 1e-12) << int(s.preset);
  }
}

TEST(CameraViews, TheWheelZoomsTowardsThePointer) {
  // Top view, orthographic, 10 m half height at aspect 1: the pointer at NDC (0.5, 0) is over
  // (5, 0, 0). One step scales the view by 0.88, so the target moves 0.12 · 5 = 0.6 m towards it.
  for (bool ortho : {true, false}) {
    render::OrbitCamera c;
    render::applyPreset(c, render::CameraPreset::Top);
    c.orthographic = ortho;
    c.distance = 10.0 / kTan20;
    zoomTowards(c, 0.5, 0.0, 1.0, 1.0);
    EXPECT_NEAR(c.distance, 0.88 * 10.0 / kTan20, 1e-9);
    EXPECT_NEAR((c.target - Vec3(0.6, 0, 0)).norm(), 0.0, 1e-9);
    // The point stays under the pointer.
    const glm::dvec3 p = ndc(c, 1.0, Vec3(5, 0, 0));
    EXPECT_NEAR(p.x, 0.5, 1e-9);
    EXPECT_NEAR(p.y, 0.0, 1e-9);
  }
  // At an angle, in perspective, a point off-centre on the target's plane stays put too.
  render::OrbitCamera c;
  c.target = Vec3(3, -2, 1);
  const double aspect = 1.6;
  const double h = c.halfHeight();
  const glm::dmat4 v = c.view();
  const glm::dvec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
  const glm::dvec3 q = glm::dvec3(3, -2, 1) + right * (-0.7 * h * aspect) + up * (0.4 * h);
  zoomTowards(c, -0.7, 0.4, aspect, -2.0);  // out
  const glm::dvec3 p = ndc(c, aspect, Vec3(q.x, q.y, q.z));
  EXPECT_NEAR(p.x, -0.7, 1e-9);
  EXPECT_NEAR(p.y, 0.4, 1e-9);
}

TEST(CameraViews, TheAxisWidgetShowsTheAxesAsTheCameraSeesThem) {
  render::OrbitCamera c;  // the default: azimuth −60°, elevation 28°
  const float r = kAxisWidgetRadius;
  const auto ends = axisEnds(c);
  // +Z points straight up on screen, shortened by the elevation: (0, −r cos 28°).
  EXPECT_NEAR(ends[2].dx, 0.0, 1e-4);
  EXPECT_NEAR(ends[2].dy, -r * std::cos(28.0 * std::numbers::pi / 180.0), 1e-4);
  // +X: screen right is (−sin a, cos a, 0) at a = −60°, so dx = r · sin 60°.
  EXPECT_NEAR(ends[0].dx, r * std::sin(60.0 * std::numbers::pi / 180.0), 1e-4);
  // A click on the +Z knob turns to the top view.
  const auto hit = axisEndAt(c, ends[2].dx + 3, ends[2].dy - 2);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->axis, 2);
  EXPECT_TRUE(hit->positive);
  EXPECT_EQ(presetOfAxis(*hit), render::CameraPreset::Top);
  EXPECT_FALSE(axisEndAt(c, r * 2, r * 2));
  // From the top +Z and −Z both lie at the centre: the click takes the nearer, +Z.
  render::applyPreset(c, render::CameraPreset::Top);
  const auto centre = axisEndAt(c, 0, 0);
  ASSERT_TRUE(centre);
  EXPECT_EQ(centre->axis, 2);
  EXPECT_TRUE(centre->positive);
  // −Y (towards the viewer's bottom edge from above) turns to the front view.
  const auto ends2 = axisEnds(c);
  EXPECT_NEAR(ends2[4].dy, r, 1e-4);
  EXPECT_EQ(presetOfAxis(ends2[4]), render::CameraPreset::Front);
}

}  // namespace
}  // namespace corbel::editor
