// Import: the lon/lat frame against great-circle distances, detection of the coordinates, and
// the clean-up's reasons on footprints drawn to be bad.
#include "city/import.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace corbel;
using namespace corbel::city;

namespace {

// A square building with its south-west corner at (lon, lat), `d` degrees a side.
std::string square(double lon, double lat, double d, const std::string& id) {
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      R"({"type":"Feature","id":"%s","properties":{"name":"%s"},"geometry":{"type":"Polygon","coordinates":[[[%.9f,%.9f],[%.9f,%.9f],[%.9f,%.9f],[%.9f,%.9f],[%.9f,%.9f]]]}})",
      id.c_str(), id.c_str(), lon, lat, lon + d, lat, lon + d, lat + d, lon, lat + d, lon, lat);
  return buf;
}

std::string collection(const std::vector<std::string>& features) {
  std::string s = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < features.size(); ++i) s += (i ? "," : "") + features[i];
  return s + "]}";
}

std::string polygon(const std::string& id, const std::vector<Vec2>& ring) {
  std::string s =
      R"({"type":"Feature","id":")" + id + R"(","properties":{},"geometry":{"type":"Polygon","coordinates":[[)";
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Vec2& p = ring[i % ring.size()];
    s += (i ? "," : "") + ("[" + std::to_string(p[0]) + "," + std::to_string(p[1]) + "]");
  }
  return s + "]]}}";
}

const Building& byId(const Town& t, const std::string& id) {
  for (const auto& b : t.buildings)
    if (b.id == "\"" + id + "\"" || b.id == id) return b;
  throw std::runtime_error("no building " + id);
}

bool hasNote(const Building& b, const std::string& word) {
  for (const auto& n : b.notes)
    if (n.find(word) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(Import, HaversineOfOneThousandthDegreeOfLatitude) {
  // R π / 180 × 0.001 by hand: 6371008.8 × 1.745329252e-5 = 111.19508 m.
  EXPECT_NEAR(haversine(11.9, 48.0, 11.9, 48.001), 111.19508, 1e-4);
  // Along the equator a degree of longitude is the same length.
  EXPECT_NEAR(haversine(0, 0, 0.001, 0), 111.19508, 1e-4);
}

TEST(Import, LonLatIsProjectedWithinTheStatedErrorOfGreatCircleDistances) {
  // Four buildings about 1.1 km apart around Moosburg (48.47° N).
  const double lons[] = {11.930, 11.945, 11.930, 11.945}, lats[] = {48.460, 48.460, 48.470, 48.470};
  std::vector<std::string> fs;
  for (int i = 0; i < 4; ++i) fs.push_back(square(lons[i], lats[i], 0.0002, "b" + std::to_string(i)));
  const Town t = readTown(collection(fs));
  ASSERT_EQ(t.frame.coordinates, Coordinates::Geographic) << t.frame.how;
  EXPECT_NEAR(t.frame.lat0, 48.4651, 1e-4);
  ASSERT_EQ(t.buildings.size(), 4u);
  for (const auto& b : t.buildings) EXPECT_EQ(b.problem, "") << b.id;
  // The outer ring starts at the south-west corner (readers keep the first corner).
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Vec2 d = t.buildings[i].loops[0][0] - t.buildings[j].loops[0][0];
      const double truth = haversine(lons[i], lats[i], lons[j], lats[j]);
      worst = std::max(worst, std::abs(d.norm() - truth) / truth);
    }
  // The stated bound: |cos lat0 / cos lat - 1| over the data, here tan(48.47°) × 0.005° ≈ 1e-4.
  EXPECT_GT(t.frame.scaleError, 0.8e-4);
  EXPECT_LT(t.frame.scaleError, 1.2e-4);
  EXPECT_LE(worst, t.frame.scaleError);
  // A building 0.0002° a side: 22.24 m north-south exactly, 22.24 cos(lat) east-west.
  const auto& r = t.buildings[0].loops[0];
  EXPECT_NEAR((r[3] - r[0]).norm(), 0.0002 * 6371008.8 * std::numbers::pi / 180, 1e-6);
  EXPECT_EQ(t.buildings[0].properties["name"], "b0");
}

TEST(Import, ProjectedCoordinatesAreDetectedAndKept) {
  const Town t = readTown(collection({polygon("a", {{500, 500}, {520, 500}, {520, 510}, {500, 510}})}));
  EXPECT_EQ(t.frame.coordinates, Coordinates::Metric);
  EXPECT_NE(t.frame.how.find("metres"), std::string::npos);
  EXPECT_EQ(t.buildings[0].loops[0][1], Vec2(520, 500));
  EXPECT_DOUBLE_EQ(t.buildings[0].area, 200);
}

TEST(Import, TheRealDataSaysItIsProjected) {
  const Town t = readTownFile(std::string(CORBEL_FOOTPRINTS) + "/kathmandu_np.geojson");
  EXPECT_EQ(t.frame.coordinates, Coordinates::Metric);
  EXPECT_NE(t.frame.how.find("frame"), std::string::npos);
  EXPECT_EQ(t.buildings.size(), 3544u);
}

TEST(Import, StreetsAreReadAsCentrelinesNotBuildings) {
  const std::string street =
      R"({"type":"Feature","properties":{"highway":"residential"},"geometry":{"type":"LineString","coordinates":[[0,-10],[50,-10],[80,0]]}})";
  const Town t = readTown(collection({polygon("a", {{0, 0}, {10, 0}, {10, 6}, {0, 6}}), street}));
  ASSERT_EQ(t.streets.size(), 1u);
  EXPECT_EQ(t.streets[0].points.size(), 3u);
  ASSERT_EQ(t.buildings.size(), 1u);
  EXPECT_EQ(t.buildings[0].problem, "");
}

TEST(Cleanup, EveryFixAndRefusalHasItsReason) {
  const Town t = readTown(collection({
      // A duplicate corner 0.4 mm from the one before it.
      polygon("duplicate", {{0, 0}, {10, 0}, {10.0004, 0}, {10, 8}, {0, 8}}),
      // A corner 3 mm off the straight line of a wall.
      polygon("colinear", {{100, 0}, {105, 0.003}, {110, 0}, {110, 8}, {100, 8}}),
      // A spike: out 6 m and back, 1 cm wide at its base.
      polygon("spike", {{200, 0}, {210, 0}, {210, 4}, {216, 4.005}, {210, 4.01}, {210, 8}, {200, 8}}),
      // 30 m long and 0.6 m wide.
      polygon("sliver", {{300, 0}, {330, 0}, {330, 0.6}, {300, 0.6}}),
      // 1.5 m × 1.5 m.
      polygon("tiny", {{400, 0}, {401.5, 0}, {401.5, 1.5}, {400, 1.5}}),
      polygon("good", {{500, 0}, {510, 0}, {510, 8}, {500, 8}}),
  }));
  const Building& dup = byId(t, "duplicate");
  EXPECT_EQ(dup.problem, "");
  EXPECT_TRUE(hasNote(dup, "1 duplicate corner")) << dup.notes.size();
  EXPECT_EQ(dup.loops[0].size(), 4u);
  const Building& col = byId(t, "colinear");
  EXPECT_TRUE(hasNote(col, "1 colinear corner"));
  EXPECT_EQ(col.loops[0].size(), 4u);
  const Building& spike = byId(t, "spike");
  EXPECT_EQ(spike.problem, "");
  EXPECT_TRUE(hasNote(spike, "spike"));
  // The spike's tip goes, then the two corners at its base are colinear with the wall.
  EXPECT_EQ(spike.loops[0].size(), 4u);
  EXPECT_NEAR(spike.area, 80, 0.1);
  EXPECT_NE(byId(t, "sliver").problem.find("sliver: about 0.588 m wide"), std::string::npos)
      << byId(t, "sliver").problem;
  EXPECT_NE(byId(t, "tiny").problem.find("tiny building: 2.25 m²"), std::string::npos) << byId(t, "tiny").problem;
  const Building& good = byId(t, "good");
  EXPECT_EQ(good.problem, "");
  EXPECT_TRUE(good.notes.empty());
}

TEST(Import, RealFootprintsInLonLatKeepTheirAreas) {
  // Moosburg back in lon/lat by the inverse of the file's own frame (its README: equirectangular
  // about lon0/lat0 on R = 6371008.8 m), read again about our own centre: each area agrees with
  // the file's area_m2 to within twice the stated scale error (areas scale in two directions)
  // plus the file's 1 mm rounding.
  const std::string path = std::string(CORBEL_FOOTPRINTS) + "/moosburg_de.geojson";
  nlohmann::json data = nlohmann::json::parse(std::ifstream(path));
  const double lon0 = data["frame"]["lon0"], lat0 = data["frame"]["lat0"], R = 6371008.8, deg = std::numbers::pi / 180;
  nlohmann::json out = {{"type", "FeatureCollection"}, {"features", nlohmann::json::array()}};
  for (std::size_t i = 0; i < data["features"].size(); i += 10) {
    nlohmann::json f = data["features"][i];
    for (auto& ring : f["geometry"]["coordinates"])
      for (auto& p : ring) {
        const double x = p[0], y = p[1];
        p[0] = lon0 + x / (R * std::cos(lat0 * deg)) / deg;
        p[1] = lat0 + y / R / deg;
      }
    out["features"].push_back(f);
  }
  const Town t = readTown(out.dump());
  ASSERT_EQ(t.frame.coordinates, Coordinates::Geographic) << t.frame.how;
  EXPECT_GT(t.frame.scaleError, 0);
  EXPECT_LT(t.frame.scaleError, 1e-3);
  std::size_t checked = 0;
  for (const auto& b : t.buildings) {
    if (!b.problem.empty() || !b.notes.empty()) continue;  // clean-up changes the area a little
    const double want = b.properties["area_m2"];
    EXPECT_NEAR(b.area, want, want * 2 * t.frame.scaleError + 0.01) << b.id;
    ++checked;
  }
  EXPECT_GT(checked, 300u);
}
