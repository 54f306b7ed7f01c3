// Generated seeds (growth/seeding.h): every seed stands at an exit of the circulation (its face
// against a staircase's or corridor's side, across exactly the circulation clearance, on a
// storey the circulation serves), the site with them is valid, the count is the smaller of the
// cap and the free exits (counted by hand on a small case), targets lie in their range, the
// same controls give the same seeds, and bad controls are named.
#include "growth/seeding.h"

#include "core/error.h"
#include "growth/engine.h"
#include "support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::growth {
namespace {

using test::box;
using test::openSite;

// An exit: the seed's box lies against one side of a circulation box (gap = the clearance,
// overlapping it along that side), on a storey whose floor the circulation spans.
bool atAnExit(const Site& site, const Box& s) {
  const double g = site.circulationClearance, e = 1e-9;
  for (const Box& c : site.circulation) {
    if (s.lo[2] < c.lo[2] - e || s.lo[2] >= c.hi[2] - e) continue;
    for (int axis = 0; axis < 2; ++axis) {
      const int other = 1 - axis;
      const bool along = std::min(s.hi[other], c.hi[other]) - std::max(s.lo[other], c.lo[other]) > e;
      const bool touches = std::abs(s.lo[axis] - (c.hi[axis] + g)) < e || std::abs(c.lo[axis] - g - s.hi[axis]) < e;
      if (along && touches) return true;
    }
  }
  return false;
}

Site corridorSite() {
  Site s = openSite(40, 30, 2);
  s.circulation.push_back(box(10, 10, 0, 22, 12, 3));  // a 12 m corridor on the ground storey
  return s;
}

// 12 m of corridor, 3 m seeds stepped by 3 m: four places along each long side (x = 10, 13, 16,
// 19) and none at its 2 m ends, so at most 8 seeds; only the ground storey is served.
TEST(GeneratedSeeds, FillTheFreeExitsOfACorridorCountedByHand) {
  Site s = corridorSite();
  SeedControls c;
  c.count = 100;
  EXPECT_EQ(generateSeeds(s, c), 8);
  ASSERT_EQ(s.seeds.size(), 8u);
  for (std::size_t i = 0; i < s.seeds.size(); ++i) {
    EXPECT_EQ(s.seeds[i].storey, 0);
    EXPECT_TRUE(atAnExit(s, s.seedBox(i))) << i;
  }
  EXPECT_NO_THROW(validateSite(s));
  // A cap below the exits is met exactly, and a seed already there takes its exit.
  Site capped = corridorSite();
  capped.seeds.push_back(test::seedAt(13, 12, 0, 50));
  c.count = 5;
  EXPECT_EQ(generateSeeds(capped, c), 5);
  EXPECT_EQ(capped.seeds.size(), 6u);
  Site full = corridorSite();
  full.seeds.push_back(test::seedAt(13, 12, 0, 50));
  c.count = 100;
  EXPECT_EQ(generateSeeds(full, c), 7);
  EXPECT_NO_THROW(validateSite(full));
}

// The Alpha site's cores and stairs with its hand-placed seeds taken away (so its exits are
// free: far more than 12): every generated seed is at an exit, within its storeys and target
// range; the site stays valid and grows without breaking a constraint.
TEST(GeneratedSeeds, OnTheAlphaSiteSitAtExitsAndGrow) {
  Site s = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  s.seeds.clear();
  const std::size_t before = 0;
  SeedControls c;
  c.count = 12;
  c.areaLo = 45;
  c.areaHi = 90;
  c.storeys = {0, 2};
  c.seed = 7;
  const int added = generateSeeds(s, c);
  EXPECT_EQ(added, 12);
  ASSERT_EQ(s.seeds.size(), before + 12);
  for (std::size_t i = before; i < s.seeds.size(); ++i) {
    EXPECT_TRUE(atAnExit(s, s.seedBox(i))) << i;
    EXPECT_TRUE(s.seeds[i].storey == 0 || s.seeds[i].storey == 2) << i;
    EXPECT_GE(s.seeds[i].targetArea, 45);
    EXPECT_LE(s.seeds[i].targetArea, 90);
  }
  EXPECT_NO_THROW(validateSite(s));
  GrowthEngine engine(s);
  engine.run(10);
  EXPECT_GT(engine.commits(), 0u) << "the generated seeds grow";
  EXPECT_TRUE(test::independentViolations(s, engine.units()).empty());
}

TEST(GeneratedSeeds, SameControlsGiveTheSameSeeds) {
  Site a = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  Site b = a, other = a;
  a.seeds.clear();
  b.seeds.clear();
  other.seeds.clear();
  SeedControls c;
  c.count = 20;
  generateSeeds(a, c);
  generateSeeds(b, c);
  c.seed = 2;
  generateSeeds(other, c);
  ASSERT_EQ(a.seeds.size(), b.seeds.size());
  bool differs = a.seeds.size() != other.seeds.size();
  for (std::size_t i = 0; i < a.seeds.size(); ++i) {
    EXPECT_EQ(a.seeds[i].at, b.seeds[i].at);
    EXPECT_EQ(a.seeds[i].targetArea, b.seeds[i].targetArea);
    if (i < other.seeds.size()) differs = differs || a.seeds[i].at != other.seeds[i].at;
  }
  EXPECT_TRUE(differs) << "another shuffle seed picks other exits";
}

TEST(GeneratedSeeds, BadControlsAreNamed) {
  auto where = [](SeedControls c) {
    Site s = corridorSite();
    try {
      generateSeeds(s, c);
    } catch (const InputError& e) {
      return e.where;
    }
    return std::string("(accepted)");
  };
  SeedControls c;
  c.count = -1;
  EXPECT_EQ(where(c), "generate_seeds.count");
  c = {};
  c.size = Vec2(2.0, 3.0);
  EXPECT_EQ(where(c), "generate_seeds.size");
  c = {};
  c.areaLo = 50;
  c.areaHi = 10;
  EXPECT_EQ(where(c), "generate_seeds.target_area");
  c = {};
  c.storeys = {5};
  EXPECT_EQ(where(c), "generate_seeds.storeys");
  c = {};
  c.spacing = std::nan("");
  EXPECT_EQ(where(c), "generate_seeds.spacing");
}

// In the site file: "generate_seeds" may stand in for "seeds"; its errors carry their path.
TEST(GeneratedSeeds, ReadFromTheSiteFile) {
  const std::string site = R"({"format": "corbel-growth-site", "version": 1,
    "envelope": {"origin": [0, 0], "size": [40, 30]}, "storeys": 2, "storey_height": 3,
    "circulation": [{"at": [10, 10, 0], "size": [12, 2, 3]}],
    "generate_seeds": {"count": 100, "target_area": [40, 40], "seed": 3}})";
  const Site s = parseSite(site);
  EXPECT_EQ(s.seeds.size(), 8u);
  for (const Seed& seed : s.seeds) EXPECT_EQ(seed.targetArea, 40);
  std::string bad = site;
  bad.replace(bad.find("[40, 40]"), 8, "[40, 4]");
  try {
    parseSite(bad);
    ADD_FAILURE() << "accepted a reversed range";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "generate_seeds.target_area");
  }
  std::string none = site;
  none.replace(none.find("\"generate_seeds\""), 16, "\"no_seeds\"");
  EXPECT_THROW(parseSite(none), InputError);  // neither seeds nor generate_seeds
}

}  // namespace
}  // namespace corbel::growth
