// Geometry sizing (Sec. 7.3.4): the moving-segment heuristic against a hand-solvable case,
// and on generated forms: the maximum area error never grows, the passes are bounded, no
// rectangle inverts and ≺x / ≺z are kept.
#include "growth/sizing.h"

#include "growth/completion.h"
#include "grid_oracle.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

TEST(Sizing, TwoSubUnitsMeetHalfWay) {
  // Two sub-units side by side in a 10 × 10 box, the shared side at x = 2: equal targets
  // (50 each) put it at x = 5.
  Cartogram c;
  c.xs = {0, 2, 10};
  c.ys = {0, 10};
  c.rects = {{0, 0, 1, 1, 0}, {1, 0, 2, 1, 1}};
  EXPECT_DOUBLE_EQ(maxAreaError(c), 0.6);  // 20 against 50, and 80
  const SizingResult r = sizeGeometry(c);
  EXPECT_NEAR(c.xs[1], 5.0, 1e-2);
  EXPECT_LT(r.after, 1e-2);
  EXPECT_DOUBLE_EQ(r.before, 0.6);
}

TEST(Sizing, GeneratedFormsGetEvenerWithoutInversion) {
  const FormSet set = generateForms(test::formRequest(5, Fraction::of(3, 10), Fraction::of(4, 10), 6));
  ASSERT_GE(set.forms.size(), 4u);
  double sumBefore = 0, sumAfter = 0;
  for (const Form& f : set.forms) {
    Cartogram c = Cartogram::of(f.plan);
    fitToRegion(c, {0, 0, 30, 20});
    const Relations before = relationsOf(c.geometry());
    SizingOptions o;
    o.maxPasses = 150;
    o.minWidth = 0.4;
    const SizingResult r = sizeGeometry(c, o);
    EXPECT_LE(r.after, r.before + 1e-12);
    EXPECT_LE(r.passes, o.maxPasses);
    sumBefore += r.before;
    sumAfter += r.after;
    double area = 0;
    for (const PlanRect& g : c.geometry()) {
      EXPECT_GE(g.x1 - g.x0, o.minWidth - 1e-9);
      EXPECT_GE(g.y1 - g.y0, o.minWidth - 1e-9);
      area += g.area();
    }
    EXPECT_NEAR(area, 600.0, 1e-6);  // still tiles the region
    EXPECT_EQ(relationsOf(c.geometry()), before);
  }
  EXPECT_LT(sumAfter, 0.8 * sumBefore);
}

}  // namespace
}  // namespace corbel::growth
