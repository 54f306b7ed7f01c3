// Form complexity F_q (Sec. 7.2) against hand counts and the series and criterion of
// Sec. 7.2.1.
#include "growth/complexity.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

constexpr int kN = 0, kE = 1, kS = 2, kW = 3;

Fraction fq(const Floorplan& p) { return formComplexity(p).value(); }

TEST(FormComplexity, TwoTouchingSquaresAreOneEighth) {
  // Sec. 7.2.1: two cubes sharing one face: one incidence over 4 + 4 faces.
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({4, 0}, 4, 4));
  EXPECT_EQ(fq(plan), Fraction::of(1, 8));
  Floorplan apart;
  apart.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  apart.addUnit(ShapeTree::canonical({5, 0}, 4, 4));
  EXPECT_EQ(fq(apart), Fraction::of(0, 1));  // trivially 0 without interlocking
}

// Three interlocking units (our stand-in for Fig. 7.5, whose drawing is not in the text):
// T1 = [0,2]², T2 = [2,4]×[0,4] that has wrapped over T1 as in Fig. 7.3, and T3 = [0,4]×[-2,0]
// below both. Hand count: T1 4 faces, T2 6 (a21, b21, c21, d23, c22, d22), T3 4 → 14.
// Links: T1–T2 (b11,d23) and (a11,c22) = 2; T1–T3 (c11,a31) = 1; T2–T3 (c21,a31) = 1 → 4.
TEST(FormComplexity, ThreeInterlockingUnitsByHand) {
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 2, 2));
  plan.addUnit(ShapeTree::canonical({2, 0}, 2, 4));
  plan.addUnit(ShapeTree::canonical({0, -2}, 4, 2));
  const SplitNodes s = plan.faceSplit(1, kW, 2);
  ASSERT_TRUE(plan.faceAdvance(1, s.second, 1));
  const Complexity c = formComplexity(plan);
  EXPECT_EQ(c.faces, 14);
  EXPECT_EQ(c.incidences, 4);
  EXPECT_EQ(c.pairs[0][1], 2);
  EXPECT_EQ(c.pairs[0][2], 1);
  EXPECT_EQ(c.pairs[1][2], 1);
  EXPECT_EQ(c.pairs[2][1], 1);
  EXPECT_EQ(c.value(), Fraction::of(2, 7));
}

TEST(FormComplexity, TypeIMovesGiveTheSeriesOneEighthTwoTenthsThreeTwelfths) {
  // Sec. 7.2.1: from two touching units, each Type I move (split a face where its contact
  // ends and advance the free piece so the new step lands on the neighbour) adds one
  // incidence and two faces: r_k = (1 + k) / (8 + 2k). Here T2 (tall) and T1 climb a
  // staircase around each other, alternately, as Fig. 7.3 begins it.
  const GridCoord n = 10, h = 40;
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, n, n));  // T1
  plan.addUnit(ShapeTree::canonical({n, 0}, 6, h));  // T2
  EXPECT_EQ(fq(plan), Fraction::of(1, 8));
  int west = kW;          // T2's west-facing piece that still has free length above the contact
  GridCoord contact = n;  // where, along it, the contact with T1 ends
  int top = kN;           // T1's top piece (runs east), whose east end is under T2
  GridCoord topLen = n;
  for (int k = 1; k <= 16; ++k) {
    if (k % 2) {  // T2 steps west over T1
      const SplitNodes s = plan.faceSplit(1, west, contact);
      ASSERT_GE(s.first, 0) << k;
      ASSERT_TRUE(plan.faceAdvance(1, s.second, 1)) << k;
      west = s.second;
      contact = 1;
    } else {  // T1 rises beside T2
      const SplitNodes s = plan.faceSplit(0, top, topLen - 1);
      ASSERT_GE(s.first, 0) << k;
      ASSERT_TRUE(plan.faceAdvance(0, s.first, 1)) << k;
      top = s.first;
      topLen -= 1;
    }
    ASSERT_EQ(fq(plan), Fraction::of(1 + k, 8 + 2 * k)) << "after move " << k;
  }
  EXPECT_EQ(fq(plan), Fraction::of(17, 40));
}

TEST(FormComplexity, TypeIMovesRaiseComplexityExactlyWhenXOverYIsBelowOneHalf) {
  // Sec. 7.2.1: r_{k+1} − r_k = (y0 − 2x0) / ((y0 + 2k + 2)(y0 + 2k)) with r_k = (x0+k)/(y0+2k).
  for (std::int64_t y0 = 8; y0 <= 40; y0 += 2)
    for (std::int64_t x0 = 0; x0 <= y0; ++x0)
      for (std::int64_t k = 0; k < 6; ++k) {
        const Fraction rk = Fraction::of(x0 + k, y0 + 2 * k), rk1 = Fraction::of(x0 + k + 1, y0 + 2 * k + 2);
        const Fraction d = rk1 - rk;
        EXPECT_EQ(d, Fraction::of(y0 - 2 * x0, (y0 + 2 * k + 2) * (y0 + 2 * k)));
        EXPECT_EQ(rk < rk1, 2 * x0 < y0);  // increases iff x0 / y0 < 1/2
      }
}

TEST(FormComplexity, ThreeSquaresWorstCaseStillRises) {
  // Sec. 7.2.1: three cubes at worst x0 = 3, y0 = 12 (two side by side, one across both on
  // top: links bottom–bottom, top–left, top–right). A Type I move on the left one's top
  // (free west of the top unit) gives 4/14 > 3/12.
  Floorplan plan;
  plan.addUnit(ShapeTree::canonical({0, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({4, 0}, 4, 4));
  plan.addUnit(ShapeTree::canonical({2, 4}, 4, 4));
  EXPECT_EQ(fq(plan), Fraction::of(3, 12));
  const SplitNodes s = plan.faceSplit(0, kN, 2);
  ASSERT_TRUE(plan.faceAdvance(0, s.first, 2));
  EXPECT_EQ(fq(plan), Fraction::of(4, 14));
  EXPECT_LT(Fraction::of(3, 12), fq(plan));
}

TEST(FormComplexity, RunningBondCounterexampleAboveOneHalfFalls) {
  // Fig. 7.7's point, with our own configuration: sixteen 4 × 4 squares in four rows, odd
  // rows shifted by 2 (running bond). Hand count: 4 rows × 3 side links = 12, 3 row pairs ×
  // 7 overlaps = 21; 33 links over 64 faces > 1/2. A Type I move then lowers F_q
  // (34/66 < 33/64): the criterion x0/y0 < 1/2 is needed.
  Floorplan plan;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) ASSERT_GE(plan.addUnit(ShapeTree::canonical({2 * (r % 2) + 4 * c, 4 * r}, 4, 4)), 0);
  const Fraction f0 = fq(plan);
  EXPECT_EQ(f0, Fraction::of(33, 64));
  EXPECT_LT(Fraction::of(1, 2), f0);
  // Row 1's last unit [14,18]×[4,8]: its south edge (x 18 → 14) touches row 0's last unit
  // over [14,16]; the piece 18 → 16 is free. Advance it south by 2: its new west-facing step
  // at x = 16 lands on row 0's last unit's east edge.
  const int unit = 1 * 4 + 3;
  const SplitNodes s = plan.faceSplit(unit, kS, 2);
  ASSERT_TRUE(plan.faceAdvance(unit, s.first, 2));
  EXPECT_EQ(plan.unit(unit).node(s.virtualNode).facing, Facing::West);
  EXPECT_EQ(fq(plan), Fraction::of(34, 66));
  EXPECT_LT(fq(plan), f0);
}

}  // namespace
}  // namespace corbel::growth
