// The parameter search (Sec. 4): envelope-theorem gradients against finite differences of y,
// searches that reach a hand-computed feasible region or stop at a local minimum, bad input.
#include "core/error.h"
#include "statics/arch.h"
#include "statics/examples.h"
#include "statics/search.h"
#include "statics/thresholds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <limits>
#include <string>

namespace corbel::statics {
namespace {

Parameter param(const std::string& name, double value, double lo, double hi) {
  Parameter p;
  p.name = name;
  p.value = value;
  p.lo = lo;
  p.hi = hi;
  return p;
}

// Two unit cubes on the ground, the top one moved by `offset` along x and `side` along y
// (the two-cube overhang of blocks_test, parametrised).
ParametricModel overhang(double offset) {
  ParametricModel m;
  m.name = "overhang";
  m.parameters.add(param("offset", offset, -0.95, 0.95));
  m.parameters.add(param("side", 0.0, -0.95, 0.95));
  m.build = [](const ParameterSet& p) {
    Assembly as;
    as.blocks.push_back(boxBlock("ground", Vec3(-3, -3, -1), Vec3(3, 3, 0), 1.0, true));
    as.blocks.push_back(boxBlock("bottom", Vec3(0, 0, 0), Vec3(1, 1, 1)));
    as.blocks.push_back(boxBlock("top", Vec3(p["offset"], p["side"], 1), Vec3(p["offset"] + 1, p["side"] + 1, 2)));
    return as;
  };
  return m;
}

// A semicircular arch of 20 voussoirs whose thickness is free: W changes with θ too.
ParametricModel thinArch(double t) {
  ParametricModel m;
  m.name = "arch";
  m.parameters.add(param("thickness", t, 0.01, 0.9));
  m.build = [](const ParameterSet& p) {
    ArchSpec s;
    s.blocks = 20;
    s.thickness = p["thickness"];
    return semicircularArch(s);
  };
  return m;
}

// Central differences of the measure itself: two extra QPs per parameter.
double differenceOfMeasure(const ParametricModel& m, const ParameterSet& at, const std::string& name, double h) {
  ParameterSet plus = at, minus = at;
  plus.set(name, at[name] + h);
  minus.set(name, at[name] - h);
  const double yp = analyse(m.build(plus)).yNormalised, ym = analyse(m.build(minus)).yNormalised;
  return (yp - ym) / (2 * h);
}

void expectGradientMatchesDifferences(const ParametricModel& m, const ParameterSet& at,
                                      const std::vector<FreeParameter>& free, double h) {
  const MeasureEvaluation ev = evaluateMeasure(m, at, free, {}, true);
  ASSERT_EQ(ev.analysis.status, SolveStatus::Optimal);
  ASSERT_GT(ev.measure, 1e-8) << "the check needs y > 0";
  ASSERT_EQ(ev.gradient.size(), free.size());
  std::vector<double> fd;
  double largest = 0;
  for (std::size_t k = 0; k < free.size(); ++k) {
    fd.push_back(differenceOfMeasure(m, at, free[k].name, h));
    largest = std::max(largest, std::abs(fd.back()));
  }
  ASSERT_GT(largest, 0.0);
  for (std::size_t k = 0; k < free.size(); ++k) {
    std::printf("%s %s: envelope %.10e, differences %.10e\n", m.name.c_str(), free[k].name.c_str(), ev.gradient[k], fd[k]);
    // 1e-5 relative; a component that vanishes (by symmetry) is held to 1e-5 of the gradient.
    EXPECT_NEAR(ev.gradient[k], fd[k], 1e-5 * std::max(std::abs(fd[k]), 1e-3 * largest)) << m.name << " " << free[k].name;
  }
}

TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheOverhang) {
  const ParametricModel m = overhang(0.7);
  ParameterSet at = m.parameters;
  at.set("side", 0.2);
  expectGradientMatchesDifferences(m, at, {{"offset", -0.9, 0.9}, {"side", -0.9, 0.9}}, 1e-5);
}

// At the edge of a parameter's valid range the geometry is differenced on one side only, and
// says so; the gradient still matches a one-sided difference of y (to its O(h) error).
TEST(ParameterSearch, EnvelopeGradientAtAValidRangeEdgeIsOneSided) {
  const ParametricModel m = overhang(0.95);  // the valid range ends at 0.95
  const MeasureEvaluation ev = evaluateMeasure(m, m.parameters, {{"offset", 0.5, 0.95}}, {}, true);
  ASSERT_EQ(ev.notes.size(), 1u);
  EXPECT_NE(ev.notes[0].find("one-sided (backward)"), std::string::npos) << ev.notes[0];
  const double h = 1e-6;
  ParameterSet below = m.parameters;
  below.set("offset", 0.95 - h);
  const double fd = (ev.measure - analyse(m.build(below)).yNormalised) / h;
  EXPECT_NEAR(ev.gradient[0], fd, 1e-4 * std::abs(fd));
}

TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheArchThickness) {
  const ParametricModel m = thinArch(0.05);
  expectGradientMatchesDifferences(m, m.parameters, {{"thickness", 0.02, 0.3}}, 1e-5);
}


TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheArchOnColumns) {
  const ParametricModel m = archOnColumnsExample();
  expectGradientMatchesDifferences(m, m.parameters, m.suggestedFree, 1e-5);
}

// Where the iterations stop short (strongly infeasible, vertical interfaces: docs/statics.md,
// "The polish") the gradient is the polished optimum's: it must match differences of y to
// 1e-5 as everywhere else (before the polish these agreed to about 1e-4).
TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheThinButtressedVault) {
  const ParametricModel m = barrelVaultExample();
  expectGradientMatchesDifferences(m, m.parameters, m.suggestedFree, 1e-5);
}

TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheLeaningTower) {
  const ParametricModel m = towerExample();
  // The first and the top levels' offsets: the base carries every level above it, the top
  // only itself.
  std::vector<FreeParameter> free;
  for (const FreeParameter& f : m.suggestedFree)
    if (f.name[0] == 'x') free.push_back(f);
  ASSERT_EQ(free.size(), 16u);
  expectGradientMatchesDifferences(m, m.parameters, free, 1e-5);
}

// The top cube tips past offset 1/2 (blocks_test): from 0.8 the search must come back to
// at most 1/2, and the strict LP test must agree that the result stands.
TEST(ParameterSearch, OverhangSearchStopsFeasibleInsideTheTippingOffset) {
  const ParametricModel m = overhang(0.8);
  for (const char* algorithm : {"slsqp", "mma", "lbfgs"}) {
    SearchOptions o;
    o.algorithm = algorithm;
    const SearchResult r = searchParameters(m, {{"offset", 0.0, 0.95}}, o);
    EXPECT_EQ(r.status, SearchStatus::Feasible) << algorithm << ": " << r.message;
    EXPECT_GT(r.initialMeasure, 1e-4);
    EXPECT_LE(r.measure, kFeasibleMeasure);
    EXPECT_LE(r.values["offset"], 0.5 + 1e-4) << algorithm;
    EXPECT_TRUE(r.standsStrictly || r.values["offset"] > 0.5 - 1e-4) << algorithm;
    EXPECT_EQ(int(r.history.size()), r.evaluations);
  }
}

// Bounds that exclude the feasible region: y decreases towards the lower bound 0.6 and the
// search must stop there, say it is a local minimum with y > 0, and not call it feasible.
TEST(ParameterSearch, BoundsWithoutAFeasibleStructureEndInALocalMinimum) {
  const ParametricModel m = overhang(0.8);
  const SearchResult r = searchParameters(m, {{"offset", 0.6, 0.95}});
  EXPECT_EQ(r.status, SearchStatus::LocalMinimum) << r.message;
  EXPECT_NEAR(r.values["offset"], 0.6, 1e-6);
  EXPECT_GT(r.measure, 1e-6);
  EXPECT_LT(r.measure, r.initialMeasure);
  EXPECT_FALSE(r.standsStrictly);
  EXPECT_EQ(r.projectedGradient, 0.0);  // the gradient pushes against the bound
}

// A thin 20-voussoir arch with free thickness: the search ends where the arch stands, at or
// just above the least thickness the strict bisection finds for 20 voussoirs.
TEST(ParameterSearch, ArchThicknessSearchReachesTheMinimumThicknessOrMore) {
  ArchSpec s;
  s.blocks = 20;
  const double least = minimumArchThickness(s, {}, 1e-6);
  const SearchResult r = searchParameters(thinArch(0.05), {{"thickness", 0.03, 0.3}});
  EXPECT_EQ(r.status, SearchStatus::Feasible) << r.message;
  EXPECT_GE(r.values["thickness"], least - 1e-3);
}

// An example that does not stand at its defaults (LP oracle) must end standing, and the
// strict LP test must agree with the search.
SearchResult expectMadeToStand(const ParametricModel& m) {
  EXPECT_FALSE(checkFeasibility(m.build(m.parameters)).feasible) << m.name;
  const SearchResult r = searchParameters(m, m.suggestedFree);
  EXPECT_EQ(r.status, SearchStatus::Feasible) << m.name << ": " << r.message;
  EXPECT_TRUE(r.standsStrictly) << m.name;
  return r;
}

// Fig. 11: the 32-parameter tower starts leaning over and must end standing.
TEST(ParameterSearch, TowerOfThirtyTwoParametersIsMadeToStand) {
  const ParametricModel m = towerExample();
  const SearchResult r = expectMadeToStand(m);
  EXPECT_TRUE(checkFeasibility(m.build(r.values)).feasible);
  for (const FreeParameter& f : m.suggestedFree) {
    EXPECT_GE(r.values[f.name], f.lo);
    EXPECT_LE(r.values[f.name], f.hi);
  }
}

// Fig. 9 and Table 1: the chapel (480 blocks) does not stand with its slender piers and thin
// walls, and its four-parameter search (pier width and depth, wall thickness, wall height)
// ends standing, inside the bounds.
TEST(ParameterSearch, ChapelOfFourParametersIsMadeToStand) {
  const ParametricModel m = chapelExample();
  ASSERT_EQ(m.suggestedFree.size(), 4u);
  const SearchResult r = expectMadeToStand(m);
  for (const FreeParameter& f : m.suggestedFree) {
    EXPECT_GE(r.values[f.name], f.lo);
    EXPECT_LE(r.values[f.name], f.hi);
  }
}

// Fig. 10 (c, d): radial flying buttresses carry the dome's thrust away from the drum, so the
// drum it needs is thinner with them than without. The least drum thickness that stands (LP
// bisection, the flyers' reach fixed, no windows) is the oracle for both.
TEST(ParameterSearch, RadialFlyersLetTheMosquesDrumBeThinner) {
  ParametricModel m = mosqueExample();
  m.parameters.set("reach", 1.7);
  m.parameters.set("windowWidth", 0.0);
  auto least = [&](int flyers) {
    ParameterSet p = m.parameters;
    p.set("flyers", flyers);
    return bisectThreshold(
        [&](double t) {
          p.set("drumThickness", t);
          return checkFeasibility(m.build(p)).feasible;
        },
        2.0, 0.25, 0.01, "drumThickness");  // a drum no thicker than the dome stands with neither
  };
  const double with = least(8), without = least(0);
  std::printf("least drum thickness: %.3f m with flyers, %.3f m without\n", with, without);
  EXPECT_LT(with, without - 0.05) << "with flyers " << with << " m, without " << without << " m";
  // And the search makes the default (a 0.3 m drum) stand.
  expectMadeToStand(mosqueExample());
}

// Fig. 10 (c, d): with the flyers the drum's windows can be as wide as the template allows
// (jambs of 5 % of a segment's inner chord), without them a 0.5 m drum stands only with
// windows about half as wide: the widest window that stands (LP bisection over its width,
// the drum and the flyers' reach fixed) is the oracle.
TEST(ParameterSearch, WithoutFlyersTheMosquesDrumNeedsSmallerWindows) {
  ParametricModel m = mosqueExample();
  m.parameters.set("reach", 1.7);
  m.parameters.set("drumThickness", 0.5);
  const double widest = 0.95;  // 0.9 of the inner chord 2 · 2.75 m · sin 11.25° = 1.073 m is 0.966 m
  auto standsWith = [&](int flyers, double width) {
    ParameterSet p = m.parameters;
    p.set("flyers", flyers);
    p.set("windowWidth", width);
    return checkFeasibility(m.build(p)).feasible;
  };
  EXPECT_TRUE(standsWith(8, widest));
  EXPECT_FALSE(standsWith(0, widest));
  const double without = bisectThreshold([&](double w) { return standsWith(0, w); }, 0.0, widest, 0.01, "windowWidth");
  std::printf("widest window in a 0.5 m drum: %.3f m without flyers, at least %.2f m with\n", without, widest);
  EXPECT_LT(without, widest - 0.2);
  EXPECT_GT(without, 0.1);  // a drum this thick does take some window
}

// Fig. 10 (a, d): the domed square hall without flyers does not stand with 0.9 m windows in
// its 0.5 m drum; the search narrows them until it stands, no wider than the widest window
// that stands (LP bisection).
TEST(ParameterSearch, TheMosqueHallsSearchNarrowsItsWindows) {
  const ParametricModel m = mosqueHallExample();
  ASSERT_EQ(m.suggestedFree.size(), 1u);
  const SearchResult r = expectMadeToStand(m);
  const double widest = bisectThreshold(
      [&](double w) {
        ParameterSet p = m.parameters;
        p.set("windowWidth", w);
        return checkFeasibility(m.build(p)).feasible;
      },
      0.1, 0.9, 0.005, "windowWidth");
  std::printf("mosque hall: the search's windows %.3f m, the widest that stand %.3f m\n", r.values["windowWidth"],
              widest);
  EXPECT_LT(r.values["windowWidth"], 0.9);
  EXPECT_LE(r.values["windowWidth"], widest + 0.005);
  EXPECT_GE(r.values["windowWidth"], 0.1);
}

// Fig. 13: as the span of the vault grows, the buttress width is searched again from the last
// result. Every update ends standing (LP oracle); a wider span never needs a narrower buttress
// than the last (the search starts there and only moves while the vault does not stand). Once
// the span makes the vault thinner than its arch can stand (t/R below the bisection's least
// thickness for 12 voussoirs), no buttress helps: a local minimum, never "feasible".
TEST(ParameterSearch, WideningTheVaultReSolvesTheButtressWidth) {
  const ParametricModel m = barrelVaultExample();
  const std::vector<FreeParameter> free = m.suggestedFree;
  SearchResult r = searchParameters(m, free);
  ASSERT_EQ(r.status, SearchStatus::Feasible) << r.message;
  double width = r.values["buttressWidth"];
  for (double radius : {2.1, 2.2}) {
    r = updateAfterEdit(m, free, r.values, "radius", radius);
    EXPECT_EQ(r.status, SearchStatus::Feasible) << radius << ": " << r.message;
    EXPECT_TRUE(r.standsStrictly) << radius;
    EXPECT_EQ(r.values["radius"], radius);
    EXPECT_GE(r.values["buttressWidth"], width - 1e-12) << radius;
    width = r.values["buttressWidth"];
  }
  ArchSpec ring;
  ring.blocks = 12;
  const double least = minimumArchThickness(ring, {}, 1e-5);
  const double tooWide = 1.1 * m.parameters["thickness"] / least;
  const SearchResult wide = updateAfterEdit(m, free, r.values, "radius", tooWide);
  EXPECT_EQ(wide.status, SearchStatus::LocalMinimum) << wide.message;
  EXPECT_FALSE(wide.standsStrictly);
  EXPECT_THROW(updateAfterEdit(m, free, r.values, "buttressWidth", 1.0), Error);
}

TEST(ParameterSearch, EnvelopeGradientMatchesDifferencesOnTheBezierArch) {
  const ParametricModel m = bezierArchExample();
  ParameterSet at = m.parameters;
  at.set("x2", 0.7);  // asymmetric: both components differ
  expectGradientMatchesDifferences(m, at, m.suggestedFree, 1e-5);
}

// Fig. 12: the round thin arch does not stand; moving the inner control points makes one that
// does (LP oracle), and as the start and the bounds are mirror-symmetric, so is the result.
TEST(ParameterSearch, BezierArchSearchFindsAStandingShape) {
  const SearchResult r = expectMadeToStand(bezierArchExample());
  EXPECT_NEAR(r.values["x1"], -r.values["x2"], 1e-6);
}

// Fig. 13 with flyers: the short flyers (reach 0.6 m) do not hold the vault's thrust; the
// search lengthens them until it stands, and widening the vault never shortens them again.
TEST(ParameterSearch, FlyingButtressesAreLengthenedUntilTheVaultStands) {
  const ParametricModel m = flyingButtressVaultExample();
  const SearchResult r = expectMadeToStand(m);
  EXPECT_GT(r.values["reach"], m.parameters["reach"]);
  const SearchResult wider = updateAfterEdit(m, m.suggestedFree, r.values, "radius", 2.2);
  EXPECT_EQ(wider.status, SearchStatus::Feasible) << wider.message;
  EXPECT_TRUE(wider.standsStrictly);
  EXPECT_GE(wider.values["reach"], r.values["reach"] - 1e-12);
}

// The progress callback sees every evaluation and can stop the search (the editor's Cancel).
TEST(ParameterSearch, ProgressCallbackCancels) {
  const ParametricModel m = towerExample();
  SearchOptions o;
  int seen = 0;
  o.progress = [&](const SearchProgress& p) {
    ++seen;
    EXPECT_EQ(p.evaluation, seen);
    EXPECT_EQ(p.values.size(), m.suggestedFree.size());
    return false;
  };
  const SearchResult r = searchParameters(m, m.suggestedFree, o);
  EXPECT_EQ(r.status, SearchStatus::Cancelled) << r.message;
  EXPECT_EQ(seen, 1);
  EXPECT_EQ(r.evaluations, 1);
}

TEST(ParameterSearch, BadFreeParametersGetAClearError) {
  auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const ParametricModel m = overhang(0.8);
  EXPECT_NE(message([&] { searchParameters(m, {{"ofset", 0, 1}}); }).find("unknown parameter 'ofset' (parameters: offset, side)"),
            std::string::npos);
  EXPECT_NE(message([&] { searchParameters(m, {{"offset", 0.5, 0.2}}); }).find("lo > hi"), std::string::npos);
  EXPECT_NE(message([&] { searchParameters(m, {{"offset", 0.0, 2.0}}); }).find("valid range"), std::string::npos);
  EXPECT_NE(message([&] { searchParameters(m, {{"offset", 0, 0.9}, {"offset", 0, 0.9}}); }).find("twice"), std::string::npos);
  EXPECT_NE(message([&] { searchParameters(m, {}); }).find("no free parameters"), std::string::npos);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message([&] { searchParameters(m, {{"offset", nan, 0.5}}); }).find("finite"), std::string::npos);
  SearchOptions o;
  o.algorithm = "simplex";
  EXPECT_NE(message([&] { searchParameters(m, {{"offset", 0, 0.9}}, o); }).find("unknown algorithm 'simplex'"),
            std::string::npos);
  const ParametricModel arch = archOnColumnsExample();
  EXPECT_NE(message([&] { searchParameters(arch, {{"voussoirs", 4, 10}}); }).find("is a count"), std::string::npos);
  // The command-line form NAME=LO:HI.
  const FreeParameter f = parseFreeParameter("thickness=0.05:0.5");
  EXPECT_EQ(f.name, "thickness");
  EXPECT_EQ(f.lo, 0.05);
  EXPECT_EQ(f.hi, 0.5);
  EXPECT_NE(message([] { parseFreeParameter("thickness"); }).find("NAME=LO:HI"), std::string::npos);
  EXPECT_NE(message([] { parseFreeParameter("thickness=0.1"); }).find("no ':'"), std::string::npos);
  EXPECT_NE(message([] { parseFreeParameter("thickness=nan:1"); }).find("not a finite number"), std::string::npos);
  EXPECT_NE(message([] { parseFreeParameter("thickness=1:0.5"); }).find("lower bound is above"), std::string::npos);
  ParameterSet p = m.parameters;
  EXPECT_NE(message([&] { p.set("offset", nan); }).find("finite"), std::string::npos);
}

}  // namespace
}  // namespace corbel::statics
