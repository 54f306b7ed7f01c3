// Issue 30's goal for the shipped masonry examples meant to stand: what the statics analysis
// calls standing (strict LP, at the saved kern) keeps every block within 1 mm for 5 s in the
// simulation, unperturbed. With the contact QP (the default solver) no block moves a
// micrometre; with Bullet's sequential impulses the chapel creeps 32 mm and the groin vault's
// ribs fall (docs/sim.md, "The shipped examples in the simulation"). The abbey runs 1 s here:
// 5 s of its 989 blocks take 6 minutes (measured: under 1e-12 m, docs/sim.md).
#include "core/project_io.h"
#include "sim/session.h"
#include "statics/analysis.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace corbel::sim {
namespace {

class ShippedExample : public ::testing::TestWithParam<std::pair<std::string, double>> {};

TEST_P(ShippedExample, WhatStaticsCallsStandingStandsStill) {
  const auto [name, seconds] = GetParam();
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name + ".corbel");
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
  ASSERT_EQ(settings.solver, Solver::ContactQp) << "the default";
  Session s(design, settings);
  s.runUntil(seconds);
  double most = 0;
  for (std::size_t i = 0; i < design.blocks.size(); ++i)
    if (!design.blocks[i].fixed) most = std::max(most, s.maxDisplacement()[i]);
  std::printf("%s: largest displacement %.3g m in %g s, %zu fallen, %ld interior-point iterations\n", name.c_str(),
              most, seconds, s.fallenBlocks().size(), s.qpIterations());
  EXPECT_TRUE(s.fallenBlocks().empty());
  EXPECT_LT(most, 1e-6) << "the issue asks for 1 mm; a solved QP leaves rounding";
  EXPECT_EQ(s.qpFailures(), 0) << "every step solved by the QP";
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedExample,
                         ::testing::Values(std::pair<std::string, double>{"masonry-groin", 5.0},
                                           std::pair<std::string, double>{"masonry-mosque", 5.0},
                                           std::pair<std::string, double>{"masonry-mosque-hall", 5.0},
                                           std::pair<std::string, double>{"masonry-chapel", 5.0},
                                           std::pair<std::string, double>{"masonry-abbey", 1.0}),
                         [](const auto& info) {
                           std::string n = info.param.first;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

}  // namespace
}  // namespace corbel::sim
