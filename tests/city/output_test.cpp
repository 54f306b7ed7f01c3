// corbel-cli city's compact output against the plain glb of the same town, each read back as a
// client reads it (tests/common/glb_read.h): with --instances, the features expanded from
// EXT_mesh_gpu_instancing are the plain file's, triangle for triangle and vertex for vertex
// within the quantization steps; with --compress, meshoptimizer's own decoder gives back the
// uncompressed file's buffer views.
#include "../common/glb_read.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iostream>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

namespace {

namespace fs = std::filesystem;
using corbel::test::GlbFile;
using corbel::test::readGlbFile;
using corbel::test::worldPrimitives;

// A folder of the running test's own (ctest runs the tests of this file side by side).
fs::path dir() {
  const fs::path d = fs::temp_directory_path() /
                     ("corbel_city_output_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(d);
  return d;
}

// The Moosburg example in the old-town style at full detail, written as `name` with `options`;
// the JSON line it prints.
nlohmann::json city(const std::string& name, const std::string& options) {
  const std::string out = (dir() / name).string();
  const std::string cmd = std::string(CORBEL_CLI) + " city " + CORBEL_SOURCE_DIR +
                          "/assets/examples/town-moosburg.geojson --style " + CORBEL_SOURCE_DIR +
                          "/assets/styles/oldtown.json --seed 1 --jobs 2 --out " + out + " " + options + " > " + out +
                          ".json 2> " + out + ".err";
  const int rc = WEXITSTATUS(std::system(cmd.c_str()));
  EXPECT_LE(rc, 1) << cmd;
  std::ifstream in(out + ".json");
  std::string line;
  std::getline(in, line);
  return nlohmann::json::parse(line);
}

std::string materialName(const GlbFile& g, int material) { return g.json["materials"][material]["name"]; }

TEST(CityOutput, InstancedFeaturesAreThePlainFilesFeatures) {
  const nlohmann::json plainLine = city("plain.glb", ""), instLine = city("instances.glb", "--instances");
  ASSERT_GT(plainLine["ok"].get<int>(), 10);
  EXPECT_EQ(instLine["ok"], plainLine["ok"]);
  const GlbFile plain = readGlbFile((dir() / "plain.glb").string());
  const GlbFile inst = readGlbFile((dir() / "instances.glb").string());
  const std::set<std::string> required = inst.json.at("extensionsRequired");
  EXPECT_EQ(required, (std::set<std::string>{"KHR_mesh_quantization", "EXT_mesh_gpu_instancing"}));

  // Each feature shape is one mesh on one instancing node; the copies are the features placed.
  std::size_t instancingNodes = 0, copies = 0;
  for (const auto& node : inst.json["nodes"])
    if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing")) {
      ++instancingNodes;
      copies += inst.json["accessors"][node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"].get<int>()]["count"].get<std::size_t>();
    }
  EXPECT_EQ(instancingNodes, instLine["feature_meshes"].get<std::size_t>());
  EXPECT_EQ(copies, instLine["instanced_features"].get<std::size_t>());
  EXPECT_GT(copies, 20 * instancingNodes);  // windows repeat: many copies of few shapes

  // Triangles by material: the instanced file, its copies expanded, draws what the plain one does.
  std::map<std::string, std::size_t> plainTriangles, instTriangles;
  // The plain file's vertices by material, hashed by 1 cm cell; its largest quantization step.
  std::map<std::string, std::unordered_map<std::int64_t, std::vector<std::array<double, 3>>>> cells;
  auto cellOf = [](double x, double y, double z) {
    auto c = [](double v) { return static_cast<std::int64_t>(std::floor(v / 0.01)) & 0x1FFFFF; };
    return c(x) << 42 | c(y) << 21 | c(z);
  };
  double plainStep = 0;
  for (const auto& p : worldPrimitives(plain)) {
    const std::string m = materialName(plain, p.material);
    plainTriangles[m] += p.indices.size() / 3;
    plainStep = std::max(plainStep, p.step);
    for (const auto& q : p.positions) cells[m][cellOf(q[0], q[1], q[2])].push_back(q);
  }
  ASSERT_GT(plainStep, 0);
  ASSERT_LE(plainStep, 1e-3);
  // Each shape's reach from its own origin (its float positions' box), for the rotations.
  std::map<int, double> reach;
  for (std::size_t m = 0; m < inst.json["meshes"].size(); ++m)
    for (const auto& p : inst.json["meshes"][m]["primitives"]) {
      const auto& a = inst.json["accessors"][p["attributes"]["POSITION"].get<int>()];
      double r2 = 0;
      for (int k = 0; k < 3; ++k)
        r2 += std::pow(std::max(std::abs(a["min"][k].get<double>()), std::abs(a["max"][k].get<double>())), 2);
      reach[static_cast<int>(m)] = std::max(reach[static_cast<int>(m)], std::sqrt(r2));
    }
  double worst = 0, allowedAtWorst = 0;
  std::size_t instanceVertices = 0;
  for (const auto& p : worldPrimitives(inst)) {
    const std::string m = materialName(inst, p.material);
    instTriangles[m] += p.indices.size() / 3;
    if (p.instance < 0) continue;
    for (const auto& q : p.positions) {
      // A copy's vertex: float translation (half an ulp at its distance from the origin, per
      // axis) and a quaternion of normalized shorts (each component within δ = 0.5 / 32767, so
      // the unit quaternion within 2δ and the rotation within 4δ radians, over the shape's
      // reach); the plain file's vertex: half its step per axis.
      const double far = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
      const double allowed = std::sqrt(3.0) * (plainStep / 2 + std::ldexp(far, -24)) +
                             4 * (0.5 / 32767) * reach[p.mesh] * 1.0001 + 1e-6;
      double nearest = INFINITY;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const std::int64_t c = cellOf(q[0] + 0.01 * dx, q[1] + 0.01 * dy, q[2] + 0.01 * dz);
            const auto it = cells[m].find(c);
            if (it == cells[m].end()) continue;
            for (const auto& r : it->second)
              nearest = std::min(nearest, std::hypot(q[0] - r[0], q[1] - r[1], q[2] - r[2]));
          }
      ASSERT_LE(nearest, allowed) << m << " at " << q[0] << " " << q[1] << " " << q[2];
      if (nearest > worst) worst = nearest, allowedAtWorst = allowed;
      ++instanceVertices;
    }
  }
  EXPECT_EQ(instTriangles, plainTriangles);
  EXPECT_GT(instanceVertices, 1000u);
  std::cout << "instance vertices " << instanceVertices << ", farthest from the plain file's " << worst << " m (allowed "
            << allowedAtWorst << " m; plain step " << plainStep << " m)\n";
  // Smaller: the features once per shape.
  EXPECT_LT(fs::file_size(dir() / "instances.glb") * 2, fs::file_size(dir() / "plain.glb"));
}

// An index accessor's triangles as a sorted list, each from its smallest index: meshoptimizer's
// TRIANGLES mode may start a triangle at another corner, keeping its winding.
std::vector<std::array<double, 3>> triangles(const std::vector<double>& v) {
  std::vector<std::array<double, 3>> out;
  for (std::size_t t = 0; t + 2 < v.size(); t += 3) {
    std::array<double, 3> a{v[t], v[t + 1], v[t + 2]};
    while (a[0] != std::min({a[0], a[1], a[2]})) a = {a[1], a[2], a[0]};
    out.push_back(a);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// An accessor's JSON without where it lies.
nlohmann::json placeless(nlohmann::json a) {
  a.erase("bufferView");
  a.erase("byteOffset");
  return a;
}

TEST(CityOutput, CompressedViewsDecodeToTheUncompressedFile) {
  for (const std::string& extra : {std::string(), std::string("--instances")}) {
    SCOPED_TRACE(extra);
    const std::string base = extra.empty() ? "u.glb" : "ui.glb", packed = extra.empty() ? "c.glb" : "ci.glb";
    city(base, extra);
    city(packed, extra + " --compress");
    const GlbFile u = readGlbFile((dir() / base).string());
    const GlbFile c = readGlbFile((dir() / packed).string());  // views decoded by meshopt_decode*
    // The extension's rules: required (the fallback buffer has no data), the fallback marked.
    const std::set<std::string> required = c.json.at("extensionsRequired");
    EXPECT_TRUE(required.count("EXT_meshopt_compression"));
    ASSERT_EQ(c.json["buffers"].size(), 2u);
    EXPECT_FALSE(c.json["buffers"][1].contains("uri"));
    EXPECT_EQ(c.json["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
    // The same document but for the buffers, the views and where each accessor lies in them.
    for (const char* key : {"meshes", "nodes", "materials", "scenes", "images"}) EXPECT_EQ(c.json[key], u.json[key]) << key;
    const auto& ua = u.json.at("accessors");
    const auto& ca = c.json.at("accessors");
    ASSERT_EQ(ca.size(), ua.size());
    std::set<int> indexAccessors;
    for (const auto& m : u.json["meshes"])
      for (const auto& p : m["primitives"]) indexAccessors.insert(p["indices"].get<int>());
    // Every accessor decodes to the uncompressed one's values; every geometry view is compressed.
    for (std::size_t i = 0; i < ua.size(); ++i) {
      EXPECT_EQ(placeless(ca[i]), placeless(ua[i])) << "accessor " << i;
      const auto& view = c.json["bufferViews"][ca[i]["bufferView"].get<int>()];
      ASSERT_TRUE(view.contains("extensions")) << "accessor " << i << " in an uncompressed view";
      const auto& e = view["extensions"]["EXT_meshopt_compression"];
      EXPECT_EQ(e["mode"], indexAccessors.count(static_cast<int>(i)) ? "TRIANGLES" : "ATTRIBUTES") << "accessor " << i;
      const std::vector<double> a = corbel::test::accessorValues(u, static_cast<int>(i)),
                                b = corbel::test::accessorValues(c, static_cast<int>(i));
      if (indexAccessors.count(static_cast<int>(i)))
        EXPECT_EQ(triangles(b), triangles(a)) << "accessor " << i;
      else
        EXPECT_EQ(b, a) << "accessor " << i;
    }
    // The chunks: a view holds at most 64 KiB decoded unless one accessor alone is larger, so a
    // kind of view (a mode and stride) comes in several views here.
    std::map<int, int> accessorsIn;
    for (const auto& a : ca) ++accessorsIn[a["bufferView"].get<int>()];
    std::map<std::string, int> viewsOfKind;
    std::size_t compressed = 0;
    for (std::size_t v = 0; v < c.json["bufferViews"].size(); ++v) {
      const auto& view = c.json["bufferViews"][v];
      if (!view.contains("extensions")) continue;
      ++compressed;
      const auto& e = view["extensions"]["EXT_meshopt_compression"];
      ++viewsOfKind[e["mode"].get<std::string>() + std::to_string(e["byteStride"].get<int>())];
      if (view["byteLength"].get<std::size_t>() > 65536) {
        EXPECT_EQ(accessorsIn[static_cast<int>(v)], 1) << "view " << v;
      }
    }
    int most = 0;
    for (const auto& [kind, n] : viewsOfKind) most = std::max(most, n);
    EXPECT_GE(most, 3);
    EXPECT_GE(compressed, 3u);
    EXPECT_EQ(compressed + c.json.value("images", nlohmann::json::array()).size(), c.json["bufferViews"].size());
    EXPECT_LT(fs::file_size(dir() / packed), fs::file_size(dir() / base));
    std::cout << base << " " << fs::file_size(dir() / base) << " bytes, compressed " << fs::file_size(dir() / packed)
              << "\n";
  }
}

// With --tiles, each tile's glb places its own buildings' features: the copies over all tiles
// are the features the town placed, each tile's drawn triangles its buildings'.
TEST(CityOutput, EachTilePlacesItsOwnFeatures) {
  const nlohmann::json line = city("whole.glb", "--instances --tiles " + (dir() / "tiles").string() + " --tile-size 200");
  ASSERT_GE(line["tiles"].get<int>(), 2);
  std::size_t copies = 0, tiles = 0;
  for (const auto& e : fs::directory_iterator(dir() / "tiles")) {
    ++tiles;
    // The copies a client draws: distinct (node, copy) pairs of the expanded primitives.
    std::set<std::pair<int, int>> drawn;
    for (const auto& p : worldPrimitives(readGlbFile(e.path().string())))
      if (p.instance >= 0) drawn.insert({p.node, p.instance});
    copies += drawn.size();
  }
  EXPECT_EQ(tiles, line["tiles"].get<std::size_t>());
  EXPECT_EQ(copies, line["instanced_features"].get<std::size_t>());
  EXPECT_GT(copies, 100u);
}

TEST(CityOutput, InstancesAndCompressionNeedAGlb) {
  const std::string out = (dir() / "town.obj").string();
  for (const char* flag : {"--instances", "--compress"}) {
    const std::string cmd = std::string(CORBEL_CLI) + " city " + CORBEL_SOURCE_DIR +
                            "/assets/examples/town-moosburg.geojson --style " + CORBEL_SOURCE_DIR +
                            "/assets/styles/oldtown.json --out " + out + " " + flag + " > /dev/null 2> " + out + ".err";
    EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 2) << flag;
    std::ifstream in(out + ".err");
    const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(err.find("give a .glb --out"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
