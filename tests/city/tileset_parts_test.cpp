// The parts of a town's tileset (city/blocks.h, city/tileset.h) against hand computation: a
// block is a closed, outward prism whose volume is its footprint's area times its height, and
// the quadtree's leaves hold at most their capacity, each point inside its own leaf's cell.
#include "city/blocks.h"
#include "city/tileset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace {

using corbel::MeshData;
using corbel::Vec2;
using corbel::Vec3;

// Signed volume by the divergence theorem (fan triangles of each face from its first corner).
double volume(const MeshData& m) {
  double v = 0;
  for (const auto& f : m.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Vec3 &a = m.points[f[0]], &b = m.points[f[k]], &c = m.points[f[k + 1]];
      v += OpenMesh::dot(a, OpenMesh::cross(b, c)) / 6;
    }
  return v;
}

// Directed edges without exactly one reverse partner.
std::size_t unpaired(const MeshData& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& f : m.faces)
    for (std::size_t k = 0; k < f.size(); ++k) ++edges[{f[k], f[(k + 1) % f.size()]}];
  std::size_t bad = 0;
  for (const auto& [e, n] : edges) {
    const auto r = edges.find({e.second, e.first});
    if (n != 1 || r == edges.end() || r->second != 1) ++bad;
  }
  return bad;
}

TEST(TilesetParts, ABlockWithACourtyardIsAClosedPrismOfItsFootprintsArea) {
  // An L-shaped outline (counter-clockwise) of 10 x 10 less a 4 x 4 corner, with a 2 x 1
  // courtyard (clockwise): area 100 - 16 - 2 = 82 m².
  const std::vector<std::vector<Vec2>> loops{
      {{0, 0}, {10, 0}, {10, 6}, {6, 6}, {6, 10}, {0, 10}},
      {{1, 1}, {1, 2}, {3, 2}, {3, 1}},
  };
  const MeshData m = corbel::city::extrudedBlock(loops, 2.0, 9.5, "plaster", "tile");
  EXPECT_EQ(unpaired(m), 0u);
  EXPECT_NEAR(volume(m), 82 * 7.5, 1e-9);  // positive: every face turned outward
  double lo = 1e9, hi = -1e9;
  for (const Vec3& p : m.points) lo = std::min(lo, p[2]), hi = std::max(hi, p[2]);
  EXPECT_EQ(lo, 2.0);
  EXPECT_EQ(hi, 9.5);
  EXPECT_TRUE(corbel::city::extrudedBlock(loops, 3, 3, "a", "b").faces.empty());
}

TEST(TilesetParts, TheBlocksMaterialsAreTheWallsAndTheRoofsThatCoverMost) {
  MeshData m = corbel::city::extrudedBlock({{{0, 0}, {10, 0}, {10, 5}, {0, 5}}}, 0, 6, "brick", "slate");
  const auto [wall, top] = corbel::city::dominantMaterials(m);
  EXPECT_EQ(wall, "brick");
  EXPECT_EQ(top, "slate");
}

TEST(TilesetParts, EveryLeafHoldsAtMostItsCapacityWithinItsSideAndItsPointsLieInItsCell) {
  std::mt19937 rng(7);
  std::normal_distribution<double> d(0, 300);
  std::vector<Vec2> points;
  for (int i = 0; i < 5000; ++i) points.emplace_back(d(rng), 0.3 * d(rng) + 1000);
  for (int i = 0; i < 40; ++i) points.emplace_back(5, 5);  // coincident: more than a leaf holds
  const auto tree = corbel::city::buildQuadtree(points, 20, 150.0);
  std::vector<std::size_t> count(tree.leafCells.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GE(tree.leafOf[i], 0);
    const auto& c = tree.cells[tree.leafCells[tree.leafOf[i]]];
    ++count[tree.leafOf[i]];
    EXPECT_TRUE(points[i][0] >= c.x0 && points[i][0] < c.x0 + c.size && points[i][1] >= c.y0 &&
                points[i][1] < c.y0 + c.size);
  }
  for (std::size_t k = 0; k < count.size(); ++k) {
    const auto& c = tree.cells[tree.leafCells[k]];
    EXPECT_TRUE((count[k] <= 20 && c.size <= 150.0) || c.size < 1.0) << "leaf " << k << ": " << count[k];
  }
  // Inner cells: at least two children, each a quadrant (or a quadrant's quadrant) inside it.
  const double rootSide = tree.cells[0].size;
  for (const auto& c : tree.cells) {
    EXPECT_NEAR(c.size, rootSide / std::pow(2, c.level), 1e-9 * rootSide);
    if (c.leaf >= 0) continue;
    EXPECT_GE(c.children.size(), 2u);
    for (int k : c.children) {
      const auto& ch = tree.cells[k];
      EXPECT_GT(ch.level, c.level);
      EXPECT_TRUE(ch.x0 >= c.x0 && ch.y0 >= c.y0 && ch.x0 + ch.size <= c.x0 + c.size + 1e-9 &&
                  ch.y0 + ch.size <= c.y0 + c.size + 1e-9);
    }
  }
}

}  // namespace
