// statics/loads.h and the template models (statics/template_models.h): loads an artist places
// on a masonry object, against hand-computed tipping, and each template alone on the ground.
#include "statics/loads.h"

#include "core/error.h"
#include "statics/analysis.h"
#include "statics/kernel.h"
#include "statics/template_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

namespace corbel::statics {
namespace {

// One square drum of side w and height h on the ground (the column template, sides 4: the
// circumradius w/√2 puts a flat side facing +x), with friction well above what sliding needs,
// so only tipping decides.
MasonrySpec squareBlock(double w, double h) {
  MasonrySpec s;
  s.model = "column";
  s.parameters = {{"drums", 1}, {"height", h}, {"radius", w / std::sqrt(2.0)}, {"sides", 4}};
  s.friction = 2.0;
  return s;
}

bool standsByLp(const MasonrySpec& spec) {
  const ParametricModel m = modelOf(spec);
  AnalysisOptions o;
  o.friction = spec.friction;
  return checkFeasibility(m.build(m.parameters), o).feasible;
}

double weightOf(const MasonrySpec& spec) {
  const ParametricModel m = modelOf(spec);
  const Assembly a = m.build(m.parameters);
  return analyse(a).totalWeight;
}

// A horizontal force F at the top of a free block of weight W, width w, height h tips it about
// its far bottom edge once F·h > W·w/2 (moments about that edge); sliding would need F > αW.
TEST(MasonryLoads, AHorizontalPointLoadAtTheTopTipsABlockPastWTimesHalfWOverH) {
  const double w = 0.4, h = 2.0;
  MasonrySpec spec = squareBlock(w, h);
  const double W = weightOf(spec);
  EXPECT_NEAR(W, 2400 * 9.81 * w * w * h, 1e-6 * W) << "the block the test means";
  const double critical = W * (w / 2) / h;
  for (const double factor : {0.97, 1.03}) {
    // The top face's centre, from the block's centre: (0, 0, h/2).
    spec.loads = {{"push", "column/drum 0", Vec3(0, 0, h / 2), Vec3(factor * critical, 0, 0), -1, 0.0}};
    EXPECT_EQ(standsByLp(spec), factor < 1) << factor;
  }
  // The same force at mid-height needs twice as much to tip the block.
  spec.loads = {{"push", "column/drum 0", Vec3(0, 0, 0), Vec3(1.9 * critical, 0, 0), -1, 0.0}};
  EXPECT_TRUE(standsByLp(spec));
}

// A pressure p on the −x face (area w·h, resultant p·w·h at mid-height) tips the block once
// p·w·h·h/2 > W·w/2, that is p > W/h².
TEST(MasonryLoads, APressureOnASideFaceTipsABlockPastWOverHSquared) {
  const double w = 0.4, h = 2.0;
  MasonrySpec spec = squareBlock(w, h);
  const double W = weightOf(spec);
  const ParametricModel m = modelOf(spec);
  const Assembly a = m.build(m.parameters);
  const Block& b = a.blocks.front();
  ASSERT_EQ(b.name, "column/drum 0");
  int minusX = -1;
  for (std::size_t f = 0; f < b.faces.size(); ++f) {
    std::vector<Vec3> corners;
    for (int v : b.faces[f]) corners.push_back(b.vertices[std::size_t(v)]);
    const Vec3 n = newellNormal(corners).normalized();
    if (n[0] < -0.999) minusX = int(f);
  }
  ASSERT_GE(minusX, 0);
  const double critical = W / (h * h);
  spec.loads = {{"wind", "column/drum 0", Vec3(0.0), Vec3(0.0), minusX, 1.0}};
  // The resolved force: p·A pushing into the face (+x), at the face's centre (x = −w/2, z = h/2).
  const std::vector<ResolvedLoad> r = resolveLoads(a, spec.loads);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0].load.force[0], w * h, 1e-12);
  EXPECT_NEAR(r[0].load.force[1], 0, 1e-12);
  EXPECT_NEAR(r[0].load.force[2], 0, 1e-12);
  EXPECT_NEAR(r[0].load.at[0], -w / 2, 1e-12);
  EXPECT_NEAR(r[0].load.at[2], h / 2, 1e-12);
  for (const double factor : {0.97, 1.03}) {
    spec.loads[0].pressure = factor * critical;
    EXPECT_EQ(standsByLp(spec), factor < 1) << factor;
  }
}

// A load keeps to its block by name when a parameter changes the block's size: the offset is
// from the block's centre, so a load at the top stays at the top.
TEST(MasonryLoads, ALoadFollowsItsBlockWhenTheModelChanges) {
  MasonrySpec spec = squareBlock(0.4, 2.0);
  spec.loads = {{"bell", "column/drum 0", Vec3(0, 0, 1.0), Vec3(0, 0, -5000), -1, 0.0}};
  spec.parameters[1].value = 3.0;  // height 3: the centre rises to 1.5
  const ParametricModel m = modelOf(spec);
  const Assembly a = m.build(m.parameters);
  ASSERT_EQ(a.blocks.front().pointLoads.size(), 1u) << "modelOf's build applies the loads";
  EXPECT_NEAR(a.blocks.front().pointLoads[0].at[2], 2.5, 1e-12);
  // The one joint, block on ground, carries the block's weight and the bell's.
  const AnalysisResult r = analyse(a);
  ASSERT_EQ(r.interfaces.size(), 1u);
  EXPECT_NEAR(r.interfaces[0].normalForce, 2400 * 9.81 * 0.16 * 3.0 + 5000, 1e-6 * 5000);
}

TEST(MasonryLoads, ALoadThatDoesNotFitIsRefusedNamingIt) {
  MasonrySpec spec = squareBlock(0.4, 2.0);
  const auto refused = [&](MasonryLoad l, const std::string& words) {
    spec.loads = {l};
    const ParametricModel m = modelOf(spec);
    try {
      m.build(m.parameters);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where, "masonry.loads[0]");
      EXPECT_NE(e.reason.find(words), std::string::npos) << e.reason;
    }
  };
  refused({"bell", "column/drum 7", Vec3(0.0), Vec3(0, 0, -1), -1, 0.0}, "\"column/drum 7\", which this model does not have");
  refused({"bell", "ground", Vec3(0.0), Vec3(0, 0, -1), -1, 0.0}, "a fixed block");
  refused({"wind", "column/drum 0", Vec3(0.0), Vec3(0.0), 6, 100.0}, "face 6 of \"column/drum 0\", which has 6 faces");
  refused({"bell", "column/drum 0", Vec3(0.0), Vec3(0, 0, std::nan("")), -1, 0.0}, "not finite");
}

// Each template alone: it builds, every block has a unique name (loads find blocks by name),
// and its parameters reach the blocks.
TEST(TemplateModels, EachBuildsWithUniqueBlockNamesAndItsParametersApply) {
  for (const std::string& name : templateModelNames()) {
    MasonrySpec spec;
    spec.model = name;
    const ParametricModel m = modelOf(spec);
    const Assembly a = m.build(m.parameters);
    std::set<std::string> names;
    for (const Block& b : a.blocks) EXPECT_TRUE(names.insert(b.name).second) << name << ": " << b.name;
    ASSERT_FALSE(m.suggestedFree.empty()) << name;
    // The suggested free parameter at its two bounds makes different blocks.
    ParameterSet lo = m.parameters, hi = m.parameters;
    lo.set(m.suggestedFree[0].name, m.suggestedFree[0].lo);
    hi.set(m.suggestedFree[0].name, m.suggestedFree[0].hi);
    EXPECT_NE(analyse(m.build(lo)).totalWeight, analyse(m.build(hi)).totalWeight) << name;
  }
}

// The semicircular arch alone stands above Heyman's least thickness t/R = 0.1075 and not below
// (Heyman 1995; 60 voussoirs lower it only a little).
TEST(TemplateModels, TheSemicircularArchStandsAboveHeymansLeastThickness) {
  MasonrySpec spec;
  spec.model = "semicircular-arch";
  spec.parameters = {{"radius", 2.0}, {"thickness", 0.12 * 2.0}, {"voussoirs", 60}};
  EXPECT_TRUE(standsByLp(spec));
  spec.parameters[1].value = 0.095 * 2.0;
  EXPECT_FALSE(standsByLp(spec));
}

// The dome on a drum: the dome's springing ring sits on the drum's top course, one contact per
// segment where that course is laid as the first (an odd number of courses: the top one is
// even), two where it is turned by half a block (running bond, an even number of courses).
TEST(TemplateModels, TheDomeSitsOnItsDrumBlockOnBlockOrAcrossJoints) {
  for (const auto& [courses, contacts] : {std::pair{3, 12}, std::pair{4, 24}}) {
    MasonrySpec spec;
    spec.model = "dome-on-drum";
    spec.parameters = {{"drumCourses", double(courses)}, {"segments", 12}};
    const ParametricModel m = modelOf(spec);
    const Assembly a = m.build(m.parameters);
    const AnalysisResult r = analyse(a);
    int drumToDome = 0;
    for (const auto& i : r.interfaces) {
      const std::string& x = a.blocks[std::size_t(i.a)].name;
      const std::string& y = a.blocks[std::size_t(i.b)].name;
      drumToDome += (x.rfind("drum/", 0) == 0 && y.rfind("dome/", 0) == 0) || (y.rfind("drum/", 0) == 0 && x.rfind("dome/", 0) == 0);
    }
    EXPECT_EQ(drumToDome, contacts) << courses << " courses";
  }
}

}  // namespace
}  // namespace corbel::statics
