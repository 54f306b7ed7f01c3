// The features of Sec. 3 with hand-computed expectations (10 m × 6 m rectangle unless said):
// gable and shed (vertical edges), walls under a hip, mansard and gambrel (edge direction
// events, Sec. 4.5.1).
#include "core/scene.h"
#include "support.h"

#include <gtest/gtest.h>

#include <map>

namespace corbel::extrude::test {
namespace {

Profile polyline(std::vector<Vec2> pts, std::vector<std::string> tags = {}) {
  Profile p;
  p.name = "p" + std::to_string(pts.size());
  p.points = std::move(pts);
  p.tags = std::move(tags);
  return p;
}
const Profile kVertical = polyline({{0, 0}, {0, 1}}, {"gable"});

// Edges of rectangle(10, 6): 0 bottom (y = 0), 1 right, 2 top, 3 left.
ExtrusionSpec rectangleWith(const std::vector<Profile>& profiles, std::vector<int> perEdge) {
  ExtrusionSpec s;
  s.profiles = profiles;
  s.loops.push_back({rectangle(10, 6), std::move(perEdge)});
  return s;
}

struct Checked {
  ShellMeasures m;
  ValidityReport v;
  std::size_t faces;
};

Checked run(const ExtrusionSpec& spec) {
  const ExtrusionResult r = extrude(spec);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << "warning: " << w;
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "plaster"));
  Checked c{measure(r.shell), scene.validate(1), r.shell.faces.size()};
  for (const auto& p : c.v.problems()) ADD_FAILURE() << p;
  EXPECT_EQ(c.v.euler, 2);
  EXPECT_NEAR(c.v.volume, c.m.volume, 1e-9 * c.m.volume) << "Scene and kernel agree on the volume";
  return c;
}

TEST(Features, GableHasVerticalTriangularEnds) {
  const Checked c = run(rectangleWith({hipProfile(45 * kDeg), kVertical}, {0, 1, 0, 1}));
  EXPECT_NEAR(c.m.maxHeight, 3.0, 1e-12);
  EXPECT_NEAR(c.m.volume, 10 * (6 * 3 / 2.0), 1e-9);     // prism of the triangular section
  EXPECT_NEAR(c.m.roofArea, 2 * 10 * 3 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(c.m.wallArea, 2 * (6 * 3 / 2.0), 1e-9);    // two gable triangles
  EXPECT_EQ(c.faces, 5u);
}

TEST(Features, ShedRisesToTheOppositeWall) {
  const Checked c = run(rectangleWith({hipProfile(60 * kDeg), kVertical}, {0, 1, 1, 1}));
  // The sloped edge (pitch 60° from horizontal) travels the 6 m to the opposite wall.
  const double rise = 6 * std::tan(60 * kDeg);
  EXPECT_NEAR(c.m.maxHeight, rise, 1e-9 * rise);
  EXPECT_NEAR(c.m.volume, 10 * 6 * rise / 2, 1e-9 * 10 * 6 * rise);
  EXPECT_NEAR(c.m.roofArea, 10 * 6 / std::cos(60 * kDeg), 1e-9 * 120);
  EXPECT_NEAR(c.m.wallArea, 10 * rise + 2 * (6 * rise / 2), 1e-9 * 10 * rise);
  EXPECT_EQ(c.faces, 5u);
}

TEST(Features, WallsUnderAHipRoof) {
  const Checked c = run(rectangleWith({wallAndRoofProfile(3.0, 45 * kDeg)}, {0, 0, 0, 0}));
  EXPECT_NEAR(c.m.maxHeight, 6.0, 1e-12);
  EXPECT_NEAR(c.m.volume, 10 * 6 * 3 + 72, 1e-9);
  EXPECT_NEAR(c.m.wallArea, 2 * (10 + 6) * 3, 1e-9);
  EXPECT_NEAR(c.m.roofArea, 60 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(c.faces, 9u);  // 4 walls, 4 roof faces, the base
}

// Mansard: steep (run 1 over rise 2) then shallow (run 2 over rise 1). At z = 2 the plan is
// 8 × 4; the frustum below holds h/6·(A0 + 4·Am + A1) = 2/6·(60 + 4·45 + 32) and the hip of
// slope ½ on 8 × 4 holds ½·b²(3a − b)/12 = ½·16·20/12.
TEST(Features, MansardChangesDirectionOnEveryEdge) {
  const Checked c = run(rectangleWith({polyline({{0, 0}, {1, 2}, {3, 3}})}, {0, 0, 0, 0}));
  EXPECT_NEAR(c.m.maxHeight, 3.0, 1e-12);
  EXPECT_NEAR(c.m.volume, 2.0 / 6 * (60 + 180 + 32) + 0.5 * 16 * 20 / 12, 1e-9);
  EXPECT_EQ(c.faces, 9u);
}

// Gambrel: the mansard profile on the long sides, vertical ends. Section: a trapezoid
// (6 → 4 wide, 2 high) under a triangle (4 wide, 1 high): 10 + 2 = 12 m², times 10 m.
TEST(Features, GambrelIsAMansardWithGableEnds) {
  const Checked c = run(rectangleWith({polyline({{0, 0}, {1, 2}, {3, 3}}), kVertical}, {0, 1, 0, 1}));
  EXPECT_NEAR(c.m.maxHeight, 3.0, 1e-12);
  EXPECT_NEAR(c.m.volume, 120.0, 1e-9);
  EXPECT_EQ(c.faces, 7u);  // two faces per long side, one per end, the base
}

// Tags on profile segments reach the Scene's faces.
TEST(Features, ProfileTagsReachTheScene) {
  const ExtrusionSpec spec = rectangleWith({polyline({{0, 0}, {0, 2.5}, {4, 6.5}}, {"render", "tiles"})}, {0, 0, 0, 0});
  const ExtrusionResult r = extrude(spec);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "plaster"));
  std::map<std::string, int> count;
  for (auto f : scene.faces(1)) ++count[scene.faceTag(f)];
  EXPECT_EQ(count["render"], 4);
  EXPECT_EQ(count["tiles"], 4);
  EXPECT_EQ(count["base"], 1);
}

// A roof material colours exactly the faces that lean inward.
TEST(Features, RoofMaterialGoesToInwardFaces) {
  ExtrusionSpec spec = rectangleWith({wallAndRoofProfile(3.0, 40 * kDeg)}, {0, 0, 0, 0});
  spec.roofMaterial = "roof_tile";
  const ExtrusionResult r = extrude(spec);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "brick"));
  std::map<std::string, int> count;
  for (auto f : scene.faces(1)) ++count[scene.faceTag(f) + "/" + scene.faceMaterial(f)];
  EXPECT_EQ(count["roof/roof_tile"], 4);
  EXPECT_EQ(count["wall/brick"], 4);
  EXPECT_EQ(count["base/brick"], 1);
}

// Eight faces meeting at one point on a symmetrical footprint (Fig. 23): a regular octagon's
// planes all meet at the apex, height r·cos(π/8)·tan φ.
TEST(Features, EightFacesMeetAtOnePoint) {
  const auto spec = uniformSpec({regularPolygon(8, 5.0)}, hipProfile(40 * kDeg));
  const Checked c = run(spec);
  const double apothem = 5.0 * std::cos(std::numbers::pi / 8);
  EXPECT_NEAR(c.m.maxHeight, apothem * std::tan(40 * kDeg), 1e-9);
  EXPECT_EQ(c.v.vertices, 9u);  // eight corners and one apex
}

// A curved plan (a 64-gon circle of radius 8 with a 4 m wall): a cone-like roof whose apex
// is at the apothem's height.
TEST(Features, CurvedPlan) {
  const auto spec = uniformSpec({regularPolygon(64, 8.0)}, wallAndRoofProfile(4.0, 35 * kDeg));
  const Checked c = run(spec);
  const double apothem = 8.0 * std::cos(std::numbers::pi / 64);
  EXPECT_NEAR(c.m.maxHeight, 4.0 + apothem * std::tan(35 * kDeg), 1e-9);
  EXPECT_EQ(c.faces, 129u);
}

// The export option: under a short stem, the two bar edges of a T come to share a line and
// their faces meet in one roof plane; merged, they are one face and the shell is the same
// solid (closed, same volume).
TEST(Features, CoplanarMergeIsAnExportOption) {
  const std::vector<Vec2> t = {{0, 5}, {4, 5}, {4, 6}, {10, 6}, {10, 14}, {-6, 14}, {-6, 6}, {0, 6}};
  ExtrusionSpec spec = uniformSpec({t}, hipProfile(45 * kDeg));
  const ExtrusionResult r = extrude(spec);
  const MeshData plain = toMeshData(r.shell, spec, "plaster");
  const MeshData merged = toMeshData(r.shell, spec, "plaster", true);
  EXPECT_EQ(plain.faces.size(), r.shell.faces.size());
  EXPECT_EQ(merged.faces.size(), plain.faces.size() - 1) << "the two bar faces of the T's top";
  Scene a, b;
  a.replaceObject(1, Kind::Shell, "plain", plain);
  b.replaceObject(1, Kind::Shell, "merged", merged);
  const ValidityReport va = a.validate(1), vb = b.validate(1);
  EXPECT_TRUE(vb.problems().empty());
  EXPECT_EQ(vb.euler, 2);
  EXPECT_NEAR(vb.volume, va.volume, 1e-9 * va.volume);
}

}  // namespace
}  // namespace corbel::extrude::test
