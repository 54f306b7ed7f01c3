// Every one of the 10,524 real footprints is either built as a closed shell or reported with a
// reason, with the three-style rule set; and the CLI writes the town and its tiles.
#include "city/town.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

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
