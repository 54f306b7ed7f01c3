// Mass properties against closed forms: a box (V = abc, I = V(b² + c²)/12 …), the same box
// turned (the principal axes turn with it), and a right tetrahedron (centroid at a quarter).
#include "sim/mass_properties.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace corbel::sim {
namespace {

TEST(MassProperties, BoxMatchesClosedForm) {
  const double a = 0.4, b = 0.6, c = 1.0;
  const auto m = massProperties(statics::boxBlock("box", Vec3(1, 2, 3), Vec3(1 + a, 2 + b, 3 + c)));
  const double v = a * b * c;
  EXPECT_NEAR(m.volume, v, 1e-12);
  EXPECT_NEAR((m.centroid - Vec3(1 + a / 2, 2 + b / 2, 3 + c / 2)).norm(), 0, 1e-12);
  // Moments come back in ascending order: about z (a² + b²), y (a² + c²), x (b² + c²).
  EXPECT_NEAR(m.principalMoments[0], v * (a * a + b * b) / 12, 1e-12);
  EXPECT_NEAR(m.principalMoments[1], v * (a * a + c * c) / 12, 1e-12);
  EXPECT_NEAR(m.principalMoments[2], v * (b * b + c * c) / 12, 1e-12);
  EXPECT_NEAR(std::abs(m.principalAxes[0][2]), 1, 1e-12);
  EXPECT_NEAR(std::abs(m.principalAxes[2][0]), 1, 1e-12);
  EXPECT_NEAR(m.leastWidth, a, 1e-12);
  const Vec3 handed = cross(m.principalAxes[0], m.principalAxes[1]);
  EXPECT_NEAR((handed - m.principalAxes[2]).norm(), 0, 1e-12);
}

TEST(MassProperties, TurnedBoxTurnsItsAxes) {
  // A 1 × 2 × 3 box turned 30° about z: its longest horizontal side lies along (cos 30°, sin 30°).
  statics::Block box = statics::boxBlock("box", Vec3(-1, -0.5, -1.5), Vec3(1, 0.5, 1.5));
  const double t = std::acos(-1.0) / 6;
  for (Vec3& p : box.vertices)
    p = Vec3(std::cos(t) * p[0] - std::sin(t) * p[1], std::sin(t) * p[0] + std::cos(t) * p[1], p[2]);
  const auto m = massProperties(box);
  const double v = 6;
  // Smallest moment about the 3 m axis (z): V (2² + 1²)/12; the largest about the 1 m side.
  EXPECT_NEAR(m.principalMoments[0], v * 5 / 12, 1e-12);
  EXPECT_NEAR(m.principalMoments[2], v * 13 / 12, 1e-12);
  // The middle moment, V (1² + 3²)/12, belongs to the axis along the 2 m side.
  EXPECT_NEAR(m.principalMoments[1], v * 10 / 12, 1e-12);
  EXPECT_NEAR(std::abs(dot(m.principalAxes[1], Vec3(std::cos(t), std::sin(t), 0))), 1, 1e-12);
}

TEST(MassProperties, TetrahedronCentroidAndVolume) {
  statics::Block t;
  t.name = "tet";
  t.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  t.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto m = massProperties(t);
  EXPECT_NEAR(m.volume, 1.0 / 6, 1e-14);
  EXPECT_NEAR((m.centroid - Vec3(0.25, 0.25, 0.25)).norm(), 0, 1e-14);
  // The trace of the inertia is 2 ∫ |x − c|² dV; on this simplex each coordinate has mean 1/4
  // and mean square 1/10, so variance 3/80, and the trace is 2 V · 3 · 3/80.
  const double trace = m.principalMoments[0] + m.principalMoments[1] + m.principalMoments[2];
  EXPECT_NEAR(trace, 2 * (1.0 / 6) * 3 * (3.0 / 80), 1e-14);
  EXPECT_NEAR(m.leastWidth, 1 / std::sqrt(3.0), 1e-12);
}

TEST(MassProperties, InsideOutBlockIsRefused) {
  statics::Block b = statics::boxBlock("inverted", Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (auto& f : b.faces) std::reverse(f.begin(), f.end());
  EXPECT_THROW(massProperties(b), Error);
}

}  // namespace
}  // namespace corbel::sim
