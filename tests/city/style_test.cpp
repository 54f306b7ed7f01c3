// Styles: parse errors name their path, rules pick types, profile choices follow their weights
// and depend only on the seed and the building.
#include "city/style.h"

#include "core/error.h"
#include "extrude/extrude.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace corbel;
using namespace corbel::city;

namespace {

const char* kStyle = R"({
  "name": "test",
  "profiles": [
    {"name": "hip", "points": [[0, 0], [0, 3], [3, 6]], "tags": ["wall", "roof"]},
    {"name": "gable", "points": [[0, 0], [0, 3], [0, 5]], "tags": ["wall", "gable"]},
    {"name": "steep", "points": [[0, 0], [0, 3], [1, 6]]},
    {"name": "dormer", "points": [[0, 0], [0, 1]]}
  ],
  "types": [
    {"name": "shed", "when": {"area": [0, 50]}, "edges": [{"profiles": "hip"}]},
    {"name": "house", "when": {"area": [50, 1e9]}, "weight": 1,
     "edges": [{"when": {"orientation": ["side"]}, "profiles": {"gable": 3, "hip": 1}}, {"profiles": "steep"}],
     "windows": [{"when": {"orientation": ["street"]}, "margin": 1, "spacing": 2, "floors": 2}],
     "door": true,
     "steps": [{"when": {"orientation": ["street"]}, "chance": 1, "height": 3, "row": true, "min_length": 6, "margin": 2,
                "spacing": 3, "front_profile": "dormer"}]},
    {"name": "shop", "when": {"property": {"use": ["shop", 7]}}, "weight": 5, "edges": [{"profiles": "hip"}]}
  ]
})";

Building box(const std::string& id, double w, double h, nlohmann::json props = nlohmann::json::object()) {
  Building b;
  b.id = id;
  b.loops = {{{0, 0}, {w, 0}, {w, h}, {0, h}}};
  b.area = w * h;
  b.properties = std::move(props);
  return b;
}

std::string parseError(const std::string& text) {
  try {
    parseStyle(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string withType(const std::string& type) {
  return R"({"profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [3, 6]]}], "types": [)" + type + "]}";
}

}  // namespace

TEST(Style, RulesPickTheTypeByAreaAndProperty) {
  const Style s = parseStyle(kStyle);
  const Building small = box("a", 5, 5), big = box("b", 10, 8), shop = box("c", 10, 8, {{"use", "shop"}}),
                 coded = box("d", 4, 4, {{"use", 7.0}});
  BuildingRandom r(1, "x");
  EXPECT_EQ(s.types[*assignType(s, small, r)].name, "shed");
  EXPECT_EQ(s.types[*assignType(s, big, r)].name, "house");
  // A shop qualifies as house and shop; by weight 1 : 5 most draws are shops, some houses.
  int shops = 0;
  for (int i = 0; i < 600; ++i) {
    BuildingRandom ri(i, "c");
    shops += s.types[*assignType(s, shop, ri)].name == "shop";
  }
  EXPECT_GT(shops, 450);  // expected 500, σ ≈ 9
  EXPECT_LT(shops, 550);
  // A numeric property matches a number in the rule (7 = 7.0); the area (16 m²) also allows a shed.
  std::set<std::string> got;
  for (int i = 0; i < 50; ++i) {
    BuildingRandom ri(i, "d");
    got.insert(s.types[*assignType(s, coded, ri)].name);
  }
  EXPECT_EQ(got, (std::set<std::string>{"shed", "shop"}));
}

TEST(Style, ExplicitAssignmentUsesTheFirstRuleThatHolds) {
  const std::string text = std::string(kStyle).substr(0, std::string(kStyle).rfind('}')) +
                           R"(, "assign": [{"when": {"area": [0, 30]}, "types": "shop"}, {"types": {"house": 1}}]})";
  const Style s = parseStyle(text);
  BuildingRandom r(3, "a");
  EXPECT_EQ(s.types[*assignType(s, box("a", 5, 5), r)].name, "shop");
  EXPECT_EQ(s.types[*assignType(s, box("b", 6, 6), r)].name, "house");  // 36 m²: second rule
}

// GIS attributes by range: a height (a number, or a string of one as OpenStreetMap writes
// heights) picks the type; what is no number, or missing, falls through to the next rule.
TEST(Style, ANumericAttributeRangePicksTheType) {
  const std::string text = std::string(kStyle).substr(0, std::string(kStyle).rfind('}')) +
                           R"(, "assign": [{"when": {"property": {"height": {"range": [12, 1000]}}}, "types": "shop"},
                                           {"when": {"property": {"roof:shape": "flat"}}, "types": "shed"},
                                           {"types": "house"}]})";
  const Style s = parseStyle(text);
  auto type = [&](const nlohmann::json& props) {
    BuildingRandom r(1, "a");
    return s.types[*assignType(s, box("a", 10, 8, props), r)].name;
  };
  EXPECT_EQ(type({{"height", 20}}), "shop");
  EXPECT_EQ(type({{"height", 12}}), "shop");  // the range holds its ends
  EXPECT_EQ(type({{"height", "15.5 m"}}), "shop");
  EXPECT_EQ(type({{"height", "15.5"}}), "shop");
  EXPECT_EQ(type({{"height", 11.99}}), "house");
  EXPECT_EQ(type({{"height", "tall"}}), "house");
  EXPECT_EQ(type({{"height", "15 ft"}}), "house");  // not metres: not taken as a height
  EXPECT_EQ(type({{"roof:shape", "flat"}}), "shed");
  EXPECT_EQ(type(nlohmann::json::object()), "house");
  EXPECT_NE(
      parseError(
          withType(
              R"({"name": "t", "when": {"property": {"height": {"range": [5, 2]}}}, "edges": [{"profiles": "hip"}]})"))
          .find("types[0].when.property.height.range: min is greater than max"),
      std::string::npos);
  EXPECT_NE(
      parseError(
          withType(R"({"name": "t", "when": {"property": {"height": {"below": 5}}}, "edges": [{"profiles": "hip"}]})"))
          .find("below"),
      std::string::npos);
}

TEST(Style, ProfileChoicesFollowTheirWeights) {
  const Style s = parseStyle(kStyle);
  const Building b = box("house", 10, 8);
  const std::vector<EdgeLabel> edges = labelEdges(b.loops, {0, -1});
  BuildingLabels L;
  L.front = {0, -1};
  L.edges = edges;
  int gables = 0, sides = 0;
  for (int seed = 0; seed < 1000; ++seed) {
    const StyledBuilding sb = styleBuilding(s, b, L, seed);
    ASSERT_EQ(sb.problem, "");
    for (const auto& e : edges) {
      const int p = sb.spec.loops[0].profile[e.edge];
      if (e.orientation == Orientation::Side) {
        ++sides;
        gables += s.profiles[p].name == "gable";
      } else {
        EXPECT_EQ(s.profiles[p].name, "steep");
      }
    }
  }
  // 3 : 1 over 2000 side edges: 1500 expected, σ ≈ 19.
  EXPECT_EQ(sides, 2000);
  EXPECT_GT(gables, 1420);
  EXPECT_LT(gables, 1580);
}

TEST(Style, TheSameSeedGivesTheSameBuildingInAnyOrder) {
  const Style s = parseStyle(kStyle);
  std::vector<Building> bs;
  for (int i = 0; i < 40; ++i) bs.push_back(box("b" + std::to_string(i), 8 + i % 7, 7 + i % 3));
  auto styleAll = [&](std::uint64_t seed, bool reversed) {
    std::vector<extrude::ExtrusionSpec> out(bs.size());
    for (std::size_t k = 0; k < bs.size(); ++k) {
      const std::size_t i = reversed ? bs.size() - 1 - k : k;
      BuildingLabels L;
      L.front = {0, -1};
      L.edges = labelEdges(bs[i].loops, L.front);
      out[i] = styleBuilding(s, bs[i], L, seed).spec;
    }
    return out;
  };
  const auto a = styleAll(7, false), b = styleAll(7, true), c = styleAll(8, false);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(Style, FeaturesArePlacedOnTheStreetEdges) {
  const Style s = parseStyle(kStyle);
  const Building b = box("house", 12, 8);
  BuildingLabels L;
  L.front = {0, -1};
  L.edges = labelEdges(b.loops, L.front);
  const StyledBuilding sb = styleBuilding(s, b, L, 1);
  ASSERT_EQ(sb.type, "house");
  // The door near the start of the 12 m front (edge 0), the windows after it, two floors.
  ASSERT_GE(sb.spec.anchors.size(), 2u);
  EXPECT_EQ(sb.spec.anchors[0].feature, FeatureKind::Door);
  EXPECT_EQ(sb.spec.anchors[0].anchor.edge, 0);
  EXPECT_EQ(sb.spec.anchors[1].feature, FeatureKind::Window);
  EXPECT_EQ(sb.spec.anchors[1].repeat.kind, RepeatKind::Grid);
  EXPECT_GT(sb.spec.anchors[1].anchor.along, sb.spec.anchors[0].anchor.along + 1);
  // Dormers from 2 m to 10 m along the front, at the eaves.
  ASSERT_EQ(sb.spec.steps.size(), 1u);
  EXPECT_EQ(sb.spec.steps[0].anchor.edge, 0);
  EXPECT_DOUBLE_EQ(sb.spec.steps[0].anchor.along, 2);
  EXPECT_DOUBLE_EQ(sb.spec.steps[0].repeat.along, 10);
  EXPECT_DOUBLE_EQ(sb.spec.steps[0].anchor.height, 3);
}

TEST(Style, FaultsNameTheirPath) {
  EXPECT_EQ(parseError(withType(R"({"name": "a", "edgez": []})")),
            "types[0].edgez: unknown key (expected one of: door, edges, "
            "material, name, parapet, priority, roof_material, steps, weight, when, windows)");
  EXPECT_EQ(parseError(withType(R"({"name": "a", "edges": [{"profiles": "gable"}]})")),
            "types[0].edges[0].profiles: no profile named \"gable\"");
  EXPECT_EQ(
      parseError(withType(R"({"name": "a", "edges": [{"when": {"orientation": ["front"]}, "profiles": "hip"}]})")),
      "types[0].edges[0].when.orientation[0]: expected \"street\", \"side\" or \"back\"");
  EXPECT_EQ(parseError(withType(R"({"name": "a", "edges": [{"profiles": {"hip": -1}}]})")),
            "types[0].edges[0].profiles.hip: -1 is outside [0, 1e+09]");
  EXPECT_EQ(parseError(R"({"profiles": [{"name": "down", "points": [[0, 0], [0, 3], [1, 2]]}], "types": []})"),
            "profiles[0]: points[2]: a profile must not go down");
  EXPECT_EQ(parseError(R"({"profiles": [], "types": []})"), "types: a style needs at least one building type");
  EXPECT_EQ(parseError(withType(R"({"name": "a", "when": {"area": [50, 10]}, "edges": [{"profiles": "hip"}]})")),
            "types[0].when.area: min is greater than max");
}

// A type's "priority" (Sec. 4.8) is its buildings' spec's: volume maximising unless it says
// otherwise; a name the kernel does not know is refused at its path.
TEST(Style, ATypesPriorityIsItsBuildings) {
  const Building b = box("house", 10, 8);
  BuildingLabels L;
  L.front = {0, -1};
  L.edges = labelEdges(b.loops, {0, -1});
  const std::pair<const char*, Priority> cases[] = {{"", Priority::MaximiseVolume},
                                                    {R"("priority": "maximise_volume", )", Priority::MaximiseVolume},
                                                    {R"("priority": "minimise_volume", )", Priority::MinimiseVolume},
                                                    {R"("priority": "manual", )", Priority::Manual}};
  for (const auto& [key, expected] : cases) {
    SCOPED_TRACE(key);
    const Style s = parseStyle(withType(std::string(R"({"name": "a", )") + key + R"("edges": [{"profiles": "hip"}]})"));
    const StyledBuilding sb = styleBuilding(s, b, L, 1);
    ASSERT_EQ(sb.problem, "");
    EXPECT_EQ(sb.spec.priority, expected);
  }
  EXPECT_EQ(parseError(withType(R"({"name": "a", "priority": "biggest", "edges": [{"profiles": "hip"}]})")),
            "types[0].priority: expected \"maximise_volume\", \"minimise_volume\" or \"manual\", found \"biggest\"");
}

// Manual priority reaches the town's shells: a box bay at the foot of the street front (walls
// 1.5 m, then 45°, 1 m deep) whose roof comes into line with the facade's wall (3 m, then 45°)
// at 2.5 m. The bay's roof tagged "high" takes the facade as minimising volume does; tagged
// "low", the wall goes on as maximising does; and the two outcomes differ.
TEST(Style, ManualPriorityRanksTheTypesTaggedSegments) {
  auto style = [](const std::string& priority, const std::string& bayRoofTag) {
    return parseStyle(R"({"profiles": [
        {"name": "main", "points": [[0, 0], [0, 3], [1, 4]], "tags": ["wall", "roof"]},
        {"name": "bay", "points": [[0, 0], [0, 1.5], [1, 2.5]], "tags": ["bay wall", ")" +
                      bayRoofTag + R"("]}],
      "types": [{"name": "house", "priority": ")" +
                      priority + R"(", "edges": [{"profiles": "main"}],
        "steps": [{"when": {"orientation": ["street"]}, "chance": 1, "height": 0, "width": 3, "depth": 1,
                   "along": 0.5, "front_profile": "bay"}]}]})");
  };
  const Building b = box("house", 10, 6);
  BuildingLabels L;
  L.front = {0, -1};
  L.edges = labelEdges(b.loops, {0, -1});
  auto volume = [&](const Style& s) {
    const StyledBuilding sb = styleBuilding(s, b, L, 1);
    EXPECT_EQ(sb.problem, "");
    EXPECT_EQ(sb.spec.steps.size(), 1u);
    const extrude::ExtrusionResult r = extrude::extrude(sb.spec);
    EXPECT_EQ(extrude::unpairedEdges(r.shell), 0u);
    EXPECT_TRUE(r.shell.warnings.empty()) << r.shell.warnings.front();
    return extrude::measure(r.shell).volume;
  };
  const double maxV = volume(style("maximise_volume", "bay roof")), minV = volume(style("minimise_volume", "bay roof"));
  ASSERT_GT(maxV - minV, 1e-3 * maxV) << "the layout must be one the priority decides";
  EXPECT_NEAR(volume(style("manual", "high")), minV, 1e-9 * minV);
  EXPECT_NEAR(volume(style("manual", "low")), maxV, 1e-9 * maxV);
}

TEST(Style, AFileFaultNamesTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_style_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.json") << withType(R"({"name": "a", "edges": []})");
  std::ofstream(dir / "user.json") << R"({"use": ["bad.json"]})";
  try {
    loadStyle((dir / "user.json").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("user.json: use[0]: "), std::string::npos) << m;
    EXPECT_NE(m.find("bad.json: types[0].edges: a building type needs at least one edge rule"), std::string::npos) << m;
  }
}

TEST(Style, TheShippedStylesLoad) {
  for (const char* name : {"suburban", "oldtown", "modern", "mixed"}) {
    const Style s = loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/" + name + ".json");
    EXPECT_FALSE(s.types.empty()) << name;
  }
  // Suburban's bungalow, two-storey house and store, the old town's two town houses and hall, and
  // modern's block, tower block and garage.
  EXPECT_EQ(loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/mixed.json").types.size(), 9u);
}

namespace {
std::string withTagTextures(const std::string& table) {
  return R"({"profiles": [{"name": "hip", "points": [[0, 0], [0, 3], [3, 6]], "tags": ["wall", "roof"]}],
             "types": [{"name": "a", "edges": [{"profiles": "hip"}]}], "tag_textures": )" +
         table + "}";
}
}  // namespace

// tag_textures: a name alone takes the texture's own tile, {texture, metres} a repeat of its own;
// the lookup handed to the exporter and renderer answers for those tags only.
TEST(Style, TagTexturesNameABuiltInTextureAndARepeat) {
  const Style s = parseStyle(withTagTextures(R"({"roof": "slate", "wall": {"texture": "brick", "metres": 0.64},
                                                 "soffit": {"texture": "timber"}})"));
  ASSERT_EQ(s.tagTextures.size(), 3u);
  EXPECT_EQ(s.tagTextures.at("roof"), (SurfaceTexture{"slate", 0}));
  EXPECT_EQ(s.tagTextures.at("wall"), (SurfaceTexture{"brick", 0.64}));
  EXPECT_EQ(s.tagTextures.at("soffit"), (SurfaceTexture{"timber", 0}));
  const TagTextures lookup = tagTexturesOf(s);
  ASSERT_TRUE(lookup);
  ASSERT_NE(lookup(7, "wall"), nullptr);
  EXPECT_EQ(lookup(7, "wall")->name, "brick");
  EXPECT_EQ(lookup(7, "gable"), nullptr);
  EXPECT_EQ(lookup(7, ""), nullptr);
  EXPECT_FALSE(tagTexturesOf(parseStyle(withType(R"({"name": "a", "edges": [{"profiles": "hip"}]})"))));
  // What a face then shows: the tag's texture and repeat, else its material's (core/textures.h).
  const TextureUse roof = textureFor(lookup(1, "roof"), "roof_tile");
  EXPECT_EQ(roof.name, "slate");
  EXPECT_TRUE(roof.own);
  EXPECT_DOUBLE_EQ(roof.metres, materialTexture("slate")->metres);
  EXPECT_DOUBLE_EQ(textureFor(lookup(1, "wall"), "plaster").metres, 0.64);
  const TextureUse gable = textureFor(lookup(1, "gable"), "plaster");
  EXPECT_EQ(gable.name, "plaster");
  EXPECT_FALSE(gable.own);
  EXPECT_EQ(textureFor(nullptr, "unobtainium").texture, nullptr);
}

// A style that uses another gets its tag textures; its own win for the same tag.
TEST(Style, TagTexturesOfAUsedStyleJoinAndTheUsersWin) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_tag_texture_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "base.json") << withTagTextures(R"({"roof": "slate", "wall": "brick"})");
  std::ofstream(dir / "user.json")
      << R"({"use": ["base.json"], "tag_textures": {"roof": {"texture": "metal", "metres": 1}}})";
  const Style s = loadStyle((dir / "user.json").string());
  EXPECT_EQ(s.tagTextures.at("roof"), (SurfaceTexture{"metal", 1}));
  EXPECT_EQ(s.tagTextures.at("wall"), (SurfaceTexture{"brick", 0}));
}

TEST(Style, TagTextureFaultsNameTheirKey) {
  EXPECT_EQ(parseError(withTagTextures(R"(["slate"])")), "tag_textures: expected an object, found an array");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": 3})")),
            "tag_textures.roof: expected a texture name or {\"texture\": name, \"metres\": m}");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": "marble"})")),
            "tag_textures.roof: no built-in texture named \"marble\" (expected one of: plaster, stone, brick, "
            "roof_tile, slate, concrete, timber, glass, metal, grass)");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": "Slate"}})")).substr(0, 52),
            "tag_textures.roof.texture: no built-in texture named");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": 5}})")),
            "tag_textures.roof.texture: expected a string, found a number");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"metres": 2}})")).substr(0, 26), "tag_textures.roof.texture:");
  for (const char* bad : {"0", "-1.5", "1e5"})
    EXPECT_EQ(parseError(withTagTextures(std::string(R"({"roof": {"texture": "slate", "metres": )") + bad + "}}")),
              "tag_textures.roof.metres: the metres of one repeat must be greater than 0 and at most 10000")
        << bad;
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": "slate", "metres": "2"}})")),
            "tag_textures.roof.metres: expected a number, found a string");
  // JSON has no NaN: null (what a NaN is written as) and an overflowing number are refused too.
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": "slate", "metres": null}})")),
            "tag_textures.roof.metres: expected a number, found null");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": "slate", "metres": 1e999}})")),
            "tag_textures.roof.metres: number is not finite (1e999 is out of range)");
  EXPECT_EQ(parseError(withTagTextures(R"({"roof": {"texture": "slate", "scale": 2}})")),
            "tag_textures.roof.scale: unknown key (expected one of: metres, texture)");
  EXPECT_EQ(parseError(withTagTextures(R"({"": "slate"})")),
            "tag_textures[\"\"]: the empty tag names no faces (faces without a tag keep their material's texture)");
}

// by_size rules come before assign (and before the types' weights) and choose by area and depth:
// a building they take gets their type whatever its properties; one they do not take is
// assigned as before, drawing the same numbers.
TEST(Style, SizeRulesComeFirstByAreaAndDepth) {
  const std::string assign = R"({"when": {"property": {"use": "shop"}}, "types": "shop"}, {"types": "house"})";
  const Style s = parseStyle(std::string(kStyle).insert(
      std::string(kStyle).rfind('}'),
      R"(, "by_size": [{"when": {"area": [1000, 1e12]}, "types": "shed"}, {"when": {"depth": [20, 1e12]}, "types": {"shed": 1}}],
          "assign": [)" +
          assign + "]"));
  ASSERT_EQ(s.bySize.size(), 2u);
  auto typeOf = [&](Building b, double depth) {
    b.depth = depth;
    BuildingRandom r(1, b.id);
    return s.types[*assignType(s, b, r)].name;
  };
  EXPECT_EQ(typeOf(box("a", 30, 19.9), 19.9), "house");  // 597 m², 19.9 m deep
  EXPECT_EQ(typeOf(box("b", 30, 20), 20), "shed");       // 20 m deep
  EXPECT_EQ(typeOf(box("c", 100, 10), 10), "shed");      // 1,000 m², 10 m deep
  EXPECT_EQ(typeOf(box("d", 30, 10, {{"use", "shop"}}), 10), "shop");
  EXPECT_EQ(typeOf(box("e", 100, 10, {{"use", "shop"}}), 10), "shed");
  // A type's own `when` takes a depth too.
  const Style deep =
      parseStyle(withType(R"({"name": "deep", "when": {"depth": [5, 8]}, "edges": [{"profiles": "hip"}]})"));
  Building b = box("f", 10, 6);
  BuildingRandom r(1, "f");
  b.depth = 4.9;
  EXPECT_FALSE(assignType(deep, b, r));
  b.depth = 6;
  EXPECT_EQ(assignType(deep, b, r), 0u);
}

TEST(Style, SizeRuleFaultsAreNamed) {
  const std::string base = std::string(kStyle).substr(0, std::string(kStyle).rfind('}'));
  EXPECT_NE(parseError(base + R"(, "by_size": [{"when": {"depth": [20, 10]}, "types": "shed"}]})")
                .find("by_size[0].when.depth"),
            std::string::npos);
  EXPECT_NE(
      parseError(base + R"(, "by_size": [{"when": {"height": [1, 2]}, "types": "shed"}]})").find("by_size[0].when"),
      std::string::npos);
  EXPECT_NE(parseError(base + R"(, "by_size": [{"types": "barn"}]})").find("by_size[0].types"), std::string::npos);
  EXPECT_NE(parseError(base + R"(, "by_size": {"types": "shed"}})").find("by_size"), std::string::npos);
}

// A style that uses another keeps its by_size rules unless it has its own, which replace them.
TEST(Style, SizeRulesAreInheritedOrReplaced) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_style_by_size_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "base.json") << std::string(kStyle).insert(
      std::string(kStyle).rfind('}'), R"(, "by_size": [{"when": {"area": [1000, 1e12]}, "types": "shed"}])");
  std::ofstream(dir / "keeps.json") << R"({"use": ["base.json"]})";
  std::ofstream(dir / "own.json")
      << R"({"use": ["base.json"], "by_size": [{"when": {"depth": [30, 1e12]}, "types": "house"}]})";
  const Style keeps = loadStyle((dir / "keeps.json").string()), own = loadStyle((dir / "own.json").string());
  ASSERT_EQ(keeps.bySize.size(), 1u);
  EXPECT_EQ(keeps.bySize[0].when.minArea, 1000);
  ASSERT_EQ(own.bySize.size(), 1u);
  EXPECT_EQ(own.bySize[0].when.minDepth, 30);
  EXPECT_EQ(own.bySize[0].when.minArea, 0);
}
