// A completed form among a grown model obeys the growth rules it sits among (growth/form_fit.h's
// formViolations, growth/sizing.h's room width): judged against hand-placed boxes and against
// the independent constraint check of support.h on the shipped housing example.
#include "core/document.h"
#include "core/project_io.h"
#include "growth/completion.h"
#include "growth/constraints.h"
#include "growth/entrances.h"
#include "growth/form_fit.h"
#include "growth/kernel.h"
#include "growth/tolerances.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

namespace corbel::growth {
namespace {

using test::box;
using test::unitOf;

// A one-storey 60 × 30 m site with a core at x 32–36, y 10–20 (clearance 1 m) and one grown
// unit at x 20–30, y 0–6.
struct Model {
  Site site;
  std::vector<Unit> units;
  Model() {
    site = test::openSite(60, 30, 1);
    site.cores.push_back({32, 10, 36, 20});
    units.push_back(unitOf(1, {box(20, 0, 0, 30, 6, 3)}));
  }
};

FittedForm formOf(std::vector<std::vector<Box>> parts) {
  FittedForm f;
  for (std::size_t k = 0; k < parts.size(); ++k) f.units.push_back(unitOf(int(k) + 1, parts[k]));
  return f;
}

TEST(FormRules, AFormThatKeepsEveryRuleBreaksNone) {
  const Model m;
  // 1 m from the core (its clearance, exactly), rooms 3 m and 4 m wide, beside the grown unit.
  const FittedForm f = formOf({{box(37, 10, 0, 40, 20, 3)}, {box(40, 10, 0, 44, 20, 3)}, {box(30, 0, 0, 34, 6, 3)}});
  EXPECT_TRUE(formViolations(m.site, m.units, f).empty());
  std::vector<Unit> all = m.units;
  for (const Unit& u : f.units) all.push_back(u), all.back().id += 10;
  EXPECT_TRUE(test::independentViolations(m.site, all).empty());
}

TEST(FormRules, EachBrokenRuleIsNamedWithTheFormsUnit) {
  const Model m;
  const FittedForm f = formOf({
      {box(40, 10, 0, 42.61, 20, 3)},  // 2.61 m wide: a room under 3 m
      {box(36.5, 19, 0, 40, 25, 3)},   // 0.5 m east of the core (its clearance is 1 m)
      {box(27, 3, 0, 31, 9, 3)},       // into the grown unit
      {box(56, 20, 0, 62, 26, 3)},     // past the envelope's east side
  });
  const std::vector<std::string> v = formViolations(m.site, m.units, f);
  auto has = [&](const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); };
  EXPECT_TRUE(has("form unit 1 part 0: under 3 m x 3 m"));
  EXPECT_TRUE(has("form unit 2 part 0: within the clearance of a core or circulation"));
  EXPECT_TRUE(has("form unit 3 part 0: overlaps unit 1 part 0"));
  EXPECT_TRUE(has("form unit 4 part 0: outside the envelope"));
  EXPECT_EQ(v.size(), 4u) << ::testing::PrintToString(v);
}

TEST(FormRules, WhatTheModelBreaksOnItsOwnIsNotTheForms) {
  Model m;
  m.units.push_back(unitOf(2, {box(0, 20, 0, 2, 30, 3)}));  // a grown unit 2 m wide
  EXPECT_FALSE(ConstraintEnforcer(m.site).violations(m.units).empty());
  EXPECT_TRUE(formViolations(m.site, m.units, formOf({{box(40, 0, 0, 44, 6, 3)}})).empty());
}

TEST(FormRules, TheClearanceZonesAreTheCoresAndCirculationGrownByTheirClearances) {
  Site s = test::openSite(60, 30, 2);
  s.cores.push_back({32, 10, 36, 20});
  s.circulation.push_back(box(10, 10, 0, 14, 12, 3));
  s.circulationClearance = 0.5;
  const std::vector<Box> z = clearanceZones(s);
  ASSERT_EQ(z.size(), 2u);
  EXPECT_EQ(z[0].lo, Vec3(31, 9, 0));
  EXPECT_EQ(z[0].hi, Vec3(37, 21, 6));
  EXPECT_EQ(z[1].lo, Vec3(9.5, 9.5, 0));
  EXPECT_EQ(z[1].hi, Vec3(14.5, 12.5, 3));
}

// Two 12 × 12 units side by side fitted into a region 5 m wide and 16 m deep: laid as they come
// each is 2.5 m wide; with the growth's room width the form is turned, each 5 × 8 m.
TEST(FormRules, AShallowRegionTurnsTheFormSoItsRoomsAreThreeMetresWide) {
  const PlanRect region{0, 0, 5, 16};
  FitOptions o;
  const FittedForm plain = fitForm(canonicalRow(2, 12), region, {}, o);
  EXPECT_NEAR(roomShortfall(plain.layout, kMinPartWidth), 2 * 0.5, 1e-9);
  o.roomWidth = kMinPartWidth;
  const FittedForm turned = fitForm(canonicalRow(2, 12), region, {}, o);
  EXPECT_EQ(roomShortfall(turned.layout, kMinPartWidth), 0.0);
  for (const Unit& u : turned.units) {
    ASSERT_EQ(u.parts.size(), 1u);
    EXPECT_DOUBLE_EQ(u.parts[0].size(0), 5);
    EXPECT_DOUBLE_EQ(u.parts[0].size(1), 8);
  }
}

// The shipped housing example as `corbel-cli complete --from` takes it, on storeys 0 and 1: the
// gap keeps the cores' clearance, and each fitted form's verdict is the independent check's.
TEST(FormRules, FormsInTheHousingExampleAreJudgedAsTheIndependentCheckJudgesThem) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/housing-alpha.corbel");
  const GrowthSpec* spec = nullptr;
  for (const DocObject& o : p.document.objects)
    if (const auto* g = std::get_if<GrowthSpec>(&o.spec)) spec = g;
  ASSERT_NE(spec, nullptr);
  const GrownModel model = grow(*spec);
  const Site& site = model.site;
  int id = 0;
  for (const Unit& u : model.units) id = std::max(id, u.id);
  int fits = 0, forms = 0;
  for (int storey : {0, 1}) {
    const EntranceOptions eo = storeyOptions(site, storey);
    const Box b = site.bounds();
    PlanRect region;
    ASSERT_TRUE(findGap(model.units, clearanceZones(site), {b.lo[0], b.lo[1], b.hi[0], b.hi[1]}, eo, kGapMinSide,
                        kGapMaxSide, region));
    const double z0 = site.base + storey * site.storeyHeight;
    const Box gap{{region.x0, region.y0, z0}, {region.x1, region.y1, z0 + site.storeyHeight}};
    for (std::size_t c = 0; c < site.cores.size(); ++c)
      EXPECT_GE(test::gapInPlan(gap, site.coreBox(c)), site.coreClearance - 1e-9) << "core " << c;
    std::vector<Vec2> doors;
    for (const Entrance& e : entrancesInRegion(model.units, region, eo, entranceObstacles(site)))
      doors.push_back(e.at);
    ASSERT_FALSE(doors.empty());
    for (std::uint64_t seed : {1, 2, 3}) {
      FormRequest rq;
      rq.seeds = int(doors.size());
      rq.lo = Fraction::of(1, 5);
      rq.hi = Fraction::of(9, 20);
      rq.count = 8;
      rq.seed = seed;
      for (const Form& form : generateForms(rq).forms) {
        FitOptions o;
        o.z0 = z0;
        o.storeyHeight = site.storeyHeight;
        o.roomWidth = kMinPartWidth;
        const FittedForm f = fitForm(form.plan, region, doors, o);
        std::vector<Unit> all = model.units;
        for (Unit u : f.units) u.id += id, all.push_back(u);
        const bool ours = formViolations(site, model.units, f).empty();
        const bool independent = test::independentViolations(site, all).empty();
        EXPECT_EQ(ours, independent) << "storey " << storey << ", seed " << seed << ", form " << forms;
        fits += ours;
        ++forms;
      }
    }
  }
  EXPECT_GE(forms, 16);
  EXPECT_GE(fits, 1);
}

}  // namespace
}  // namespace corbel::growth
