// collapseShortEdges, mergeUntoldEdges and weldLoopCorners: vertices a rounding apart merged
// (docs/extrude.md).
#include "extrude/extrude.h"
#include "extrude/footprints.h"
#include "extrude/sweep.h"
#include "saved_plan_checks.h"
#include "shell_checks.h"
#include "support.h"
#include "volume_oracle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::extrude::test {
namespace {

// The unit cube, its top corner (1, 1, 1) doubled by a point `gap` away along −x: the top and
// back faces have five corners, joined by an edge `gap` long.
SweepOutput splitCube(double gap) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),      Vec3(0, 0, 1),
              Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1), Vec3(1 - gap, 1, 1)};
  auto face = [&](std::vector<int> loop, Vec3 n) { addFace(s, std::move(loop), n); };
  face({0, 3, 2, 1}, Vec3(0, 0, -1));
  face({4, 5, 6, 8, 7}, Vec3(0, 0, 1));
  face({0, 1, 5, 4}, Vec3(0, -1, 0));
  face({3, 7, 8, 6, 2}, Vec3(0, 1, 0));
  face({0, 4, 7, 3}, Vec3(-1, 0, 0));
  face({1, 2, 6, 5}, Vec3(1, 0, 0));
  return s;
}

TEST(CollapseShortEdges, MergesTheEndsOfAnEdgeShorterThanTheLengthAndKeepsTheShellClosed) {
  SweepOutput s = splitCube(1e-9);
  ASSERT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(collapseShortEdges(s, 1e-8), 1u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 6u);
  for (const ShellFace& f : s.faces) EXPECT_EQ(f.loops[0].size(), 4u) << "every face of a cube is a quad";
  EXPECT_NEAR(measure(s).volume, 1.0, 1e-8);
}

TEST(CollapseShortEdges, LeavesLongerEdgesAlone) {
  SweepOutput s = splitCube(1e-6);
  EXPECT_EQ(collapseShortEdges(s, 1e-8), 0u);
  EXPECT_EQ(s.faces[1].loops[0].size(), 5u);
}

// A sliver triangle between the two doubled corners: collapsing its short edge removes it, and
// the faces around still pair.
TEST(CollapseShortEdges, DropsAFaceThatVanishes) {
  SweepOutput s = splitCube(1e-9);
  // Replace the back face's piece 8 → 6 by a detour through a third point on a triangle face.
  s.points.push_back(Vec3(1 - 0.5e-9, 1, 1 + 0.5e-9));  // 9
  s.faces[3].loops[0] = {3, 7, 8, 9, 6, 2};
  ShellFace tri;
  tri.loops = {{8, 6, 9}};
  tri.normal = Vec3(0, 1, 0);  // nominal: the sliver stands in the back plane
  s.faces.push_back(tri);
  ASSERT_EQ(unpairedEdges(s), 0u);
  EXPECT_GE(collapseShortEdges(s, 1e-8), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(s.faces.size(), 6u) << "the sliver is gone";
}

// The cube with its corner (1, 1, 1) cut off by a triangle `cut` across: within tinyFace the
// triangle becomes a point again, and the cube is whole.
TEST(CollapseShortEdges, ATinyFaceBecomesAPoint) {
  const double cut = 1e-7;
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0),       Vec3(1, 1, 0),       Vec3(0, 1, 0),       Vec3(0, 0, 1),
              Vec3(1, 0, 1), Vec3(1 - cut, 1, 1), Vec3(1, 1 - cut, 1), Vec3(1, 1, 1 - cut), Vec3(0, 1, 1)};
  auto face = [&](std::vector<int> loop, Vec3 n) { addFace(s, std::move(loop), n); };
  face({0, 3, 2, 1}, Vec3(0, 0, -1));
  face({4, 5, 7, 6, 9}, Vec3(0, 0, 1));
  face({0, 1, 5, 4}, Vec3(0, -1, 0));
  face({3, 9, 6, 8, 2}, Vec3(0, 1, 0));
  face({0, 4, 9, 3}, Vec3(-1, 0, 0));
  face({1, 2, 8, 7, 5}, Vec3(1, 0, 0));
  face({6, 7, 8}, Vec3(1, 1, 1) / std::sqrt(3.0));
  ASSERT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(collapseShortEdges(s, 1e-9), 0u) << "no edge is that short";
  EXPECT_EQ(collapseShortEdges(s, 1e-9, 1e-6), 2u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 6u);
  for (const ShellFace& f : s.faces) EXPECT_EQ(f.loops[0].size(), 4u);
  EXPECT_NEAR(measure(s).volume, 1.0, 1e-6);
}

// The cube standing on its base face, a vertex `h` above its base corner (1, 1, 0) on the
// vertical edge there (the right and back faces pass through it). Within baseHeight of the base
// it is the corner's; higher, it stays a vertex of its own, however short the edge: taking the
// corner's place, an event a little above the base would lay the faces through it on the base
// (random3091, docs/extrude.md).
TEST(CollapseShortEdges, KeepsAVertexAboveTheBaseOffTheBasesCorners) {
  const double h = 1e-9;
  auto cube = [&] {
    SweepOutput s;
    s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1), Vec3(1, 1, h)};
    auto face = [&](std::vector<int> loop, Vec3 n) { addFace(s, std::move(loop), n); };
    face({0, 3, 2, 1}, Vec3(0, 0, -1));
    s.faces.back().base = true;
    face({4, 5, 6, 7}, Vec3(0, 0, 1));
    face({0, 1, 5, 4}, Vec3(0, -1, 0));
    face({3, 7, 6, 8, 2}, Vec3(0, 1, 0));
    face({0, 4, 7, 3}, Vec3(-1, 0, 0));
    face({1, 2, 8, 6, 5}, Vec3(1, 0, 0));
    return s;
  };
  SweepOutput above = cube();
  ASSERT_EQ(unpairedEdges(above), 0u);
  EXPECT_EQ(collapseShortEdges(above, 1e-8, 0, 0.5 * h), 0u) << "h is above the base's height tolerance";
  EXPECT_EQ(above.faces[3].loops[0].size(), 5u);
  EXPECT_EQ(above.points[8], Vec3(1, 1, h));
  SweepOutput within = cube();
  EXPECT_EQ(collapseShortEdges(within, 1e-8, 0, 2 * h), 1u) << "h is within the base's height tolerance";
  EXPECT_EQ(unpairedEdges(within), 0u);
  for (const ShellFace& f : within.faces) EXPECT_EQ(f.loops[0].size(), 4u) << "every face of a cube is a quad";
  EXPECT_EQ(within.points[2], Vec3(1, 1, 0)) << "the base corner stays where it is";
}

// The unit cube, its top split at x = 0.5 into F (left) and G (right), where G's side along the
// back runs from its corner m' = (0.5 + gap, 1, 1) along the back edge to t = (0.25, 1, 1) and
// back to m = (0.5, 1, 1), the corner F, G and the back share: a spur `gap` wide whose two sides
// have different faces across (the back, then F). m and m' are two vertices, not one edge.
enum TopFaces { F = 1, G = 2 };
SweepOutput cubeWithARidgeSpur(double gap) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),   Vec3(0, 1, 0), Vec3(0, 0, 1),         Vec3(0.5, 0, 1),
              Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0.5, 1, 1), Vec3(0, 1, 1), Vec3(0.5 + gap, 1, 1), Vec3(0.25, 1, 1)};
  enum { m = 8, m2 = 10, t = 11 };
  auto face = [&](std::vector<int> loop, Vec3 n) { addFace(s, std::move(loop), n); };
  face({0, 3, 2, 1}, Vec3(0, 0, -1));
  face({4, 5, m, t, 9}, Vec3(0, 0, 1));      // F
  face({5, 6, 7, m2, t, m}, Vec3(0, 0, 1));  // G
  face({0, 1, 6, 5, 4}, Vec3(0, -1, 0));
  face({2, 3, 9, t, m2, 7}, Vec3(0, 1, 0));  // the back
  face({3, 0, 4, 9}, Vec3(-1, 0, 0));
  face({1, 2, 7, 6}, Vec3(1, 0, 0));
  return s;
}

// Welded, m and m' are one vertex: G's spur, now of no width, leaves it (G is the quad
// 0.5 × 1 again), F and the back meet along m–t, and the cube is closed, every face simple, of
// volume 1 to the rounding the weld moved.
TEST(WeldLoopCorners, TwoCornersOfALoopARoundingApartBecomeOneAndTheSpurBetweenGoes) {
  SweepOutput s = cubeWithARidgeSpur(1e-7);
  ASSERT_EQ(unpairedEdges(s), 0u);
  ASSERT_FALSE(simpleInItsPlane(s, s.faces[G], s.faces[G].loops[0]));
  EXPECT_EQ(collapseShortEdges(s, 1e-6), 0u) << "m and m' are not joined by an edge";
  EXPECT_EQ(weldLoopCorners(s, 1e-6), 1u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  ASSERT_EQ(s.faces.size(), 7u);
  EXPECT_EQ(s.faces[G].loops[0].size(), 4u);
  EXPECT_NEAR(faceArea(s, s.faces[G]), 0.5, 1e-6);
  EXPECT_EQ(s.faces[F].loops[0].size(), 5u) << "t stays a corner of F, in line with m and (0, 1, 1)";
  for (const ShellFace& f : s.faces) EXPECT_TRUE(simpleInItsPlane(s, f, f.loops[0]));
  EXPECT_NEAR(measure(s).volume, 1.0, 1e-6);
}

// Corners farther apart than the length stay; so do a loop's neighbours, however close (they
// are collapseShortEdges' to merge).
TEST(WeldLoopCorners, LeavesCornersFartherApartAndNeighboursAlone) {
  SweepOutput far = cubeWithARidgeSpur(1e-5);
  EXPECT_EQ(weldLoopCorners(far, 1e-6), 0u);
  EXPECT_EQ(far.faces[G].loops[0].size(), 6u);
  SweepOutput cube = splitCube(1e-9);
  EXPECT_EQ(weldLoopCorners(cube, 1e-8), 0u);
  EXPECT_EQ(cube.faces[1].loops[0].size(), 5u);
}

// The unit cube with its top in two faces, F (x < 1/2) and G (x > 1/2), that meet the back's
// top edge at c = (1/2, 1, 1) and c' = (1/2 + e, 1, 1 + h): G runs c' → c along the back, and
// the back takes both into its top. With h = 0 every face through c or c' holds the line
// through them (the top, the back): none tells them apart.
enum { kCupTop = 1, kCupG = 2, kCupBack = 4 };
SweepOutput cubeWithATwiceMadeNode(double e, double h) {
  SweepOutput s;
  s.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),   Vec3(0, 1, 0),   Vec3(0, 0, 1),          Vec3(1, 0, 1),
              Vec3(1, 1, 1), Vec3(0, 1, 1), Vec3(0.5, 0, 1), Vec3(0.5, 1, 1), Vec3(0.5 + e, 1, 1 + h)};
  auto face = [&](std::vector<int> loop, Vec3 n) { addFace(s, std::move(loop), n); };
  face({0, 3, 2, 1}, Vec3(0, 0, -1));
  face({4, 8, 9, 7}, Vec3(0, 0, 1));      // F
  face({8, 5, 6, 10, 9}, Vec3(0, 0, 1));  // G
  face({0, 1, 5, 8, 4}, Vec3(0, -1, 0));
  face({3, 7, 9, 10, 6, 2}, Vec3(0, 1, 0));  // the back
  face({0, 4, 7, 3}, Vec3(-1, 0, 0));
  face({1, 2, 6, 5}, Vec3(1, 0, 0));
  return s;
}

// c and c', 1e-6 apart in line, are one vertex: G and the back lose a corner, the cube stays
// closed, and it holds 1 m³ exactly (no face moved off its plane).
TEST(MergeUntoldEdges, MergesAShortEdgeNoFaceThroughItsEndsTellsApart) {
  SweepOutput s = cubeWithATwiceMadeNode(1e-6, 0);
  ASSERT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(collapseShortEdges(s, 1e-7), 0u) << "longer than the collapse length";
  EXPECT_EQ(mergeUntoldEdges(s, 1e-5, 1e-8), 1u);
  EXPECT_EQ(unpairedEdges(s), 0u);
  EXPECT_EQ(s.faces[kCupG].loops[0].size(), 4u);
  EXPECT_EQ(s.faces[kCupBack].loops[0].size(), 5u);
  for (const ShellFace& f : s.faces) EXPECT_TRUE(simpleInItsPlane(s, f, f.loops[0]));
  EXPECT_NEAR(measure(s).volume, 1.0, 1e-15);
}

// A face that tells the ends apart keeps them: c' 1e-6 above the top (off G's plane), or the
// cube's corner (1, 1, 1) and the point 1e-6 from it along the back's top (off the right
// face's plane, x = 1). So does an edge longer than the length, and a shell that is not closed.
TEST(MergeUntoldEdges, LeavesEndsAFaceTellsApartLongerEdgesAndOpenShells) {
  SweepOutput raised = cubeWithATwiceMadeNode(1e-6, 1e-6);
  EXPECT_EQ(mergeUntoldEdges(raised, 1e-5, 1e-8), 0u);
  EXPECT_EQ(raised.faces[kCupG].loops[0].size(), 5u);
  SweepOutput corner = splitCube(1e-6);
  EXPECT_EQ(mergeUntoldEdges(corner, 1e-5, 1e-8), 0u);
  EXPECT_EQ(corner.faces[1].loops[0].size(), 5u);
  SweepOutput longer = cubeWithATwiceMadeNode(1e-4, 0);
  EXPECT_EQ(mergeUntoldEdges(longer, 1e-5, 1e-8), 0u);
  SweepOutput open = cubeWithATwiceMadeNode(1e-6, 0);
  open.faces.erase(open.faces.begin());
  EXPECT_EQ(mergeUntoldEdges(open, 1e-5, 1e-8), 0u);
  EXPECT_EQ(open.faces[kCupG - 1].loops[0].size(), 5u);
}

// osm:w177178374#0, a garage whose front bends 4e-5 rad at a corner, under a 45° hip roof:
// the ridge's node above that corner was made twice, 4.4e-6 m apart along the ridge, and the
// back roof's exported cut spanned the ridge with a sliver the front faces' triangles crossed.
// Merged, the shell passes the shell checks (CGAL's exact predicates over the exported
// triangles) and holds CGAL's skeleton's volume.
TEST(MergeUntoldEdges, AGaragesRidgeNodeMadeTwiceIsOne) {
  const auto fps = readGeoJsonFile(std::string(CORBEL_SOURCE_DIR) + "/tests/data/extrude/moosburg_w177178374.geojson");
  ASSERT_EQ(fps.size(), 1u);
  ExtrusionSpec spec;
  spec.profiles = {hipProfile(45 * kDeg)};
  spec.loops.push_back({fps[0].loops[0], std::vector<int>(fps[0].loops[0].size(), 0)});
  const ExtrusionResult r = extrude(spec);
  EXPECT_EQ(unpairedEdges(r.shell), 0u);
  EXPECT_EQ(shellGeometryProblem(r.shell, spec), "");
  const VolumeOracle o = independentVolume(spec);
  ASSERT_EQ(o.kind, VolumeOracle::Cgal);
  EXPECT_NEAR(measure(r.shell).volume, o.volume, 1e-6 * o.volume);
}

// random18359, a perturbed regular polygon whose corners reach its apex within 1.3e-6 m of one
// another: merged where no face tells them apart, the apex's triangles no longer cross.
TEST(MergeUntoldEdges, CornersAtAnApexNoFaceTellsApartAreOne) {
  expectClean("tests/data/extrude/untold_corners_at_an_apex.corbel");
}

}  // namespace
}  // namespace corbel::extrude::test
