// The example projects' extrusions (Fig. 1 house, Fig. 5 temple, terrace with bays, town
// block from real footprints) build closed 2-manifold shells without warnings, and a shell
// does not depend on where the building stands or which corner its plan starts at.
#include "core/project_io.h"
#include "core/scene.h"
#include "support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace corbel::extrude::test {
namespace {

namespace fs = std::filesystem;

ValidityReport validated(const ExtrusionSpec& spec, const ExtrusionResult& r) {
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, spec, "plaster"));
  return scene.validate(1);
}

TEST(Examples, EveryExtrusionIsAClosedShellWithoutWarnings) {
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(CORBEL_SOURCE_DIR) / "assets/examples")) {
    if (entry.path().extension() != ".corbel") continue;
    const Document d = loadProject(entry.path().string()).document;
    for (const DocObject& o : d.objects) {
      const auto* spec = std::get_if<ExtrusionSpec>(&o.spec);
      if (!spec) continue;
      SCOPED_TRACE(entry.path().filename().string() + ": " + o.name);
      const ExtrusionResult r = extrude(*spec);
      for (const auto& w : r.shell.warnings) ADD_FAILURE() << w;
      const ValidityReport v = validated(*spec, r);
      for (const auto& p : v.problems()) ADD_FAILURE() << p;
      EXPECT_EQ(v.euler, 2 - 2 * (static_cast<int>(spec->loops.size()) - 1)) << "a sphere, less two per courtyard";
      EXPECT_NEAR(v.volume, measure(r.shell).volume, 1e-9 * v.volume);
      for (const AnchorFrame& a : r.anchors) EXPECT_TRUE(a.instanced) << a.name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 90);  // house, temple, two terraces, 87 town buildings, the extrusions example
}

// Moving the plan, rotating it, or starting its loops at another corner changes nothing
// measurable: an oracle that needs no second implementation.
TEST(Examples, HouseIsInvariantUnderRigidMotionsAndRelabelling) {
  const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
  const ExtrusionSpec house = std::get<ExtrusionSpec>(d.objects[0].spec);
  const ShellMeasures ref = measure(extrude(house).shell);
  for (int variant = 0; variant < 4; ++variant) {
    ExtrusionSpec s = house;
    const double a = 0.3 + variant * 1.1;
    for (PlanLoop& l : s.loops)
      for (Vec2& p : l.points) p = Vec2(std::cos(a) * p[0] - std::sin(a) * p[1] + 123.4, std::sin(a) * p[0] + std::cos(a) * p[1] - 56.7);
    // Start loop 0 at corner `variant`: edge indices in anchors move with it.
    PlanLoop& l = s.loops[0];
    const int n = static_cast<int>(l.points.size());
    std::rotate(l.points.begin(), l.points.begin() + variant, l.points.end());
    std::rotate(l.profile.begin(), l.profile.begin() + variant, l.profile.end());
    for (PlanStep& st : s.steps) st.anchor.edge = (st.anchor.edge - variant + n) % n;
    for (MeshAnchor& m : s.anchors) m.anchor.edge = (m.anchor.edge - variant + n) % n;
    const ExtrusionResult r = extrude(s);
    EXPECT_TRUE(r.shell.warnings.empty());
    EXPECT_TRUE(validated(s, r).problems().empty());
    const ShellMeasures m = measure(r.shell);
    EXPECT_NEAR(m.volume, ref.volume, 1e-9 * ref.volume) << variant;
    EXPECT_NEAR(m.roofArea, ref.roofArea, 1e-9 * ref.roofArea) << variant;
    EXPECT_NEAR(m.wallArea, ref.wallArea, 1e-9 * ref.wallArea) << variant;
    EXPECT_NEAR(m.soffitArea, ref.soffitArea, 1e-9 * ref.soffitArea) << variant;
    EXPECT_NEAR(m.maxHeight, ref.maxHeight, 1e-9) << variant;
  }
}

}  // namespace
}  // namespace corbel::extrude::test
