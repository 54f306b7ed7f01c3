// corbel-cli export leaves nothing the view shows out of the file: a ray-marched KIFS building
// is meshed (the same mesh `kifs --mesh` makes at that resolution), and a town is written as
// `corbel-cli city` writes it (a node per building, the same names, triangles and textures).
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace {

using corbel::test::cli;
using corbel::test::quote;
using corbel::test::sourcePath;
using corbel::test::TempDir;

struct GlbCounts {
  bool ok = false;
  std::string error;
  std::map<std::string, std::size_t> trianglesByNode;
  std::size_t triangles = 0, images = 0;
};

GlbCounts countGlb(const std::string& path) {
  GlbCounts c;
  tinygltf::Model m;
  std::string warn;
  tinygltf::TinyGLTF loader;
  c.ok = loader.LoadBinaryFromFile(&m, &c.error, &warn, path);
  for (const tinygltf::Node& n : m.nodes) {
    if (n.mesh < 0) continue;
    std::size_t t = 0;
    for (const tinygltf::Primitive& p : m.meshes.at(n.mesh).primitives) t += m.accessors.at(p.indices).count / 3;
    c.trianglesByNode[n.name] += t;
    c.triangles += t;
  }
  c.images = m.images.size();
  return c;
}

TEST(CliExport, ARayMarchedKifsBuildingIsMeshedForTheFile) {
  TempDir dir;
  const std::string project = sourcePath("assets/examples/kifs-h.corbel");
  const auto r = cli(dir, "export " + quote(project) + " --out " + quote(dir.file("h.glb")) + " --kifs-resolution 40");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("meshed at 40 cells"), std::string::npos) << r.err;
  const GlbCounts glb = countGlb(dir.file("h.glb"));
  ASSERT_TRUE(glb.ok) << glb.error;
  ASSERT_EQ(glb.trianglesByNode.count("H building"), 1u);
  // The mesher on its own, through the kifs command, at the same resolution.
  const auto alone = cli(dir, "kifs " + quote(project) + " --mesh " + quote(dir.file("alone.glb")) + " --resolution 40");
  ASSERT_EQ(alone.code, 0) << alone.err;
  EXPECT_EQ(glb.trianglesByNode.at("H building"), countGlb(dir.file("alone.glb")).triangles);
  EXPECT_GT(glb.trianglesByNode.at("H building"), 1000u);
}

TEST(CliExport, ATownIsWrittenAsTheCityCommandWritesIt) {
  TempDir dir;
  const auto exported =
      cli(dir, "export " + quote(sourcePath("assets/examples/town-modern.corbel")) + " --object Town --out " +
                        quote(dir.file("e.glb")));
  ASSERT_EQ(exported.code, 0) << exported.err;
  const auto city = cli(dir, "city " + quote(sourcePath("assets/examples/town-moosburg.geojson")) + " --style " +
                                 quote(sourcePath("assets/styles/modern.json")) +
                                 " --seed 1 --detail full --out " + quote(dir.file("c.glb")));
  ASSERT_EQ(city.code, 0) << city.err;
  const GlbCounts a = countGlb(dir.file("e.glb")), b = countGlb(dir.file("c.glb"));
  ASSERT_TRUE(a.ok) << a.error;
  ASSERT_TRUE(b.ok) << b.error;
  EXPECT_GT(b.trianglesByNode.size(), 30u);  // central Moosburg: 32 footprints
  EXPECT_EQ(a.trianglesByNode, b.trianglesByNode);  // a node per building, same names, same triangles
  EXPECT_EQ(a.images, b.images);                     // and the same textures
  EXPECT_GT(a.images, 0u);
  // And the same place on the Earth: the footprints' frame (their "frame" member's lon0/lat0 and
  // the equirectangular projection it describes), and OpenStreetMap's attribution.
  const nlohmann::json source =
      nlohmann::json::parse(std::ifstream(sourcePath("assets/examples/town-moosburg.geojson")));
  for (const std::string& file : {dir.file("e.glb"), dir.file("c.glb")}) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, file)) << err;
    EXPECT_NE(model.asset.copyright.find("OpenStreetMap contributors"), std::string::npos) << file;
    const tinygltf::Value& geo = model.scenes.at(0).extras.Get("georeference");
    ASSERT_TRUE(geo.IsObject()) << file;
    EXPECT_EQ(geo.Get("proj").Get<std::string>().rfind("+proj=eqc", 0), 0u) << file;
    EXPECT_NEAR(geo.Get("origin").Get(0).GetNumberAsDouble(), source["frame"]["lon0"].get<double>(), 1e-9) << file;
    EXPECT_NEAR(geo.Get("origin").Get(1).GetNumberAsDouble(), source["frame"]["lat0"].get<double>(), 1e-9) << file;
  }
}

// Town tiles, like every export, get the mode a new file gets under the user's umask.
TEST(CliExport, TownTilesFollowTheUmask) {
  TempDir dir;
  const mode_t old = ::umask(027);
  const auto r = cli(dir, "city " + quote(sourcePath("assets/examples/town-moosburg.geojson")) + " --style " +
                              quote(sourcePath("assets/styles/modern.json")) + " --detail massing --tiles " +
                              quote(dir.file("tiles")) + " --out " + quote(dir.file("town.glb")));
  ::umask(old);
  ASSERT_EQ(r.code, 0) << r.err;
  auto modeOf = [](const std::filesystem::path& p) {
    struct stat st {};
    EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
    return st.st_mode & 07777;
  };
  EXPECT_EQ(modeOf(dir.file("town.glb")), 0640u);
  int tiles = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("tiles"))) {
    EXPECT_EQ(modeOf(entry.path()), 0640u) << entry.path();
    ++tiles;
  }
  EXPECT_GT(tiles, 1);
}

}  // namespace
