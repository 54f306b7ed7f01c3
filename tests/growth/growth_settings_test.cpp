// The growth behaviour's settings in the site file (docs/growth.md, "Growth settings"): parsed
// into Site::growth, carried into a run by optionsFor, used by the Document's builder; bad values
// named.
#include "core/error.h"
#include "growth/engine.h"
#include "growth/kernel.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace corbel::growth {
namespace {

nlohmann::json alpha() {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  return nlohmann::json::parse(in);
}

std::string fault(const nlohmann::json& j) {
  try {
    parseSite(j.dump());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(GrowthSettings, WithoutTheKeyARunHasTheDocumentedDefaults) {
  nlohmann::json j = alpha();
  j.erase("growth");  // the shipped Alpha sets double_volume_chance
  const Site site = parseSite(j.dump());
  EXPECT_EQ(site.growth, GrowthSettings{});
  const GrowthOptions o = optionsFor(site, 7);
  EXPECT_EQ(o.seed, 7u);
  // docs/growth.md's defaults.
  EXPECT_EQ(o.tau, 0.3);
  EXPECT_EQ(o.intrusionPenalty, 0.5);
  EXPECT_EQ(o.viewGoalRatio, 0.5);
  EXPECT_EQ(o.aspectChance, 0.25);
  EXPECT_EQ(o.doubleVolumeChance, 0.35);
  EXPECT_EQ(o.maxAspect, 3.0);
  EXPECT_EQ(o.patience, 5);
  EXPECT_EQ(o.minSubUnits, 2);
  EXPECT_EQ(o.maxSubUnits, 3);
}

TEST(GrowthSettings, TheSiteFilesValuesReachTheRun) {
  nlohmann::json j = alpha();
  j["growth"] = {{"tau", 0.1},          {"intrusion_penalty", 2},    {"view_goal_ratio", 0.4},
                 {"aspect_chance", 0.6}, {"double_volume_chance", 1}, {"max_aspect", 2},
                 {"patience", 3},        {"sub_units", {1, 1}}};
  const Site site = parseSite(j.dump());
  const GrowthOptions o = optionsFor(site, 1);
  EXPECT_EQ(o.tau, 0.1);
  EXPECT_EQ(o.intrusionPenalty, 2);
  EXPECT_EQ(o.viewGoalRatio, 0.4);
  EXPECT_EQ(o.aspectChance, 0.6);
  EXPECT_EQ(o.doubleVolumeChance, 1);
  EXPECT_EQ(o.maxAspect, 2);
  EXPECT_EQ(o.patience, 3);
  // One sub-unit each, and every unit wants a double volume.
  const GrowthEngine engine(site, o);
  for (const UnitState& s : engine.states()) {
    EXPECT_EQ(s.subUnits, 1);
    EXPECT_TRUE(s.wantsDoubleVolume);
  }
  // The Document's builder grows with them: the engine given the same options by hand.
  const GrownModel grown = grow(GrowthSpec{j.dump(), 1, 12});
  GrowthOptions by;
  by.seed = 1;
  by.tau = 0.1, by.intrusionPenalty = 2, by.viewGoalRatio = 0.4, by.aspectChance = 0.6;
  by.doubleVolumeChance = 1, by.maxAspect = 2, by.patience = 3, by.minSubUnits = by.maxSubUnits = 1;
  GrowthEngine hand(site, by);
  for (int i = 0; i < 12; ++i) hand.step();
  ASSERT_EQ(grown.units.size(), hand.units().size());
  bool same = true;
  for (std::size_t i = 0; i < grown.units.size(); ++i) same = same && grown.units[i].parts == hand.units()[i].parts;
  EXPECT_TRUE(same);
  // ... and not what the defaults grow.
  const GrownModel plain = grow(GrowthSpec{alpha().dump(), 1, 12});
  bool differs = false;
  for (std::size_t i = 0; i < plain.units.size(); ++i) differs = differs || plain.units[i].parts != grown.units[i].parts;
  EXPECT_TRUE(differs);
}

TEST(GrowthSettings, ThreeSubUnitsWhenTheSiteAsksAndTheTargetAllows) {
  nlohmann::json j = alpha();
  j["growth"] = {{"sub_units", {3, 3}}};
  const Site site = parseSite(j.dump());
  const GrowthEngine engine(site, optionsFor(site, 1));
  // Alpha's targets are 30–100 m²: three sub-units where each keeps 18 m² (54 m² and up).
  for (std::size_t i = 0; i < site.seeds.size(); ++i) {
    const double target = site.seeds[i].targetArea;
    EXPECT_EQ(engine.states()[i].subUnits, target / 3 >= 18 ? 3 : target / 2 >= 18 ? 2 : 1) << target;
  }
}

TEST(GrowthSettings, BadValuesAreNamed) {
  nlohmann::json j = alpha();
  j["growth"] = {{"tau", 1.5}};
  EXPECT_EQ(fault(j).rfind("growth.tau: ", 0), 0u) << fault(j);
  j["growth"] = {{"sub_units", {3, 2}}};
  EXPECT_EQ(fault(j), "growth.sub_units: the most is less than the least");
  j["growth"] = {{"sub_units", {0, 2}}};
  EXPECT_EQ(fault(j).rfind("growth.sub_units[0]: ", 0), 0u) << fault(j);
  j["growth"] = {{"patience", 0}};
  EXPECT_EQ(fault(j).rfind("growth.patience: ", 0), 0u) << fault(j);
  j["growth"] = {{"max_aspect", 0.5}};
  EXPECT_EQ(fault(j).rfind("growth.max_aspect: ", 0), 0u) << fault(j);
  j["growth"] = 3;
  EXPECT_EQ(fault(j).rfind("growth: ", 0), 0u) << fault(j);
}

}  // namespace
}  // namespace corbel::growth
