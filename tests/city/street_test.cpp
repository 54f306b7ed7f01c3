// Street plots (Fig. 26): the plots tile the frontage on both sides of a spline, and town
// houses built on them stay closed when the street is reshaped.
#include "city/street.h"
#include "city/town.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace corbel;
using namespace corbel::city;

namespace {

double area(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    a += p[i][0] * p[(i + 1) % p.size()][1] - p[i][1] * p[(i + 1) % p.size()][0];
  return a / 2;
}

// Whether some edge of ring a is the reverse of an edge of ring b (corners within tol).
bool shareAnEdge(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double tol) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if ((a[i] - b[(j + 1) % b.size()]).norm() < tol && (a[(i + 1) % a.size()] - b[j]).norm() < tol) return true;
  return false;
}

// Frontage tiling, checked from the plots alone: every plot is counter-clockwise, the plots
// of one side add up to the strip's area (Steiner: length × depth on the two sides together,
// the curvature terms cancel), and each plot's end edge is its neighbour's start edge.
// Where the street bends sharply plots are shallower on the inside (fullDepth false): then
// neighbours share their front corner, and the depths add up to less than the strip.
void expectTiles(const Town& t, const PlotOptions& o, bool fullDepth = true) {
  double length = 0;
  for (std::size_t i = 1; i < t.streets[0].points.size(); ++i)
    length += (t.streets[0].points[i] - t.streets[0].points[i - 1]).norm();
  double total = 0;
  std::size_t perSide = t.buildings.size() / 2;
  for (const auto& b : t.buildings) {
    ASSERT_EQ(b.problem, "") << b.id;
    ASSERT_GT(area(b.loops[0]), 0) << b.id;
    total += area(b.loops[0]);
  }
  if (fullDepth)
    EXPECT_NEAR(total, 2 * length * o.depth, 2 * length * o.depth * 2e-3);
  else
    EXPECT_LT(total, 2 * length * o.depth);
  // Widths: the frontage is cut evenly, within the wanted plot width.
  EXPECT_EQ(perSide, static_cast<std::size_t>(std::floor(length / o.plotWidth)));
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t k = 0; k + 1 < perSide; ++k) {
      // Shared boundary: some edge of plot k is the reverse of an edge of plot k + 1.
      const auto& a = t.buildings[side * perSide + k].loops[0];
      const auto& b = t.buildings[side * perSide + k + 1].loops[0];
      bool shared = fullDepth && shareAnEdge(a, b, 1e-9);
      for (std::size_t i = 0; i < a.size() && !fullDepth && !shared; ++i)
        for (std::size_t j = 0; j < b.size() && !shared; ++j) shared = (a[i] - b[j]).norm() < 1e-9;
      EXPECT_TRUE(shared) << side << " " << k;
    }
}

// Grown plots (PlotMethod::Skeleton) tile their strip: counter-clockwise, their areas add up to
// the two strips' (Steiner: 2 L × depth), neighbours share an edge (some edge of one is the
// reverse of an edge of the other), and every plot has a corner on the front line.
void expectTilesGrown(const Town& t, const PlotOptions& o) {
  double length = 0;
  for (std::size_t i = 1; i < t.streets[0].points.size(); ++i)
    length += (t.streets[0].points[i] - t.streets[0].points[i - 1]).norm();
  double total = 0;
  const std::size_t perSide = t.buildings.size() / 2;
  EXPECT_EQ(perSide, static_cast<std::size_t>(std::floor(length / o.plotWidth)));
  for (const auto& b : t.buildings) {
    ASSERT_EQ(b.problem, "") << b.id;
    ASSERT_GT(area(b.loops[0]), 0) << b.id;
    total += area(b.loops[0]);
  }
  EXPECT_NEAR(total, 2 * length * o.depth, 2 * length * o.depth * 2e-3);
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t k = 0; k + 1 < perSide; ++k) {
      const auto& a = t.buildings[side * perSide + k].loops[0];
      const auto& b = t.buildings[side * perSide + k + 1].loops[0];
      EXPECT_TRUE(shareAnEdge(a, b, 1e-6)) << side << " " << k;
    }
  // A corner on the front line: at the front distance from the centreline (its sampled polyline).
  const double front = o.streetWidth / 2 + o.setback;
  const auto& line = t.streets[0].points;
  for (const auto& b : t.buildings) {
    double best = 1e9;
    for (const Vec2& p : b.loops[0]) {
      double d = 1e9;
      for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2 ab = line[i + 1] - line[i];
        const double u = std::clamp(((p - line[i]) | ab) / (ab | ab), 0.0, 1.0);
        d = std::min(d, (line[i] + u * ab - p).norm());
      }
      best = std::min(best, std::abs(d - front));
    }
    EXPECT_LT(best, 0.05) << b.id << " does not reach the street";
  }
}

}  // namespace

TEST(Street, ASplineThroughItsPointsEndsAtThem) {
  const std::vector<Vec2> c{{0, 0}, {30, 10}, {60, 0}, {90, 15}};
  const auto s = catmullRom(c, 8);
  EXPECT_EQ(s.size(), 3u * 8 + 1);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR((s[i * 8] - c[i]).norm(), 0, 1e-12);
}

TEST(Street, PlotsOfAStraightStreetAreEqualRectangles) {
  PlotOptions o;
  const Town t = streetTown({{0, 0}, {100, 0}}, o);
  ASSERT_EQ(t.buildings.size(), 28u);  // floor(100 / 7) = 14 a side
  for (const auto& b : t.buildings) {
    EXPECT_EQ(b.loops[0].size(), 4u) << b.id;  // colinear stations removed
    EXPECT_NEAR(b.area, 100.0 / 14 * 12, 1e-9);
  }
  expectTiles(t, o);
}

TEST(Street, PlotsTileTheFrontageOfACurvedStreetAndFollowItsReshaping) {
  PlotOptions o;
  const Town a = streetTown({{0, 0}, {60, 12}, {120, 4}, {180, 20}}, o);
  expectTiles(a, o);
  // Dragging one point: the plots follow, still tiling.
  const Town b = streetTown({{0, 0}, {40, -15}, {80, 10}, {120, 40}}, o);  // sharper bends
  expectTiles(b, o, false);
  EXPECT_NE(a.buildings[3].loops[0][0], b.buildings[3].loops[0][0]);
}

// The paper's plots (Fig. 26): seeds grown by a second application of the skeleton. On a
// straight street the seeds are evenly spaced on the strip's middle line, so the line where two
// neighbours' fronts meet is the perpendicular halfway between them: the plots are the normal
// cuts' rectangles, corner for corner.
TEST(Street, SkeletonPlotsOfAStraightStreetAreTheNormalCuts) {
  PlotOptions o;
  const Town cuts = streetTown({{0, 0}, {100, 0}}, o);
  o.method = PlotMethod::Skeleton;
  const Town grown = streetTown({{0, 0}, {100, 0}}, o);
  ASSERT_EQ(grown.buildings.size(), cuts.buildings.size());
  for (std::size_t i = 0; i < cuts.buildings.size(); ++i) {
    const Building& g = grown.buildings[i];
    const Building& c = cuts.buildings[i];
    ASSERT_EQ(g.problem, "") << g.id;
    EXPECT_EQ(g.id, c.id);
    ASSERT_FALSE(g.notes.empty());
    EXPECT_NE(g.notes.front().find("skeleton"), std::string::npos) << g.notes.front();
    EXPECT_NEAR(g.area, c.area, 1e-6 * c.area) << g.id;
    ASSERT_EQ(g.loops[0].size(), 4u) << g.id;
    // The same corners, up to 1e-6 m.
    for (const Vec2& p : c.loops[0]) {
      double nearest = 1e9;
      for (const Vec2& q : g.loops[0]) nearest = std::min(nearest, (p - q).norm());
      EXPECT_LT(nearest, 1e-6) << g.id;
    }
  }
  expectTiles(grown, o);
}

// On a curved street the grown plots still tile the frontage (shared edges, Steiner's area) and
// each keeps a piece of the front line; they follow a reshaped street too.
TEST(Street, SkeletonPlotsTileACurvedFrontage) {
  PlotOptions o;
  o.method = PlotMethod::Skeleton;
  const Town a = streetTown({{0, 0}, {60, 12}, {120, 4}, {180, 20}}, o);
  for (const auto& b : a.buildings) {
    ASSERT_FALSE(b.notes.empty()) << b.id;
    EXPECT_NE(b.notes.front().find("grown from its seed"), std::string::npos) << b.id << ": " << b.notes.front();
  }
  expectTilesGrown(a, o);
}

TEST(Street, TownHousesFaceTheStreetAndBuildClosed) {
  const Style style = loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/oldtown.json");
  for (const auto& control : std::vector<std::vector<Vec2>>{{{0, 0}, {40, 20}, {80, 10}, {120, 40}},
                                                            {{0, 0}, {40, -15}, {80, 10}, {120, 40}}}) {
    for (const PlotMethod method : {PlotMethod::Normals, PlotMethod::Skeleton}) {
      PlotOptions o;
      o.method = method;
      const Town t = streetTown(control, o);
      const auto labels = labelTown(t, style.labels);
      for (std::size_t i = 0; i < t.buildings.size(); ++i) {
        EXPECT_TRUE(labels[i].fromStreet);
        // The plot's front edge (the one nearest the street) is labelled street.
        bool street = false;
        for (const auto& e : labels[i].edges) street = street || e.orientation == Orientation::Street;
        EXPECT_TRUE(street) << t.buildings[i].id;
      }
      std::size_t built = 0;
      buildTown(t, labels, style, {}, [&](const BuildingReport& r, MeshData* m) {
        EXPECT_TRUE(r.ok) << r.id << ": " << r.error;
        built += m != nullptr;
      });
      EXPECT_EQ(built, t.buildings.size());
    }
  }
}

TEST(Street, TheTownIsTheSameForAnyNumberOfJobsAndChunks) {
  const Style style = loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/suburban.json");
  const Town t = streetTown({{0, 0}, {60, 12}, {120, 4}, {180, 20}});
  const auto labels = labelTown(t, style.labels);
  auto build = [&](unsigned jobs, std::size_t chunk, std::uint64_t seed) {
    TownOptions o;
    o.jobs = jobs;
    o.chunk = chunk;
    o.seed = seed;
    std::vector<std::vector<Vec3>> points;
    buildTown(t, labels, style, o,
              [&](const BuildingReport&, MeshData* m) { points.push_back(m ? m->points : std::vector<Vec3>{}); });
    return points;
  };
  const auto a = build(1, 1024, 5), b = build(2, 3, 5), c = build(2, 1024, 6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(Street, FacesTakeTheMaterialTheStyleGivesTheirTag) {
  // suburban.json: chimneys of brick, their tops of stone; other faces keep their own.
  const Style style = loadStyle(std::string(CORBEL_SOURCE_DIR) + "/assets/styles/suburban.json");
  ASSERT_EQ(style.tagMaterials.at("chimney"), "brick");
  const Town t = streetTown({{0, 0}, {120, 0}});
  std::size_t chimneyFaces = 0, walls = 0;
  buildTown(t, labelTown(t, style.labels), style, {}, [&](const BuildingReport&, MeshData* m) {
    ASSERT_NE(m, nullptr);
    for (std::size_t f = 0; f < m->faces.size(); ++f) {
      const std::string& tag = m->tags[m->faceTag[f]];
      const std::string& material = m->materials[m->faceMaterial[f]];
      if (tag == "chimney") {
        ++chimneyFaces;
        EXPECT_EQ(material, "brick");
      }
      if (tag == "chimney top") {
        EXPECT_EQ(material, "stone");
      }
      if (tag == "wall") {
        ++walls;
        EXPECT_EQ(material, "plaster");
      }
    }
  });
  EXPECT_GT(chimneyFaces, 0u);
  EXPECT_GT(walls, 0u);
}
