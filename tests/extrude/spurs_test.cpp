// zipSpurs: zero-width spurs zipped out of the traced faces (docs/extrude.md, "Decisions").
#include "core/project_io.h"
#include "extrude/extrude.h"
#include "extrude/sweep.h"
#include "saved_plan_checks.h"
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

TEST(ZipSpurs, ARoofsSpurAlongAWallIsZipped) { expectCleanAndAgreeing(kBesideAWall, VolumeOracle::Unperturbed); }

TEST(ZipSpurs, ASpurWithOneFaceAcrossBothSidesIsZipped) { expectCleanAndAgreeing(kBothSides, VolumeOracle::Cgal); }

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

// A gable roof, 4 m long and 2 m deep, its ridge 1 m up along y = 1. The ridge's two faces F
// (front) and G (back) and the two gables; with `tip` the front runs along the ridge from its
// right end out to the tip and straight back past that end to its left end, and the back runs
// the same corners backwards: one spur in both. With `bend` both run through a middle corner
// of the ridge instead.
enum Gable { Front = 0, Back = 1 };
SweepOutput gable(const Vec3* tip, const Vec3* bend) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0), Vec3(4, 1, 1), Vec3(0, 1, 1)};
  std::vector<int> front{0, 1, 4}, back{2, 3, 5};
  if (tip || bend) s.points.push_back(tip ? *tip : *bend);
  if (tip) {
    front.insert(front.end(), {6, 5});  // 4 → tip → 5, past 4
    back.insert(back.end(), {6, 4});    // 5 → tip → 4
  } else if (bend) {
    front.insert(front.end(), {6, 5});
    back.insert(back.end(), {6, 4});
  } else {
    front.push_back(5);
    back.push_back(4);
  }
  addFace(s, front, Vec3(0, -1, 1) / std::sqrt(2.0));
  addFace(s, back, Vec3(0, 1, 1) / std::sqrt(2.0));
  addFace(s, {1, 2, 4}, Vec3(1, 0, 0));
  addFace(s, {3, 0, 5}, Vec3(-1, 0, 0));
  addFace(s, {0, 3, 2, 1}, Vec3(0, 0, -1));
  return s;
}

// The needle of the issue: both roof faces run out along the ridge 1 m past its end, 1e-7 m
// above it, and back; each is simple in its plane, but both cover the needle's sliver, and the
// shell crosses itself there. The tip leaves both; the prism is left, 4 × 2 × 1 / 2 = 4 m³,
// each roof face 4 × √2 m².
TEST(ZipSpurs, ASpurBothFacesAcrossItRunIsZippedOutOfBoth) {
  const Vec3 tip(5, 1, 1 + 1e-7);
  SweepOutput s = gable(&tip, nullptr);
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_TRUE(simpleInItsPlane(s, s.faces[Front], s.faces[Front].loops[0]));
  ASSERT_TRUE(simpleInItsPlane(s, s.faces[Back], s.faces[Back].loops[0]));
  EXPECT_EQ(zipSpurs(s, 1e-6), 1u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(s.faces[Front].loops[0], (std::vector<int>{0, 1, 4, 5}));
  EXPECT_EQ(s.faces[Back].loops[0], (std::vector<int>{2, 3, 5, 4}));
  EXPECT_NEAR(faceArea(s, s.faces[Front]), 4 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(faceArea(s, s.faces[Back]), 4 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(measure(s).volume, 4.0, 1e-12);
}

// A corner of the ridge only the two roof faces pass, 1e-7 m above the straight ridge: both
// turn towards their inside there and both cover the sliver under it (the shell crosses
// itself); it leaves both, and the ridge is straight. 1e-7 m below, each face turns out, the
// shell has a dent of no width and does not cross itself, and the corner stays, as it does
// where it lies 1e-5 m above, wider than the width.
TEST(ZipSpurs, ACornerBothFacesCoverIsTakenOutOfBoth) {
  for (const double dz : {1e-7, -1e-7, 1e-5}) {
    const Vec3 bend(2, 1, 1 + dz);
    SweepOutput s = gable(nullptr, &bend);
    ASSERT_EQ(unpairedEdges(s), 0u);
    const bool folded = dz == 1e-7;
    EXPECT_EQ(zipSpurs(s, 1e-6), folded ? 1u : 0u) << dz;
    EXPECT_EQ(unpairedEdges(s), 0u);
    EXPECT_EQ(s.faces[Front].loops[0], folded ? (std::vector<int>{0, 1, 4, 5}) : (std::vector<int>{0, 1, 4, 6, 5}))
        << dz;
    EXPECT_EQ(s.faces[Back].loops[0], folded ? (std::vector<int>{2, 3, 5, 4}) : (std::vector<int>{2, 3, 5, 6, 4}))
        << dz;
  }
}

// Three perturbed plans from the random run whose shells crossed themselves where two faces
// covered one sliver. random20186 (one profile): a corner racing along a ridge overshot its
// end by 7 m, and both roof faces ran the needle. random25734: a spur of a face that was not
// simple was zipped into the face across, which then ran a spur a third face ran backwards
// (its sweep diverged and capped a loop of no area, and says so). random15864 (one profile):
// a ridge 7.5 m long over a strip 1.5 m wide has a corner 2.4 m along it that only its two
// roof faces pass, 1.3e-7 m above the line, and both cover the sliver under it. Each shell now
// passes the checks and holds its oracle's volume to 1e-6: CGAL's straight skeleton under the
// profile, or the unperturbed plan (random25734, roof area too).
TEST(ZipSpurs, AMirroredSpurAlongARidgeIsZipped) {
  expectCleanAndAgreeing("tests/data/extrude/spur_mirrored_along_a_ridge.corbel", VolumeOracle::Cgal);
}

TEST(ZipSpurs, ASpurMirroredByAnEarlierZipIsZipped) {
  expectCleanAndAgreeing("tests/data/extrude/spur_mirrored_after_a_zip.corbel", VolumeOracle::Unperturbed, true);
}

TEST(ZipSpurs, AFoldAlongARidgeIsTakenOut) {
  expectCleanAndAgreeing("tests/data/extrude/fold_along_a_ridge.corbel", VolumeOracle::Cgal);
}

// random88897: zipping a spur put a corner into the face across, where it left a fold of
// 3.7e-7 m with a third face along a ridge, the same sliver triangle in both faces' cuts. The
// clean-up zips again until nothing is left to zip, and the shell passes the shell checks.
TEST(ZipSpurs, AFoldAZipLeavesIsZippedInTheNextRound) { expectClean("tests/data/extrude/fold_left_by_a_zip.corbel"); }

// A 2 × 2 × 1 box whose front is two walls, W (x in [0, 1]) and V (x in [1, 2]), under one
// top R. W's top runs from its end (1, 0, 1) on past V's top to T = (2, 0, 1 + lift) and
// straight back to (0, 0, 1): a spur whose sides, V's top and R's front edge, lie lift / 2
// apart, with a different face across each. W's loop is simple in its plane, but its cut lays
// the spur's sliver along R's edge, and the shell touches itself there (random11920).
SweepOutput boxWithAWallTopPastItsEnd(double lift) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0),        Vec3(0, 2, 0),
              Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(2, 0, 1 + lift), Vec3(2, 2, 1), Vec3(0, 2, 1)};
  addFace(s, {0, 1, 6, 7, 5}, Vec3(0, -1, 0));  // W
  addFace(s, {1, 2, 7, 6}, Vec3(0, -1, 0));     // V
  addFace(s, {5, 7, 8, 9}, Vec3(0, 0, 1));      // R
  addFace(s, {2, 3, 8, 7}, Vec3(1, 0, 0));
  addFace(s, {3, 4, 9, 8}, Vec3(0, 1, 0));
  addFace(s, {4, 0, 5, 9}, Vec3(-1, 0, 0));
  addFace(s, {0, 4, 3, 2, 1}, Vec3(0, 0, -1));
  return s;
}

// Straight (its sides within the straight width, here 1e-8 for sides 5e-9 apart), the spur is
// zipped though W's loop is simple: T leaves W, and R takes W's top end (1, 0, 1) into its
// front edge, which V's top now meets. By hand: W is the unit square, R's area 4 (to the lift),
// and the box's volume 4.
TEST(ZipSpurs, AStraightSpurOfASimpleLoopIsZipped) {
  const double lift = 1e-8;
  SweepOutput s = boxWithAWallTopPastItsEnd(lift);
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_TRUE(simpleInItsPlane(s, s.faces[0], s.faces[0].loops[0]));
  EXPECT_EQ(zipSpurs(s, 1e-6, 1e-8), 1u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(s.faces[0].loops[0], (std::vector<int>{0, 1, 6, 5}));
  EXPECT_EQ(s.faces[2].loops[0], (std::vector<int>{5, 6, 7, 8, 9}));
  EXPECT_EQ(s.faces[1].loops[0], (std::vector<int>{1, 2, 7, 6})) << "V is unchanged";
  EXPECT_NEAR(faceArea(s, s.faces[0]), 1.0, 1e-12);
  EXPECT_NEAR(faceArea(s, s.faces[2]), 4.0, 4 * lift);
  EXPECT_NEAR(measure(s).volume, 4.0, 4 * lift);
}

// The straight width decides, as the width does for loops that are not simple: without it, or
// below the spur's width (sides 5e-9 apart, straight width 1e-9), a spur of a simple loop with a
// different face across each side stays.
TEST(ZipSpurs, ASpurOfASimpleLoopWiderThanStraightStays) {
  for (const double straight : {0.0, 1e-9}) {
    SweepOutput s = boxWithAWallTopPastItsEnd(1e-8);
    const std::vector<int> before = s.faces[0].loops[0];
    EXPECT_EQ(zipSpurs(s, 1e-6, straight), 0u) << straight;
    EXPECT_EQ(s.faces[0].loops[0], before) << straight;
  }
}

// Three perturbed orthogonal plans from the random run whose wall's top ran past its end and
// back, along the edge of a roof with no corner at that end: random11920 (1.5 m past, the
// sides 3e-8 m apart), random40645 (2.1e-7 m) and random73734 (3 m past, 5.4e-8 m). Zipped,
// each shell passes the shell checks.
TEST(ZipSpurs, AWallTopPastItsEndIsZipped) {
  expectClean("tests/data/extrude/wall_top_past_its_end.corbel");
  expectClean("tests/data/extrude/wall_top_past_its_end_too.corbel");
  expectClean("tests/data/extrude/wall_top_past_its_end_by_3_m.corbel");
}

}  // namespace
}  // namespace corbel::extrude::test
