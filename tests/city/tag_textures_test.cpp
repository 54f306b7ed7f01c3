// A style's tag_textures through a town build into the glb, read back by tinygltf: the tagged
// faces' primitives show the named texture (decoded texels equal the generated ones) at the
// requested repeat, checked on a hipped house of known size by hand; untagged faces keep their
// material's texture; tag_materials still gives the tagged faces their material (colour).
#include "city/labels.h"
#include "city/style.h"
#include "city/town.h"
#include "core/export.h"
#include "core/scene.h"
#include "core/textures.h"

#include "../common/glb_read.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

using namespace corbel;
using namespace corbel::city;

namespace {

// One house, 12 m along x by 8 m: brick walls 6 m high, then a 45° hipped roof (tag "roof") that
// closes 4 m in, at 10 m, on a ridge 4 m long. Its roof is timber by tag_materials and shows slate
// at 1.5 m per repeat by tag_textures.
const char* kStyle = R"({
  "name": "tagged",
  "tag_materials": {"roof": "timber"},
  "tag_textures": {"roof": {"texture": "slate", "metres": 1.5}},
  "profiles": [{"name": "hip", "points": [[0, 0], [0, 6], [6, 12]], "tags": ["wall", "roof"]}],
  "types": [{"name": "house", "material": "brick", "roof_material": "roof_tile", "edges": [{"profiles": "hip"}]}]
})";

Scene builtTown(const Style& style) {
  Town town;
  Building b;
  b.id = "house";
  b.loops = {{{0, 0}, {12, 0}, {12, 8}, {0, 8}}};
  b.area = 96;
  town.buildings.push_back(b);
  const auto labels = labelTown(town, style.labels, 1);
  Scene scene;
  ObjectId next = 1;
  TownOptions options;
  options.jobs = 1;
  const TownSummary sum = buildTown(town, labels, style, options, [&](const BuildingReport& r, MeshData* mesh) {
    EXPECT_TRUE(r.ok) << r.error;
    if (mesh) scene.replaceObject(next++, Kind::Shell, r.id, *mesh);
  });
  EXPECT_EQ(sum.ok, 1u);
  return scene;
}

tinygltf::Model loadGlb(const std::string& path) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << err;
  return m;
}

using NormalKey = std::tuple<int, int, int>;  // glTF normal × 100, rounded (byte normals are within 0.005)

struct Corner {
  Vec3 p;  // corbel's frame (Z up)
  Vec2 uv;
};

// The corners of a primitive, placed (tests/common/glb_read.h), grouped by their face's normal.
std::map<NormalKey, std::vector<Corner>> cornersByNormal(const corbel::test::WorldPrimitive& p) {
  std::map<NormalKey, std::vector<Corner>> out;
  // The vertices this primitive's triangles use (the textured materials share a vertex set).
  for (std::size_t i : std::set<std::size_t>(p.indices.begin(), p.indices.end())) {
    const auto& n = p.normals[i];
    const NormalKey key{int(std::lround(n[0] * 100)), int(std::lround(n[1] * 100)), int(std::lround(n[2] * 100))};
    const auto& q = p.positions[i];
    out[key].push_back({Vec3(q[0], -q[2], q[1]), Vec2(p.uvs.at(i)[0], p.uvs.at(i)[1])});
  }
  return out;
}

// The extent of the corners' UVs, (u span, v span).
Vec2 span(const std::vector<Corner>& corners) {
  Vec2 lo(1e30, 1e30), hi(-1e30, -1e30);
  for (const Corner& c : corners)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], c.uv[k]), hi[k] = std::max(hi[k], c.uv[k]);
  return hi - lo;
}

// Distance of x from the nearest whole number.
double offWhole(double x) { return std::abs(x - std::round(x)); }

const tinygltf::Image& imageOf(const tinygltf::Model& m, const tinygltf::Material& mat) {
  const int t = mat.pbrMetallicRoughness.baseColorTexture.index;
  EXPECT_GE(t, 0) << mat.name;
  return m.images.at(m.textures.at(std::max(t, 0)).source);
}

void expectTexels(const tinygltf::Image& image, const std::string& texture) {
  const MaterialTexture* want = materialTexture(texture);
  ASSERT_NE(want, nullptr);
  ASSERT_EQ(image.width, want->size);
  ASSERT_EQ(image.height, want->size);
  ASSERT_GE(image.component, 3);
  std::size_t differ = 0;
  for (int px = 0; px < want->size * want->size; ++px)
    for (int k = 0; k < 3; ++k) differ += image.image[px * image.component + k] != want->rgb[px * 3 + k];
  EXPECT_EQ(differ, 0u) << texture;
}

TEST(TagTextures, TaggedFacesShowTheirTextureAtTheirRepeatInTheGlb) {
  const Style style = parseStyle(kStyle);
  const Scene scene = builtTown(style);
  const auto dir = std::filesystem::temp_directory_path() / "corbel_city_tag_textures_glb";
  std::filesystem::create_directories(dir);
  ExportOptions options;
  options.textures = true;
  options.tagTextures = tagTexturesOf(style);
  exportScene(scene, (dir / "town.glb").string(), options);
  const tinygltf::Model m = loadGlb((dir / "town.glb").string());

  // The roof's faces: material timber (tag_materials) showing slate; the walls: brick showing
  // brick. No face shows roof_tile or timber, so neither is embedded.
  std::map<std::string, int> byName;
  for (std::size_t i = 0; i < m.materials.size(); ++i) byName[m.materials[i].name] = int(i);
  ASSERT_TRUE(byName.count("timber (texture slate)")) << "materials: " << m.materials.size();
  ASSERT_TRUE(byName.count("brick (texture brick)"));
  EXPECT_FALSE(byName.count("timber") || byName.count("timber (texture timber)"));
  EXPECT_FALSE(byName.count("roof_tile") || byName.count("roof_tile (texture roof_tile)"));
  const tinygltf::Material& roofMat = m.materials[byName["timber (texture slate)"]];
  EXPECT_EQ(roofMat.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 1, 1, 1}));
  EXPECT_EQ(imageOf(m, roofMat).name, "slate");
  expectTexels(imageOf(m, roofMat), "slate");
  EXPECT_EQ(imageOf(m, m.materials[byName["brick (texture brick)"]]).name, "brick");
  expectTexels(imageOf(m, m.materials[byName["brick (texture brick)"]]), "brick");
  std::set<std::string> images;
  for (const auto& im : m.images) images.insert(im.name);
  EXPECT_EQ(images, (std::set<std::string>{"brick", "slate"}));

  ASSERT_EQ(m.meshes.size(), 1u);
  const double a = 1 / std::sqrt(2.0), slope = 4 * std::sqrt(2.0);  // the roof rises 4 m over 4 m
  bool sawRoof = false, sawWalls = false;
  const corbel::test::GlbFile file = corbel::test::readGlbFile((dir / "town.glb").string());
  for (const corbel::test::WorldPrimitive& p : corbel::test::worldPrimitives(file)) {
    const std::string& name = m.materials.at(p.material).name;
    SCOPED_TRACE(name);
    ASSERT_FALSE(p.uvs.empty());
    // A corner lies within half a quantization step of where it was built: so far off its
    // repeat's whole number.
    const double off = 1e-5 + p.step;
    const auto faces = cornersByNormal(p);
    auto expectSpan = [&](NormalKey n, double uMetres, double vMetres, double tile) {
      const auto it = faces.find(n);
      ASSERT_NE(it, faces.end()) << std::get<0>(n) << " " << std::get<1>(n) << " " << std::get<2>(n);
      const Vec2 s = span(it->second);
      EXPECT_NEAR(s[0], uMetres / tile, 2 * off / tile);
      EXPECT_NEAR(s[1], vMetres / tile, 2 * off / tile);
    };
    if (name == "timber (texture slate)") {
      sawRoof = true;
      // glTF normals are (x, z, -y) of corbel's: the south slope (0, -a, a) is (0, a, a).
      expectSpan({0, 71, 71}, 12, slope, 1.5);   // south: 12 m of eaves, 4√2 m up the slope
      expectSpan({0, 71, -71}, 12, slope, 1.5);  // north
      expectSpan({71, 71, 0}, 8, slope, 1.5);    // east: a triangle on the 8 m end
      expectSpan({-71, 71, 0}, 8, slope, 1.5);   // west
      EXPECT_EQ(faces.size(), 4u);
      // On the south slope u runs along x and v up the slope, a (y + z) metres, flipped: by
      // hand, u·1.5 − x and v·1.5 + a (y + z) are whole repeats of 1.5 m at every corner.
      for (const Corner& c : faces.at({0, 71, 71})) {
        EXPECT_LT(offWhole(c.uv[0] - c.p[0] / 1.5), off / 1.5);
        EXPECT_LT(offWhole(c.uv[1] + a * (c.p[1] + c.p[2]) / 1.5), 2 * off / 1.5);
      }
    } else if (name == "brick (texture brick)") {
      sawWalls = true;
      const double tile = materialTexture("brick")->metres;  // 1.28 m: the material's own
      expectSpan({0, 0, 100}, 12, 6, tile);                  // south wall
      expectSpan({0, 0, -100}, 12, 6, tile);                 // north wall
      expectSpan({100, 0, 0}, 8, 6, tile);                   // east wall
      expectSpan({-100, 0, 0}, 8, 6, tile);                  // west wall
      // The south wall: u = x, v = z flipped.
      for (const Corner& c : faces.at({0, 0, 100})) {
        EXPECT_LT(offWhole(c.uv[0] - c.p[0] / tile), off / tile);
        EXPECT_LT(offWhole(c.uv[1] + c.p[2] / tile), off / tile);
      }
    }
  }
  EXPECT_TRUE(sawRoof);
  EXPECT_TRUE(sawWalls);

  // Without textures the roof is plain timber by its tag's material, and nothing is embedded.
  options.textures = false;
  exportScene(scene, (dir / "plain.glb").string(), options);
  const tinygltf::Model plain = loadGlb((dir / "plain.glb").string());
  std::set<std::string> plainNames;
  for (const auto& mat : plain.materials) plainNames.insert(mat.name);
  EXPECT_TRUE(plainNames.count("timber"));
  EXPECT_FALSE(plainNames.count("timber (texture slate)"));
  EXPECT_TRUE(plain.images.empty());
}

}  // namespace
