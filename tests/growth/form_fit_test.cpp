// growth/form_fit.h: a generated form fitted into a region (Fig. 8.6) has its bounding box on the
// region exactly, tiles it with its sub-units and sea, keeps every unit inside it, and, given
// entrances, gives each to a different unit.
#include "growth/form_fit.h"

#include "core/error.h"
#include "growth/completion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

namespace corbel::growth {
namespace {

struct Bounds {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
};
Bounds boundsOf(const Layout& l) {
  Bounds b;
  for (const PlanRect& r : l.rects) b.x0 = std::min(b.x0, r.x0), b.y0 = std::min(b.y0, r.y0), b.x1 = std::max(b.x1, r.x1), b.y1 = std::max(b.y1, r.y1);
  return b;
}

void expectFitted(const FittedForm& f, const PlanRect& region, int units) {
  const Bounds b = boundsOf(f.layout);
  EXPECT_EQ(b.x0, region.x0);  // exact: the corners are mapped onto the region's corners
  EXPECT_EQ(b.y0, region.y0);
  EXPECT_EQ(b.x1, region.x1);
  EXPECT_EQ(b.y1, region.y1);
  double area = 0;
  for (const PlanRect& r : f.layout.rects) area += r.area();
  EXPECT_NEAR(area, region.area(), 1e-9 * region.area());  // sub-units and sea tile the region
  ASSERT_EQ(int(f.units.size()), units);
  for (const Unit& u : f.units) {
    EXPECT_FALSE(u.parts.empty());
    for (const Box& p : u.parts) {
      EXPECT_GE(p.lo[0], region.x0);
      EXPECT_LE(p.hi[0], region.x1);
      EXPECT_GE(p.lo[1], region.y0);
      EXPECT_LE(p.hi[1], region.y1);
      EXPECT_LT(p.lo[0], p.hi[0]);
      EXPECT_LT(p.lo[1], p.hi[1]);
    }
  }
}

TEST(FormFit, ACanonicalRowIsStretchedProportionallyOntoTheRegion) {
  // Three 12 × 12 squares (36 × 12) onto 30 × 12: each unit 10 m wide, in order.
  const PlanRect region{10, 20, 40, 32};
  FitOptions o;
  o.size = false;
  o.orientation = 0;
  o.z0 = 6;
  const FittedForm f = fitForm(canonicalRow(3, 12), region, {}, o);
  expectFitted(f, region, 3);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(f.units[std::size_t(i)].parts.size(), 1u);
    const Box& b = f.units[std::size_t(i)].parts[0];
    EXPECT_DOUBLE_EQ(b.lo[0], 10 + 10 * i);
    EXPECT_DOUBLE_EQ(b.hi[0], 20 + 10 * i);
    EXPECT_DOUBLE_EQ(b.lo[1], 20);
    EXPECT_DOUBLE_EQ(b.hi[1], 32);
    EXPECT_DOUBLE_EQ(b.lo[2], 6);
    EXPECT_DOUBLE_EQ(b.hi[2], 9);
  }
}

TEST(FormFit, AQuarterTurnLaysTheRowUpTheRegion) {
  EXPECT_EQ(orient(1, Vec2(1, 0)), Vec2(0, 1));
  EXPECT_EQ(orient(4, Vec2(1, 2)), Vec2(-1, 2));
  const PlanRect region{0, 0, 12, 36};
  FitOptions o;
  o.size = false;
  o.orientation = 1;  // (x, y) → (−y, x): unit 0 (least x) ends lowest
  const FittedForm f = fitForm(canonicalRow(3, 12), region, {}, o);
  expectFitted(f, region, 3);
  for (int i = 0; i < 3; ++i) {
    const Box& b = f.units[std::size_t(i)].parts[0];
    EXPECT_DOUBLE_EQ(b.lo[1], 12 * i);
    EXPECT_DOUBLE_EQ(b.hi[1], 12 * (i + 1));
    EXPECT_DOUBLE_EQ(b.lo[0], 0);
    EXPECT_DOUBLE_EQ(b.hi[0], 12);
  }
}

TEST(FormFit, GeneratedFormsSizedStillFillTheRegionExactly) {
  FormRequest rq;
  rq.seeds = 5;
  rq.count = 4;
  const FormSet set = generateForms(rq);
  ASSERT_FALSE(set.forms.empty());
  const PlanRect region{36, 13, 54, 38};
  for (const Form& form : set.forms) {
    const FittedForm f = fitForm(form.plan, region);
    expectFitted(f, region, 5);
    EXPECT_LE(f.sizing.after, f.sizing.before + 1e-12);
  }
}

TEST(FormFit, EachEntranceIsTakenByADifferentUnitInTheNearestOrientation) {
  const FormSet set = generateForms(FormRequest{});
  ASSERT_FALSE(set.forms.empty());
  const Floorplan& plan = set.forms[0].plan;
  const PlanRect region{0, 0, 30, 20};
  const std::vector<Vec2> entrances{{0, 10}, {30, 10}, {15, 20}, {15, 0}, {0, 0}};
  FitOptions unsized;
  unsized.size = false;  // the orientation is chosen before sizing
  const FittedForm chosen = fitForm(plan, region, entrances, unsized);
  expectFitted(chosen, region, 5);
  expectFitted(fitForm(plan, region, entrances), region, 5);
  std::set<int> taken;
  for (int e : chosen.entranceOf) {
    ASSERT_GE(e, 0);
    EXPECT_TRUE(taken.insert(e).second);
  }
  for (int g = 0; g < 8; ++g) {
    FitOptions o = unsized;
    o.orientation = g;
    EXPECT_LE(chosen.entranceDistance, fitForm(plan, region, entrances, o).entranceDistance + 1e-9) << g;
  }
}

TEST(FormFit, AnEmptyFormOrRegionIsAnInputError) {
  EXPECT_THROW(fitForm(Floorplan{}, {0, 0, 10, 10}), InputError);
  EXPECT_THROW(fitForm(canonicalRow(2, 12), {0, 0, 0, 10}), InputError);
}

}  // namespace
}  // namespace corbel::growth
