// Issue 30's goal for the shipped masonry examples meant to stand: what the statics analysis
// calls standing (strict LP, at the saved kern) keeps every block within 1 mm for 5 s in the
// simulation, unperturbed. Not met yet, so disabled: the chapel settles 2.5 mm in 0.5 s and
// creeps to 32 mm by 5 s, the groin vault loses its ribs (docs/sim.md, "The shipped examples
// in the simulation"). Run it with --gtest_also_run_disabled_tests: about 10 minutes, the
// abbey 5 of them.
#include "core/project_io.h"
#include "sim/session.h"
#include "statics/analysis.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace corbel::sim {
namespace {

class ShippedExample : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedExample, DISABLED_WhatStaticsCallsStandingStaysWithinAMillimetreForFiveSeconds) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + GetParam() + ".corbel");
  const MasonrySpec* spec = nullptr;
  for (const DocObject& o : p.document.objects)
    if (const auto* s = std::get_if<MasonrySpec>(&o.spec)) spec = s;
  ASSERT_NE(spec, nullptr);
  const statics::ParametricModel model = statics::modelOf(*spec);
  const statics::Assembly design = model.build(model.parameters);
  statics::AnalysisOptions options;
  options.friction = spec->friction;
  options.kernShrink = spec->kern;
  ASSERT_TRUE(statics::checkFeasibility(design, options).feasible) << "the oracle: the statics LP";

  SimSettings settings;
  settings.friction = spec->friction;
  Session s(design, settings);
  s.runUntil(5.0);
  double most = 0;
  for (std::size_t i = 0; i < design.blocks.size(); ++i)
    if (!design.blocks[i].fixed) most = std::max(most, s.maxDisplacement()[i]);
  std::printf("%s: largest displacement %.3f mm in 5 s, %zu fallen\n", GetParam(), most * 1e3, s.fallenBlocks().size());
  EXPECT_TRUE(s.fallenBlocks().empty());
  EXPECT_LT(most, 1e-3);
}

// The groin vault with its ribs, which Bullet's sequential impulses let fall (21 blocks by 2 s),
// stands still with the contact QP: the statics LP's verdict, within a nanometre for 5 s.
TEST(ShippedExampleWithTheContactQp, TheGroinVaultStandsStill) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-groin.corbel");
  const MasonrySpec* spec = nullptr;
  for (const DocObject& o : p.document.objects)
    if (const auto* s = std::get_if<MasonrySpec>(&o.spec)) spec = s;
  ASSERT_NE(spec, nullptr);
  const statics::ParametricModel model = statics::modelOf(*spec);
  const statics::Assembly design = model.build(model.parameters);
  statics::AnalysisOptions options;
  options.friction = spec->friction;
  options.kernShrink = spec->kern;
  ASSERT_TRUE(statics::checkFeasibility(design, options).feasible) << "the oracle: the statics LP";
  SimSettings settings;
  settings.friction = spec->friction;
  settings.solver = Solver::ContactQp;
  Session s(design, settings);
  s.runUntil(5.0);
  double most = 0;
  for (std::size_t i = 0; i < design.blocks.size(); ++i)
    if (!design.blocks[i].fixed) most = std::max(most, s.maxDisplacement()[i]);
  EXPECT_TRUE(s.fallenBlocks().empty());
  EXPECT_LT(most, 1e-9);
  EXPECT_EQ(s.qpFailures(), 0);
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedExample,
                         ::testing::Values("masonry-groin", "masonry-mosque", "masonry-mosque-hall", "masonry-chapel",
                                           "masonry-abbey"),
                         [](const auto& info) {
                           std::string n = info.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

}  // namespace
}  // namespace corbel::sim
