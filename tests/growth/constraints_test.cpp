// The constraint enforcer on hand-built configurations: each rule rejects what it should and
// trims advances to the exact distance left.
#include "growth/constraints.h"
#include "growth/tolerances.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

TEST(Constraints, AdvanceIsTrimmedToTheNextUnitAndThenBlocked) {
  Site site = test::openSite(30, 30, 2);
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 4, 4, 3)}), unitOf(2, {box(4.2, 1, 0, 8, 5, 3)})};
  Verdict v = e.check(units, 0, Move::advance(0, Side::PosX, 0.3));
  ASSERT_TRUE(v.ok);
  EXPECT_NEAR(v.move.distance, 0.2, 1e-12);
  applyMove(units[0], v.move);
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::PosX, 0.3)).ok);
  EXPECT_TRUE(e.violations(units).empty());
  // The other way is open, and the envelope stops -x at once.
  EXPECT_NEAR(e.check(units, 0, Move::advance(0, Side::PosY, 0.3)).move.distance, 0.3, 1e-12);
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::NegX, 0.3)).ok);
}

TEST(Constraints, CoreClearanceIsKept) {
  Site site = test::openSite(30, 30, 2);
  site.cores.push_back({10, 0, 14, 4});
  site.coreClearance = 1.0;
  ConstraintEnforcer e(site);
  // On storey 1 with nothing below: held only once it reaches the core's clearance zone.
  std::vector<Unit> units{unitOf(1, {box(5.5, 0, 3, 8.9, 4, 6)})};
  EXPECT_FALSE(e.plausible(units, 0));
  const Verdict v = e.check(units, 0, Move::advance(0, Side::PosX, 0.5));
  ASSERT_TRUE(v.ok) << v.reason;
  EXPECT_NEAR(v.move.distance, 0.1, 1e-9);  // stops 1 m short of the core at x = 10
  applyMove(units[0], v.move);
  EXPECT_TRUE(e.plausible(units, 0));
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::PosX, 0.5)).ok);
  // Reaching 4 m (the cantilever limit) from the core: x = 5 is the farthest west.
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::NegX, 0.6)).ok);
  EXPECT_TRUE(e.check(units, 0, Move::advance(0, Side::NegX, 0.5)).ok);
}

TEST(Constraints, PolygonEnvelopeTrimsAtASlantedEdge) {
  Site site = test::openSite(1, 1, 1);
  site.plan = {Vec2(0, 0), Vec2(20, 0), Vec2(10, 10), Vec2(0, 10)};  // x + y ≤ 20 for x ≥ 10
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(8, 0, 0, 11, 3, 3)})};
  // The corner (x, 3) stays inside while x ≤ 17.
  const double d = e.freeDistance(units, 0, 0, Side::PosX, 10.0);
  EXPECT_NEAR(d, 6.0, 1e-6);
  EXPECT_TRUE(site.contains(sweptRegion(units[0].parts[0], Side::PosX, d)));
  EXPECT_FALSE(site.contains(sweptRegion(units[0].parts[0], Side::PosX, d + 1e-3)));
}

TEST(Constraints, CantileverLimitHoldsUpperUnits) {
  Site site = test::openSite(40, 40, 3);
  site.cantilever = 2.0;
  ConstraintEnforcer e(site);
  // Unit 2 on storey 1 rests on unit 1 ([0, 6] x [0, 6]); it may reach 2 m past x = 6.
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 6, 6, 3)}), unitOf(2, {box(0, 0, 3, 6, 6, 6)})};
  for (int i = 0; i < 4; ++i) {
    const Verdict v = e.check(units, 1, Move::advance(0, Side::PosX, 0.5));
    ASSERT_TRUE(v.ok) << i;
    applyMove(units[1], v.move);
  }
  EXPECT_NEAR(units[1].parts[0].hi[0], 8.0, 1e-12);
  const Verdict v = e.check(units, 1, Move::advance(0, Side::PosX, 0.5));
  EXPECT_FALSE(v.ok);
  EXPECT_NE(v.reason.find("cantilever"), std::string::npos);
  // A unit on storey 2 with nothing under it and nothing beside it is not plausible.
  units.push_back(unitOf(3, {box(20, 20, 6, 23, 23, 9)}));
  EXPECT_FALSE(e.plausible(units, 2));
  EXPECT_FALSE(e.violations(units).empty());
}

TEST(Constraints, SplitsLeaveBothPiecesThreeMetresWide) {
  Site site = test::openSite(30, 30, 2);
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 7, 4, 3)})};
  EXPECT_TRUE(e.check(units, 0, Move::split(0, 0, 3.0)).ok);
  EXPECT_TRUE(e.check(units, 0, Move::split(0, 0, 4.0)).ok);
  EXPECT_FALSE(e.check(units, 0, Move::split(0, 0, 2.9)).ok);
  EXPECT_FALSE(e.check(units, 0, Move::split(0, 0, 4.1)).ok);
  EXPECT_FALSE(e.check(units, 0, Move::split(0, 1, 2.0)).ok);  // only 4 m deep: no room for two
}

TEST(Constraints, DoubleVolumeOnceAndTwoStoreysAtMost) {
  Site site = test::openSite(30, 30, 4);
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 8, 4, 3)})};
  applyMove(units[0], Move::split(0, 0, 4));
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::Top, 0.3)).ok);  // floors move by a storey
  ASSERT_TRUE(e.check(units, 0, Move::advance(0, Side::Top, 3)).ok);
  applyMove(units[0], Move::advance(0, Side::Top, 3));
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::Top, 3)).ok);  // already double
  EXPECT_TRUE(e.check(units, 0, Move::advance(1, Side::Top, 3)).ok);
  EXPECT_FALSE(e.check(units, 0, Move::advance(1, Side::Bottom, 3)).ok);  // the ground
  EXPECT_TRUE(e.violations(units).empty());
}

TEST(Constraints, LockedFacesNeverAdvance) {
  Site site = test::openSite(30, 30, 2);
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(5, 5, 0, 8, 8, 3)})};
  units[0].locked[int(Side::PosY)] = true;
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::PosY, 0.3)).ok);
  EXPECT_TRUE(e.check(units, 0, Move::advance(0, Side::NegY, 0.3)).ok);
}

TEST(Constraints, FacesTouchingTheirOwnPartsDoNotAdvance) {
  Site site = test::openSite(30, 30, 2);
  ConstraintEnforcer e(site);
  std::vector<Unit> units{unitOf(1, {box(0, 0, 0, 8, 4, 3)})};
  applyMove(units[0], Move::split(0, 0, 4));
  EXPECT_FALSE(e.check(units, 0, Move::advance(0, Side::PosX, 0.3)).ok);
  EXPECT_TRUE(e.check(units, 0, Move::advance(1, Side::PosX, 0.3)).ok);
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

TEST(Constraints, LookAheadAssumesGrowingNeighboursComeCloser) {
  Site site = test::openSite(40, 40, 2);
  ConstraintEnforcer e(site);
  const std::vector<Unit> units{test::unitOf(1, {test::box(0, 0, 0, 4, 4, 3)}),
                                test::unitOf(2, {test::box(9, 1, 0, 13, 5, 3)})};
  EXPECT_NEAR(e.freeDistance(units, 0, 0, Side::PosX, 100), 5, 1e-12);
  EXPECT_NEAR(e.lookAhead(units, 0, 0, Side::PosX, 100, 3, {true, true}), 2, 1e-12);
  EXPECT_NEAR(e.lookAhead(units, 0, 0, Side::PosX, 100, 3, {true, false}), 5, 1e-12);  // unit 2 has stopped
  // Grown by 3 m, unit 2 spans x 6..16: still clear of the strip in front of unit 1's +y face
  // (x 0..4), which the envelope alone limits.
  EXPECT_NEAR(e.lookAhead(units, 0, 0, Side::PosY, 100, 3, {true, true}), 36, 1e-6);  // the envelope (within kEps)
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// Fig. 5.4 by hand: unit 1 on storey 2 (z 6–9), fixed to a stair tower at x = 6, its +x face at
// x = 9.9, 0.1 m short of a staircase of storey 0 (x 10–14, y 2–6, roof at z = 3).
struct StairCase {
  Site site = test::openSite(30, 20, 3);
  std::vector<Unit> units{unitOf(1, {box(6, 2, 6, 9.9, 5, 9)})};
  StairCase() { site.circulation = {box(3, 2, 0, 6, 5, 9), box(10, 2, 0, 14, 6, 3)}; }
};

TEST(Constraints, AStairBaseIsTheStaircasesWholeTop) {
  StairCase c;
  ConstraintEnforcer e(c.site);
  const Verdict v = e.check(c.units, 0, Move::stairBase(0, Side::PosX, 1));
  ASSERT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(v.move.box, box(9.9, 2, 3, 14, 6, 9));
  applyMove(c.units[0], v.move);
  EXPECT_NEAR(c.units[0].floorArea(), 3.9 * 3 + 4.1 * 4, 1e-9);       // 28.1 m²
  EXPECT_NEAR(c.units[0].volume(), 3.9 * 3 * 3 + 4.1 * 4 * 6, 1e-9);  // 133.5 m³
  EXPECT_TRUE(test::independentViolations(c.site, c.units).empty());
  EXPECT_TRUE(e.violations(c.units).empty());
  // Its face now touches the new part: no second stair base, no advance there.
  EXPECT_FALSE(e.check(c.units, 0, Move::stairBase(0, Side::PosX, 1)).ok);
  EXPECT_FALSE(e.check(c.units, 0, Move::advance(0, Side::PosX, 0.3)).ok);
}

TEST(Constraints, AStairBaseIsRefusedWhenAnyOfTheTopIsTaken) {
  StairCase c;
  ConstraintEnforcer e(c.site);
  EXPECT_EQ(e.check(c.units, 0, Move::stairBase(0, Side::PosX, 0)).reason,
            "the staircase's roof is not one storey below the part's floor");  // the tower
  EXPECT_EQ(e.check(c.units, 0, Move::stairBase(0, Side::PosX, 2)).reason, "no such staircase");
  EXPECT_FALSE(e.check(c.units, 0, Move::stairBase(0, Side::NegY, 1)).ok);
  // Unit 2 of storey 1 stands on the top's east end (x 12–14): the whole is refused.
  c.units.push_back(unitOf(2, {box(12, 2.5, 3, 15, 5.5, 6)}));
  ASSERT_TRUE(e.violations(c.units).empty());
  const Verdict v = e.check(c.units, 0, Move::stairBase(0, Side::PosX, 1));
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "the staircase's top is not wholly free (unit 2)");
  // A locked face does not reach it either.
  c.units.pop_back();
  c.units[0].locked[int(Side::PosX)] = true;
  EXPECT_EQ(e.check(c.units, 0, Move::stairBase(0, Side::PosX, 1)).reason, "the face is locked");
}

// The behaviour's look-ahead before proposing a stair base: unit 2 beside the top (its -x face
// 0.2 m east of it, on storey 1) would reach it in its next advance while it grows.
TEST(Constraints, LookAheadFromAStairBasesFace) {
  StairCase c;
  c.units.push_back(unitOf(2, {box(14.2, 2.5, 3, 17.2, 5.5, 6)}));
  ConstraintEnforcer e(c.site);
  const Box face{{9.9, 2, 3}, {9.9, 6, 9}};
  EXPECT_NEAR(e.lookAheadFrom(c.units, 0, face, Side::PosX, 4.1, 0.3, {true, true}), 4.0, 1e-9);
  EXPECT_NEAR(e.lookAheadFrom(c.units, 0, face, Side::PosX, 4.1, 0.3, {true, false}), 4.1, 1e-9);
  EXPECT_TRUE(e.check(c.units, 0, Move::stairBase(0, Side::PosX, 1)).ok);  // free now, all of it
}

}  // namespace
}  // namespace corbel::growth
