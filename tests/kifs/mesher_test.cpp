// Specifications of kifs/mesher.h: the isosurface of a sphere is a closed 2-manifold of the
// sphere's volume with its vertices on the sphere; the KIFS building meshes into a closed
// 2-manifold of the Scene whose vertices lie on the estimate's zero set; cancellation stops it.
#include "core/error.h"
#include "core/scene.h"
#include "kifs/mesher.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <numbers>

namespace corbel::kifs::test {
namespace {

TEST(KifsMesher, SphereIsAClosedManifoldOfItsVolume) {
  const double r = 1.3;
  const glm::dvec3 c(0.2, -0.1, 0.4);
  const Aabb box{c - 1.5, c + 1.5};
  for (int resolution : {12, 40}) {
    const MeshData m = meshIsosurface([&](const glm::dvec3& p) { return glm::length(p - c) - r; }, box, resolution);
    Scene scene;
    scene.replaceObject(1, Kind::Ornament, "sphere", m);
    const ValidityReport v = scene.validate(1);
    EXPECT_TRUE(v.closedManifold()) << resolution << ": " << v.problems().size() << " problems";
    EXPECT_EQ(v.components, 1u);
    EXPECT_EQ(v.euler, 2);  // a sphere's genus 0
    const double h = 3.0 / resolution;
    const double exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    EXPECT_NEAR(v.volume, exact, exact * 3 * h / r) << resolution;  // inscribed: O(h) from below
    for (const Vec3& p : m.points) EXPECT_NEAR(glm::length(glm::dvec3(p[0], p[1], p[2]) - c), r, h * h);
  }
}

TEST(KifsMesher, RefusesBadResolutionsAndStopsWhenCancelled) {
  const Aabb box{glm::dvec3(0.0), glm::dvec3(1.0)};
  auto f = [](const glm::dvec3& p) { return glm::length(p - 0.5) - 0.3; };
  EXPECT_THROW(meshIsosurface(f, box, 0), Error);
  EXPECT_THROW(meshIsosurface(f, box, kMaxMeshResolution + 1), Error);
  Progress progress;
  progress.cancel();
  EXPECT_THROW(meshIsosurface(f, box, 16, &progress), Cancelled);
}

// Sampling is shared among threads; the mesh does not depend on how they interleave.
TEST(KifsMesher, TwoRunsGiveTheSameMesh) {
  const Building b(preset("curved"));
  const MeshData a = meshBuilding(b, 32), c = meshBuilding(b, 32);
  ASSERT_EQ(a.points.size(), c.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) ASSERT_EQ(a.points[i], c.points[i]);
  EXPECT_EQ(a.faces, c.faces);
}

TEST(KifsMesher, BuildingIsAClosedManifoldOnItsSurface) {
  for (const std::string& name : {std::string("box"), std::string("h")}) {
    const Building b(preset(name));
    Progress progress;
    const int resolution = 48;
    const MeshData m = meshBuilding(b, resolution, &progress);
    EXPECT_DOUBLE_EQ(progress.fraction(), 1.0);
    Scene scene;
    scene.replaceObject(1, Kind::Ornament, name, m);
    const ValidityReport v = scene.validate(1);
    EXPECT_TRUE(v.closedManifold()) << name << ": boundary " << v.boundary_edges << ", non-manifold "
                                    << v.non_manifold_vertices << ", rejected " << v.rejected_faces << ", degenerate "
                                    << v.degenerate_faces << ", volume " << v.volume;
    // Vertices interpolate the estimate along grid edges: within a cell of the offset there,
    // but within a cell of a storey plane (Eq. 4) or a facade-id plane, where it jumps.
    const glm::dvec3 size = b.worldBounds().size();
    const double h = std::max({size.x, size.y, size.z}) / resolution, storey = b.params().floors.height;
    int far = 0;
    for (const Vec3& p : m.points) {
      if (std::abs(b.evaluate({p[0], p[1], p[2]}).surface - kMeshOffset * h) < h) continue;
      ++far;
      const double m = glslMod(p[2] - b.params().floors.y0, storey);
      const FacadeFold fx = facadeFold(p[0], b.params().facade), fz = facadeFold(p[1], b.params().facade);
      const double idGap = 0.5 * std::min(fx.gap, fz.gap) * b.params().facade.period;
      EXPECT_TRUE(std::min(m, storey - m) < h || (b.idsCut() && idGap < h))
          << name << ": vertex " << p[0] << ", " << p[1] << ", " << p[2] << " is off the surface";
    }
    EXPECT_LT(far, int(m.points.size() / 100)) << name;
  }
}

}  // namespace
}  // namespace corbel::kifs::test
