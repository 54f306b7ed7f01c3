// corbel-cli export writes placed objects where the scene shows them: the glb's vertices are
// the placement applied to the unplaced geometry (a box's corners worked by hand; a KIFS
// building meshed for the file, vertex by vertex against the same building unplaced), and the
// node's extras record the placement (corbel_placement).
#include "cli_run.h"
#include "../common/glb_read.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <fstream>
#include <set>

namespace {

using corbel::test::cli;
using corbel::test::quote;
using corbel::test::TempDir;

struct Node {
  std::vector<std::array<double, 3>> positions;  // glTF's frame: y up, so corbel's (x, y, z) is (x, z, −y)
  double step = 0;                               // the quantization step (docs/export.md)
  tinygltf::Value extras;
};

std::map<std::string, Node> readNodes(const std::string& path) {
  tinygltf::Model m;
  std::string err, warn;
  tinygltf::TinyGLTF loader;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
  std::map<std::string, Node> out;
  for (const tinygltf::Node& n : m.nodes) {
    if (n.mesh < 0) continue;
    out[n.name].extras = n.extras;
  }
  // The vertices as a client places them (tests/common/glb_read.h: dequantized by the node).
  for (const auto& p : corbel::test::worldPrimitives(corbel::test::readGlbFile(path))) {
    Node& node = out[p.nodeName];
    node.positions.insert(node.positions.end(), p.positions.begin(), p.positions.end());
    node.step = p.step;
  }
  return out;
}

std::string project(const std::string& placement) {
  return R"({"format": "corbel", "version": 2, "objects": [
    {"id": 1, "name": "Box", "box": {"size": [2, 4, 6]})" + placement + R"(},
    {"id": 2, "name": "Tower", "kifs": {"preset": "h"})" + placement + R"(}]})";
}

TEST(CliPlacement, ExportWritesTheVerticesPlacedAndSaysHow) {
  TempDir dir;
  // t = (10, 20, 1), a quarter turn: corbel (x, y, z) → (10 − y, 20 + x, 1 + z). The box is
  // scaled by half; KIFS buildings cannot be scaled, so the tower gets the same without scale.
  std::ofstream(dir.file("placed.corbel"))
      << R"({"format": "corbel", "version": 2, "objects": [
    {"id": 1, "name": "Box", "box": {"size": [2, 4, 6]}, "placement": {"translation": [10, 20, 1], "rotation": 90, "scale": 0.5}},
    {"id": 2, "name": "Tower", "kifs": {"preset": "h"}, "placement": {"translation": [10, 20, 1], "rotation": 90}}]})";
  std::ofstream(dir.file("unplaced.corbel")) << project("");
  for (const char* name : {"placed", "unplaced"}) {
    const auto r = cli(dir, "export " + quote(dir.file(std::string(name) + ".corbel")) + " --out " +
                                quote(dir.file(std::string(name) + ".glb")) + " --kifs-resolution 24");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto placed = readNodes(dir.file("placed.glb")), unplaced = readNodes(dir.file("unplaced.glb"));
  ASSERT_EQ(placed.count("Box"), 1u);
  // The box: x −1..1, y −2..2, z 0..6, halved and turned: x 9..11, y 19.5..20.5, z 1..4; in
  // glTF (x, z, −y).
  // Each within half a quantization step along each axis.
  std::set<std::array<double, 3>> corners, seen;
  for (double x : {9.0, 11.0})
    for (double y : {19.5, 20.5})
      for (double z : {1.0, 4.0}) corners.insert({x, z, -y});
  const double half = placed.at("Box").step / 2 + 1e-12;
  ASSERT_GT(half, 1e-12);
  for (const auto& p : placed.at("Box").positions) {
    bool near = false;
    for (const auto& c : corners)
      if (std::abs(p[0] - c[0]) <= half && std::abs(p[1] - c[1]) <= half && std::abs(p[2] - c[2]) <= half) {
        seen.insert(c);
        near = true;
      }
    EXPECT_TRUE(near) << p[0] << " " << p[1] << " " << p[2];
  }
  EXPECT_EQ(seen, corners);
  // The tower: every vertex is the unplaced mesh's vertex, moved and turned, each within half a
  // quantization step of its own file's along each axis.
  const auto& a = placed.at("Tower").positions;
  const auto& b = unplaced.at("Tower").positions;
  const double tol = (placed.at("Tower").step + unplaced.at("Tower").step) / 2 + 1e-5;
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    // Unplaced corbel point (x, y, z) = (b0, −b2, b1); placed (10 + b2, 20 + b0, 1 + b1) → glTF (10 + b2, 1 + b1, −20 − b0).
    EXPECT_NEAR(a[i][0], 10 + b[i][2], tol) << i;
    EXPECT_NEAR(a[i][1], 1 + b[i][1], tol) << i;
    EXPECT_NEAR(a[i][2], -20 - b[i][0], tol) << i;
  }
  // The extras say how, in corbel's frame; an unplaced node has no such entry.
  const tinygltf::Value& pl = placed.at("Box").extras.Get("corbel_placement");
  ASSERT_TRUE(pl.IsObject());
  EXPECT_EQ(pl.Get("translation").Get(1).GetNumberAsDouble(), 20.0);
  EXPECT_EQ(pl.Get("rotation_deg").GetNumberAsDouble(), 90.0);
  EXPECT_EQ(pl.Get("scale").GetNumberAsDouble(), 0.5);
  EXPECT_FALSE(unplaced.at("Box").extras.Has("corbel_placement"));
}

}  // namespace
