// splitBlock: the two parts of a cut convex block are closed convex blocks whose volumes add up
// to the block's and lie on their sides of the plane; the shear crack runs at 45° between the
// longest and the shortest side.
#include "sim/split.h"

#include "core/error.h"
#include "sim/mass_properties.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::sim {
namespace {

void expectClosedConvex(const statics::Block& b) {
  statics::Assembly as;
  as.blocks = {b};
  EXPECT_NO_THROW(statics::validateAssembly(as, 1e-9)) << b.name;
}

TEST(SplitBlock, PlaneAcrossACubeLeavesTwoBoxes) {
  const statics::Block cube = statics::boxBlock("cube", Vec3(0, 0, 0), Vec3(1, 1, 1));
  const auto parts = splitBlock(cube, Vec3(0.3, 0, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(massProperties(parts[0]).volume, 0.3, 1e-12);
  EXPECT_NEAR(massProperties(parts[1]).volume, 0.7, 1e-12);
  for (const Vec3& p : parts[0].vertices) EXPECT_LE(p[0], 0.3 + 1e-12);
  for (const Vec3& p : parts[1].vertices) EXPECT_GE(p[0], 0.3 - 1e-12);
  EXPECT_EQ(parts[0].vertices.size(), 8u);
  EXPECT_EQ(parts[0].faces.size(), 6u);
  EXPECT_EQ(parts[0].name, "cube (part 1)");
  for (const auto& p : parts) expectClosedConvex(p);
}

TEST(SplitBlock, DiagonalCutThroughTheCentroidHalvesABox) {
  const statics::Block box = statics::boxBlock("pier", Vec3(0, 0, 0), Vec3(0.3, 0.4, 1.2));
  const Vec3 n = shearCrackNormal(box);
  // Longest side along z, shortest along x: the crack's normal is (±1, 0, ±1)/√2.
  EXPECT_NEAR(std::abs(n[0]), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(n[1], 0, 1e-12);
  EXPECT_NEAR(std::abs(n[2]), std::sqrt(0.5), 1e-12);
  const auto parts = splitBlock(box, Vec3(0.15, 0.2, 0.6), n);
  const double whole = 0.3 * 0.4 * 1.2;
  EXPECT_NEAR(massProperties(parts[0]).volume, whole / 2, 1e-12);
  EXPECT_NEAR(massProperties(parts[1]).volume, whole / 2, 1e-12);
  for (const auto& p : parts) expectClosedConvex(p);
}

TEST(SplitBlock, PlaneThatMissesIsRefused) {
  const statics::Block cube = statics::boxBlock("cube", Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_THROW(splitBlock(cube, Vec3(2, 0, 0), Vec3(1, 0, 0)), Error);
  EXPECT_THROW(splitBlock(cube, Vec3(1, 0, 0), Vec3(1, 0, 0)), Error) << "a face's own plane";
  EXPECT_THROW(splitBlock(cube, Vec3(0.5, 0, 0), Vec3(0, 0, 0)), Error);
}

}  // namespace
}  // namespace corbel::sim
