// Wall heights from footprint attributes (a style's "heights", docs/city.md): footprints written
// by hand as GeoJSON, turned into a GeoPackage by GDAL's ogr2ogr, built by corbel-cli city, and
// the glb read back: each building stands as tall as its attribute says, against the geometry of
// its profile (a flat roof at the wall's top; a 45° hipped roof on a 10 m square rises 5 m more).
#include "city/import.h"
#include "city/style.h"
#include "core/error.h"

#include "../common/glb_read.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

using namespace corbel;
using namespace corbel::city;
namespace fs = std::filesystem;

namespace {

int shell(const std::string& cmd) { return WEXITSTATUS(std::system(cmd.c_str())); }

// A 10 m square at x0 (metres about a local origin) with these properties.
nlohmann::json square(double x0, const std::string& id, const nlohmann::json& props) {
  nlohmann::json ring = nlohmann::json::array();
  for (auto [x, y] : {std::pair{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}) ring.push_back({x0 + x, y});
  nlohmann::json p = props;
  p["id"] = id;
  return {{"type", "Feature"}, {"properties", p}, {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}}};
}

// A style of one type whose every edge takes `profile`, walls from "height", else from
// "building:levels" at 3 m a storey.
std::string styleWith(const std::string& profile) {
  return R"({"name": "t", "heights": {"walls": ["height", "building:height"], "levels": "building:levels", "storey": 3},
    "profiles": [{"name": "p", "points": )" +
         profile + R"(}], "types": [{"name": "house", "edges": [{"profiles": "p"}]}]})";
}

// Each building's highest point in the glb (glTF +Y up), by node name.
std::map<std::string, double> tops(const std::string& glb) {
  std::map<std::string, double> top;
  for (const auto& p : corbel::test::worldPrimitives(corbel::test::readGlbFile(glb)))
    for (const auto& q : p.positions) top[p.nodeName] = std::max(top.count(p.nodeName) ? top[p.nodeName] : -1e9, q[1]);
  return top;
}

}  // namespace

TEST(Heights, AFootprintsHeightOrLevelsSetItsWalls) {
  const fs::path dir = fs::temp_directory_path() / ("corbel-heights-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  nlohmann::json fc = {{"type", "FeatureCollection"}, {"features", nlohmann::json::array()}};
  // OSM writes heights as strings, with or without a unit.
  fc["features"].push_back(square(0, "h12.5", {{"height", "12.5 m"}}));
  fc["features"].push_back(square(20, "levels4", {{"building:levels", "4"}}));
  fc["features"].push_back(square(40, "both", {{"height", 7.25}, {"building:levels", 9}}));  // walls first
  fc["features"].push_back(square(60, "low", {{"height", 0.5}}));                            // ignored: under 2 m
  fc["features"].push_back(square(80, "none", nlohmann::json::object()));
  std::ofstream(dir / "in.geojson") << fc.dump();
  ASSERT_EQ(shell("ogr2ogr -f GPKG \"" + (dir / "in.gpkg").string() + "\" \"" + (dir / "in.geojson").string() +
                  "\" 2>/dev/null"),
            0);
  // The walls the attributes ask for; "low" and "none" keep the profile's own 3 m.
  const std::map<std::string, double> walls = {{"h12.5", 12.5}, {"levels4", 12}, {"both", 7.25}, {"low", 3}, {"none", 3}};
  struct Case {
    const char* name;
    const char* profile;
    double above;  // the roof's top above the walls' for a 10 m square
  };
  for (const Case& c : {Case{"flat", "[[0, 0], [0, 3], [6, 3], [7, 4]]", 0.0}, Case{"hipped", "[[0, 0], [0, 3], [8, 11]]", 5.0}}) {
    SCOPED_TRACE(c.name);
    const fs::path style = dir / (std::string(c.name) + ".json"), glb = dir / (std::string(c.name) + ".glb");
    std::ofstream(style) << styleWith(c.profile);
    const int rc = shell(std::string(CORBEL_CLI) + " city \"" + (dir / "in.gpkg").string() + "\" --crs local --style \"" +
                         style.string() + "\" --textures off --jobs 2 --out \"" + glb.string() + "\" > /dev/null 2>&1");
    ASSERT_EQ(rc, 0);
    const auto top = tops(glb.string());
    ASSERT_EQ(top.size(), walls.size());
    // glb positions are quantized to steps of at most 1 mm.
    for (const auto& [id, wall] : walls) EXPECT_NEAR(top.at(id), wall + c.above, 1e-3) << id;
  }
  fs::remove_all(dir);
}

TEST(Heights, TheRoofKeepsItsShapeOnTallerWalls) {
  extrude::Profile p{"eaves", {{0, 0}, {0, 2}, {0, 7}, {-0.3, 7}, {5, 13.3}}, {"wall", "wall", "soffit", "roof"}};
  EXPECT_EQ(wallTop(p), 7);
  const extrude::Profile q = withWallHeight(p, 10);
  // One wall segment up to 10 m, then the soffit and the roof 3 m higher.
  ASSERT_EQ(q.points.size(), 4u);
  EXPECT_EQ(q.points[1], Vec2(0, 10));
  EXPECT_EQ(q.points[2], Vec2(-0.3, 10));
  EXPECT_EQ(q.points[3], Vec2(5, 16.3));
  EXPECT_EQ(q.tags, (std::vector<std::string>{"wall", "soffit", "roof"}));
  // A profile without walls gets one.
  const extrude::Profile r = withWallHeight({"roof", {{0, 0}, {1, 1}}, {"roof"}}, 4);
  EXPECT_EQ(r.points, (std::vector<Vec2>{{0, 0}, {0, 4}, {1, 5}}));
  EXPECT_EQ(r.tags, (std::vector<std::string>{"wall", "roof"}));
}

TEST(Heights, StyleFaultsAreNamed) {
  try {
    parseStyle(R"({"heights": {"storey": 3}, "profiles": [], "types": []})");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heights"), std::string::npos) << e.what();
  }
}
