// Sites: the JSON of docs/growth.md and the errors a bad site gets.
#include "growth/site.h"
#include "core/error.h"
#include "support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::growth {
namespace {

const char* kSite = R"({
  "format": "corbel-growth-site", "version": 1,
  "envelope": {"origin": [0, 0], "size": [40, 30]},
  "storeys": 3, "storey_height": 3.2, "alpha": 0.4, "cantilever": 5,
  "clearance": {"core": 1.5, "circulation": 0},
  "cores": [{"at": [10, 10], "size": [4, 4]}],
  "circulation": [{"at": [14, 11, 0], "size": [6, 2, 3.2]}],
  "seeds": [{"at": [20, 11], "storey": 0, "target_area": 60, "locked": ["+x", "top"]},
            {"at": [2, 2], "size": [4, 3], "storey": 1, "target_volume": 200, "behaviour": "view"}]
})";

// Parses kSite with one substitution and returns the error, or "" when it loads.
std::string errorWith(const std::string& from, const std::string& to, std::string* where = nullptr) {
  std::string text = kSite;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    parseSite(text);
  } catch (const InputError& e) {
    if (where) *where = e.where;
    return e.what();
  }
  return "";
}

TEST(Site, ParsesEveryField) {
  std::vector<std::string> warnings;
  const Site s = parseSite(kSite, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(s.storeys, 3);
  EXPECT_DOUBLE_EQ(s.storeyHeight, 3.2);
  EXPECT_DOUBLE_EQ(s.top(), 9.6);
  EXPECT_DOUBLE_EQ(s.area(), 1200.0);
  EXPECT_DOUBLE_EQ(s.alpha, 0.4);
  EXPECT_DOUBLE_EQ(s.cantilever, 5);
  EXPECT_DOUBLE_EQ(s.coreClearance, 1.5);
  ASSERT_EQ(s.cores.size(), 1u);
  EXPECT_EQ(s.cores[0], (Rect{10, 10, 14, 14}));
  ASSERT_EQ(s.seeds.size(), 2u);
  EXPECT_TRUE(s.seeds[0].locked[int(Side::PosX)] && s.seeds[0].locked[int(Side::Top)]);
  EXPECT_FALSE(s.seeds[0].locked[int(Side::NegX)]);
  EXPECT_EQ(s.seedBox(1), test::box(2, 2, 3.2, 6, 5, 6.4));
  EXPECT_DOUBLE_EQ(s.seeds[1].targetVolume, 200);
}

TEST(Site, UnknownKeysAreWarnings) {
  std::vector<std::string> warnings;
  std::string text = kSite;
  text.replace(text.find("\"storeys\""), 0, "\"colour\": 1, ");
  parseSite(text, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("colour"), std::string::npos);
}

TEST(Site, BadSitesNameTheField) {
  std::string where;
  EXPECT_NE(errorWith("\"at\": [2, 2]", "\"at\": [38, 2]", &where).find("outside the site envelope"),
            std::string::npos);
  EXPECT_EQ(where, "seeds[1].at");
  EXPECT_NE(errorWith("\"storey\": 1", "\"storey\": 3", &where).find("0..2"), std::string::npos);
  EXPECT_EQ(where, "seeds[1].storey");
  const std::string overlap =
      errorWith("\"cores\": [{\"at\": [10, 10], \"size\": [4, 4]}]",
                "\"cores\": [{\"at\": [10, 10], \"size\": [4, 4]}, {\"at\": [12, 12], \"size\": [4, 4]}]", &where);
  EXPECT_NE(overlap.find("overlaps cores[0]"), std::string::npos) << overlap;
  EXPECT_EQ(where, "cores[1]");
  errorWith("\"size\": [4, 3]", "\"size\": [4, -3]", &where);
  EXPECT_EQ(where, "seeds[1].size");
  EXPECT_NE(errorWith("\"size\": [4, 3]", "\"size\": [2.5, 3]", &where).find("3 m x 3 m"), std::string::npos);
  EXPECT_NE(errorWith("\"alpha\": 0.4", "\"alpha\": 0.6", &where).find("[0.2, 0.5]"), std::string::npos);
  EXPECT_EQ(where, "alpha");
  EXPECT_NE(errorWith("\"at\": [20, 11]", "\"at\": [14.5, 14.2]", &where).find("clearance of cores[0]"),
            std::string::npos);
  EXPECT_NE(errorWith("\"target_area\": 60", "\"target_area\": 60, \"target_volume\": 9", &where).find("exactly one"),
            std::string::npos);
  EXPECT_NE(errorWith("\"locked\": [\"+x\", \"top\"]", "\"locked\": [\"north\"]", &where).find("-x, +x"),
            std::string::npos);
  EXPECT_EQ(where, "seeds[0].locked[0]");
  EXPECT_NE(errorWith("\"storey_height\": 3.2", "\"storey_height\": \"tall\"", &where).find("expected a number"),
            std::string::npos);
  EXPECT_EQ(where, "storey_height");
}

// The core is [10, 14]² from z = 0 to the top (9.6); kSite's landing [14, 20] × [11, 13] touches
// its +x side (a lift door opening onto it) and loads (Site.ParsesEveryField).
TEST(Site, CirculationSharingACoresInteriorIsRefused) {
  std::string where;
  // 0.5 m into the core at every height of the ground storey.
  const std::string into = errorWith("\"at\": [14, 11, 0]", "\"at\": [13.5, 11, 0]", &where);
  EXPECT_NE(into.find("overlaps cores[0]"), std::string::npos) << into;
  EXPECT_EQ(where, "circulation[0]");
  // On the top storey (z 6.4..9.6): the core runs the full height, so it still overlaps.
  errorWith("\"at\": [14, 11, 0], \"size\": [6, 2, 3.2]", "\"at\": [11, 11, 6.4], \"size\": [2, 2, 3.2]", &where);
  EXPECT_EQ(where, "circulation[0]");
  // Touching at a corner only ((14, 14)), or lying 0.01 m off the core: no shared interior.
  EXPECT_EQ(errorWith("\"at\": [14, 11, 0]", "\"at\": [14, 14, 0]"), "");
  EXPECT_EQ(errorWith("\"at\": [14, 11, 0], \"size\": [6, 2, 3.2]", "\"at\": [14.01, 11, 0], \"size\": [5.99, 2, 3.2]"),
            "");
}

TEST(Site, NonFiniteValuesInAProgrammaticSiteNameTheField) {
  Site s = test::openSite(20, 20, 2);
  s.seeds.push_back(test::seedAt(1, 1, 0, 30));
  s.seeds[0].at[1] = std::nan("");
  try {
    validateSite(s);
    FAIL() << "a NaN seed was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "seeds[0].at");
  }
  s.seeds[0].at[1] = 1;
  s.cores.push_back({5, 5, 5 + INFINITY, 8});
  EXPECT_THROW(validateSite(s), InputError);
}

TEST(Site, PolygonEnvelopeContainsOnlyWhatIsInside) {
  // An L: the square [0, 20]² without its corner [10, 20]².
  Site s = test::openSite(1, 1, 1);
  s.plan = {Vec2(0, 0), Vec2(20, 0), Vec2(20, 10), Vec2(10, 10), Vec2(10, 20), Vec2(0, 20)};
  EXPECT_DOUBLE_EQ(s.area(), 300.0);
  EXPECT_TRUE(s.planContains({0, 0, 20, 10}));  // touching the boundary counts as inside
  EXPECT_TRUE(s.planContains({2, 2, 10, 18}));
  EXPECT_FALSE(s.planContains({9, 9, 12, 12}));  // reaches into the missing corner
  EXPECT_FALSE(s.planContains({12, 12, 15, 15}));
  // All four corners inside but the re-entrant corner inside the rectangle: a slanted plan.
  s.plan = {Vec2(0, 0), Vec2(20, 0), Vec2(20, 20), Vec2(10, 5), Vec2(0, 20)};
  EXPECT_FALSE(s.planContains({5, 1, 15, 8}));
  EXPECT_TRUE(s.planContains({5, 1, 15, 4}));
}

// A bow tie's lobes have equal and opposite signed areas; a plan may not cross itself, touch
// itself or repeat a corner, whatever its area. Colinear corners (a corner halfway along an
// edge, as the Site tab's "+" makes) are a simple polygon and load.
TEST(Site, AnEnvelopeThatCrossesOrTouchesItselfIsRefused) {
  Site s = test::openSite(1, 1, 1);
  auto where = [&](std::vector<Vec2> plan) -> std::string {
    s.plan = std::move(plan);
    try {
      validateSite(s);
    } catch (const InputError& e) {
      return e.where;
    }
    return "";
  };
  // A bow tie whose lobes differ (|area| > 0, so the area check alone would pass it).
  EXPECT_EQ(where({Vec2(0, 0), Vec2(20, 10), Vec2(20, 0), Vec2(0, 20)}), "envelope.polygon");
  // A square whose fifth corner touches its first edge from inside.
  EXPECT_EQ(where({Vec2(0, 0), Vec2(20, 0), Vec2(20, 20), Vec2(10, 0), Vec2(0, 20)}), "envelope.polygon");
  // A corner given twice.
  EXPECT_EQ(where({Vec2(0, 0), Vec2(20, 0), Vec2(20, 0), Vec2(20, 20), Vec2(0, 20)}), "envelope.polygon");
  EXPECT_EQ(where({Vec2(0, 0), Vec2(10, 0), Vec2(20, 0), Vec2(20, 20), Vec2(0, 20)}), "");
  // Clockwise is the same region: accepted.
  EXPECT_EQ(where({Vec2(0, 0), Vec2(0, 20), Vec2(20, 20), Vec2(20, 0)}), "");
  EXPECT_DOUBLE_EQ(s.area(), 400.0);
}

}  // namespace
}  // namespace corbel::growth
