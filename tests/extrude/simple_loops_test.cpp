// simpleInItsPlane (sweep.h), the test the clean-up, the batch and the editor's builder put to
// every face loop, against CGAL's is_simple_2 on the same points: the two must agree on every
// loop, degenerate ones above all (corners twice, sides along one line, sides turning back).
#include "extrude/sweep.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace corbel::extrude::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// A shell of one face in the plane `axis` = const (its normal along that axis), its one loop
// through the given points in order.
struct OneFace {
  SweepOutput shell;
  ShellFace face;
};

OneFace oneFace(const std::vector<std::array<double, 2>>& pts, int axis) {
  OneFace o;
  o.face.normal = Vec3(0, 0, 0);
  o.face.normal[axis] = 1;
  std::vector<int> loop;
  for (const auto& q : pts) {
    Vec3 p(0.25, 0.25, 0.25);  // off the other planes
    p[(axis + 1) % 3] = q[0];
    p[(axis + 2) % 3] = q[1];
    loop.push_back(static_cast<int>(o.shell.points.size()));
    o.shell.points.push_back(p);
  }
  o.face.loops = {loop};
  return o;
}

bool cgalSays(const std::vector<std::array<double, 2>>& pts) {
  std::vector<K::Point_2> p;
  for (const auto& q : pts) p.emplace_back(q[0], q[1]);
  return p.size() >= 3 && CGAL::is_simple_2(p.begin(), p.end(), K());
}

TEST(SimpleLoops, HandMadeLoops) {
  const std::vector<std::pair<std::vector<std::array<double, 2>>, bool>> cases = {
      {{{0, 0}, {1, 0}, {0, 1}}, true},                   // a triangle
      {{{0, 0}, {1, 0}, {2, 0}}, false},                  // a triangle of no area
      {{{0, 0}, {2, 0}, {1, 0}, {1, 1}}, false},          // a side turning back along the last
      {{{0, 0}, {1, 0}, {2, 0}, {1, 1}}, true},           // a corner straight through
      {{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {2, 0}}, false},  // a corner twice
      {{{0, 0}, {2, 0}, {0, 2}, {2, 2}}, false},          // a bow tie
      {{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, false},  // a corner on a side (touching)
      {{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, false},          // a side of no length
      {{{0, 0}, {1, 0}}, false},                          // two corners
  };
  for (const auto& [pts, simple] : cases) {
    ASSERT_EQ(cgalSays(pts), simple) << "the case itself is wrong";
    for (int axis = 0; axis < 3; ++axis) {
      const OneFace o = oneFace(pts, axis);
      EXPECT_EQ(simpleInItsPlane(o.shell, o.face, o.face.loops[0]), simple) << pts.size() << " corners, axis " << axis;
    }
  }
}

// Random loops of 3 to 8 corners on a 4 × 4 grid (many corners twice, sides along one line), and
// of 3 to 30 round the unit circle, some corners nudged by an ulp, some swapped or repeated, both
// ways round: the verdict is CGAL's on each.
TEST(SimpleLoops, AgreeWithCgalOnRandomLoops) {
  std::mt19937_64 rng(28);
  std::uniform_int_distribution<int> grid(0, 3), small(3, 8), large(3, 30);
  std::uniform_real_distribution<double> unit(0, 1);
  int simple = 0, notSimple = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    const int n = trial % 2 == 0 ? small(rng) : large(rng);
    std::vector<std::array<double, 2>> pts;
    if (trial % 2 == 0) {
      for (int i = 0; i < n; ++i) pts.push_back({double(grid(rng)), double(grid(rng))});
    } else {
      // Corners in order round a circle (simple unless a nudge or a swap breaks it).
      std::vector<double> a(n);
      for (double& x : a) x = unit(rng) * 6.283185307179586;
      std::sort(a.begin(), a.end());
      for (double x : a) {
        double px = std::cos(x), py = std::sin(x);
        if (unit(rng) < 0.3) px = std::nextafter(px, unit(rng) < 0.5 ? -2.0 : 2.0);
        pts.push_back({px, py});
      }
      if (unit(rng) < 0.3) std::swap(pts[0], pts[n / 2]);
      if (unit(rng) < 0.2) pts[n - 1] = pts[0];
    }
    if (trial % 4 == 1) std::reverse(pts.begin(), pts.end());
    const bool expected = cgalSays(pts);
    (expected ? simple : notSimple)++;
    const OneFace o = oneFace(pts, trial % 3);
    ASSERT_EQ(simpleInItsPlane(o.shell, o.face, o.face.loops[0]), expected)
        << "trial " << trial << ", " << n << " corners";
  }
  // Both verdicts are common enough to mean something.
  EXPECT_GT(simple, 4000);
  EXPECT_GT(notSimple, 4000);
}

}  // namespace
}  // namespace corbel::extrude::test
