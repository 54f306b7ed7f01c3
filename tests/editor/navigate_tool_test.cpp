// editor/navigate_tool.h and viewport.h: the 3D view's gestures from input events alone, held
// to the camera's own formulas and to the geometry of the view's rays.
#include "editor/navigate_tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace corbel::editor {
namespace {

using T = InputEvent::Type;
constexpr int kShift = 340;  // GLFW_KEY_LEFT_SHIFT

InputEvent move(double x, double y) {
  InputEvent e{T::Move};
  e.x = x, e.y = y;
  return e;
}
InputEvent button(int b, bool down) { return {T::Button, b, down}; }

struct Harness {
  Viewport view;
  NavigateTool tool;
  ToolContext context;
  std::vector<Ray> clicks, drags;
  int grabs = 0, releases = 0;
  bool grabAnswer = false;
  Harness() {
    view.setRect(100, 50, 800, 600);
    view.camera.target = Vec3(1, 2, 3);
    context.viewport = &view;
    context.click = [this](const Ray& r) { clicks.push_back(r); };
    context.grab = [this](const Ray&) {
      ++grabs;
      return grabAnswer;
    };
    context.dragTo = [this](const Ray& r) { drags.push_back(r); };
    context.release = [this] { ++releases; };
  }
  void send(const InputEvent& e, bool overUi = false) { tool.handle(e, overUi, context); }
};

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(Viewport, TheCentreRayRunsFromTheNearPlaneToTheTarget) {
  Viewport v;
  v.setRect(100, 50, 800, 600);
  v.camera.target = Vec3(4, -2, 1);
  v.camera.azimuth_deg = 35, v.camera.elevation_deg = 20, v.camera.distance = 40;
  const Ray r = v.ray(100 + 400, 50 + 300);
  Vec3 toTarget = v.camera.target - v.camera.eye();
  toTarget.normalize();
  EXPECT_NEAR(dot(r.direction, toTarget), 1.0, 1e-12);
  EXPECT_NEAR((r.origin - v.camera.eye()).norm(), v.camera.nearPlane(), 1e-9);
}

TEST(Viewport, ARayAtTheTopEdgeIsHalfTheFieldOfViewFromTheCentre) {
  Viewport v;
  v.setRect(0, 0, 640, 480);
  const Ray centre = v.ray(320, 240), top = v.ray(320, 0);
  const double angle = std::acos(std::clamp(dot(centre.direction, top.direction), -1.0, 1.0)) * 180 / std::numbers::pi;
  EXPECT_NEAR(angle, v.camera.fov_deg / 2, 1e-9);
  EXPECT_TRUE(v.contains(0, 0));
  EXPECT_FALSE(v.contains(640, 10));
}

TEST(NavigateTool, ALeftDragOrbitsByTheCameraRate) {
  Harness h;
  const double az = h.view.camera.azimuth_deg, el = h.view.camera.elevation_deg;
  h.send(move(300, 300));
  h.send(button(0, true));
  for (int i = 1; i <= 5; ++i) h.send(move(300 + 10 * i, 300 - 4 * i));  // 50 px right, 20 px up
  h.send(button(0, false));
  render::OrbitCamera expected;
  expected.azimuth_deg = az, expected.elevation_deg = el;
  expected.orbit(50, -20);  // one step of the whole drag: the rate is linear in pixels
  EXPECT_NEAR(h.view.camera.azimuth_deg, expected.azimuth_deg, 1e-9);
  EXPECT_NEAR(h.view.camera.elevation_deg, expected.elevation_deg, 1e-9);
  EXPECT_TRUE(h.clicks.empty());
  EXPECT_FALSE(h.tool.busy());
}

TEST(NavigateTool, AClickWithoutMovingPicksAlongTheRayUnderThePointer) {
  Harness h;
  h.send(move(420, 310));
  h.send(button(0, true));
  h.send(move(421, 311));  // within the slop
  h.send(button(0, false));
  ASSERT_EQ(h.clicks.size(), 1u);
  const Ray expected = h.view.ray(421, 311);
  EXPECT_NEAR((h.clicks[0].direction - expected.direction).norm(), 0.0, 1e-12);
  EXPECT_EQ(h.grabs, 1);  // the press offered the drag first
}

TEST(NavigateTool, ShiftDragAndRightDragPanWithoutTurning) {
  for (int way = 0; way < 2; ++way) {
    Harness h;
    const double az = h.view.camera.azimuth_deg;
    const Vec3 before = h.view.camera.target;
    h.send(move(300, 300));
    if (way == 0) h.send({T::Key, kShift, true});
    h.send(button(way == 0 ? 0 : 1, true));
    h.send(move(340, 300));
    h.send(button(way == 0 ? 0 : 1, false));
    EXPECT_EQ(h.view.camera.azimuth_deg, az);
    render::OrbitCamera expected = h.view.camera;
    expected.target = before;
    expected.pan(40, 0, 600);
    EXPECT_NEAR((h.view.camera.target - expected.target).norm(), 0.0, 1e-12);
    EXPECT_GT((h.view.camera.target - before).norm(), 0.0);
    EXPECT_TRUE(h.clicks.empty());
  }
}

TEST(NavigateTool, TheWheelZoomsOnlyOverTheView) {
  Harness h;
  const double d = h.view.camera.distance;
  InputEvent wheel{T::Scroll};
  wheel.y = 2;
  h.send(move(50, 300));  // left of the view (the object panel)
  h.send(wheel);
  EXPECT_EQ(h.view.camera.distance, d);
  h.send(move(300, 300));
  h.send(wheel, true);  // a panel over the view has the pointer
  EXPECT_EQ(h.view.camera.distance, d);
  h.send(wheel);
  EXPECT_NEAR(h.view.camera.distance, d * 0.88 * 0.88, 1e-12);
}

TEST(NavigateTool, APressOverAPanelOrOutsideStartsNothing) {
  Harness h;
  const double az = h.view.camera.azimuth_deg;
  h.send(move(300, 300));
  h.send(button(0, true), true);
  h.send(move(400, 300));
  h.send(button(0, false));
  h.send(move(20, 20));
  h.send(button(0, true));
  h.send(move(200, 200));
  h.send(button(0, false));
  EXPECT_EQ(h.view.camera.azimuth_deg, az);
  EXPECT_TRUE(h.clicks.empty());
  EXPECT_EQ(h.grabs, 0);
}

TEST(NavigateTool, AGrabFollowsThePointerEvenOutsideTheViewAndIsReleasedOnce) {
  Harness h;
  h.grabAnswer = true;
  const render::OrbitCamera before = h.view.camera;
  h.send(move(300, 300));
  h.send(button(0, true));
  EXPECT_TRUE(h.tool.busy());
  h.send(move(320, 300));
  h.send(move(5, 5));  // over the object panel: the drag goes on
  h.send(button(0, false));
  EXPECT_EQ(h.drags.size(), 2u);
  EXPECT_EQ(h.releases, 1);
  EXPECT_TRUE(h.clicks.empty());
  EXPECT_EQ(h.view.camera.azimuth_deg, before.azimuth_deg);
  EXPECT_FALSE(h.tool.busy());
}

}  // namespace
}  // namespace corbel::editor
