// export.h: every format read back by independent readers (assimp for OBJ, PLY and OFF, as
// Blender's and Godot's importers read them; tinygltf for glb; OpenMesh IO for PLY's custom
// properties) and compared with the scene's counts, analytic areas, names, materials and bounds.
#include "core/export.h"

#include "core/error.h"
#include "core/materials.h"
#include "core/textures.h"
#include "test_support.h"
#include "../common/glb_read.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <array>
#include <cmath>
#include <filesystem>
#include <sys/stat.h>
#include <tuple>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

namespace {

using corbel::Kind;
using corbel::MeshData;
using corbel::ObjectId;
using corbel::Scene;
using corbel::Vec2;
using corbel::Vec3;
using corbel::test::handBox;
using corbel::test::readText;
using corbel::test::TempDir;

// A prism over a counter-clockwise 2D outline from z0 to z1: caps of n corners, n quads.
MeshData prism(const std::vector<Vec2>& outline, double z0, double z1, const std::string& material) {
  MeshData m;
  const int mat = m.addMaterial(material);
  const int n = static_cast<int>(outline.size());
  for (const Vec2& p : outline) m.addPoint(Vec3(p[0], p[1], z0));
  for (const Vec2& p : outline) m.addPoint(Vec3(p[0], p[1], z1));
  std::vector<int> bottom, top;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(i);
  for (int i = 0; i < n; ++i) top.push_back(n + i);
  m.addFace(bottom, 0, mat);
  m.addFace(top, 0, mat);
  for (int i = 0; i < n; ++i) m.addFace({i, (i + 1) % n, n + (i + 1) % n, n + i}, 0, mat);
  return m;
}

double shoelace(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    a += p[i][0] * p[(i + 1) % p.size()][1] - p[(i + 1) % p.size()][0] * p[i][1];
  return 0.5 * a;
}

double perimeter(const std::vector<Vec2>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) s += (p[(i + 1) % p.size()] - p[i]).norm();
  return s;
}

const std::vector<Vec2> kPentagon = {{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}};
const std::vector<Vec2> kLShape = {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}};

struct Expected {
  std::string name;
  std::size_t faces, vertices, triangles;
  double area;
};

// Four objects: a box, a pentagonal prism, an L-shaped (concave) prism and a box without a
// material (written under its kind's name).
Scene testScene(std::vector<Expected>* expected = nullptr) {
  Scene s;
  s.replaceObject(1, Kind::Mass, "Hall", handBox(Vec3(0, 0, 0), Vec3(18, 10, 7), "stone"));
  s.replaceObject(2, Kind::Shell, "Tower Top", prism(kPentagon, 7, 9.5, "brick"));
  s.replaceObject(3, Kind::Feature, "Porch", prism(kLShape, 0, 3, "glass"));
  s.replaceObject(4, Kind::Site, "Ground", handBox(Vec3(-30, -20, -0.5), Vec3(30, 20, 0), ""));
  if (expected) {
    *expected = {
        {"Hall", 6, 8, 12, 2 * (18 * 10 + 10 * 7 + 7 * 18.0)},
        {"Tower Top", 7, 10, 2 * 3 + 5 * 2, 2 * shoelace(kPentagon) + perimeter(kPentagon) * 2.5},
        {"Porch", 8, 12, 2 * 4 + 6 * 2, 2 * shoelace(kLShape) + perimeter(kLShape) * 3},
        {"Ground", 6, 8, 12, 2 * (60 * 40 + 40 * 0.5 + 0.5 * 60)},
    };
  }
  return s;
}

struct Totals {
  std::size_t faces = 0, vertices = 0, triangles = 0;
  double area = 0;
};

Totals totals(const std::vector<Expected>& e, const std::set<std::string>& only = {}) {
  Totals t;
  for (const auto& x : e) {
    if (!only.empty() && !only.count(x.name)) continue;
    t.faces += x.faces;
    t.vertices += x.vertices;
    t.triangles += x.triangles;
    t.area += x.area;
  }
  return t;
}

// What assimp makes of a file, triangulated: its triangles, their area, the names of the nodes
// that hold meshes (OBJ's objects), and the materials' names and diffuse colours.
struct AssimpRead {
  bool ok = false;
  std::string error;
  std::size_t triangles = 0;
  double area = 0;
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  std::vector<std::string> nodes;
  std::map<std::string, corbel::Rgb> materials;
};

void collectNodes(const aiNode* n, std::vector<std::string>& out) {
  if (n->mNumMeshes > 0) out.push_back(n->mName.C_Str());
  for (unsigned i = 0; i < n->mNumChildren; ++i) collectNodes(n->mChildren[i], out);
}

AssimpRead readWithAssimp(const std::string& path) {
  AssimpRead r;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
  if (!scene || !scene->mRootNode) {
    r.error = importer.GetErrorString();
    return r;
  }
  r.ok = true;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      for (int k = 0; k < 3; ++k) {
        r.lo[k] = std::min(r.lo[k], double(mesh->mVertices[v][k]));
        r.hi[k] = std::max(r.hi[k], double(mesh->mVertices[v][k]));
      }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      ++r.triangles;
      const aiVector3D a = mesh->mVertices[face.mIndices[0]], b = mesh->mVertices[face.mIndices[1]],
                       c = mesh->mVertices[face.mIndices[2]];
      r.area += 0.5 * ((b - a) ^ (c - a)).Length();
    }
  }
  collectNodes(scene->mRootNode, r.nodes);
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
    aiString name;
    aiColor3D kd(0, 0, 0);
    scene->mMaterials[m]->Get(AI_MATKEY_NAME, name);
    scene->mMaterials[m]->Get(AI_MATKEY_COLOR_DIFFUSE, kd);
    r.materials[name.C_Str()] = {kd.r, kd.g, kd.b};
  }
  return r;
}

// The file holds the scene's triangles and area, as assimp reads it (area kept in 32-bit floats).
void expectReadBack(const std::string& path, const Totals& t) {
  const AssimpRead r = readWithAssimp(path);
  ASSERT_TRUE(r.ok) << path << ": " << r.error;
  EXPECT_EQ(r.triangles, t.triangles) << path;
  EXPECT_NEAR(r.area, t.area, 1e-6 * t.area) << path;
}

TEST(Export, FormatFromExtension) {
  EXPECT_EQ(corbel::exportFormatFor("a/b.obj"), corbel::ExportFormat::Obj);
  EXPECT_EQ(corbel::exportFormatFor("B.OBJ"), corbel::ExportFormat::Obj);
  EXPECT_EQ(corbel::exportFormatFor("x.Ply"), corbel::ExportFormat::Ply);
  EXPECT_EQ(corbel::exportFormatFor("x.off"), corbel::ExportFormat::Off);
  EXPECT_EQ(corbel::exportFormatFor("x.glb"), corbel::ExportFormat::Glb);
  for (const char* bad : {"x.stl", "x", "x.gltf", "obj", "x.obj.bak"}) {
    try {
      corbel::exportFormatFor(bad);
      ADD_FAILURE() << bad;
    } catch (const corbel::Error& e) {
      EXPECT_NE(std::string(e.what()).find("unknown extension"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST(Export, UnknownExtensionWritesNothing) {
  TempDir dir;
  const Scene s = testScene();
  EXPECT_THROW(corbel::exportScene(s, dir.file("model.stl")), corbel::Error);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Export, ObjReadsBackWithTheSameCountsAndArea) {
  TempDir dir;
  std::vector<Expected> expected;
  const Scene s = testScene(&expected);
  corbel::exportScene(s, dir.file("village.obj"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"village.mtl", "village.obj"}));
  expectReadBack(dir.file("village.obj"), totals(expected));
}

TEST(Export, ObjNamesObjectsAndMtlListsMaterials) {
  TempDir dir;
  const Scene s = testScene();
  corbel::exportScene(s, dir.file("village.obj"));
  const std::string obj = readText(dir.file("village.obj"));
  std::istringstream lines(obj);
  std::vector<std::string> objects;
  std::set<std::string> used;
  std::string line;
  bool mtllib = false;
  while (std::getline(lines, line)) {
    if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
    if (line.rfind("usemtl ", 0) == 0) used.insert(line.substr(7));
    if (line == "mtllib village.mtl") mtllib = true;
  }
  EXPECT_TRUE(mtllib);
  // One token each (docs/export.md): assimp cuts a name at its first space.
  EXPECT_EQ(objects, (std::vector<std::string>{"Hall", "Tower_Top", "Porch", "Ground"}));
  EXPECT_EQ(readWithAssimp(dir.file("village.obj")).nodes, objects);
  EXPECT_EQ(used, (std::set<std::string>{"stone", "brick", "glass", "site"}));

  // The .mtl: one newmtl per used material, Kd = the palette's color.
  std::istringstream mtl(readText(dir.file("village.mtl")));
  std::map<std::string, corbel::Rgb> kd;
  std::string current;
  while (std::getline(mtl, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "newmtl") {
      words >> current;
      EXPECT_FALSE(kd.count(current)) << "listed twice: " << current;
      kd[current] = {-1, -1, -1};
    } else if (key == "Kd") {
      words >> kd[current][0] >> kd[current][1] >> kd[current][2];
    }
  }
  std::set<std::string> listed;
  for (const auto& [name, c] : kd) listed.insert(name);
  EXPECT_EQ(listed, used);
  const std::map<std::string, corbel::Rgb> palette = {{"stone", corbel::materialColor("stone", Kind::Mass)},
                                                      {"brick", corbel::materialColor("brick", Kind::Shell)},
                                                      {"glass", corbel::materialColor("glass", Kind::Feature)},
                                                      {"site", corbel::kindColor(Kind::Site)}};
  for (const auto& [name, c] : palette) {
    ASSERT_TRUE(kd.count(name)) << name;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(kd[name][k], c[k], 1e-5) << name;
  }
}

TEST(Export, PlyAndOffReadBackWithMatchingCounts) {
  TempDir dir;
  std::vector<Expected> expected;
  const Scene s = testScene(&expected);
  for (const char* name : {"village.ply", "village.off"}) {
    corbel::exportScene(s, dir.file(name));
    expectReadBack(dir.file(name), totals(expected));
  }
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"village.off", "village.ply"}));
}

TEST(Export, PlyAndOffKeepFaceColors) {
  TempDir dir;
  const Scene s = testScene();
  // Multiset of colors, quantised to 8 bits, must match the palette colors of the faces.
  auto key = [](float r, float g, float b) {
    auto q = [](float x) { return static_cast<int>(std::lround(x * 255.0f)); };
    return std::tuple<int, int, int>(q(r), q(g), q(b));
  };
  std::multiset<std::tuple<int, int, int>> want;
  for (auto f : s.mesh().faces()) {
    const corbel::Rgb c = corbel::materialColor(s.faceMaterial(f), s.faceKind(f));
    want.insert(key(c[0], c[1], c[2]));
  }
  const std::set<std::tuple<int, int, int>> distinct(want.begin(), want.end());
  ASSERT_EQ(distinct.size(), 4u);
  {  // PLY through OpenMesh's reader, which reads face colours and the custom properties.
    corbel::exportScene(s, dir.file("colors.ply"));
    corbel::PolyMesh back;
    back.request_face_colors();
    OpenMesh::IO::Options opt = OpenMesh::IO::Options::FaceColor;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(back, dir.file("colors.ply"), opt));
    ASSERT_TRUE(opt.check(OpenMesh::IO::Options::FaceColor));
    std::multiset<std::tuple<int, int, int>> got;
    for (auto f : back.faces()) {
      const auto c = back.color(f);
      got.insert(key(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f));
    }
    EXPECT_EQ(got, want);
    EXPECT_NE(readText(dir.file("colors.ply")).find("format binary_little_endian 1.0\n"), std::string::npos);
  }
  {  // OFF as Geomview's format defines it: "OFF", then each face's corners and its colour.
    corbel::exportScene(s, dir.file("colors.off"));
    std::istringstream in(readText(dir.file("colors.off")));
    std::string header;
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> header >> nv >> nf >> ne;
    EXPECT_EQ(header, "OFF");
    for (std::size_t i = 0; i < nv; ++i) {
      double x, y, z;
      in >> x >> y >> z;
    }
    std::multiset<std::tuple<int, int, int>> got;
    for (std::size_t i = 0; i < nf; ++i) {
      std::size_t n = 0;
      in >> n;
      for (std::size_t k = 0; k < n; ++k) {
        std::size_t index;
        in >> index;
        EXPECT_LT(index, nv);
      }
      float r, g, b;
      in >> r >> g >> b;
      got.insert(key(r, g, b));
    }
    EXPECT_TRUE(in) << "the file ended early";
    std::string rest;
    EXPECT_FALSE(in >> rest) << "more than the header says: " << rest;
    EXPECT_EQ(got, want);
  }
}

struct Glb {
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
};

Glb loadGlb(const std::string& path) {
  Glb g;
  tinygltf::TinyGLTF loader;
  g.ok = loader.LoadBinaryFromFile(&g.model, &g.err, &g.warn, path);
  return g;
}

TEST(Export, GlbLoadsWithNamesMaterialsTrianglesAndBounds) {
  TempDir dir;
  std::vector<Expected> expected;
  const Scene s = testScene(&expected);
  corbel::exportScene(s, dir.file("village.glb"));
  const Glb g = loadGlb(dir.file("village.glb"));
  ASSERT_TRUE(g.ok) << g.err;
  EXPECT_TRUE(g.warn.empty()) << g.warn;
  const tinygltf::Model& m = g.model;
  EXPECT_EQ(m.asset.version, "2.0");
  ASSERT_EQ(m.nodes.size(), 4u);
  ASSERT_EQ(m.scenes.size(), 1u);
  EXPECT_EQ(m.scenes[0].nodes.size(), 4u);

  std::set<std::string> materialNames;
  for (const auto& mat : m.materials) EXPECT_TRUE(materialNames.insert(mat.name).second) << "duplicate " << mat.name;
  EXPECT_EQ(materialNames, (std::set<std::string>{"stone", "brick", "glass", "site"}));
  for (const auto& mat : m.materials) {
    const corbel::Rgb c =
        mat.name == "site" ? corbel::kindColor(Kind::Site) : corbel::materialColor(mat.name, Kind::Mass);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mat.pbrMetallicRoughness.baseColorFactor[k], c[k], 1e-6) << mat.name;
  }

  // The geometry as a client places it (tests/common/glb_read.h): positions dequantized by the
  // node's translation and scale, normals from bytes.
  const corbel::test::GlbFile file = corbel::test::readGlbFile(dir.file("village.glb"));
  EXPECT_EQ(file.json.at("extensionsRequired"), nlohmann::json::array({"KHR_mesh_quantization"}));
  std::size_t triangles = 0;
  double area = 0;
  std::map<std::string, const Expected*> byName;
  for (const auto& e : expected) byName[e.name] = &e;
  for (const tinygltf::Node& node : m.nodes) {
    ASSERT_TRUE(byName.count(node.name));
    const ObjectId id = static_cast<ObjectId>(node.extras.Get("corbel_object_id").Get<int>());
    EXPECT_EQ(s.objects().at(id).name, node.name);
    ASSERT_GE(node.mesh, 0);
    EXPECT_EQ(m.meshes.at(node.mesh).name, node.name);
  }
  std::map<std::string, std::size_t> nodeTriangles;
  std::map<std::string, std::pair<std::array<double, 3>, std::array<double, 3>>> bounds;
  std::map<std::string, double> steps;
  for (const corbel::test::WorldPrimitive& p : corbel::test::worldPrimitives(file)) {
    SCOPED_TRACE(p.nodeName);
    // Each object's positions are 16-bit integers, a step of at most 1 mm (its size / 65534).
    const auto& accessor = file.json["accessors"][file.json["meshes"][p.mesh]["primitives"][0]["attributes"]["POSITION"].get<int>()];
    EXPECT_EQ(accessor["componentType"], 5122);
    EXPECT_GT(p.step, 0);
    EXPECT_LE(p.step, 1e-3);
    steps[p.nodeName] = p.step;
    ASSERT_EQ(p.indices.size() % 3, 0u);
    nodeTriangles[p.nodeName] += p.indices.size() / 3;
    auto& [lo, hi] = bounds.try_emplace(p.nodeName, std::array<double, 3>{1e300, 1e300, 1e300},
                                        std::array<double, 3>{-1e300, -1e300, -1e300})
                         .first->second;
    for (const auto& q : p.positions)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
      Vec3 v[3];
      for (int c = 0; c < 3; ++c) {
        ASSERT_LT(p.indices[t + c], p.positions.size());
        const auto& q = p.positions[p.indices[t + c]];
        v[c] = Vec3(q[0], q[1], q[2]);
      }
      const Vec3 cr = OpenMesh::cross(v[1] - v[0], v[2] - v[0]);
      area += 0.5 * cr.norm();
      // Each triangle faces the way its flat normal says.
      const auto& nq = p.normals[p.indices[t]];
      EXPECT_GT(OpenMesh::dot(cr, Vec3(nq[0], nq[1], nq[2])), 0.0);
    }
  }
  for (const auto& [name, e] : byName) {
    SCOPED_TRACE(name);
    EXPECT_EQ(nodeTriangles[name], e->triangles);
    triangles += nodeTriangles[name];
    // Y up: (x, y, z) -> (x, z, -y), so min = (lo.x, lo.z, -hi.y) and max = (hi.x, hi.z, -lo.y),
    // each within half a quantization step.
    ObjectId id = 0;
    for (const auto& [oid, info] : s.objects())
      if (info.name == name) id = oid;
    const corbel::BBox b = s.bounds(id);
    const double wantLo[3] = {b.lo[0], b.lo[2], -b.hi[1]}, wantHi[3] = {b.hi[0], b.hi[2], -b.lo[1]};
    const double tol = steps[name] / 2 + 1e-9 * 64;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(bounds[name].first[k], wantLo[k], tol) << "min " << k;
      EXPECT_NEAR(bounds[name].second[k], wantHi[k], tol) << "max " << k;
    }
  }
  EXPECT_EQ(triangles, totals(expected).triangles);
  // Quantization moves each corner by at most half a step along each axis (under 0.5 mm).
  EXPECT_NEAR(area, totals(expected).area, 1e-4 * totals(expected).area);
}

// OBJ is Y up unless asked (Blender, Godot and f3d read OBJ as Y up); PLY and OFF keep Z up
// unless asked. The scene spans z in [-0.5, 9.5] and y in [-20, 20] (the ground).
TEST(Export, EachFormatIsUpAsItsReadersExpect) {
  TempDir dir;
  const Scene s = testScene();
  auto bounds = [&](const std::string& name, corbel::UpAxis up) {
    corbel::ExportOptions o;
    o.up = up;
    corbel::exportScene(s, dir.file(name), o);
    const AssimpRead r = readWithAssimp(dir.file(name));
    EXPECT_TRUE(r.ok) << r.error;
    return std::make_pair(r.lo, r.hi);
  };
  const double tol = 1e-5;
  for (const auto& [name, up, yUp] : {std::tuple{"a.obj", corbel::UpAxis::Default, true},
                                      std::tuple{"b.obj", corbel::UpAxis::Z, false},
                                      std::tuple{"c.ply", corbel::UpAxis::Default, false},
                                      std::tuple{"d.ply", corbel::UpAxis::Y, true},
                                      std::tuple{"e.off", corbel::UpAxis::Default, false},
                                      std::tuple{"f.off", corbel::UpAxis::Y, true}}) {
    SCOPED_TRACE(name);
    const auto [lo, hi] = bounds(name, up);
    const int upAxis = yUp ? 1 : 2;
    EXPECT_NEAR(lo[upAxis], -0.5, tol);
    EXPECT_NEAR(hi[upAxis], 9.5, tol);
    EXPECT_NEAR(lo[yUp ? 2 : 1], -20, tol);  // the ground's y, as -z when Y is up
    EXPECT_NEAR(hi[yUp ? 2 : 1], 20, tol);
  }
  EXPECT_NE(readText(dir.file("a.obj")).find("# corbel export: meters, Y up"), std::string::npos);
}

// Faces come grouped by material within each object: one `usemtl` per object and material,
// so a reader makes one draw per material, not one per change.
TEST(Export, ObjGroupsEachObjectsFacesByMaterial) {
  TempDir dir;
  Scene s;
  MeshData m = prism(kPentagon, 0, 3, "brick");
  const int glass = m.addMaterial("glass");
  for (std::size_t f = 0; f < m.faceMaterial.size(); f += 2) m.faceMaterial[f] = glass;  // alternate
  s.replaceObject(1, Kind::Shell, "striped", m);
  corbel::exportScene(s, dir.file("s.obj"));
  std::istringstream obj(readText(dir.file("s.obj")));
  std::vector<std::string> usemtl;
  for (std::string line; std::getline(obj, line);)
    if (line.rfind("usemtl ", 0) == 0) usemtl.push_back(line.substr(7));
  EXPECT_EQ(usemtl, (std::vector<std::string>{"brick", "glass"}));
}

// Names as one token; two names that map alike stay apart.
TEST(Export, ObjNamesAreOneTokenEach) {
  EXPECT_EQ(corbel::objToken("Tower Top"), "Tower_Top");
  EXPECT_EQ(corbel::objToken("osm:w1#2"), "osm_w1_2");
  EXPECT_EQ(corbel::objToken("Fenêtre-1.b"), "Fen__tre-1.b");  // UTF-8 bytes, each replaced
  EXPECT_EQ(corbel::objToken(""), "_");
  TempDir dir;
  Scene s;
  s.replaceObject(1, Kind::Mass, "A B", handBox(Vec3(0, 0, 0), Vec3(1, 1, 1), "stone"));
  s.replaceObject(2, Kind::Mass, "A:B", handBox(Vec3(2, 0, 0), Vec3(3, 1, 1), "stone"));
  corbel::exportScene(s, dir.file("n.obj"));
  EXPECT_EQ(readWithAssimp(dir.file("n.obj")).nodes, (std::vector<std::string>{"A_B", "A_B_2"}));
}

// New files are readable as the user's umask allows, like any other file they make.
TEST(Export, FilesFollowTheUmask) {
  TempDir dir;
  const mode_t old = ::umask(022);
  const Scene s = testScene();
  for (const char* name : {"u.obj", "u.ply", "u.off", "u.glb"}) {
    corbel::exportScene(s, dir.file(name));
    struct stat st {};
    ASSERT_EQ(::stat(dir.file(name).c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0644u) << name;
  }
  ::umask(old);
}

TEST(Export, IncludeFilterWritesOnlyThoseObjects) {
  TempDir dir;
  std::vector<Expected> expected;
  const Scene s = testScene(&expected);
  corbel::ExportOptions only;
  only.include = [](ObjectId id) { return id == 2 || id == 3; };
  const Totals want = totals(expected, {"Tower Top", "Porch"});
  for (const char* name : {"part.obj", "part.ply", "part.off"}) {
    corbel::exportScene(s, dir.file(name), only);
    expectReadBack(dir.file(name), want);
  }
  std::istringstream obj(readText(dir.file("part.obj")));
  std::vector<std::string> objects;
  for (std::string line; std::getline(obj, line);)
    if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
  EXPECT_EQ(objects, (std::vector<std::string>{"Tower_Top", "Porch"}));
  const std::string mtl = readText(dir.file("part.mtl"));
  EXPECT_EQ(mtl.find("stone"), std::string::npos);
  EXPECT_NE(mtl.find("newmtl brick"), std::string::npos);

  corbel::exportScene(s, dir.file("part.glb"), only);
  const Glb g = loadGlb(dir.file("part.glb"));
  ASSERT_TRUE(g.ok) << g.err;
  std::set<std::string> nodes;
  for (const auto& n : g.model.nodes) nodes.insert(n.name);
  EXPECT_EQ(nodes, (std::set<std::string>{"Tower Top", "Porch"}));
  std::set<std::string> materials;
  for (const auto& mat : g.model.materials) materials.insert(mat.name);
  EXPECT_EQ(materials, (std::set<std::string>{"brick", "glass"}));
}

TEST(Export, ReplacesAnExistingFileAtomically) {
  TempDir dir;
  std::vector<Expected> expected;
  const Scene s = testScene(&expected);
  corbel::test::writeText(dir.file("out.off"), "stale");
  corbel::exportScene(s, dir.file("out.off"));
  expectReadBack(dir.file("out.off"), totals(expected));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.off"});
  EXPECT_THROW(corbel::exportScene(s, dir.file("missing/out.glb")), corbel::Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.off"});
}

}  // namespace

namespace {

TEST(Export, EmptySelectionWritesValidEmptyFiles) {
  TempDir dir;
  const Scene s = testScene();
  corbel::ExportOptions none;
  none.include = [](ObjectId) { return false; };
  for (const char* name : {"empty.obj", "empty.ply", "empty.off"}) {
    corbel::exportScene(s, dir.file(name), none);
    corbel::PolyMesh back;
    OpenMesh::IO::read_mesh(back, dir.file(name));
    EXPECT_EQ(back.n_faces(), 0u) << name;
  }
  EXPECT_EQ(readText(dir.file("empty.obj")).find("\no "), std::string::npos);
  corbel::exportScene(s, dir.file("empty.glb"), none);
  const Glb g = loadGlb(dir.file("empty.glb"));
  ASSERT_TRUE(g.ok) << g.err;
  EXPECT_TRUE(g.model.nodes.empty());
  EXPECT_TRUE(g.model.meshes.empty());
}

}  // namespace

namespace {

// Positions, normals and UVs of one primitive, read back.
struct PrimData {
  std::vector<float> positions, normals, uvs;
};

// Per face of a primitive (the writer gives each face its own corners, so corners sharing a
// normal and an edge-connected run of the index list are a face; here each face is found as
// the corners with one normal): the UV extent along u and v.
std::map<std::tuple<int, int, int>, std::pair<Vec2, Vec2>> uvSpanByNormal(const PrimData& p) {
  std::map<std::tuple<int, int, int>, std::pair<Vec2, Vec2>> out;
  for (std::size_t i = 0; i < p.normals.size() / 3; ++i) {
    // Hundredths: the byte normals are within 0.005 of the true ones (0, ±0.6, ±0.8, ±1 here).
    const auto key = std::make_tuple(static_cast<int>(std::lround(p.normals[3 * i] * 100)),
                                     static_cast<int>(std::lround(p.normals[3 * i + 1] * 100)),
                                     static_cast<int>(std::lround(p.normals[3 * i + 2] * 100)));
    const Vec2 uv(p.uvs[2 * i], p.uvs[2 * i + 1]);
    auto [it, fresh] = out.try_emplace(key, uv, uv);
    if (!fresh)
      for (int k = 0; k < 2; ++k) {
        it->second.first[k] = std::min(it->second.first[k], uv[k]);
        it->second.second[k] = std::max(it->second.second[k], uv[k]);
      }
  }
  return out;
}

TEST(Export, GlbTexturesPerMaterialWithPlaneUvs) {
  TempDir dir;
  Scene s = testScene();
  // A roof plane 4 m along its contour (x) and 5 m up its slope (3 m across, 4 m up).
  MeshData roof;
  const int tile = roof.addMaterial("roof_tile");
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 3, 4), Vec3(0, 3, 4)}) roof.addPoint(p);
  roof.addFace({0, 1, 2, 3}, 0, tile);
  s.replaceObject(5, Kind::Shell, "Roof", roof);
  corbel::ExportOptions textured;
  textured.textures = true;
  corbel::exportScene(s, dir.file("textured.glb"), textured);
  const Glb g = loadGlb(dir.file("textured.glb"));
  ASSERT_TRUE(g.ok) << g.err;
  const corbel::test::GlbFile file = corbel::test::readGlbFile(dir.file("textured.glb"));
  const tinygltf::Model& m = g.model;

  // One image and texture per textured material, decoded back to the generated texels.
  const std::set<std::string> texturedNames = {"stone", "brick", "glass", "roof_tile"};
  EXPECT_EQ(m.images.size(), texturedNames.size());
  EXPECT_EQ(m.textures.size(), texturedNames.size());
  std::map<std::string, int> materialByName;
  // A textured material is named "M (texture T)", never as a plain one: the rest are plain.
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    std::string name = m.materials[i].name;
    if (const auto t = name.find(" (texture "); t != std::string::npos) {
      EXPECT_EQ(name, name.substr(0, t) + " (texture " + name.substr(0, t) + ")");
      name = name.substr(0, t);
    } else {
      EXPECT_FALSE(texturedNames.count(name)) << "a textured material named as a plain one: " << name;
    }
    materialByName[name] = static_cast<int>(i);
  }
  ASSERT_EQ(materialByName.size(), 5u);
  for (const auto& [name, index] : materialByName) {
    SCOPED_TRACE(name);
    const int t = m.materials[index].pbrMetallicRoughness.baseColorTexture.index;
    if (!texturedNames.count(name)) {
      EXPECT_EQ(t, -1);  // the site's kind colour has no texture
      continue;
    }
    ASSERT_GE(t, 0);
    const tinygltf::Image& image = m.images.at(m.textures.at(t).source);
    const corbel::MaterialTexture* want = corbel::materialTexture(name);
    ASSERT_NE(want, nullptr);
    EXPECT_EQ(image.mimeType, "image/png");
    ASSERT_EQ(image.width, want->size);
    ASSERT_EQ(image.height, want->size);
    EXPECT_LE(want->size, 256);
    ASSERT_GE(image.component, 3);
    std::size_t differ = 0;
    for (int px = 0; px < want->size * want->size; ++px)
      for (int k = 0; k < 3; ++k) differ += image.image[px * image.component + k] != want->rgb[px * 3 + k];
    EXPECT_EQ(differ, 0u);
    const int sampler = m.textures[t].sampler;
    ASSERT_GE(sampler, 0);
    EXPECT_EQ(m.samplers[sampler].wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
    EXPECT_EQ(m.samplers[sampler].wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
  }

  // Every textured primitive has one UV per corner; the site has none. The UV extent of each
  // face of the hand-made solids is its size in metres over the tile's size.
  for (const tinygltf::Mesh& mesh : m.meshes)
    for (const tinygltf::Primitive& p : mesh.primitives) {
      SCOPED_TRACE(mesh.name);
      const std::string full = m.materials.at(p.material).name;
      const std::string name = full.substr(0, full.find(" (texture "));
      const auto uv = p.attributes.find("TEXCOORD_0");
      if (!texturedNames.count(name)) {
        EXPECT_EQ(uv, p.attributes.end());
        continue;
      }
      ASSERT_NE(uv, p.attributes.end());
      EXPECT_EQ(m.accessors.at(uv->second).count, m.accessors.at(p.attributes.at("POSITION")).count);
      EXPECT_EQ(m.accessors.at(uv->second).type, TINYGLTF_TYPE_VEC2);
      // The vertices this primitive's triangles use (the material's primitives share a vertex set).
      const auto normals = corbel::test::accessorValues(file, p.attributes.at("NORMAL"));
      const auto uvs = corbel::test::accessorValues(file, uv->second);
      std::set<std::size_t> used;
      for (double i : corbel::test::accessorValues(file, p.indices)) used.insert(static_cast<std::size_t>(i));
      PrimData d;
      for (std::size_t i : used) {
        for (int k = 0; k < 3; ++k) d.normals.push_back(static_cast<float>(normals[3 * i + k]));
        for (int k = 0; k < 2; ++k) d.uvs.push_back(static_cast<float>(uvs[2 * i + k]));
      }
      const double tileM = corbel::materialTexture(name)->metres;
      const auto spans = uvSpanByNormal(d);
      auto expectSpan = [&](std::tuple<int, int, int> normal, double uMetres, double vMetres) {
        const auto it = spans.find(normal);
        ASSERT_NE(it, spans.end());
        EXPECT_NEAR(it->second.second[0] - it->second.first[0], uMetres / tileM, 1e-5);
        EXPECT_NEAR(it->second.second[1] - it->second.first[1], vMetres / tileM, 1e-5);
      };
      // glTF is Y up: corbel's (x, y, z) normal is (x, z, -y) there.
      if (mesh.name == "Hall") {           // the 18 x 10 x 7 m box
        expectSpan({0, 0, 100}, 18, 7);   // south wall, normal -y
        expectSpan({0, 0, -100}, 18, 7);  // north wall
        expectSpan({100, 0, 0}, 10, 7);   // east wall
        expectSpan({-100, 0, 0}, 10, 7);  // west wall
        expectSpan({0, 100, 0}, 18, 10);  // the flat top, in plan
      } else if (mesh.name == "Roof") {
        expectSpan({0, 60, 80}, 4, 5);  // normal (0, -0.8, 0.6) in corbel's frame
      }
      for (float v : d.uvs) EXPECT_TRUE(std::isfinite(v));
    }
}

TEST(Export, PlaneUvRunsAlongTheWallAndUpTheSlope) {
  // A south wall (normal -y): u = x to the right seen from outside, v = z.
  const Vec2 a = corbel::planeUv(Vec3(3, 0, 2), Vec3(0, -1, 0));
  EXPECT_NEAR(a[0], 3, 1e-12);
  EXPECT_NEAR(a[1], 2, 1e-12);
  // Seen from outside, a north wall's right is -x.
  EXPECT_NEAR(corbel::planeUv(Vec3(3, 5, 2), Vec3(0, 1, 0))[0], -3, 1e-12);
  // A roof rising 4 m over 3 m northwards: v grows by 5 m from eaves to ridge.
  const Vec3 n = Vec3(0, -0.8, 0.6);
  EXPECT_NEAR(corbel::planeUv(Vec3(1, 3, 4), n)[1] - corbel::planeUv(Vec3(1, 0, 0), n)[1], 5, 1e-12);
  EXPECT_NEAR(corbel::planeUv(Vec3(1, 3, 4), n)[0] - corbel::planeUv(Vec3(1, 0, 0), n)[0], 0, 1e-12);
  // Flat: plan coordinates.
  const Vec2 f = corbel::planeUv(Vec3(7, -2, 9), Vec3(0, 0, 1));
  EXPECT_EQ(f, Vec2(7, -2));
  // Unknown materials have no texture; built-ins are seamless at most 256 px tiles.
  EXPECT_EQ(corbel::materialTexture("unobtainium"), nullptr);
  const corbel::MaterialTexture* brick = corbel::materialTexture("brick");
  ASSERT_NE(brick, nullptr);
  EXPECT_LE(brick->size, 256);
}

}  // namespace

namespace {

// Two quads in one plane sharing an edge, and a third standing on the far edge: the plane's six
// corners are six vertices (the shared edge's two welded), the standing quad's four its own
// (another normal, though two positions are the plane's), all indexed by 16 bits.
TEST(Export, GlbWeldsCornersThatShareANormal) {
  TempDir dir;
  MeshData m;
  const int stone = m.addMaterial("stone");
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0),
                        Vec3(2, 0, 1), Vec3(2, 1, 1)})
    m.addPoint(p);
  m.addFace({0, 1, 4, 3}, 0, stone);
  m.addFace({1, 2, 5, 4}, 0, stone);
  m.addFace({5, 2, 6, 7}, 0, stone);  // standing on the edge x = 2, facing +x
  Scene s;
  s.replaceObject(1, Kind::Shell, "Fold", m);
  corbel::exportScene(s, dir.file("fold.glb"));
  const corbel::test::GlbFile g = corbel::test::readGlbFile(dir.file("fold.glb"));
  const auto& prim = g.json.at("meshes").at(0).at("primitives");
  ASSERT_EQ(prim.size(), 1u);
  EXPECT_EQ(g.json["accessors"][prim[0]["attributes"]["POSITION"].get<int>()]["count"], 6 + 4);
  EXPECT_EQ(g.json["accessors"][prim[0]["indices"].get<int>()]["componentType"], 5123);
  EXPECT_EQ(g.json["accessors"][prim[0]["indices"].get<int>()]["count"], 3 * 6);
}

// Texture coordinates and normals as KHR_mesh_quantization allows them, read back as the glTF
// spec maps normalized integers (c / 32767, c / 127) and checked against coordinates worked by
// hand from docs/city.md's rule (a wall's u runs along it, v up; a slope's v up the slope; v
// flipped; whole repeats do not show). Two coplanar quads across a repeat boundary (u from 2.0 to
// 2.8 and 2.8 to 3.6 m over stone's 2.4 m) are one patch: one shift, their shared edge's two
// corners welded (6 vertices, not 8). A sloped quad gets its normal to within the byte lattice's
// step, and an 18 m wall (7.5 repeats, too wide for [-1, 1]) keeps float coordinates.
TEST(Export, GlbTextureCoordinatesAreShortsWithinHalfAStep) {
  TempDir dir;
  Scene s;
  MeshData frame;
  const int stone = frame.addMaterial("stone");
  for (const Vec3& p : {Vec3(2.0, 0, 1), Vec3(2.8, 0, 1), Vec3(3.6, 0, 1), Vec3(2.0, 0, 2), Vec3(2.8, 0, 2),
                        Vec3(3.6, 0, 2)})
    frame.addPoint(p);
  frame.addFace({0, 1, 4, 3}, 0, stone);  // facing -y (south)
  frame.addFace({1, 2, 5, 4}, 0, stone);
  s.replaceObject(1, Kind::Shell, "Frame", frame);
  MeshData slope;  // 0.6 m along x, rising 0.3 m over 0.4 m: normal (0, -0.6, 0.8), 0.5 m up the slope
  const int tile = slope.addMaterial("roof_tile");
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.6, 0, 0), Vec3(0.6, 0.4, 0.3), Vec3(0, 0.4, 0.3)}) slope.addPoint(p);
  slope.addFace({0, 1, 2, 3}, 0, tile);
  s.replaceObject(2, Kind::Shell, "Slope", slope);
  MeshData wall;
  const int stone2 = wall.addMaterial("stone");
  for (const Vec3& p : {Vec3(0, 10, 0), Vec3(18, 10, 0), Vec3(18, 10, 7), Vec3(0, 10, 7)}) wall.addPoint(p);
  wall.addFace({0, 1, 2, 3}, 0, stone2);
  s.replaceObject(3, Kind::Shell, "Wall", wall);
  corbel::ExportOptions textured;
  textured.textures = true;
  corbel::exportScene(s, dir.file("q.glb"), textured);
  const corbel::test::GlbFile g = corbel::test::readGlbFile(dir.file("q.glb"));

  // Each corner (glTF's frame: corbel's (x, y, z) is (x, z, -y)) with its hand-worked (u, v) in
  // repeats before the flip, and the glTF normal.
  struct Corner {
    std::array<double, 3> p;
    double u, v;
  };
  const double stoneM = 2.4, tileM = 2.0;
  std::map<std::string, std::vector<Corner>> want;
  for (double x : {2.0, 2.8, 3.6})
    for (double z : {1.0, 2.0}) want["Frame"].push_back({{x, z, 0}, x / stoneM, z / stoneM});
  // On the slope u = x (along the contour) and v = 0.8 y + 0.6 z (up the slope).
  for (const auto& [x, y, z] : {std::array<double, 3>{0, 0, 0}, {0.6, 0, 0}, {0.6, 0.4, 0.3}, {0, 0.4, 0.3}})
    want["Slope"].push_back({{x, z, -y}, x / tileM, (0.8 * y + 0.6 * z) / tileM});
  const std::map<std::string, std::array<double, 3>> normal{{"Frame", {0, 0, 1}}, {"Slope", {0, 0.8, 0.6}}};
  const double uvStep = 1.0 / 32767, normalStep = 1.0 / 127;

  std::set<std::string> seen;
  for (const corbel::test::WorldPrimitive& p : corbel::test::worldPrimitives(g)) {
    SCOPED_TRACE(p.nodeName);
    seen.insert(p.nodeName);
    const auto& mesh = g.json["meshes"][p.mesh];
    ASSERT_EQ(mesh["primitives"].size(), 1u);
    const auto& uvAccessor = g.json["accessors"][mesh["primitives"][0]["attributes"]["TEXCOORD_0"].get<int>()];
    if (p.nodeName == "Wall") {
      EXPECT_EQ(uvAccessor["componentType"], 5126);
      continue;
    }
    EXPECT_EQ(uvAccessor["componentType"], 5122);
    EXPECT_EQ(uvAccessor.value("normalized", false), true);
    const std::vector<Corner>& corners = want[p.nodeName];
    ASSERT_EQ(p.positions.size(), corners.size());  // the Frame's shared edge welded: 6 vertices
    std::set<std::pair<long, long>> shifts;
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
      // The corner this vertex is: positions are within half a step (at most 0.5 mm) of it.
      std::size_t best = 0;
      double bestD = 1e300;
      for (std::size_t c = 0; c < corners.size(); ++c) {
        double d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(p.positions[i][k] - corners[c].p[k]));
        if (d < bestD) bestD = d, best = c;
      }
      EXPECT_LE(bestD, 0.5e-3);
      const double u = p.uvs[i][0], v = p.uvs[i][1];
      EXPECT_LE(std::abs(u), 1.0);
      EXPECT_LE(std::abs(v), 1.0);
      // Written u = hand u - a whole number, v = -(hand v) - a whole number, each rounded to the
      // nearest 1 / 32767: within half that step of a whole-number shift.
      const double du = corners[best].u - u, dv = -corners[best].v - v;
      EXPECT_NEAR(du, std::round(du), uvStep / 2 + 1e-9);
      EXPECT_NEAR(dv, std::round(dv), uvStep / 2 + 1e-9);
      shifts.insert({std::lround(du), std::lround(dv)});
      // Byte normals: each component within one lattice step of the true unit normal.
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.normals[i][k], normal.at(p.nodeName)[k], normalStep);
    }
    EXPECT_EQ(shifts.size(), 1u);  // one patch, one shift: the coplanar quads share their edge
  }
  EXPECT_EQ(seen, (std::set<std::string>{"Frame", "Slope", "Wall"}));
}

// An object wider than 65 m keeps float positions (16 bits would step more than 1 mm); one with
// more than 65,535 vertices gets 32-bit indices.
TEST(Export, GlbFallsBackToFloatsAndWideIndices) {
  TempDir dir;
  Scene s;
  s.replaceObject(1, Kind::Site, "Field", handBox(Vec3(0, 0, 0), Vec3(200, 10, 1), "stone"));
  // 22,000 triangles apart from each other: 66,000 corners that cannot weld.
  MeshData fan;
  const int stone = fan.addMaterial("stone");
  for (int i = 0; i < 22000; ++i) {
    const double x = 0.3 * (i % 100), y = 0.25 * (i / 100), tilt = 0.01 * (1 + i % 50);  // 30 x 55 m
    const int a = fan.addPoint(Vec3(x, y, 0)), b = fan.addPoint(Vec3(x + 0.2, y, tilt)),
              c = fan.addPoint(Vec3(x, y + 0.2, 0.001 * (i % 7)));
    fan.addFace({a, b, c}, 0, stone);
  }
  s.replaceObject(2, Kind::Shell, "Scales", fan);
  corbel::exportScene(s, dir.file("wide.glb"));
  const corbel::test::GlbFile g = corbel::test::readGlbFile(dir.file("wide.glb"));
  for (const auto& node : g.json.at("nodes")) {
    const auto& p = g.json["meshes"][node["mesh"].get<int>()]["primitives"][0];
    const auto& pos = g.json["accessors"][p["attributes"]["POSITION"].get<int>()];
    const auto& idx = g.json["accessors"][p["indices"].get<int>()];
    if (node["name"] == "Field") {
      EXPECT_EQ(pos["componentType"], 5126);
      EXPECT_FALSE(node.contains("scale"));
      EXPECT_EQ(pos["max"][0], 200.0);
    } else {
      EXPECT_EQ(pos["componentType"], 5122);
      EXPECT_EQ(pos["count"], 66000);
      EXPECT_EQ(idx["componentType"], 5125);
    }
  }
  std::size_t triangles = 0;
  for (const auto& p : corbel::test::worldPrimitives(g)) triangles += p.indices.size() / 3;
  EXPECT_EQ(triangles, 12u + 22000u);
}

}  // namespace

namespace {

// ExportOptions::compress: meshoptimizer's decoder gives back the same placed triangles; other
// formats refuse it.
TEST(Export, GlbCompressedDecodesToTheSameTriangles) {
  TempDir dir;
  const Scene s = testScene();
  corbel::ExportOptions packed;
  packed.compress = true;
  corbel::exportScene(s, dir.file("plain.glb"));
  corbel::exportScene(s, dir.file("packed.glb"), packed);
  auto triangles = [](const std::string& path) {
    std::multiset<std::array<std::array<double, 3>, 3>> out;
    for (const auto& p : corbel::test::worldPrimitives(corbel::test::readGlbFile(path)))
      for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        std::array<std::array<double, 3>, 3> tri{p.positions[p.indices[t]], p.positions[p.indices[t + 1]],
                                                 p.positions[p.indices[t + 2]]};
        while (tri[0] != std::min({tri[0], tri[1], tri[2]})) tri = {tri[1], tri[2], tri[0]};  // same winding
        out.insert(tri);
      }
    return out;
  };
  const auto a = triangles(dir.file("plain.glb")), b = triangles(dir.file("packed.glb"));
  EXPECT_EQ(a.size(), totals(std::vector<Expected>{}).triangles + 12 + 16 + 20 + 12);
  EXPECT_EQ(a, b);
  const nlohmann::json j = corbel::test::readGlbFile(dir.file("packed.glb")).json;
  EXPECT_EQ(j["extensionsRequired"], nlohmann::json::array({"EXT_meshopt_compression", "KHR_mesh_quantization"}));
  EXPECT_THROW(corbel::exportScene(s, dir.file("packed.obj"), packed), corbel::Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("packed.obj")));
}

}  // namespace
