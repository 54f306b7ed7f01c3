// kifs/kernel.h: a KIFS object of the Document is the kernel's building, number for number, and
// reaches the Scene through SceneSync (ray-marched, or meshed into a closed shell).
#include "kifs/kernel.h"

#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "test_support.h"
#include "../common/one_object.h"

#include <gtest/gtest.h>

namespace corbel::kifs::test {
namespace {

// Every field of the parameters, so a field lost on the way through a spec shows.
void expectSame(const KifsParams& a, const KifsParams& b) {
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.centre, b.centre);
  for (const auto& [x, y] : {std::pair{a.r1, b.r1}, std::pair{a.r2, b.r2}}) {
    EXPECT_EQ(x.xDeg, y.xDeg);
    EXPECT_EQ(x.yDeg, y.yDeg);
    EXPECT_EQ(x.zDeg, y.zDeg);
  }
  EXPECT_EQ(a.bailout, b.bailout);
  EXPECT_EQ(a.mass.footprint, b.mass.footprint);
  EXPECT_EQ(a.mass.halfWidth, b.mass.halfWidth);
  EXPECT_EQ(a.mass.halfDepth, b.mass.halfDepth);
  EXPECT_EQ(a.mass.height, b.mass.height);
  EXPECT_EQ(a.mass.wing, b.mass.wing);
  EXPECT_EQ(a.mass.shell, b.mass.shell);
  EXPECT_EQ(a.facade.period, b.facade.period);
  EXPECT_EQ(a.facade.r, b.facade.r);
  EXPECT_EQ(a.facade.a1, b.facade.a1);
  EXPECT_EQ(a.facade.a2, b.facade.a2);
  EXPECT_EQ(a.facade.b1, b.facade.b1);
  EXPECT_EQ(a.facade.b2, b.facade.b2);
  EXPECT_EQ(a.floors.height, b.floors.height);
  EXPECT_EQ(a.floors.y0, b.floors.y0);
  EXPECT_EQ(a.floors.sy, b.floors.sy);
  EXPECT_EQ(a.curvilinear.enabled, b.curvilinear.enabled);
  EXPECT_EQ(a.curvilinear.sTheta, b.curvilinear.sTheta);
  EXPECT_EQ(a.curvilinear.cTheta, b.curvilinear.cTheta);
  EXPECT_EQ(a.curvilinear.sR, b.curvilinear.sR);
  EXPECT_EQ(a.curvilinear.cR, b.curvilinear.cR);
  EXPECT_EQ(a.curvilinear.z0, b.curvilinear.z0);
  EXPECT_EQ(a.trace.maxSteps, b.trace.maxSteps);
  EXPECT_EQ(a.trace.lipschitz, b.trace.lipschitz);
  EXPECT_EQ(a.trace.overRelax, b.trace.overRelax);
  EXPECT_EQ(a.trace.hitFactor, b.trace.hitFactor);
}

TEST(KifsSpec, TheDefaultSpecIsTheDefaultBuilding) { expectSame(paramsOf(KifsSpec{}), KifsParams{}); }

TEST(KifsSpec, EveryPresetSurvivesTheSpecAndGivesTheSameDistances) {
  std::mt19937_64 rng(5);
  for (const std::string& name : presetNames()) {
    SCOPED_TRACE(name);
    const KifsParams p = preset(name);
    const KifsSpec s = specOf(p, name);
    EXPECT_EQ(s.preset, name);
    expectSame(paramsOf(s), p);
    const Building direct(p), viaSpec(paramsOf(s));
    const Aabb box = direct.worldBounds();
    for (int i = 0; i < 200; ++i) {
      const glm::dvec3 x = uniformIn(rng, box.lo - 2.0, box.hi + 2.0);
      EXPECT_EQ(direct.evaluate(x).bound, viaSpec.evaluate(x).bound);
    }
  }
}

TEST(KifsSpec, BadValuesNameTheFieldAsTheProjectFileDoes) {
  auto fault = [](KifsSpec s) {
    try {
      paramsOf(s);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  KifsSpec s;
  s.scale = 0.5;
  EXPECT_EQ(fault(s).rfind("kifs.scale:", 0), 0u) << fault(s);
  s = {};
  s.mass.footprint = "L";
  EXPECT_EQ(fault(s).rfind("kifs.mass.footprint:", 0), 0u) << fault(s);
  s = {};
  s.mass.shell = 50;
  EXPECT_EQ(fault(s).rfind("kifs.mass.shell:", 0), 0u) << fault(s);
  s = {};
  s.iterations = 31;
  EXPECT_EQ(fault(s).rfind("kifs.iterations:", 0), 0u) << fault(s);
}

struct Synced : corbel::test::OneObject {
  explicit Synced(const KifsSpec& spec) : OneObject(spec, registerKernel) {}
};

TEST(KifsKernel, ARaymarchedBuildingHasNoFacesInTheScene) {
  const Synced s(specOf(preset("box"), "box"));
  EXPECT_EQ(s.error(), "");
  EXPECT_EQ(s.scene.validate(s.id).faces, 0u);
}

TEST(KifsKernel, AMeshedBuildingIsAClosedShellOfOrnamentInItsMaterial) {
  KifsSpec spec = specOf(preset("box"), "box");
  spec.meshResolution = 32;
  spec.material = "concrete";
  const Synced s(spec);
  ASSERT_EQ(s.error(), "");
  const ValidityReport r = s.scene.validate(s.id);
  EXPECT_GT(r.faces, 100u);
  EXPECT_TRUE(r.closedManifold()) << ::testing::PrintToString(r.problems());
  const Aabb box = Building(paramsOf(spec)).worldBounds();
  const BBox b = s.scene.bounds(s.id);
  for (int k = 0; k < 3; ++k) {  // inside the building's bounds, with the mesher's one-cell margin
    const double cell = std::max({box.hi.x - box.lo.x, box.hi.y - box.lo.y, box.hi.z - box.lo.z}) / 32;
    EXPECT_GE(b.lo[k], box.lo[k] - cell);
    EXPECT_LE(b.hi[k], box.hi[k] + cell);
  }
  for (auto f : s.scene.mesh().faces()) {
    EXPECT_EQ(s.scene.faceKind(f), Kind::Ornament);
    EXPECT_EQ(s.scene.faceMaterial(f), "concrete");
    break;
  }
}

TEST(KifsKernel, ABadValueInTheFileIsTheObjectsErrorNamingItsPath) {
  const LoadedProject p = parseProject(
      R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "K", "kifs": {"mass": {"shell": 50}}}]})");
  Scene scene;
  SceneSync sync;
  registerKernel(sync);
  sync.update(p.document, scene);
  const std::string& error = sync.status().at(1).error;
  EXPECT_EQ(error.rfind("kifs.mass.shell:", 0), 0u) << error;
}

}  // namespace
}  // namespace corbel::kifs::test
