// unfoldSharedRuns: folds taken out of the boundary two faces share (docs/extrude.md, "Decisions").
#include "extrude/extrude.h"
#include "extrude/sweep.h"
#include "saved_plan_checks.h"
#include "shell_checks.h"
#include "support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace corbel::extrude::test {
namespace {

// A 4 × 4 × 1 box whose flat top is three faces: F the back-left part, G the front-left part
// and H the strip x ≥ 3. F and G meet along a run of corners that no other face has, from
// (0, 2) through p, c1 and c2 to q on H's side x = 3. With the default corners the run goes
// out past x = 3 and back, (2, 2) → (3.5, 2) → (3.5, 1.5) → (3, 1.5): F's side from q up to
// (3, 4) then crosses F's side p → c1, as the roofs of the random run's folds do, and G runs
// round the fold's far side.
enum Top { F = 0, G = 1, H = 2 };
SweepOutput boxWithAFold(Vec3 p = Vec3(2, 2, 1), Vec3 c1 = Vec3(3.5, 2, 1), Vec3 c2 = Vec3(3.5, 1.5, 1),
                         Vec3 q = Vec3(3, 1.5, 1)) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 1),
              Vec3(3, 0, 1),
              Vec3(4, 0, 1),
              Vec3(4, 4, 1),
              Vec3(3, 4, 1),
              Vec3(0, 4, 1),
              Vec3(0, 2, 1),
              p,
              c1,
              c2,
              q,
              Vec3(0, 0, 0),
              Vec3(4, 0, 0),
              Vec3(4, 4, 0),
              Vec3(0, 4, 0)};
  addFace(s, {6, 7, 8, 9, 10, 4, 5}, Vec3(0, 0, 1));  // F
  addFace(s, {0, 1, 10, 9, 8, 7, 6}, Vec3(0, 0, 1));  // G
  addFace(s, {1, 2, 3, 4, 10}, Vec3(0, 0, 1));        // H
  addFace(s, {11, 12, 2, 1, 0}, Vec3(0, -1, 0));
  addFace(s, {12, 13, 3, 2}, Vec3(1, 0, 0));
  addFace(s, {13, 14, 5, 4, 3}, Vec3(0, 1, 0));
  addFace(s, {14, 11, 0, 6, 5}, Vec3(-1, 0, 0));
  addFace(s, {11, 14, 13, 12}, Vec3(0, 0, -1));
  return s;
}

TEST(UnfoldSharedRuns, StraightensAFoldedRunBetweenTwoFacesOfOnePlane) {
  SweepOutput s = boxWithAFold();
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_FALSE(simpleInItsPlane(s, s.faces[F], s.faces[F].loops[0]));
  ASSERT_TRUE(simpleInItsPlane(s, s.faces[G], s.faces[G].loops[0]));
  // By hand: p, c1 and c2 lie on F and G alone; the run ends at (0, 2), which the west wall
  // meets, and at q, which H meets. F and G are divided by the straight edge from (0, 2) to q
  // instead, and H keeps its loop.
  EXPECT_EQ(unfoldSharedRuns(s), 3u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 8u);
  EXPECT_EQ(s.faces[F].loops[0], (std::vector<int>{6, 10, 4, 5}));
  EXPECT_EQ(s.faces[G].loops[0], (std::vector<int>{0, 1, 10, 6}));
  EXPECT_EQ(s.faces[H].loops[0], (std::vector<int>{1, 2, 3, 4, 10}));
  for (const ShellFace& f : s.faces) EXPECT_TRUE(simpleInItsPlane(s, f, f.loops[0]));
  // F is the box's back-left 3 × 4 less the trapezoid under the line from (0, 2) to (3, 1.5);
  // the top's three faces still cover 4 × 4 once, and the volume is the box's.
  EXPECT_NEAR(topArea(s, F), 12 - 3 * (2 + 1.5) / 2, 1e-12);
  EXPECT_NEAR(topArea(s, G), 3 * (2 + 1.5) / 2, 1e-12);
  EXPECT_NEAR(topArea(s, H), 4.0, 1e-12);
  EXPECT_NEAR(measure(s).volume, 16.0, 1e-12);
}

// A run that bends but does not fold, (2, 2) → (2, 3) → (2.5, 3) → (3, 3), leaves both faces
// simple: it is left as the sweep made it.
TEST(UnfoldSharedRuns, LeavesARunThatDoesNotFold) {
  SweepOutput s = boxWithAFold(Vec3(2, 2, 1), Vec3(2, 3, 1), Vec3(2.5, 3, 1), Vec3(3, 3, 1));
  ASSERT_TRUE(simpleInItsPlane(s, s.faces[F], s.faces[F].loops[0]));
  const SweepOutput before = s;
  EXPECT_EQ(unfoldSharedRuns(s), 0u);
  for (std::size_t i = 0; i < s.faces.size(); ++i) EXPECT_EQ(s.faces[i].loops, before.faces[i].loops);
}

// Without its bottom the box is not closed: which face lies across an edge is not known, and
// nothing is changed.
TEST(UnfoldSharedRuns, LeavesAShellThatIsNotClosed) {
  SweepOutput s = boxWithAFold();
  s.faces.pop_back();
  const std::vector<int> before = s.faces[F].loops[0];
  EXPECT_EQ(unfoldSharedRuns(s), 0u);
  EXPECT_EQ(s.faces[F].loops[0], before);
}

// Two perturbed orthogonal plans from the random run. random14398: the sides x = 13.5 of a
// building's right wing, either side of a 3 m link, lie on one line with one profile; once the
// link's roof has closed they are neighbours, and their roofs lie in one plane. A corner racing
// along the wing's ridge meets the second side's plane (within rounding of the first's) 1.5 m
// past their corner, and the two sides are left as a loop of no area that runs on until the
// roof is capped; their faces fold over each other along it, a tab 1.5 m square. random96656
// does the same after its sweep diverged. Unfolded, every face is simple, and the oracles
// (volume_oracle.h) hold: random14398 has one profile, and CGAL's straight skeleton integrated
// under it gives the same volume to 1e-6; random96656 gives its unperturbed plan's volume and
// roof area to 1e-6. The warnings stay: the sweep did cap a loop (of no area).
constexpr const char* kTwoRoofs = "tests/data/extrude/fold_between_two_roofs_of_one_line.corbel";
constexpr const char* kDiverged = "tests/data/extrude/fold_after_a_diverged_sweep.corbel";

TEST(UnfoldSharedRuns, TheFoldOfTwoRoofsOfOneLineGoes) { expectCleanAndAgreeing(kTwoRoofs, VolumeOracle::Cgal, true); }

TEST(UnfoldSharedRuns, TheFoldAfterADivergedSweepGoes) {
  expectCleanAndAgreeing(kDiverged, VolumeOracle::Unperturbed, true);
}

}  // namespace
}  // namespace corbel::extrude::test
