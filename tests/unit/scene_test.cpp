// scene.h: topology and measures from Scene::validate against hand-computed solids, and the
// bookkeeping of objects and per-face properties across replace, remove and copy.
#include "core/scene.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <thread>
#include <tuple>

namespace {

using corbel::Kind;
using corbel::MeshData;
using corbel::ObjectId;
using corbel::Scene;
using corbel::ValidityReport;
using corbel::Vec3;
using corbel::test::handBox;

MeshData reversedFaces(MeshData m) {
  for (auto& f : m.faces) std::reverse(f.begin(), f.end());
  return m;
}

// Torus from an n x m quad grid (u around the Z axis, v around the tube), outward-facing.
MeshData torus(int n, int m, double R, double r) {
  MeshData out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      out.addPoint(Vec3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  auto at = [&](int i, int j) { return ((i % n) * m) + (j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) out.addFace({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return out;
}

// What one face looks like, independent of handles: object, kind, tag, material and its
// corner positions starting at the smallest one (order preserved).
struct FaceDesc {
  ObjectId object;
  Kind kind;
  std::string tag, material;
  std::vector<std::tuple<double, double, double>> corners;
  auto operator<=>(const FaceDesc&) const = default;
};

std::multiset<FaceDesc> describe(const Scene& s, ObjectId id) {
  std::multiset<FaceDesc> out;
  for (auto f : s.faces(id)) {
    FaceDesc d{s.faceObject(f), s.faceKind(f), s.faceTag(f), s.faceMaterial(f), {}};
    for (auto v : s.mesh().fv_range(f)) {
      const Vec3& p = s.mesh().point(v);
      d.corners.emplace_back(p[0], p[1], p[2]);
    }
    std::rotate(d.corners.begin(), std::min_element(d.corners.begin(), d.corners.end()), d.corners.end());
    out.insert(std::move(d));
  }
  return out;
}

void expectClosedBox(const ValidityReport& r, double a, double b, double c) {
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 12u);
  EXPECT_EQ(r.faces, 6u);
  EXPECT_EQ(r.euler, 2);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 0u);
  EXPECT_EQ(r.rejected_faces, 0u);
  EXPECT_EQ(r.degenerate_faces, 0u);
  EXPECT_EQ(r.non_finite_points, 0u);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistent());
  EXPECT_TRUE(r.closedManifold());
  EXPECT_TRUE(r.problems().empty());
  const double volume = a * b * c, area = 2 * (a * b + b * c + c * a);
  EXPECT_NEAR(r.volume, volume, 1e-12 * volume);
  EXPECT_NEAR(r.area, area, 1e-12 * area);
}

TEST(Scene, UnitCubeIsAClosedManifold) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "cube", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  expectClosedBox(s.validate(1), 1, 1, 1);
  EXPECT_DOUBLE_EQ(s.validate(1).volume, 1.0);
  EXPECT_DOUBLE_EQ(s.validate(1).area, 6.0);
}

TEST(Scene, RectangularBoxesHaveAnalyticVolumeAndArea) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "a", handBox(Vec3(-1, 2, 0.5), Vec3(1, 5, 5.5)));             // 2 x 3 x 5
  s.replaceObject(2, Kind::Block, "b", handBox(Vec3(100, -7, -3), Vec3(100.25, -6.5, 9.75)));  // .25 x .5 x 12.75
  expectClosedBox(s.validate(1), 2, 3, 5);
  expectClosedBox(s.validate(2), 0.25, 0.5, 12.75);
}

TEST(Scene, BoxMissingAFaceHasFourBoundaryEdges) {
  MeshData m = handBox(Vec3(0, 0, 0), Vec3(2, 3, 4));
  m.faces.pop_back();
  m.faceTag.pop_back();
  m.faceMaterial.pop_back();
  Scene s;
  s.replaceObject(7, Kind::Mass, "open", m);
  const ValidityReport r = s.validate(7);
  EXPECT_EQ(r.faces, 5u);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 12u);
  EXPECT_EQ(r.euler, 1);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_FALSE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_FALSE(r.closedManifold());
  EXPECT_NEAR(r.area, 2 * (6 + 12 + 8) - 12, 1e-12);
  EXPECT_FALSE(r.problems().empty());
}

TEST(Scene, ReversedBoxHasNegativeVolumeAndIsNotConsistent) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "inside out", reversedFaces(handBox(Vec3(0, 0, 0), Vec3(2, 3, 4))));
  const ValidityReport r = s.validate(1);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_NEAR(r.volume, -24.0, 1e-12);
  EXPECT_FALSE(r.consistent());
  EXPECT_FALSE(r.closedManifold());
  EXPECT_FALSE(r.problems().empty());
}

TEST(Scene, TorusHasEulerCharacteristicZero) {
  for (auto [n, m] : {std::pair{3, 3}, std::pair{8, 5}, std::pair{64, 32}}) {
    SCOPED_TRACE(std::to_string(n) + "x" + std::to_string(m));
    const double R = 3.0, r = 1.0;
    Scene s;
    s.replaceObject(1, Kind::Ornament, "torus", torus(n, m, R, r));
    const ValidityReport rep = s.validate(1);
    EXPECT_EQ(rep.vertices, static_cast<std::size_t>(n * m));
    EXPECT_EQ(rep.edges, static_cast<std::size_t>(2 * n * m));
    EXPECT_EQ(rep.faces, static_cast<std::size_t>(n * m));
    EXPECT_EQ(rep.euler, 0);
    EXPECT_EQ(rep.components, 1u);
    EXPECT_TRUE(rep.watertight());
    EXPECT_TRUE(rep.manifold());
    EXPECT_GT(rep.volume, 0.0);  // outward-facing
    if (n == 64) {
      // Fine grid: close to the solid torus 2 pi^2 R r^2 (discretisation error ~ (pi/m)^2).
      EXPECT_NEAR(rep.volume / (2 * std::numbers::pi * std::numbers::pi * R * r * r), 1.0, 0.03);
    }
  }
}

TEST(Scene, ThreeFacesOnOneEdgeAreRejected) {
  MeshData m;
  const int a = m.addPoint(Vec3(0, 0, 0)), b = m.addPoint(Vec3(1, 0, 0));
  const int c = m.addPoint(Vec3(0.5, 1, 0)), d = m.addPoint(Vec3(0.5, -1, 0)), e = m.addPoint(Vec3(0.5, 0, 1));
  m.addFace({a, b, c});
  m.addFace({b, a, d});
  m.addFace({a, b, e});  // a third face on edge a-b
  Scene s;
  s.replaceObject(1, Kind::Mass, "fin", m);
  const ValidityReport r = s.validate(1);
  EXPECT_GT(r.rejected_faces, 0u);
  EXPECT_EQ(r.faces + r.rejected_faces, 3u);
  EXPECT_FALSE(r.manifold());
  EXPECT_FALSE(r.watertight());
  EXPECT_EQ(s.objects().at(1).rejected_faces, r.rejected_faces);
}

TEST(Scene, FacesWithBadIndicesAreRejectedAndUnusedPointsDropped) {
  MeshData m = handBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  m.addPoint(Vec3(50, 50, 50));  // used by no face
  m.addFace({0, 1, 99});         // out of range
  m.addFace({0, -1, 2});         // negative
  m.addFace({0, 1});             // too short
  Scene s;
  s.replaceObject(1, Kind::Mass, "cube", m);
  const ValidityReport r = s.validate(1);
  EXPECT_EQ(r.rejected_faces, 3u);
  EXPECT_EQ(r.faces, 6u);
  EXPECT_EQ(s.mesh().n_vertices(), 8u);
  EXPECT_EQ(s.bounds(1).hi, Vec3(1, 1, 1));
}

TEST(Scene, NonFinitePointsAreCounted) {
  MeshData m = handBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  m.points[3][1] = std::numeric_limits<double>::quiet_NaN();
  m.points[5][2] = std::numeric_limits<double>::infinity();
  Scene s;
  s.replaceObject(1, Kind::Mass, "bad", m);
  const ValidityReport r = s.validate(1);
  EXPECT_EQ(r.non_finite_points, 2u);
  EXPECT_FALSE(r.consistent());
  EXPECT_FALSE(r.closedManifold());
  EXPECT_FALSE(r.problems().empty());
}

TEST(Scene, ZeroAreaFaceIsDegenerate) {
  MeshData m = handBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  // A separate sliver whose three points lie on a line.
  const int a = m.addPoint(Vec3(3, 0, 0)), b = m.addPoint(Vec3(4, 1, 1)), c = m.addPoint(Vec3(5, 2, 2));
  m.addFace({a, b, c});
  Scene s;
  s.replaceObject(1, Kind::Mass, "sliver", m);
  const ValidityReport r = s.validate(1);
  EXPECT_EQ(r.degenerate_faces, 1u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_FALSE(r.consistent());
}

// A face much smaller than its object is still a face: the extrusion kernel's natural steps
// leave soffits 1e-5 of the plan's size across. Only a collapse below 1e-14 s² (s the object's
// diagonal) counts as zero area.
TEST(Scene, TinyButRealFacesAreNotDegenerate) {
  for (const double leg : {1e-5, 1e-8}) {
    MeshData m = handBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
    const int a = m.addPoint(Vec3(0.5, 0.5, 2)), b = m.addPoint(Vec3(0.5 + leg, 0.5, 2)), c = m.addPoint(Vec3(0.5, 0.5 + leg, 2));
    m.addFace({a, b, c});
    Scene s;
    s.replaceObject(1, Kind::Mass, "speck", m);
    const ValidityReport r = s.validate(1);
    const double scale = std::sqrt(1.0 + 1.0 + 4.0);  // the bounding box (0,0,0)–(1,1,2)
    SCOPED_TRACE(leg);
    EXPECT_EQ(r.degenerate_faces, 0.5 * leg * leg > 1e-14 * scale * scale ? 0u : 1u);
  }
}

TEST(Scene, CollapsedBoxFacesAreDegenerate) {
  // A box of zero height: top and bottom coincide, every wall has zero area.
  Scene s;
  s.replaceObject(1, Kind::Mass, "flat", handBox(Vec3(0, 0, 0), Vec3(2, 3, 0)));
  const ValidityReport r = s.validate(1);
  EXPECT_EQ(r.degenerate_faces, 4u);
  EXPECT_NEAR(r.volume, 0.0, 1e-12);
  EXPECT_NEAR(r.area, 12.0, 1e-12);
}

TEST(Scene, ValidateOfAnUnknownObjectIsEmpty) {
  Scene s;
  const ValidityReport r = s.validate(42);
  EXPECT_EQ(r.faces, 0u);
  EXPECT_FALSE(r.problems().empty());  // "no faces"
}

TEST(Scene, ReplaceObjectLeavesOtherObjectsIntact) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1), "stone", "wall"));
  s.replaceObject(2, Kind::Shell, "two", handBox(Vec3(5, 0, 0), Vec3(7, 2, 3), "brick", "roofline"));
  s.replaceObject(3, Kind::Site, "three", handBox(Vec3(-9, -9, -1), Vec3(9, 9, 0), "grass", "ground"));
  const auto before1 = describe(s, 1), before3 = describe(s, 3);
  ASSERT_EQ(before1.size(), 6u);
  ASSERT_EQ(before3.size(), 6u);
  EXPECT_EQ(before1.begin()->material, "stone");
  EXPECT_EQ(before3.begin()->kind, Kind::Site);

  // Replace the middle object with something of a different size (forces garbage collection
  // and moves the handles of the faces behind it).
  s.replaceObject(2, Kind::Block, "two again", torus(6, 4, 3, 1));
  EXPECT_EQ(describe(s, 1), before1);
  EXPECT_EQ(describe(s, 3), before3);
  EXPECT_EQ(s.faces(2).size(), 24u);
  for (auto f : s.faces(2)) {
    EXPECT_EQ(s.faceKind(f), Kind::Block);
    EXPECT_EQ(s.faceTag(f), "");
    EXPECT_EQ(s.faceMaterial(f), "");
  }
  EXPECT_EQ(s.objects().at(2).name, "two again");
  EXPECT_EQ(s.objects().at(2).kind, Kind::Block);
  EXPECT_EQ(s.mesh().n_faces(), 36u);
  EXPECT_EQ(s.mesh().n_vertices(), 8u + 24u + 8u);
  expectClosedBox(s.validate(1), 1, 1, 1);
  expectClosedBox(s.validate(3), 18, 18, 1);
}

TEST(Scene, RemoveObject) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1), "stone"));
  s.replaceObject(2, Kind::Mass, "two", handBox(Vec3(5, 0, 0), Vec3(7, 2, 3), "brick"));
  const auto before2 = describe(s, 2);
  s.removeObject(1);
  EXPECT_FALSE(s.hasObject(1));
  EXPECT_TRUE(s.hasObject(2));
  EXPECT_TRUE(s.faces(1).empty());
  EXPECT_EQ(s.mesh().n_faces(), 6u);
  EXPECT_EQ(s.mesh().n_vertices(), 8u);
  EXPECT_EQ(describe(s, 2), before2);
  EXPECT_TRUE(s.bounds(1).empty());
  s.removeObject(99);  // unknown: no effect on the rest
  EXPECT_EQ(s.objects().size(), 1u);
  s.removeObject(2);
  EXPECT_TRUE(s.objects().empty());
  EXPECT_EQ(s.mesh().n_faces(), 0u);
  EXPECT_EQ(s.mesh().n_vertices(), 0u);
  EXPECT_TRUE(s.bounds().empty());
}

TEST(Scene, BoundsPerObjectAndOverall) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(-1, -2, -3), Vec3(1, 2, 3)));
  s.replaceObject(2, Kind::Mass, "two", handBox(Vec3(10, 20, 30), Vec3(11, 22, 33)));
  EXPECT_EQ(s.bounds(1).lo, Vec3(-1, -2, -3));
  EXPECT_EQ(s.bounds(1).hi, Vec3(1, 2, 3));
  EXPECT_EQ(s.bounds(2).lo, Vec3(10, 20, 30));
  EXPECT_EQ(s.bounds(2).hi, Vec3(11, 22, 33));
  EXPECT_EQ(s.bounds().lo, Vec3(-1, -2, -3));
  EXPECT_EQ(s.bounds().hi, Vec3(11, 22, 33));
  EXPECT_TRUE(s.bounds(3).empty());
}

TEST(Scene, CopyKeepsFacePropertiesAndIsIndependent) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1), "stone", "wall"));
  s.replaceObject(2, Kind::Feature, "two", handBox(Vec3(5, 0, 0), Vec3(7, 2, 3), "glass", "pane"));
  s.replaceObject(3, Kind::Unit, "three", handBox(Vec3(0, 5, 0), Vec3(1, 6, 1), "timber", "beam"));
  const auto d1 = describe(s, 1), d2 = describe(s, 2), d3 = describe(s, 3);

  Scene copy(s);
  EXPECT_EQ(describe(copy, 1), d1);
  EXPECT_EQ(describe(copy, 2), d2);
  EXPECT_EQ(describe(copy, 3), d3);
  EXPECT_EQ(copy.objects().size(), 3u);
  EXPECT_EQ(copy.objects().at(2).name, "two");

  // Garbage collection in the copy must move the copy's properties, not the original's.
  copy.removeObject(1);
  EXPECT_EQ(describe(copy, 2), d2);
  EXPECT_EQ(describe(copy, 3), d3);
  copy.replaceObject(4, Kind::Mass, "four", handBox(Vec3(0, 0, 9), Vec3(1, 1, 10), "slate", "cap"));
  EXPECT_EQ(describe(s, 1), d1);
  EXPECT_EQ(describe(s, 2), d2);
  EXPECT_EQ(describe(s, 3), d3);
  EXPECT_FALSE(s.hasObject(4));

  Scene assigned;
  assigned.replaceObject(9, Kind::Mass, "nine", handBox(Vec3(0, 0, 0), Vec3(3, 3, 3)));
  assigned = copy;
  EXPECT_FALSE(assigned.hasObject(9));
  EXPECT_EQ(describe(assigned, 2), d2);
  assigned.removeObject(2);
  EXPECT_EQ(describe(assigned, 3), d3);
  EXPECT_EQ(describe(assigned, 4), describe(copy, 4));
}

TEST(Scene, RevisionIncreasesOnEveryChange) {
  // A scene made before the changes below: assigning it must still count as a change, so
  // caches keyed by revision never see an old number again.
  Scene older;
  older.replaceObject(5, Kind::Mass, "five", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1)));

  Scene s;
  std::uint64_t last = s.revision();
  auto increased = [&](const char* what) {
    EXPECT_GT(s.revision(), last) << what;
    last = s.revision();
  };
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  increased("replaceObject (new)");
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(2, 1, 1)));
  increased("replaceObject (existing)");
  s.setObjectName(1, "renamed");
  increased("setObjectName");
  s.replaceObject(2, Kind::Mass, "two", handBox(Vec3(5, 0, 0), Vec3(6, 1, 1)));
  increased("replaceObject (second)");
  s.removeObject(2);
  increased("removeObject");
  s.clear();
  increased("clear");
  EXPECT_TRUE(s.objects().empty());
  EXPECT_EQ(s.mesh().n_faces(), 0u);

  s = older;
  increased("assignment from an older scene");
  EXPECT_NE(s.revision(), older.revision());
  s.replaceObject(6, Kind::Mass, "six", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  increased("replaceObject after assignment");

  // A copy differs from its source and each changes independently.
  Scene copy(s);
  EXPECT_NE(copy.revision(), s.revision());
  const std::uint64_t copyRevision = copy.revision();
  s.removeObject(6);
  increased("removeObject after copy");
  EXPECT_EQ(copy.revision(), copyRevision);
}

TEST(Scene, TagAndMaterialTablesAreShared) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "one", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1), "stone", "wall"));
  s.replaceObject(2, Kind::Mass, "two", handBox(Vec3(2, 0, 0), Vec3(3, 1, 1), "stone", "wall"));
  const auto& mats = s.materialNames();
  EXPECT_EQ(std::count(mats.begin(), mats.end(), "stone"), 1);
  EXPECT_EQ(mats[0], "");
  const auto& tags = s.tagNames();
  EXPECT_EQ(std::count(tags.begin(), tags.end(), "wall"), 1);
  for (auto f : s.mesh().faces()) EXPECT_EQ(s.materialNames()[s.faceMaterialIndex(f)], "stone");
}

TEST(Scene, KindNamesRoundTrip) {
  std::set<std::string_view> names;
  for (int k = 0; k < corbel::kKindCount; ++k) {
    const auto kind = static_cast<Kind>(k);
    names.insert(corbel::kindName(kind));
    EXPECT_EQ(corbel::kindFromName(corbel::kindName(kind)), kind);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(corbel::kKindCount));
  EXPECT_FALSE(corbel::kindFromName("castle").has_value());
}

}  // namespace

namespace {

// Two unit cubes sharing only the corner (1, 1, 1): as one vertex, no polygon mesh takes it;
// split into one vertex per fan, it is two closed cubes that touch.
TEST(MeshData, SplitPinchedVerticesGivesEachFanItsOwnVertex) {
  MeshData m = handBox(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const MeshData b = handBox(Vec3(1, 1, 1), Vec3(2, 2, 2));
  const int shared = 7;  // handBox's v[1][1][1]
  ASSERT_EQ(m.points[shared], Vec3(1, 1, 1));
  const int offset = static_cast<int>(m.points.size());
  m.append(b);
  ASSERT_EQ(m.points[offset], Vec3(1, 1, 1));  // b's v[0][0][0]
  for (auto& f : m.faces)
    for (int& v : f)
      if (v == offset) v = shared;
  Scene before;
  before.replaceObject(1, Kind::Mass, "pinched", m);
  EXPECT_FALSE(before.validate(1).closedManifold());
  EXPECT_EQ(corbel::splitPinchedVertices(m), 1u);
  Scene after;
  after.replaceObject(1, Kind::Mass, "touching", m);
  const ValidityReport r = after.validate(1);
  EXPECT_TRUE(r.closedManifold());
  EXPECT_EQ(r.components, 2u);
  EXPECT_NEAR(r.volume, 2.0, 1e-12);
  EXPECT_EQ(corbel::splitPinchedVertices(m), 0u) << "nothing left to split";
}

// The batch extruder builds a Scene per job on every worker thread at once. The first Scene
// quietens OpenMesh's one global error stream, whose set-up is not thread-safe; this test runs
// in its own process (one test per ctest entry), so the threads here make the first Scenes.
TEST(Scene, ScenesMayBeBuiltOnManyThreadsAtOnce) {
  constexpr int kThreads = 16;
  std::atomic<int> ready{0};
  std::vector<double> volumes(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < kThreads) std::this_thread::yield();
      Scene s;
      s.replaceObject(1, Kind::Mass, "cube", handBox(Vec3(0, 0, 0), Vec3(1, 1, t + 1.0)));
      volumes[t] = s.validate(1).volume;
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_DOUBLE_EQ(volumes[t], t + 1.0);
}

}  // namespace
