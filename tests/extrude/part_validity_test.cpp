// A building checked in parts (extrude/part_validity.h) gets the report a Scene gives for the
// whole mesh, its shell and its features' parts appended as appendFeatures appends them: every
// count equal and the area and volume equal to the last bit (the same sums in the same order),
// for closed buildings and for the faults a part or the shell can have.
#include "core/scene.h"
#include "extrude/features.h"
#include "extrude/part_validity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace corbel::extrude::test {
namespace {

// The oracle: the whole mesh in a Scene of its own.
ValidityReport wholeReport(const MeshData& shell, const std::vector<PlacedFeature>& features) {
  MeshData all = shell;
  appendFeatures(all, features);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "b", all);
  return scene.validate(1);
}

// Equal to the last bit (NaN to NaN included).
bool sameBits(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

void expectSame(const ValidityReport& a, const ValidityReport& b) {
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.euler, b.euler);
  EXPECT_EQ(a.boundary_edges, b.boundary_edges);
  EXPECT_EQ(a.non_manifold_vertices, b.non_manifold_vertices);
  EXPECT_EQ(a.rejected_faces, b.rejected_faces);
  EXPECT_EQ(a.degenerate_faces, b.degenerate_faces);
  EXPECT_EQ(a.non_finite_points, b.non_finite_points);
  EXPECT_TRUE(sameBits(a.area, b.area)) << a.area << " " << b.area;
  EXPECT_TRUE(sameBits(a.volume, b.volume)) << a.volume << " " << b.volume;
  EXPECT_EQ(a.problems(), b.problems());
}

// An axis-aligned box, faces counter-clockwise from outside.
MeshData box(Vec3 lo, Vec3 hi) {
  MeshData m;
  for (int k = 0; k < 8; ++k) m.addPoint(Vec3(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]));
  for (const std::vector<int>& f : std::vector<std::vector<int>>{
           {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}})
    m.addFace(f);
  return m;
}

AnchorFrame frameAt(Vec3 at, Vec3 normal) {
  AnchorFrame f;
  f.instanced = true;
  f.position = at;
  f.normal = normal / normal.norm();
  f.along = Vec3(1, 0, 0);
  if (std::abs(f.normal[0]) > 0.9) f.along = Vec3(0, 1, 0);
  f.along -= f.normal * OpenMesh::dot(f.along, f.normal);
  f.along.normalize();
  f.up = OpenMesh::cross(f.normal, f.along);
  return f;
}

PlacedFeature feature(FeatureKind kind, FeatureSize size, const AnchorFrame& f) {
  return {featurePlacement(kind, size, f), featureParts(kind, size, f)};
}

// A house of 7.3 × 5.9 × 6.1 m off the origin, with a door and windows on its walls, a roof
// window on a sloped frame and a chimney pot on top: coordinates that round, so that sums in
// another order would differ in their last bits.
struct House {
  MeshData shell = box(Vec3(101.37, 57.11, 0.3), Vec3(108.67, 63.01, 6.4));
  std::vector<PlacedFeature> features;
  House() {
    features.push_back(feature(FeatureKind::Door, {1.03, 2.17, 0.13}, frameAt(Vec3(103.1, 57.11, 0.3), Vec3(0, -1, 0))));
    for (int i = 0; i < 4; ++i)
      features.push_back(feature(FeatureKind::Window, {0.93, 1.31, 0.11},
                                 frameAt(Vec3(101.9 + 1.7 * i, 63.01, 3.7), Vec3(0, 1, 0))));
    features.push_back(
        feature(FeatureKind::Window, {0.77, 1.13, 0.09}, frameAt(Vec3(108.67, 60.3, 1.9), Vec3(1, 0, 0))));
    features.push_back(
        feature(FeatureKind::RoofWindow, {0.71, 0.97, 0.07}, frameAt(Vec3(104.2, 60.4, 6.4), Vec3(0, -0.6, 0.8))));
    features.push_back(
        feature(FeatureKind::ChimneyPot, {0.31, 0.63, 0.31}, frameAt(Vec3(105.3, 61.2, 6.4), Vec3(0, 0.6, 0.8))));
  }
};

TEST(PartValidity, AHouseWithItsFeaturesGetsTheWholeMeshReport) {
  const House h;
  const ValidityReport whole = wholeReport(h.shell, h.features);
  expectSame(validateWithFeatures(h.shell, h.features, "b"), whole);
  // By hand: a box and 8 features of 2 or 3 closed parts (door 3, window 3, roof window 2,
  // pot 2): 1 + 3 + 5 × 3 + 2 + 2 = 23 pieces.
  EXPECT_EQ(whole.components, 23u);
  EXPECT_TRUE(whole.closedManifold());
  // And again, with every shape now known to the thread.
  expectSame(validateWithFeatures(h.shell, h.features, "b"), whole);
}

TEST(PartValidity, NoFeaturesIsTheShellAlone) {
  const House h;
  expectSame(validateWithFeatures(h.shell, {}, "b"), wholeReport(h.shell, {}));
}

TEST(PartValidity, ShellFacesAreCollapsedRelativeToTheWholeBox) {
  // A box 1e-10 m thick: its four sides have 1e-10 m² (or less), above 1e-14 × its own
  // diagonal² (2e-14) but below 1e-14 × the diagonal² of a box that reaches 1 km away (1e-8),
  // where a window stands.
  const MeshData slab = box(Vec3(0, 0, 0), Vec3(1, 1, 1e-10));
  const std::vector<PlacedFeature> far{
      feature(FeatureKind::Window, {1.2, 1.4, 0.12}, frameAt(Vec3(1000, 0, 0), Vec3(0, -1, 0)))};
  const ValidityReport whole = wholeReport(slab, far);
  EXPECT_EQ(whole.degenerate_faces, 4u);
  expectSame(validateWithFeatures(slab, far, "b"), whole);
  expectSame(validateWithFeatures(slab, {}, "b"), wholeReport(slab, {}));
  EXPECT_EQ(wholeReport(slab, {}).degenerate_faces, 0u);
}

TEST(PartValidity, APartWithAFaceMissingLeavesItsEdgesOpen) {
  House h;
  h.features[1].parts[0].faces.pop_back();  // a window frame without its last face
  const ValidityReport whole = wholeReport(h.shell, h.features);
  EXPECT_GT(whole.boundary_edges, 0u);
  EXPECT_FALSE(whole.closedManifold());
  expectSame(validateWithFeatures(h.shell, h.features, "b"), whole);
}

TEST(PartValidity, APartWithAFaceTwiceHasItRefused) {
  House h;
  h.features[2].parts[1].faces.push_back(h.features[2].parts[1].faces.front());
  const ValidityReport whole = wholeReport(h.shell, h.features);
  EXPECT_EQ(whole.rejected_faces, 1u);
  expectSame(validateWithFeatures(h.shell, h.features, "b"), whole);
}

TEST(PartValidity, APartCollapsedToAPointHasDegenerateFaces) {
  House h;
  for (Vec3& p : h.features[3].parts[2].points) p = Vec3(104, 63.01, 3);  // a sill squashed flat
  const ValidityReport whole = wholeReport(h.shell, h.features);
  EXPECT_EQ(whole.degenerate_faces, h.features[3].parts[2].faces.size());
  expectSame(validateWithFeatures(h.shell, h.features, "b"), whole);
}

TEST(PartValidity, NonFinitePointsInAPartOrTheShell) {
  House h;
  h.features[4].parts[0].points[2][1] = std::numeric_limits<double>::quiet_NaN();
  expectSame(validateWithFeatures(h.shell, h.features, "b"), wholeReport(h.shell, h.features));
  House g;
  g.shell.points[5][2] = std::numeric_limits<double>::infinity();
  const ValidityReport whole = wholeReport(g.shell, g.features);
  EXPECT_EQ(whole.non_finite_points, 1u);
  expectSame(validateWithFeatures(g.shell, g.features, "b"), whole);
}

}  // namespace
}  // namespace corbel::extrude::test
