// Import: the lon/lat frame against great-circle distances, detection of the coordinates, and
// the clean-up's reasons on footprints drawn to be bad.
#include "city/import.h"

#include <geodesic.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

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

TEST(Import, LonLatIsProjectedWithinTheStatedErrorOfGeodesicDistances) {
  // Four buildings about 1.1 km apart around Moosburg (48.47° N).
  const double lons[] = {11.930, 11.945, 11.930, 11.945}, lats[] = {48.460, 48.460, 48.470, 48.470};
  std::vector<std::string> fs;
  for (int i = 0; i < 4; ++i) fs.push_back(square(lons[i], lats[i], 0.0002, "b" + std::to_string(i)));
  const Town t = readTown(collection(fs));
  ASSERT_EQ(t.frame.coordinates, Coordinates::Geographic) << t.frame.how;
  EXPECT_EQ(t.frame.crs, "EPSG:4326");
  // The frame's origin is the middle of the data's extent.
  EXPECT_NEAR(t.frame.lon0, 11.9376, 1e-4);
  EXPECT_NEAR(t.frame.lat0, 48.4651, 1e-4);
  ASSERT_EQ(t.buildings.size(), 4u);
  for (const auto& b : t.buildings) EXPECT_EQ(b.problem, "") << b.id;
  // Distances between the south-west corners against the geodesic ones on the WGS 84 ellipsoid
  // (PROJ's geodesic library, Karney's algorithm): within the stated scale error, which for a
  // transverse Mercator about the centre is x² / (2 R²) at 560 m east or west: about 4e-9.
  geod_geodesic g;
  geod_init(&g, 6378137, 1 / 298.257223563);
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Vec2 d = t.buildings[i].loops[0][0] - t.buildings[j].loops[0][0];
      double truth = 0, az1 = 0, az2 = 0;
      geod_inverse(&g, lats[i], lons[i], lats[j], lons[j], &truth, &az1, &az2);
      worst = std::max(worst, std::abs(d.norm() - truth) / truth);
    }
  EXPECT_GT(t.frame.scaleError, 2e-9);
  EXPECT_LT(t.frame.scaleError, 1e-8);
  EXPECT_LE(worst, t.frame.scaleError);
  // A side of 0.0002° of latitude: its geodesic length.
  const auto& r = t.buildings[0].loops[0];
  double side = 0, az1 = 0, az2 = 0;
  geod_inverse(&g, lats[0], lons[0], lats[0] + 0.0002, lons[0], &side, &az1, &az2);
  EXPECT_NEAR((r[3] - r[0]).norm(), side, side * 1e-8);
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
  EXPECT_TRUE(hasNote(col, "1 corner(s) within 0.01 m"));
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

// Real footprints in lon/lat, UTM, web Mercator and other formats against geodesic areas:
// gis_input_test.cpp.

namespace {

// n corners evenly on a circle of radius r about c, counter-clockwise.
std::vector<Vec2> circle(std::size_t n, double r, const Vec2& c = Vec2(0, 0)) {
  std::vector<Vec2> ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back(c + Vec2(r * std::cos(a), r * std::sin(a)));
  }
  return ring;
}

double shoelace(const std::vector<Vec2>& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    twice += p[0] * q[1] - p[1] * q[0];
  }
  return twice / 2;
}

double toSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.sqrnorm(), 0.0, 1.0);
  return (p - (a + d * t)).norm();
}

}  // namespace

// A circle of radius 100 m drawn with 100,000 corners (6.3 mm apart) is a building, not a
// tiny one: the clean-up keeps its outline within its stated tolerance (every corner of the
// input within 1 cm of the cleaned ring), so the area is πr² less at most the perimeter times the
// tolerance, 2πr × 0.01 m (the input polygon itself is short of πr² by n r²/2 sin(2π/n), 2e-5 m²).
// A clean-up that compares each corner with a neighbour it has just dropped walks round the
// ring and leaves a sliver of it.
TEST(Cleanup, ADenseCircleKeepsItsShapeWithinTheTolerance) {
  const double r = 100, tolerance = CleanupOptions().colinear;
  const std::vector<Vec2> dense = circle(100000, r);
  const Town t = readTown(collection({polygon("round", dense)}));
  const Building& b = byId(t, "round");
  ASSERT_EQ(b.problem, "");
  ASSERT_EQ(b.loops.size(), 1u);
  const auto& ring = b.loops[0];
  const double pi = std::numbers::pi;
  EXPECT_LE(std::abs(b.area - pi * r * r), 2 * pi * r * tolerance + 1e-3) << b.area;
  EXPECT_NEAR(b.area, shoelace(ring), 1e-9 * b.area);
  // Every kept corner is a corner of the input (on the circle, to the file's micrometres), and
  // every corner of the input lies within the tolerance of the cleaned outline.
  for (const Vec2& p : ring) EXPECT_NEAR(p.norm(), r, 2e-6);
  double worst = 0;
  for (const Vec2& p : dense) {
    double d = INFINITY;
    for (std::size_t i = 0; i < ring.size(); ++i) d = std::min(d, toSegment(p, ring[i], ring[(i + 1) % ring.size()]));
    worst = std::max(worst, d);
  }
  EXPECT_LE(worst, tolerance + 1e-6);
  // Chords with a sagitta of at most 1 cm are at most 2 sqrt(2 r 0.01) = 2.83 m long: at least
  // 2πr / 2.83 = 222 of them.
  EXPECT_GE(ring.size(), 222u);
  EXPECT_TRUE(hasNote(b, "corner(s) within 0.01 m"));
  // About twice the radius deep.
  EXPECT_NEAR(b.depth, 2 * r, 2 * 0.005 * 2 * r);  // to half a percent of its 200 m extent
}

// The same bound for a ring with its corners bunched up (0.5 mm apart, so the duplicate merge
// takes every other one), holes too.
TEST(Cleanup, ACourtyardOfDenseCornersKeepsItsArea) {
  std::vector<Vec2> hole = circle(40000, 3.0);
  std::reverse(hole.begin(), hole.end());
  std::string feature = R"({"type":"Feature","id":"ring","properties":{},"geometry":{"type":"Polygon","coordinates":[)";
  auto ringJson = [](const std::vector<Vec2>& ring) {
    std::string s = "[";
    for (std::size_t i = 0; i <= ring.size(); ++i) {
      const Vec2& p = ring[i % ring.size()];
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s[%.9f,%.9f]", i ? "," : "", p[0], p[1]);
      s += buf;
    }
    return s + "]";
  };
  feature += ringJson({{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}) + "," + ringJson(hole) + "]}}";
  const Town t = readTown(collection({feature}));
  const Building& b = byId(t, "ring");
  ASSERT_EQ(b.problem, "");
  ASSERT_EQ(b.loops.size(), 2u);
  const double pi = std::numbers::pi, want = 400 - pi * 9;
  EXPECT_LE(std::abs(b.area - want), 2 * pi * 3 * CleanupOptions().colinear + 1e-3) << b.area;
  EXPECT_TRUE(hasNote(b, "duplicate corner"));
}

// The diameter against every pair of points, on random clouds and on rings.
TEST(Cleanup, TheDiameterIsTheFarthestPairOfPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2> pts(3 + trial % 40);
    for (auto& p : pts) p = Vec2(u(rng), trial % 3 == 0 ? std::round(u(rng)) : u(rng));
    double brute = 0;
    for (const Vec2& p : pts)
      for (const Vec2& q : pts) brute = std::max(brute, (p - q).norm());
    EXPECT_NEAR(diameter(pts), brute, 1e-9) << trial;
  }
  EXPECT_NEAR(diameter(circle(1000, 7)), 14, 1e-9);  // an even count: opposite corners
  EXPECT_EQ(diameter({{0, 0}, {3, 0}, {3, 4}}), 5);
  EXPECT_EQ(diameter({{0, 0}, {1, 1}, {2, 2}}), std::sqrt(8.0));  // colinear
}

// A building is at most 5 km across (the farthest two corners); one wider is refused before any
// other clean-up, with the figures. The 3-4-5 triangle's rectangle is exactly at the limit.
TEST(Cleanup, ABuildingWiderThanTheLimitIsRefused) {
  const Town t = readTown(collection({
      polygon("limit", {{0, 0}, {3000, 0}, {3000, 4000}, {0, 4000}}),
      polygon("over", {{0, 5000}, {3000, 5000}, {3000, 9001}, {0, 9001}}),
      polygon("huge", {{0, 0}, {1e9, 0}, {1e9, 1e9}, {0, 1e9}}),
  }),
                          // Positions 10⁶ km out are no CRS the reader can tell: it is given.
                          Coordinates::Metric);
  EXPECT_EQ(byId(t, "limit").problem, "");
  EXPECT_EQ(byId(t, "over").problem,
            "too large: 5001 m across (the farthest two corners), over the 5000 m a building may span");
  EXPECT_EQ(byId(t, "huge").problem.rfind("too large: 1.41e+09 m across", 0), 0u) << byId(t, "huge").problem;
}

// Depth is twice the radius of the largest circle inside: the shorter side of a rectangle, and
// for a 30 m square with a 10 m square courtyard in its middle, the circle in a corner of the
// ring, on the diagonal at (t, t) where the outer walls (15 - t away) and the courtyard's corner
// (sqrt 2 (t - 5) away) are as far: t = (15 + 5 sqrt 2) / (1 + sqrt 2).
TEST(Cleanup, DepthIsTwiceTheRadiusOfTheLargestCircleInside) {
  const Town t = readTown(collection({
      polygon("long", {{0, 0}, {30, 0}, {30, 12}, {0, 12}}),
      polygon("tilted", {{100, 0}, {100 + 24 * 0.6, 24 * 0.8}, {100 + 24 * 0.6 - 9 * 0.8, 24 * 0.8 + 9 * 0.6},
                         {100 - 9 * 0.8, 9 * 0.6}}),
  }));
  // As the importer finds it: to 5 cm or half a percent of the narrower extent (12 m; 20.4 m).
  EXPECT_NEAR(byId(t, "long").depth, 12, 2 * 0.06);
  EXPECT_NEAR(byId(t, "tilted").depth, 9, 2 * 0.102);
  const double precision = 0.01;
  const double s2 = std::sqrt(2.0), at = (15 + 5 * s2) / (1 + s2);
  std::vector<std::vector<Vec2>> ring{{{-15, -15}, {15, -15}, {15, 15}, {-15, 15}}, {{-5, -5}, {-5, 5}, {5, 5}, {5, -5}}};
  EXPECT_NEAR(inscribedDepth(ring, precision), 2 * (15 - at), 2 * precision);
  EXPECT_NEAR(inscribedDepth({ring[0]}, precision), 30, 2 * precision);
}
