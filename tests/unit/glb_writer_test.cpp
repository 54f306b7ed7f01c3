// glb_writer.h: a glb written object by object from soups is, byte for byte, the file
// exportScene writes from a Scene that holds the same soups (the Scene's insertion is the
// oracle): the faces a Scene takes, in its order, with materials, tags, textures, placements,
// instances, compression and the include filter as the options say.
#include "core/glb_writer.h"

#include "core/export.h"
#include "core/scene.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <functional>
#include <string>
#include <vector>

namespace {

using corbel::ExportOptions;
using corbel::GlbWriter;
using corbel::InstancedMesh;
using corbel::Kind;
using corbel::MeshData;
using corbel::ObjectId;
using corbel::Scene;
using corbel::Vec2;
using corbel::Vec3;
using corbel::test::handBox;
using corbel::test::readText;
using corbel::test::TempDir;

// A prism over a counter-clockwise outline: bottom and top first, then the sides (so the
// Scene's order, grown across shared edges from the bottom, is not the soup's).
MeshData prism(const std::vector<Vec2>& outline, double z0, double z1, const std::string& material,
               const std::string& roofTag) {
  MeshData m;
  const int mat = m.addMaterial(material), roof = m.addTag(roofTag), wall = m.addTag("wall");
  const int n = static_cast<int>(outline.size());
  for (const Vec2& p : outline) m.addPoint(Vec3(p[0], p[1], z0));
  for (const Vec2& p : outline) m.addPoint(Vec3(p[0], p[1], z1));
  std::vector<int> bottom, top;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);
  for (int i = 0; i < n; ++i) top.push_back(n + i);
  m.addFace(bottom, 0, mat);
  m.addFace(top, roof, 0);
  for (int i = 0; i < n; ++i) m.addFace({i, (i + 1) % n, n + (i + 1) % n, n + i}, wall, mat);
  return m;
}

// Two tetrahedra touching at one corner: the smaller fan's faces are refused by a Scene.
MeshData pinched() {
  MeshData m;
  const Vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (const Vec3& q : p) m.addPoint(Vec3(q[0] + 20, q[1] + 3, q[2] + 1));
  for (const std::vector<int>& f : std::vector<std::vector<int>>{
           {0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 5, 6}, {0, 6, 4}})
    m.addFace(f, 0, m.addMaterial("stone"));
  m.addFace({1, 1, 2});  // a corner twice: refused
  m.addFace({1, 2, 99});  // no such point: refused
  return m;
}

struct Object {
  ObjectId id;
  Kind kind;
  std::string name;
  MeshData mesh;
};

std::vector<Object> objects() {
  std::vector<Object> o;
  o.push_back({1, Kind::Shell, "house A", prism({{0, 0}, {7.3, 0}, {7.3, 5.1}, {3.6, 7.9}, {0, 5.1}}, 0, 6.2, "brick", "roof")});
  o.push_back({2, Kind::Shell, "house B", prism({{10, 0}, {14.2, 0.3}, {13.9, 4.4}, {10.1, 4}}, 0.4, 9.7, "plaster", "flat")});
  o.push_back({3, Kind::Mass, "box", handBox(Vec3(-5, -5, 0), Vec3(-1, -2, 3), "", "side")});
  o.push_back({4, Kind::Shell, "nothing", MeshData()});
  o.push_back({7, Kind::Shell, "pinched", pinched()});
  o.push_back({9, Kind::Shell, "far", prism({{900, 0}, {990, 0}, {990, 40}, {900, 40}}, 0, 3, "concrete", "roof")});
  return o;
}

std::vector<InstancedMesh> instances() {
  InstancedMesh im;
  im.name = "window";
  im.mesh = prism({{-0.5, 0}, {0.5, 0}, {0.5, 0.1}, {-0.5, 0.1}}, 0, 1.2, "glass", "window");
  for (int k = 0; k < 3; ++k) {
    corbel::RigidPlacement p;
    p.translation = Vec3(1.5 + 2.1 * k, -0.05, 1.3);
    im.placements.push_back(p);
  }
  return {im};
}

ExportOptions options(bool textures, bool compress) {
  ExportOptions o;
  o.textures = textures;
  static const corbel::SurfaceTexture tiles{"roof_tile", 2.0};
  o.tagTextures = [](ObjectId, const std::string& tag) { return tag == "roof" ? &tiles : nullptr; };
  o.georeference = {"EPSG:25832", "+proj=tmerc +lat_0=48.46 +lon_0=11.94 +units=m", 11.94, 48.46, 420};
  o.copyright = "test data";
  o.placements[2] = corbel::Placement{Vec3(3, 4, 0), 30, 1};
  o.compress = compress;
  return o;
}

// The same objects through a Scene and exportScene, and through the writer.
void expectSameFile(const ExportOptions& o, const std::string& what) {
  SCOPED_TRACE(what);
  TempDir dir;
  Scene scene;
  GlbWriter writer(o);
  for (const Object& obj : objects()) {
    scene.replaceObject(obj.id, obj.kind, obj.name, obj.mesh);
    writer.add(obj.id, obj.kind, obj.name, obj.mesh);
  }
  exportScene(scene, dir.file("scene.glb"), o);
  writer.write(dir.file("writer.glb"));
  const std::string a = readText(dir.file("scene.glb")), b = readText(dir.file("writer.glb"));
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << "sizes " << a.size() << " and " << b.size();
}

TEST(GlbWriter, WritesTheFileExportSceneWritesFromAScene) {
  const std::vector<InstancedMesh> inst = instances();
  for (bool textures : {false, true})
    for (bool compress : {false, true})
      for (bool withInstances : {false, true}) {
        ExportOptions o = options(textures, compress);
        if (withInstances) o.instances = &inst;
        expectSameFile(o, std::string(textures ? "textured" : "plain") + (compress ? ", compressed" : "") +
                              (withInstances ? ", instances" : ""));
      }
}

// Copies handed to place() rather than held in the meshes' placements: the same file, byte for
// byte, as exportScene writes with every copy in memory. Enough copies of two shapes, given in
// turn, that each shape's go through the temporary file in many blocks; one shape keeps some of
// its copies itself (those come first), and a third shape is known before any copy of it is.
TEST(GlbWriter, CopiesGivenToPlaceAreThoseHeldInTheMeshes) {
  TempDir dir, tmp;
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  setenv("TMPDIR", tmp.path().c_str(), 1);
  std::vector<InstancedMesh> held = instances();
  InstancedMesh door;
  door.name = "door";
  door.mesh = prism({{-0.6, 0}, {0.6, 0}, {0.6, 0.2}, {-0.6, 0.2}}, 0, 2.1, "wood", "door");
  held.push_back(door);
  std::vector<std::pair<std::size_t, corbel::RigidPlacement>> copies;
  for (int k = 0; k < 5000; ++k) {
    corbel::RigidPlacement p;
    const double a = 0.001 * k;  // turned about z
    p.translation = Vec3(3.7 * (k % 90), 11.0 * (k / 90), 0.1 * (k % 7));
    p.ex = Vec3(std::cos(a), std::sin(a), 0);
    p.ey = Vec3(-std::sin(a), std::cos(a), 0);
    copies.emplace_back(k % 3 ? 0 : 1, p);
    held[copies.back().first].placements.push_back(p);
  }
  InstancedMesh unused;
  unused.name = "chimney pot";
  unused.mesh = prism({{0, 0}, {0.3, 0}, {0.3, 0.3}, {0, 0.3}}, 0, 0.5, "clay", "chimney_pot");
  held.push_back(unused);
  for (bool compress : {false, true}) {
    SCOPED_TRACE(compress);
    std::vector<InstancedMesh> shapes = held;
    for (InstancedMesh& m : shapes) m.placements.clear();
    shapes[0].placements = instances()[0].placements;  // the window's own three, first
    ExportOptions a = options(false, compress), b = a;
    a.instances = &held;
    b.instances = &shapes;
    Scene scene;
    GlbWriter writer(b);
    for (const Object& obj : objects()) {
      scene.replaceObject(obj.id, obj.kind, obj.name, obj.mesh);
      writer.add(obj.id, obj.kind, obj.name, obj.mesh);
    }
    for (const auto& [mesh, p] : copies) writer.place(mesh, p);
    exportScene(scene, dir.file("scene.glb"), a);
    writer.write(dir.file("writer.glb"));
    const std::string x = readText(dir.file("scene.glb")), y = readText(dir.file("writer.glb"));
    if (!compress) {
      EXPECT_GT(x.size(), 5000u * 20);  // a copy takes 20 bytes uncompressed
    }
    EXPECT_TRUE(x == y) << "sizes " << x.size() << " and " << y.size();
  }
  if (before)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
  EXPECT_TRUE(tmp.entries().empty());
}

TEST(GlbWriter, KeepsToTheIncludeFilterAndTexturedChoice) {
  ExportOptions o = options(false, false);
  o.include = [](ObjectId id) { return id != 2; };
  o.textured = [](ObjectId id) { return id == 1 || id == 9; };
  expectSameFile(o, "include and textured");
}

TEST(GlbWriter, ASceneRefusesTheSmallerFanOfAPinchedCorner) {
  // The oracle's premise: the pinched soup loses faces in a Scene (the second tetrahedron's
  // three and the two bad ones), so the writer is checked on faces it must leave out.
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "pinched", pinched());
  EXPECT_EQ(scene.objects().at(1).rejected_faces, 5u);
  EXPECT_EQ(scene.faces(1).size(), 4u);
}

}  // namespace

namespace {

// A town's worth of objects: the buffer views and the JSON's accessors, meshes and nodes pass
// 64 KiB each and go through temporary files. The JSON chunk is still what nlohmann writes of the
// whole document (its own compact dump, members in key order), every accessor names a buffer
// view of its kind's bytes, the chunks' lengths add up to the file's, and no temporary file is
// left in the temporary folder.
TEST(GlbWriter, AWriterFedATownSpillsAndStillWritesOneDocument) {
  TempDir dir, tmp;
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  setenv("TMPDIR", tmp.path().c_str(), 1);
  const int n = 6000;
  {
    GlbWriter writer(options(false, false));
    for (int k = 0; k < n; ++k) {
      const double x = 30.0 * (k % 80), y = 30.0 * (k / 80);
      writer.add(static_cast<ObjectId>(k + 1), Kind::Shell, "house " + std::to_string(k),
                 prism({{x, y}, {x + 7.3, y}, {x + 7.3, y + 5.1}, {x + 3.6, y + 7.9 + k % 5}, {x, y + 5.1}}, 0,
                       6.2 + k % 7, k % 2 ? "brick" : "plaster", "roof"));
    }
    writer.write(dir.file("town.glb"));
  }
  if (before)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
  EXPECT_TRUE(tmp.entries().empty());
  const std::string f = readText(dir.file("town.glb"));
  ASSERT_GT(f.size(), 4u << 20);
  auto u32 = [&](std::size_t at) {
    std::uint32_t x;
    std::memcpy(&x, f.data() + at, 4);
    return x;
  };
  EXPECT_EQ(u32(0), 0x46546C67u);
  EXPECT_EQ(u32(8), f.size());
  const std::uint32_t jsonBytes = u32(12);
  EXPECT_EQ(u32(16), 0x4E4F534Au);
  const std::uint32_t binBytes = u32(20 + jsonBytes);
  EXPECT_EQ(20 + jsonBytes + 8 + binBytes, f.size());
  std::string text = f.substr(20, jsonBytes);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  const nlohmann::json doc = nlohmann::json::parse(text);
  EXPECT_TRUE(doc.dump() == text);
  EXPECT_EQ(doc["nodes"].size(), static_cast<std::size_t>(n));
  EXPECT_EQ(doc["meshes"].size(), static_cast<std::size_t>(n));
  EXPECT_GT(doc["accessors"].size(), 3u * n);
  for (const auto& a : doc["accessors"]) {
    ASSERT_TRUE(a.contains("bufferView"));
    const auto& view = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
    EXPECT_LE(a["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>());
  }
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>() + 3 >= binBytes, true);
}

}  // namespace
