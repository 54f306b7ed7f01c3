// The shell checks' own triangulation (shell_checks.h): a check that cuts a face badly reports
// a needle the kernel did not make.
#include "shell_checks.h"
#include "skeleton_oracle.h"

#include "core/project_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

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

// A driver, not a test: CORBEL_SHELL_CHECK_FILES names project files (space-separated, as the
// random run saves them under extrude-random-failures/geometry/); each one's first extrusion
// is built and its shell checked, and the problem printed. Run with
// --gtest_also_run_disabled_tests --gtest_filter='ShellChecks.DISABLED_Files'.
TEST(ShellChecks, DISABLED_Files) {
  const char* files = std::getenv("CORBEL_SHELL_CHECK_FILES");
  if (!files) GTEST_SKIP() << "CORBEL_SHELL_CHECK_FILES names no files";
  std::istringstream in(files);
  for (std::string path; in >> path;) {
    const Document d = loadProject(path).document;
    const ExtrusionSpec& spec = std::get<ExtrusionSpec>(d.objects.at(0).spec);
    std::string problem;
    try {
      // CORBEL_SHELL_CHECK_FACTOR: the tolerance factor (as a rebuild uses), 1 unless given.
      const char* factor = std::getenv("CORBEL_SHELL_CHECK_FACTOR");
      const SweepOutput shell = extrude(spec, nullptr, ExtrudeOptions{0.0, factor ? std::atof(factor) : 1.0, false}).shell;
      std::cout.precision(12);
      std::cout << "volume " << measure(shell).volume << ", roof area " << measure(shell).roofArea << "\n";
      problem = shellGeometryProblem(shell, spec);
      // One profile on every edge: the top against CGAL's skeleton (the random run's check).
      bool one = spec.steps.empty() && spec.offsets.empty();
      for (const auto& l : spec.loops)
        for (int k : l.profile) one = one && spec.profiles[k].points == spec.profiles[spec.loops[0].profile[0]].points;
      if (one) {
        std::vector<std::vector<Vec2>> loops;
        for (const auto& l : spec.loops) loops.push_back(l.points);
        std::cout << "top " << shell.maxHeight << " m, CGAL's skeleton "
                  << cgalHeightUnderProfile(loops, spec.profiles[spec.loops[0].profile[0]].points) << " m\n";
      }
      // CORBEL_SHELL_CHECK_FACE=N also prints face N's corners.
      if (const char* face = std::getenv("CORBEL_SHELL_CHECK_FACE")) {
        const ShellFace& f = shell.faces.at(std::atoi(face));
        std::cout.precision(12);
        for (const auto& loop : f.loops) {
          std::cout << "loop:";
          for (int v : loop) std::cout << " v" << v << " (" << shell.points[v][0] << ", " << shell.points[v][1] << ", " << shell.points[v][2] << ")";
          std::cout << "\n";
        }
      }
    } catch (const std::exception& e) {
      problem = std::string("build failed: ") + e.what();
    }
    std::cout << path << ": " << (problem.empty() ? "ok" : problem) << "\n";
  }
}

}  // namespace
}  // namespace corbel::extrude::test
