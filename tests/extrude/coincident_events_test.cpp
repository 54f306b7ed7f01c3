// Intersection events that fall exactly on an edge direction event's height (Sec. 4.4, 4.5): the
// edges change direction first, and the corners they make must still meet what they touch at
// that height. Interior dormers (Fig. 23) whose sides vanish as they turn, and flared columns
// (Fig. 24) that touch as their flare ends, against volumes by hand and lower envelopes of
// convex plans integrated on a grid.
#include "core/scene.h"
#include "shell_checks.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace corbel::extrude::test {
namespace {

// Closed, a 2-manifold, its faces simple and touching itself at most at split vertices, no
// warnings; its volume.
double closedVolume(const ExtrusionSpec& spec) {
  const ExtrusionResult r = extrude(spec);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
  EXPECT_EQ(unpairedEdges(r.shell), 0u);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "plaster"));
  const ValidityReport v = scene.validate(1);
  for (const auto& p : v.problems()) ADD_FAILURE() << p;
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
  const double volume = measure(r.shell).volume;
  EXPECT_NEAR(v.volume, volume, 1e-9 * volume);
  return volume;
}

// A 10 × 6 hip house (walls 3 m, 45°) with a 2 m wide recess into its front slope at height a:
// a natural step of negative depth d (Fig. 23's interior dormer). Its back wall rises
// vertically for good; its sides rise 1 m, then lean in at 45°.
ExtrusionSpec interiorDormer(double a, double d) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg));
  s.profiles.push_back(polyline("recess back", {{0, 0}, {0, 1}}));
  s.profiles.push_back(polyline("recess side", {{0, 0}, {0, 1}, {1, 2}}));
  PlanStep st;
  st.name = "interior dormer";
  st.anchor = {0, 0, false, 0.5, a};
  st.width = 2;
  st.depth = d;
  st.frontProfile = 1;
  st.sideProfile = 2;
  s.steps.push_back(st);
  return s;
}

// The front slope reaches the recess's back wall in line at a + |d|. Where the recess is no
// deeper than its sides' walls are high (|d| ≤ 1), the sides are still vertical then (or, at
// |d| = 1, just turning) and vanish there; where it is deeper, the sides have leant out by
// |d| − 1 and their corners with the front and the back meet at that height, so they vanish
// there too. Either way, maximising volume (Sec. 4.8), the back wall's vertical profile takes
// the whole front line from a + |d| up. So behind that line the top is the least of the other
// three edges' heights, and in front of it the least of all the edges' (the sides' from the
// recess's front line back), but for the recess's floor (a ledge at a) where it is cut.
double interiorDormerVolume(double a, double d) {
  const double front = a - 3, back = front + std::abs(d);  // y of the recess's front and back
  return integrate(0, 10, 0, 6, 2000, 1200, [&](double x, double y) {
    const double hips = std::min({3 + x, 13 - x, 9 - y});
    if (y >= back) return hips;
    if (x > 4 && x < 6 && y > front) return a;
    double top = std::min(hips, 3 + y);
    if (y > front) top = std::min(top, a + 1 + (x <= 4 ? 4 - x : x - 6));
    return top;
  });
}

TEST(CoincidentEvents, InteriorDormersClose) {
  for (double a : {3.2, 3.5, 4.5, 5.0})
    for (double d : {-0.5, -1.0, -1.5}) {
      SCOPED_TRACE("anchor at " + std::to_string(a) + " m, depth " + std::to_string(d) + " m");
      const double v = closedVolume(interiorDormer(a, d));
      const double expect = interiorDormerVolume(a, d);
      // The integral's 5 mm grid is good to a few 1e-7 here; the sides' term alone is 1.6e-4 of
      // the volume at a = 3.2 m, d = −1.5 m.
      EXPECT_NEAR(v, expect, 1e-6 * expect);
    }
}

// Fig. 24's columns: square columns whose walls rise 2 m, flare out `flare` m over `rise` m,
// rise 0.5 m more and close with a 45° roof.
ExtrusionSpec columns(int n, double size, double spacing, double flare, double rise) {
  std::vector<std::vector<Vec2>> loops;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) loops.push_back(rectangle(size, size, i * spacing, j * spacing));
  return uniformSpec(
      loops, polyline("column", {{0, 0}, {0, 2}, {-flare, 2 + rise}, {-flare, 2.5 + rise}, {-flare + 1, 3.5 + rise}}));
}

// A square of side b flaring to side B over height h: a frustum, h/3 (b² + B² + bB).
double frustum(double b, double B, double h) { return h / 3 * (b * b + B * B + b * B); }

TEST(CoincidentEvents, FlaredColumnsThatTouchExactlyMerge) {
  // Four 1 m columns 4 m apart flaring 1.5 m over 3 m touch as their flare ends, at 5 m: above,
  // one 8 × 8 m block, 0.5 m of wall and a pyramid 4 m high.
  {
    SCOPED_TRACE("four columns, touching");
    const double expect = 4 * (2 + frustum(1, 4, 3)) + 64 * 0.5 + 64 * 4 / 3.0;
    EXPECT_NEAR(closedVolume(columns(2, 1, 4, 1.5, 3)), expect, 1e-9 * expect);
  }
  {
    SCOPED_TRACE("four columns, apart");  // each on its own: 3.8 m wide, a pyramid 1.9 m high
    const double expect = 4 * (2 + frustum(1, 3.8, 3) + 3.8 * 3.8 * 0.5 + 3.8 * 3.8 * 1.9 / 3);
    EXPECT_NEAR(closedVolume(columns(2, 1, 4, 1.4, 3)), expect, 1e-9 * expect);
  }
  {
    // Flaring 1.6 m, they touch once each has flared 1.5 m, at 2 + 3 · 1.5 / 1.6 m, all along the
    // gaps at once: above, one 8 m square flaring on to 8.2 m at 5 m, 0.5 m of wall and a
    // pyramid 4.1 m high.
    SCOPED_TRACE("four columns, overlapping");
    const double touch = 3 * 1.5 / 1.6;
    const double expect = 4 * (2 + frustum(1, 4, touch)) + frustum(8, 8.2, 3 - touch) + 8.2 * 8.2 * (0.5 + 4.1 / 3);
    EXPECT_NEAR(closedVolume(columns(2, 1, 4, 1.6, 3)), expect, 1e-9 * expect);
  }
  {
    // Nine 0.5 m columns on a 3 m grid flaring 1.25 m at 45°: a 9 × 9 m block from 3.25 m.
    SCOPED_TRACE("nine columns, touching");
    const double expect = 9 * (0.5 + frustum(0.5, 3, 1.25)) + 81 * 0.5 + 81 * 4.5 / 3;
    EXPECT_NEAR(closedVolume(columns(3, 0.5, 3, 1.25, 1.25)), expect, 1e-9 * expect);
  }
}

}  // namespace
}  // namespace corbel::extrude::test
