// Geometry sizing (Sec. 7.3.4): the moving-segment heuristic against a hand-solvable case,
// and on generated forms: the maximum area error never grows, the passes are bounded, no
// rectangle inverts and ≺x / ≺z are kept.
#include "growth/sizing.h"

#include "grid_oracle.h"
#include "growth/completion.h"

#include <gtest/gtest.h>

#include <random>

namespace corbel::growth {
namespace {

TEST(Sizing, TwoSubUnitsMeetHalfWay) {
  // Two sub-units side by side in a 10 × 10 box, the shared side at x = 2: equal targets
  // (50 each) put it at x = 5.
  Layout l;
  l.rects = {{0, 0, 2, 10}, {2, 0, 10, 10}};
  l.unit = {0, 1};
  EXPECT_DOUBLE_EQ(maxAreaError(l), 0.6);  // 20 against 50, and 80
  const SizingResult r = sizeGeometry(l);
  EXPECT_EQ(r.segments, 1);
  EXPECT_NEAR(l.rects[0].x1, 5.0, 1e-2);
  EXPECT_EQ(l.rects[0].x1, l.rects[1].x0);
  EXPECT_LT(r.after, 1e-2);
  EXPECT_DOUBLE_EQ(r.before, 0.6);
}

TEST(Sizing, ASegmentMovesAloneAndStopsAtCorners) {
  // Three sub-units: A = [0,4]×[0,10] left, B = [4,10]×[0,5], C = [4,10]×[5,10]. The side
  // between B and C (y = 5, from x = 4 to 10) is one segment, the side x = 4 another. Targets
  // are 100/3 each; B and C already equal, so the split at x = 4 must move to 10/3 while
  // the B–C side stays at y = 5.
  Layout l;
  l.rects = {{0, 0, 4, 10}, {4, 0, 10, 5}, {4, 5, 10, 10}};
  l.unit = {0, 1, 2};
  const SizingResult r = sizeGeometry(l);
  EXPECT_EQ(r.segments, 2);
  EXPECT_NEAR(l.rects[0].x1, 10.0 / 3.0, 1e-2);
  EXPECT_EQ(l.rects[1].x0, l.rects[0].x1);
  EXPECT_EQ(l.rects[2].x0, l.rects[0].x1);
  EXPECT_NEAR(l.rects[1].y1, 5.0, 1e-2);
  EXPECT_LT(r.after, 1e-2);
}

TEST(Sizing, GeneratedFormsGetEvenerWithoutInversion) {
  const FormSet set = generateForms(test::formRequest(5, Fraction::of(3, 10), Fraction::of(4, 10), 6));
  ASSERT_GE(set.forms.size(), 4u);
  double sumBefore = 0, sumAfter = 0;
  for (const Form& f : set.forms) {
    Cartogram c = Cartogram::of(f.plan);
    fitToRegion(c, {0, 0, 30, 20});
    Layout l = Layout::of(c);
    const Relations before = relationsOf(l.rects);
    SizingOptions o;
    o.maxPasses = 150;
    o.minWidth = 0.4;
    const SizingResult r = sizeGeometry(l, o);
    EXPECT_LE(r.after, r.before + 1e-12);
    EXPECT_LE(r.passes, o.maxPasses);
    EXPECT_GT(r.moves, 0);
    sumBefore += r.before;
    sumAfter += r.after;
    double area = 0;
    for (const PlanRect& g : l.rects) {
      EXPECT_GE(g.x1 - g.x0, o.minWidth - 1e-9);
      EXPECT_GE(g.y1 - g.y0, o.minWidth - 1e-9);
      area += g.area();
    }
    EXPECT_NEAR(area, 600.0, 1e-6);  // still tiles the region
    // Segments moved one by one: the corners' order along every segment, so ≺x and ≺z for
    // every pair of corners, are those of the unsized form.
    EXPECT_EQ(relationsOf(l.rects), before);
  }
  RecordProperty("mean_error_before", std::to_string(sumBefore / double(set.forms.size())));
  RecordProperty("mean_error_after", std::to_string(sumAfter / double(set.forms.size())));
  EXPECT_LT(sumAfter, 0.8 * sumBefore);
}

TEST(EdgeMoves, CascadingMovePushesTheNextSide) {
  // Fig. 7.16-7.17: three rectangles in a row, [0,2] [2,4] [4,10] (× [0,4]). Bringing the
  // first one's south-east corner to x = 5 squeezes the middle one to minWidth = 0.5, so the
  // side at x = 4 is pushed on to 5.5.
  Layout l;
  l.rects = {{0, 0, 2, 4}, {2, 0, 4, 4}, {4, 0, 10, 4}};
  l.unit = {0, 1, 2};
  std::string why;
  ASSERT_TRUE(realizeBySegments(l, {{{0, 1}, 5.0, 0.0}}, 0.5, &why)) << why;
  EXPECT_DOUBLE_EQ(l.rects[0].x1, 5.0);
  EXPECT_DOUBLE_EQ(l.rects[1].x0, 5.0);
  EXPECT_DOUBLE_EQ(l.rects[1].x1, 5.5);
  EXPECT_DOUBLE_EQ(l.rects[2].x0, 5.5);
  // Past the box's side it cannot go.
  EXPECT_FALSE(realizeBySegments(l, {{{0, 1}, 9.8, 0.0}}, 0.5, &why));
  EXPECT_DOUBLE_EQ(l.rects[0].x1, 5.0);
}

TEST(EdgeMoves, StaircaseMovePushesTheStepAbove) {
  // Fig. 7.18: bottom row A = [0,4]×[0,2], B = [4,10]×[0,2]; top row C = [0,6]×[2,4],
  // D = [6,10]×[2,4]. e1 (x = 4, below y = 2) and e2 (x = 6, above) are one step apart.
  // Moving e1 to x = 7 would slide its end past e2's on y = 2, so e2 goes to 7.5, and A's
  // south-east corner stays ≺x C's south-east corner.
  Layout l;
  l.rects = {{0, 0, 4, 2}, {4, 0, 10, 2}, {0, 2, 6, 4}, {6, 2, 10, 4}};
  l.unit = {0, 1, 2, 3};
  const Relations before = relationsOf(l.rects);
  ASSERT_TRUE(before.x[1][2 * 4 + 1]);  // A.SE ≺x C.SE
  std::string why;
  ASSERT_TRUE(realizeBySegments(l, {{{0, 1}, 7.0, 0.0}}, 0.5, &why)) << why;
  EXPECT_DOUBLE_EQ(l.rects[0].x1, 7.0);
  EXPECT_DOUBLE_EQ(l.rects[2].x1, 7.5);
  EXPECT_DOUBLE_EQ(l.rects[3].x0, 7.5);
  EXPECT_EQ(relationsOf(l.rects), before);
}

TEST(EdgeMoves, RandomTargetsKeepBothRelationsOrChangeNothing) {
  // Property: on generated forms fitted into a region, a random corner sent a few meters
  // away either lands there with ≺x and ≺z unchanged for every pair of corners and every
  // rectangle still minWidth wide, or the layout is left exactly as it was.
  std::mt19937_64 rng(5);
  int moved = 0, refused = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const Form& f : generateForms(test::formRequest(4, Fraction::of(3, 10), Fraction::of(4, 10), 3, seed)).forms) {
      Cartogram c = Cartogram::of(f.plan);
      fitToRegion(c, {0, 0, 30, 20});
      for (int trial = 0; trial < 10; ++trial) {
        Layout l = Layout::of(c);
        const Relations before = relationsOf(l.rects);
        const CornerRef corner{int(rng() % l.rects.size()), int(rng() % 4)};
        const auto at = cornerAt(l.rects, corner);
        const Correspondence t{corner, at[0] + double(int(rng() % 9) - 4) * 0.5,
                               at[1] + double(int(rng() % 9) - 4) * 0.5};
        const Layout was = l;
        if (!realizeBySegments(l, {t}, 0.4)) {
          ++refused;
          for (std::size_t i = 0; i < l.rects.size(); ++i) EXPECT_EQ(l.rects[i].x0, was.rects[i].x0);
          continue;
        }
        ++moved;
        const auto now = cornerAt(l.rects, corner);
        EXPECT_NEAR(now[0], t.x, 1e-9);
        EXPECT_NEAR(now[1], t.y, 1e-9);
        for (const PlanRect& r : l.rects) EXPECT_GE(std::min(r.x1 - r.x0, r.y1 - r.y0), 0.4 - 1e-9);
        EXPECT_EQ(relationsOf(l.rects), before);
      }
    }
  RecordProperty("moved", moved);
  RecordProperty("refused", refused);
  EXPECT_GT(moved, refused);
}

}  // namespace
}  // namespace corbel::growth
