// The shell checks' own triangulation (shell_checks.h): a check that cuts a face badly reports
// a needle the kernel did not make.
#include "shell_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace corbel::extrude::test {
namespace {

double distanceToSegment(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(OpenMesh::dot(q - a, ab) / OpenMesh::dot(ab, ab), 0.0, 1.0);
  return (q - (a + ab * t)).norm();
}

// A notch whose reflex corner lies 1e-13 m beyond the cut of the first convex corner's ear: in
// exact arithmetic that ear holds no corner, but its cut passes within rounding of the notch,
// and in space (a face planar only to rounding) such a sliver crosses the faces meeting there.
// The triangles must tile the polygon (their areas add up to the shoelace area) and no cut may
// pass that close to a corner it does not end at.
TEST(ShellChecks, NoCutPassesWithinToleranceOfAnotherCorner) {
  const std::vector<Vec3> pts{{0, -1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1e-13, 0}, {-1, 1, 0}, {-1, 0, 0}};
  const std::vector<int> polygon{0, 1, 2, 3, 4, 5};
  const double tolerance = 1e-9;
  const auto tris = cutIntoTriangles(pts, polygon, tolerance);
  // Shoelace: the square's lower diamond (1) plus the two upper quarters (0.5 each) less the
  // notch's triangle down to (0, 1e-13) (about 1).
  double shoelace = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3 &a = pts[i], &b = pts[(i + 1) % pts.size()];
    shoelace += 0.5 * (a[0] * b[1] - a[1] * b[0]);
  }
  double sum = 0;
  for (const auto& t : tris) {
    sum += 0.5 * OpenMesh::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]])[2];
    for (int k = 0; k < 3; ++k)
      for (int q = 0; q < static_cast<int>(pts.size()); ++q) {
        const int a = t[k], b = t[(k + 1) % 3];
        if (q == t[0] || q == t[1] || q == t[2]) continue;
        EXPECT_GT(distanceToSegment(pts[q], pts[a], pts[b]), tolerance)
            << "the cut " << a << "-" << b << " passes corner " << q;
      }
  }
  EXPECT_EQ(tris.size(), 4u);
  EXPECT_NEAR(sum, shoelace, 1e-12);
}

}  // namespace
}  // namespace corbel::extrude::test
