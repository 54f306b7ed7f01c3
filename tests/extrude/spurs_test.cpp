// zipSpurs: zero-width spurs zipped out of the traced faces (docs/extrude.md, "Decisions").
#include "core/project_io.h"
#include "extrude/extrude.h"
#include "extrude/sweep.h"
#include "shell_checks.h"
#include "skeleton_oracle.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace corbel::extrude::test {
namespace {

// A 2 × 2 × 1 box whose top is three faces: G the front-left square, H the right half, and F
// the back-left square with a spur down the line x = 1 to the front edge: seen from above, F
// runs (1, 1) → (spurX, 0.5) → (1, 0) and straight back to (1, 2). G lies across the spur's
// first side, H across its second; F's loop is not simple in its plane.
enum Top { F = 0, G = 1, H = 2 };
SweepOutput boxWithASpur(double spurX = 1) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(2, 0, 1), Vec3(2, 2, 1),       Vec3(1, 2, 1),
              Vec3(0, 2, 1), Vec3(0, 1, 1), Vec3(1, 1, 1), Vec3(spurX, 0.5, 1),  // 8: on the spur
              Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  addFace(s, {6, 7, 8, 1, 4, 5}, Vec3(0, 0, 1));  // F
  addFace(s, {0, 1, 8, 7, 6}, Vec3(0, 0, 1));     // G
  addFace(s, {1, 2, 3, 4}, Vec3(0, 0, 1));        // H
  addFace(s, {9, 10, 2, 1, 0}, Vec3(0, -1, 0));
  addFace(s, {10, 11, 3, 2}, Vec3(1, 0, 0));
  addFace(s, {11, 12, 5, 4, 3}, Vec3(0, 1, 0));
  addFace(s, {12, 9, 0, 6, 5}, Vec3(-1, 0, 0));
  addFace(s, {9, 12, 11, 10}, Vec3(0, 0, -1));
  return s;
}

TEST(ZipSpurs, ZipsASpurCornerByCornerAndKeepsTheShellClosed) {
  SweepOutput s = boxWithASpur();
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_FALSE(simpleInItsPlane(s, s.faces[F], s.faces[F].loops[0]));
  // By hand: the tip (1, 0) leaves F and H takes (1, 0.5) into its side (1, 2) → (1, 0); then
  // (1, 0.5) leaves F and H takes (1, 1).
  EXPECT_EQ(zipSpurs(s, 1e-9), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 8u);
  EXPECT_EQ(s.faces[F].loops[0], (std::vector<int>{6, 7, 4, 5}));
  EXPECT_EQ(s.faces[G].loops[0], (std::vector<int>{0, 1, 8, 7, 6})) << "the face across the near side is unchanged";
  EXPECT_EQ(s.faces[H].loops[0], (std::vector<int>{1, 2, 3, 4, 7, 8}));
  for (const ShellFace& f : s.faces) EXPECT_TRUE(simpleInItsPlane(s, f, f.loops[0]));
  // The areas of the squares and the half, and the box's volume, as drawn.
  EXPECT_NEAR(topArea(s, F), 1.0, 1e-12);
  EXPECT_NEAR(topArea(s, G), 1.0, 1e-12);
  EXPECT_NEAR(topArea(s, H), 2.0, 1e-12);
  EXPECT_NEAR(measure(s).volume, 4.0, 1e-12);
}

// The width decides: a spur whose sides lie 1e-4 apart is zipped at a width of 1e-3, not at 1e-6.
TEST(ZipSpurs, LeavesASpurWiderThanTheWidth) {
  SweepOutput s = boxWithASpur(1 + 1e-4);
  const std::vector<int> before = s.faces[F].loops[0];
  EXPECT_EQ(zipSpurs(s, 1e-6), 0u);
  EXPECT_EQ(s.faces[F].loops[0], before);
  EXPECT_EQ(zipSpurs(s, 1e-3), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(s.faces[F].loops[0], (std::vector<int>{6, 7, 4, 5}));
}

// Without its bottom the box is not closed: which face lies across an edge is not known, and
// nothing is zipped.
TEST(ZipSpurs, LeavesAShellThatIsNotClosed) {
  SweepOutput s = boxWithASpur();
  s.faces.pop_back();
  const std::vector<int> before = s.faces[F].loops[0];
  EXPECT_EQ(zipSpurs(s, 1e-9), 0u);
  EXPECT_EQ(s.faces[F].loops[0], before);
}

// Two perturbed orthogonal plans from the random run, each with a face that ran out along a
// line and straight back. random8614: a shallow roof swept over a 4.5 m strip reaches the wall
// beyond it 1.7e-7 m beside the corner it meets; the edge between them, 0.2 µm long, runs 1.5
// m along that wall before anything ends it, and the roof's face has a spur 0.86 m long and
// 6e-8 m wide along the wall's top. random11689: a gable's face runs 2.6 m out and back with
// one face across both sides of the spur. Zipped, every face is simple; the oracles
// (volume_oracle.h): random8614 unperturbed (its exact axis-parallel plan) gives the same volume
// and roof area to 1e-6; random11689 has one profile, and CGAL's straight skeleton integrated
// under it the same volume to 1e-6.
constexpr const char* kBesideAWall = "tests/data/extrude/spur_beside_a_wall.corbel";
constexpr const char* kBothSides = "tests/data/extrude/spur_between_two_sides_of_a_face.corbel";

void expectZippedAndAgreeing(const std::string& file) {
  const ExtrusionSpec spec = savedSpec(file);
  const ExtrusionResult r = extrude(spec);
  EXPECT_EQ(unpairedEdges(r.shell), 0u);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
  const VolumeOracle o = independentVolume(spec);
  ASSERT_NE(o.kind, VolumeOracle::None);
  const ShellMeasures m = measure(r.shell);
  EXPECT_NEAR(m.volume, o.volume, 1e-6 * o.volume);
  if (o.kind == VolumeOracle::Unperturbed) {
    EXPECT_NEAR(m.roofArea, o.roofArea, 1e-6 * o.roofArea);
  }
}

TEST(ZipSpurs, ARoofsSpurAlongAWallIsZipped) {
  EXPECT_EQ(independentVolume(savedSpec(kBesideAWall)).kind, VolumeOracle::Unperturbed);
  expectZippedAndAgreeing(kBesideAWall);
}

TEST(ZipSpurs, ASpurWithOneFaceAcrossBothSidesIsZipped) {
  EXPECT_EQ(independentVolume(savedSpec(kBothSides)).kind, VolumeOracle::Cgal);
  expectZippedAndAgreeing(kBothSides);
}

// random31830 (one profile on every edge): the sweep ran a corner 0.52 m up past a ridge and
// back, a needle of no width. Zipped, the needle's tip is in no face, and the shell's top is
// the top of the corners its faces use: CGAL's straight skeleton's, within the kernel's
// tolerances (skeletonTopTolerance, the random run's check).
TEST(ZipSpurs, ANeedlesZippedTipIsNoPartOfTheTop) {
  const ExtrusionSpec spec = savedSpec("tests/data/extrude/needle_zipped_off_a_ridge.corbel");
  const ExtrusionResult r = extrude(spec);
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
  double top = -INFINITY;
  for (const ShellFace& f : r.shell.faces)
    for (const auto& loop : f.loops)
      for (int v : loop) top = std::max(top, r.shell.points[v][2]);
  EXPECT_EQ(r.shell.maxHeight, top);
  std::vector<std::vector<Vec2>> loops;
  for (const auto& l : spec.loops) loops.push_back(l.points);
  const Profile& profile = spec.profiles[spec.loops[0].profile[0]];
  const double skeleton = cgalHeightUnderProfile(loops, profile.points);
  const Tolerances t = Tolerances::forScale(r.scale);
  EXPECT_LE(r.shell.maxHeight, skeleton + skeletonTopTolerance(profile, r.shell.maxHeight, t.height, t.cluster));
}

}  // namespace
}  // namespace corbel::extrude::test
