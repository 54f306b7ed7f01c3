#include "support.h"

#include "core/scene.h"

#include <gtest/gtest.h>

namespace corbel::extrude::test {
namespace {

TEST(ExtrudeSmoke, TenBySixRectangleAt45Degrees) {
  const auto spec = uniformSpec({rectangle(10, 6)}, hipProfile(45 * kDeg));
  const ExtrusionResult r = extrude(spec);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << w;
  const ShellMeasures m = measure(r.shell);
  EXPECT_NEAR(m.maxHeight, 3.0, 1e-12);
  EXPECT_NEAR(m.volume, 72.0, 1e-9);
  EXPECT_NEAR(m.roofArea, 60 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(m.faces, 5u);
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "r", toMeshData(r.shell, spec, "plaster"));
  const ValidityReport v = scene.validate(1);
  for (const auto& p : v.problems()) ADD_FAILURE() << p;
  EXPECT_EQ(v.euler, 2);
  EXPECT_NEAR(v.volume, 72.0, 1e-9);
}

}  // namespace
}  // namespace corbel::extrude::test
