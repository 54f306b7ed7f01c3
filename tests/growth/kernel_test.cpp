// growth/kernel.h: a growth site of the Document is grown into the Scene as the engine grows it
// on its own, every unit a closed shell of its boxes' volume, every constraint holding; a bad
// site is the object's error, named by its path in the project file.
#include "growth/kernel.h"

#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "growth/engine.h"
#include "support.h"
#include "../common/one_object.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace corbel::growth {
namespace {

std::string alphaSite() {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Grown : corbel::test::OneObject {
  explicit Grown(const GrowthSpec& spec) : OneObject(spec, registerKernel) {}
};

TEST(GrowthKernel, GrowsWhatTheEngineGrowsAndTheShellsHoldTheUnitsVolume) {
  const std::string text = alphaSite();
  for (int steps : {0, 5}) {
    SCOPED_TRACE(steps);
    GrowthSpec spec{text, 3, steps};
    const Grown g(spec);
    ASSERT_EQ(g.error(), "");
    EXPECT_EQ(stoppedAfter(g.status().warnings), -1);  // a few steps do not finish Alpha
    const Site site = parseSite(text);
    GrowthEngine engine(site, optionsFor(site, 3));
    for (int i = 0; i < steps; ++i) engine.step();
    double volume = 0;
    for (const Unit& u : engine.units()) volume += u.volume();
    for (std::size_t i = 0; i < site.cores.size(); ++i) volume += site.coreBox(i).volume();
    for (const Box& c : site.circulation) volume += c.volume();
    const ValidityReport r = g.scene.validate(g.id);
    EXPECT_TRUE(r.closedManifold()) << ::testing::PrintToString(r.problems());
    EXPECT_EQ(r.components, engine.units().size() + site.cores.size() + site.circulation.size());
    EXPECT_NEAR(r.volume, volume, 1e-6 * volume);
  }
}

TEST(GrowthKernel, GrowingToTheEndSaysWhenEveryUnitStoppedAndKeepsTheConstraints) {
  const std::string text = alphaSite();
  const Grown g(GrowthSpec{text, 1, -1});
  ASSERT_EQ(g.error(), "");
  const int stopped = stoppedAfter(g.status().warnings);
  ASSERT_GT(stopped, 0);
  const Site site = parseSite(text);
  GrowthEngine engine(site, optionsFor(site, 1));  // the site's growth settings, as the build's
  EXPECT_EQ(engine.run(100000), stopped);
  EXPECT_TRUE(test::independentViolations(site, engine.units()).empty());
  // The same count of steps gives the same growth, now finished too.
  const Grown again(GrowthSpec{text, 1, stopped});
  EXPECT_EQ(again.scene.validate(again.id).volume, g.scene.validate(g.id).volume);
  EXPECT_EQ(stoppedAfter(again.status().warnings), stopped);
}

TEST(GrowthKernel, ABadSiteIsTheObjectsErrorNamedByItsPath) {
  const LoadedProject p = parseProject(
      R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "G", "growth": {"site": )"
      R"({"envelope": {"origin": [0, 0], "size": [20, 20]}, "storeys": 2, "seeds": [{"at": [50, 5], "target_area": 30}]}}}]})");
  Scene scene;
  SceneSync sync;
  registerKernel(sync);
  sync.update(p.document, scene);
  const std::string& error = sync.status().at(1).error;
  EXPECT_EQ(error.rfind("growth.site.seeds[0]", 0), 0u) << error;
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

std::string withFinish(const std::string& roof) {
  nlohmann::json j = nlohmann::json::parse(alphaSite());
  j["roof"] = nlohmann::json::parse(roof);
  j["openings"] = nlohmann::json::object();
  return j.dump();
}

TEST(GrowthKernel, ASiteThatAsksForRoofsAndOpeningsIsBuiltFinished) {
  const std::string text = withFinish(R"({"profile": "gable", "pitch": 35})");
  const Site site = parseSite(text);
  ASSERT_TRUE(site.roof && site.openings);
  EXPECT_EQ(site.roof->profile, RoofProfile::Gable);
  EXPECT_EQ(site.roof->pitch, 35);
  EXPECT_EQ(site.openings->spacing, 3);  // the default
  const Grown g(GrowthSpec{text, 1, 30});
  ASSERT_EQ(g.error(), "");
  for (const std::string& w : g.status().warnings) EXPECT_EQ(w.find("roof"), std::string::npos) << w;
  // The roofs and openings are what roofs.h and openings.h make of the units the engine grows.
  GrowthEngine engine(site, optionsFor(site, 1));
  for (int i = 0; i < 30; ++i) engine.step();
  std::vector<std::string> warnings;
  const MeshData finish = finishMesh(site, engine.units(), warnings);
  EXPECT_TRUE(warnings.empty());
  std::size_t tagged = 0;
  for (int f : finish.faceTag) tagged += finish.tags[f] == "roof" || finish.tags[f] == "window" || finish.tags[f] == "door";
  EXPECT_GT(tagged, 100u);
  std::size_t bare = 0;
  for (const Unit& u : engine.units()) bare += unitMesh(u).faces.size();
  bare += 6 * (site.cores.size() + site.circulation.size());
  EXPECT_EQ(g.scene.faces(g.id).size(), bare + finish.faces.size());
}

TEST(GrowthKernel, BadRoofAndOpeningSettingsAreNamed) {
  const auto where = [](const std::string& text) {
    try {
      parseSite(text);
    } catch (const InputError& e) {
      return e.where + ": " + e.reason;
    }
    return std::string("accepted");
  };
  nlohmann::json j = nlohmann::json::parse(alphaSite());
  j["roof"] = {{"profile", "dome"}};
  EXPECT_EQ(where(j.dump()), "roof.profile: expected one of flat, shed, gable, hip");
  j["roof"] = {{"pitch", 80}};
  EXPECT_EQ(where(j.dump()).rfind("roof.pitch: ", 0), 0u);
  j["roof"] = {{"parapet", -1}};
  EXPECT_EQ(where(j.dump()).rfind("roof.parapet: ", 0), 0u);
  j.erase("roof");
  j["openings"] = {{"window", {4, 1.4, 0.1}}};
  EXPECT_EQ(where(j.dump()), "openings.window: wider than the spacing of windows");
  j["openings"] = {{"door", {1, -2, 0.1}}};
  EXPECT_EQ(where(j.dump()), "openings.door: width, height and depth must be positive");
  j["openings"] = {{"spacing", 0.8}};
  EXPECT_EQ(where(j.dump()), "openings.spacing: must be at least the window's width");
  j["openings"] = {{"sill", 1}, {"colour", "red"}};
  std::vector<std::string> warnings;
  parseSite(j.dump(), &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "openings.colour: unknown key ignored");
}

}  // namespace
}  // namespace corbel::growth
