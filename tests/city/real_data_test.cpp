// Every one of the 10,524 real footprints is either built as a closed shell or reported with a
// reason, with the three-style rule set; and the CLI writes the town and its tiles.
#include "city/town.h"
#include "core/materials.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

using namespace corbel;
using namespace corbel::city;

TEST(RealData, EveryBuildingIsClosedOrReportedWithAReason) {
  const Style style = loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/mixed.json");
  std::size_t total = 0, ok = 0;
  for (const char* file : {"kathmandu_np.geojson", "moosburg_de.geojson"}) {
    const Town t = readTownFile(std::string(CORBEL_FOOTPRINTS) + "/" + file);
    const auto labels = labelTown(t, style.labels);
    std::size_t seen = 0;
    const TownSummary s = buildTown(t, labels, style, {}, [&](const BuildingReport& r, MeshData* m) {
      ++seen;
      if (r.ok) {
        ASSERT_NE(m, nullptr);
        EXPECT_FALSE(m->faces.empty());
      } else {
        EXPECT_EQ(m, nullptr);
        EXPECT_FALSE(r.error.empty()) << r.id;
      }
    });
    EXPECT_EQ(seen, t.buildings.size());
    EXPECT_EQ(s.ok + s.refused + s.failed, t.buildings.size());
    total += seen;
    ok += s.ok;
    std::printf("%s: %zu buildings, %zu built, %zu refused, %zu failed\n", file, s.buildings, s.ok, s.refused,
                s.failed);
  }
  EXPECT_EQ(total, 10524u);  // 3,544 + 6,980 (the data's README)
  EXPECT_GT(ok, 10524u * 98 / 100);
}

TEST(RealData, TheCliWritesTheTownAndItsTiles) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_cli_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string cmd = std::string(CORBEL_CLI) + " city " + CORBEL_FOOTPRINTS + "/kathmandu_np.geojson --style " +
                          CORBEL_SOURCE_DIR + "/assets/styles/suburban.json --jobs 2 --detail steps --out " +
                          (dir / "town.glb").string() + " --tiles " + (dir / "tiles").string() + " --tile-size 400 > " +
                          (dir / "out.json").string() + " 2> " + (dir / "err.txt").string();
  const int rc = std::system(cmd.c_str());
  EXPECT_TRUE(WEXITSTATUS(rc) == 0 || WEXITSTATUS(rc) == 1) << rc;
  std::ifstream in(dir / "out.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["buildings"], 3544);
  EXPECT_GT(std::filesystem::file_size(dir / "town.glb"), 1000u);
  std::size_t tiles = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "tiles")) tiles += e.path().extension() == ".glb";
  EXPECT_EQ(tiles, j["tiles"].get<std::size_t>());
  EXPECT_GT(tiles, 1u);
}

// The glb of a street of old-town houses is textured by tag: read as bytes and its JSON chunk
// parsed, every material the style's tags give a built-in name has its texture, the faces of the
// style's tag_textures theirs, every primitive of such a material a UV per corner; `--textures
// off` writes none, a bad value is named.
TEST(RealData, TheCliTexturesTheGlbByTag) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_texture_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run = [&](const std::string& name, const std::string& extra) {
    const std::string cmd = std::string(CORBEL_CLI) + " city --street \"0,0;40,20;80,10\" --style " +
                            CORBEL_SOURCE_DIR + "/assets/styles/oldtown.json --out " + (dir / name).string() + " " +
                            extra + " > " + (dir / "out.json").string() + " 2> " + (dir / "err.txt").string();
    return WEXITSTATUS(std::system(cmd.c_str()));
  };
  auto gltfOf = [&](const std::string& name) {
    std::ifstream in(dir / name, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_GT(bytes.size(), 20u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
  };
  ASSERT_EQ(run("town.glb", ""), 0);
  const nlohmann::json g = gltfOf("town.glb");
  // A material "M (texture T)" is M on faces whose tag shows T (the style's tag_textures: soffits
  // of timber, dormer roofs of metal); every other textured material shows its own texture. One
  // image and texture per texture name, named by it.
  std::set<std::string> textured;
  std::map<std::string, int> textureOfName;
  bool tagTextured = false;
  for (const auto& m : g["materials"]) {
    const std::string name = m["name"];
    const bool has = m["pbrMetallicRoughness"].contains("baseColorTexture");
    std::string texture = name;
    if (const auto own = name.find(" (texture "); own != std::string::npos) {
      texture = name.substr(own + 10, name.size() - own - 11);
      // A material's own texture, or a tag's: timber soffits, metal dormer roofs.
      EXPECT_TRUE(texture == name.substr(0, own) || texture == "timber" || texture == "metal") << name;
      EXPECT_TRUE(has) << name;
      tagTextured = tagTextured || texture == "timber";
    } else {
      EXPECT_EQ(has, isBuiltinMaterial(name)) << name;  // the table of core/materials.h
    }
    if (has) {
      textured.insert(name);
      const int index = m["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>();
      EXPECT_EQ(textureOfName.emplace(texture, index).first->second, index) << name;
      EXPECT_EQ(g["images"][g["textures"][index]["source"].get<int>()]["name"], texture) << name;
    }
  }
  EXPECT_TRUE(textured.count("plaster (texture plaster)") || textured.count("brick (texture brick)"));
  EXPECT_TRUE(textured.count("timber (texture timber)"));  // the gables' tag material
  EXPECT_TRUE(tagTextured);               // the soffits' tag texture
  EXPECT_EQ(g["images"].size(), textureOfName.size());
  EXPECT_EQ(g["textures"].size(), textureOfName.size());
  std::size_t primitives = 0;
  for (const auto& mesh : g["meshes"])
    for (const auto& p : mesh["primitives"]) {
      const std::string name = g["materials"][p["material"].get<int>()]["name"];
      ASSERT_EQ(p["attributes"].contains("TEXCOORD_0"), textured.count(name) > 0) << name;
      if (!textured.count(name)) continue;
      ++primitives;
      EXPECT_EQ(g["accessors"][p["attributes"]["TEXCOORD_0"].get<int>()]["count"],
                g["accessors"][p["attributes"]["POSITION"].get<int>()]["count"]);
    }
  EXPECT_GT(primitives, 0u);

  ASSERT_EQ(run("plain.glb", "--textures off"), 0);
  EXPECT_FALSE(gltfOf("plain.glb").contains("images"));
  EXPECT_EQ(run("bad.glb", "--textures maybe"), 2);
  std::ifstream err(dir / "err.txt");
  const std::string message((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("--textures: expected on or off, not 'maybe'"), std::string::npos) << message;
}

// `--plots skeleton` grows a street's plots from seeds (Fig. 26): as many plots as the normal
// cuts, all built; a bad value, or plots without a street, are refused by name.
TEST(RealData, TheCliGrowsStreetPlotsBySkeleton) {
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_plots_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto run = [&](const std::string& args, nlohmann::json* summary = nullptr) {
    const std::string cmd = std::string(CORBEL_CLI) + " city " + args + " --style " + CORBEL_SOURCE_DIR +
                            "/assets/styles/oldtown.json --out " + (dir / "t.glb").string() + " > " +
                            (dir / "out.json").string() + " 2> " + (dir / "err.txt").string();
    const int rc = WEXITSTATUS(std::system(cmd.c_str()));
    if (summary) {
      std::ifstream in(dir / "out.json");
      std::string line, last;
      while (std::getline(in, line))
        if (!line.empty()) last = line;
      *summary = nlohmann::json::parse(last);
    }
    return rc;
  };
  auto error = [&] {
    std::ifstream err(dir / "err.txt");
    return std::string((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  };
  nlohmann::json cuts, grown;
  ASSERT_EQ(run("--street \"0,0;40,20;80,10\"", &cuts), 0) << error();
  ASSERT_EQ(run("--street \"0,0;40,20;80,10\" --plots skeleton", &grown), 0) << error();
  EXPECT_EQ(grown["buildings"], cuts["buildings"]);
  EXPECT_EQ(grown["ok"], grown["buildings"]);
  EXPECT_EQ(run("--street \"0,0;40,20;80,10\" --plots voronoi"), 2);
  EXPECT_NE(error().find("--plots: expected normals or skeleton"), std::string::npos) << error();
  EXPECT_EQ(run(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/town-moosburg.geojson --plots skeleton"), 2);
  EXPECT_NE(error().find("--plots requires --street"), std::string::npos) << error();
}
