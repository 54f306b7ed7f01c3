// Units and the shape operators (Sec. 5.1) against hand-computed volumes and closed shells.
#include "growth/unit.h"
#include "core/scene.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

using test::box;

Unit oneBox() {
  Unit u;
  u.id = 1;
  u.parts = {box(0, 0, 0, 6, 4, 3)};
  return u;
}

TEST(Unit, FaceAdvanceAddsTheFaceAreaTimesAlpha) {
  for (Side s : kAllSides) {
    Unit u = oneBox();
    const double face = s == Side::NegX || s == Side::PosX ? 4 * 3 : s == Side::NegY || s == Side::PosY ? 6 * 3 : 6 * 4;
    applyMove(u, Move::advance(0, s, 0.35));
    EXPECT_NEAR(u.volume(), 72 + face * 0.35, 1e-12) << sideName(s);
    // The face moved, the opposite one did not.
    EXPECT_NEAR(sideCoord(u.parts[0], s), sideCoord(oneBox().parts[0], s) + sideSign(s) * 0.35, 1e-12);
    EXPECT_EQ(sideCoord(u.parts[0], opposite(s)), sideCoord(oneBox().parts[0], opposite(s)));
  }
}

TEST(Unit, FaceSplitKeepsTheUnionAndMakesTwoFaces) {
  Unit u = oneBox();
  applyMove(u, Move::split(0, 0, 3.5));
  ASSERT_EQ(u.parts.size(), 2u);
  EXPECT_EQ(u.parts[0], box(0, 0, 0, 3.5, 4, 3));
  EXPECT_EQ(u.parts[1], box(3.5, 0, 0, 6, 4, 3));
  EXPECT_DOUBLE_EQ(u.volume(), 72);
  EXPECT_DOUBLE_EQ(u.floorArea(), 24);
  // The cut faces touch each other; the split +y face is now two faces that advance alone.
  EXPECT_TRUE(sideTouchesOwnPart(u, 0, Side::PosX));
  EXPECT_TRUE(sideTouchesOwnPart(u, 1, Side::NegX));
  EXPECT_FALSE(sideTouchesOwnPart(u, 1, Side::PosY));
  applyMove(u, Move::advance(1, Side::PosY, 0.5));
  EXPECT_NEAR(u.volume(), 72 + 2.5 * 3 * 0.5, 1e-12);
}

// The union surface is a closed 2-manifold whose volume is the parts' and whose area is the
// hand-computed area of the L-shaped polyhedron.
TEST(Unit, MeshOfAnLShapedUnitIsClosedWithTheRightVolumeAndArea) {
  Unit u = oneBox();
  applyMove(u, Move::split(0, 0, 3));
  applyMove(u, Move::advance(1, Side::PosY, 2));  // part 1: [3, 6] x [0, 6]
  Scene scene;
  scene.replaceObject(1, Kind::Unit, "unit", unitMesh(u));
  const ValidityReport r = scene.validate(1);
  EXPECT_TRUE(r.closedManifold()) << r.problems().size();
  EXPECT_NEAR(r.volume, 3 * 4 * 3 + 3 * 6 * 3, 1e-9);
  // Plan: L of area 30 and perimeter 6 + 6 + 3 + 2 + 3 + 4 = 24; walls 24 x 3.
  EXPECT_NEAR(r.area, 2 * 30 + 24 * 3, 1e-9);
}

// Fig. 5.4's stair base appends its box: a one-storey part on storey 2 and a two-storey part
// from the staircase's roof (z = 3) up to its ceiling, meeting over the 3 × 3 m face at x = 9.9.
TEST(Unit, StairBaseMeshIsClosedWithTheRightVolumeAndArea) {
  Unit u;
  u.id = 1;
  u.parts = {box(6, 2, 6, 9.9, 5, 9)};
  Move m = Move::stairBase(0, Side::PosX, 1);
  m.box = box(9.9, 2, 3, 14, 6, 9);
  applyMove(u, m);
  ASSERT_EQ(u.parts.size(), 2u);
  EXPECT_EQ(u.parts[0], box(6, 2, 6, 9.9, 5, 9));  // untouched
  Scene scene;
  scene.replaceObject(1, Kind::Unit, "unit", unitMesh(u));
  const ValidityReport r = scene.validate(1);
  EXPECT_TRUE(r.closedManifold()) << r.problems().size();
  EXPECT_NEAR(r.volume, 3.9 * 3 * 3 + 4.1 * 4 * 6, 1e-9);  // 133.5 m³
  // The two boxes' areas (64.8 and 130 m²) less the shared 3 × 3 m face on each.
  EXPECT_NEAR(r.area, 64.8 + 130 - 2 * 9, 1e-9);
  EXPECT_NEAR(u.floorArea(), 3.9 * 3 + 4.1 * 4, 1e-9);
}

TEST(Unit, DoubleVolumeMeshIsClosed) {
  Unit u = oneBox();
  applyMove(u, Move::split(0, 1, 3));            // [0,6]x[0,3] and [0,6]x[3,4]... pieces
  applyMove(u, Move::advance(0, Side::Top, 3));  // part 0 two storeys
  Scene scene;
  scene.replaceObject(1, Kind::Unit, "unit", unitMesh(u));
  const ValidityReport r = scene.validate(1);
  EXPECT_TRUE(r.closedManifold());
  EXPECT_NEAR(r.volume, 72 + 6 * 3 * 3, 1e-9);
  EXPECT_DOUBLE_EQ(u.floorArea(), 24);  // a double volume counts its floor once
}

}  // namespace
}  // namespace corbel::growth
