#include "statics/scene_blocks.h"

#include "core/error.h"
#include "statics/interfaces.h"
#include "statics/tolerances.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace corbel::statics {
namespace {

// Typical densities of the built-in materials (core/materials.h), kg/m³: dressed stone and
// concrete about 2,400, fired brick and clay tiles 1,900, slate 2,800, gypsum plaster 1,200,
// softwood 600, glass 2,500, steel 7,850. Grass has none: it is not a building material.
struct DensityEntry {
  std::string_view name;
  double density;
};
constexpr DensityEntry kDensities[] = {{"stone", 2400},     {"concrete", 2400}, {"brick", 1900},
                                       {"roof_tile", 1900}, {"slate", 2800},    {"plaster", 1200},
                                       {"timber", 600},     {"glass", 2500},    {"metal", 7850}};

struct Piece {
  ObjectId object = 0;
  int index = 0;
  Block block;
  std::string material;
  bool ground = false, nonstructural = false;
};

// The object's faces split into connected pieces (shared vertices), each as a block whose
// faces keep the Scene's orientation (outward, counter-clockwise seen from outside).
std::vector<Piece> piecesOf(const Scene& scene, ObjectId id, const std::vector<PolyMesh::FaceHandle>& faces,
                            bool nonstructural) {
  const PolyMesh& mesh = scene.mesh();
  std::map<int, int> parent;  // vertex index → parent vertex index
  auto find = [&](int x) {
    while (parent.at(x) != x) x = parent[x] = parent.at(parent.at(x));
    return x;
  };
  for (auto f : faces) {
    int first = -1;
    for (auto v : mesh.fv_range(f)) {
      parent.emplace(v.idx(), v.idx());
      if (first < 0) {
        first = v.idx();
      } else {
        parent[find(v.idx())] = find(first);
      }
    }
  }
  std::map<int, int> pieceOfRoot;  // in order of first appearance
  std::vector<Piece> pieces;
  std::vector<std::map<int, int>> local;  // per piece: mesh vertex → block vertex
  std::vector<std::map<std::string, double>> materialArea;
  const std::string& objectName = scene.objects().at(id).name;
  for (auto f : faces) {
    const int root = find((*mesh.fv_range(f).begin()).idx());
    auto [it, added] = pieceOfRoot.emplace(root, int(pieces.size()));
    if (added) {
      pieces.emplace_back();
      pieces.back().object = id;
      pieces.back().index = it->second;
      pieces.back().nonstructural = nonstructural;
      local.emplace_back();
      materialArea.emplace_back();
    }
    Piece& p = pieces[std::size_t(it->second)];
    std::vector<int> loop;
    std::vector<Vec3> pts;
    for (auto v : mesh.fv_range(f)) {
      auto [lv, fresh] = local[std::size_t(it->second)].emplace(v.idx(), int(p.block.vertices.size()));
      if (fresh) {
        const auto& q = mesh.point(v);
        p.block.vertices.emplace_back(q[0], q[1], q[2]);
      }
      loop.push_back(lv->second);
      pts.push_back(p.block.vertices[std::size_t(lv->second)]);
    }
    p.block.faces.push_back(std::move(loop));
    const std::string& tag = scene.faceTag(f);
    p.ground = p.ground || tag == "ground";
    p.nonstructural = p.nonstructural || tag == "nonstructural";
    materialArea[std::size_t(it->second)][scene.faceMaterial(f)] += 0.5 * newellNormal(pts).norm();
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    // The material covering most of the piece's surface gives its density.
    const auto& areas = materialArea[i];
    pieces[i].material = std::max_element(areas.begin(), areas.end(), [](const auto& x, const auto& y) {
                           return x.second < y.second;
                         })->first;
    pieces[i].block.name = pieces.size() == 1 ? objectName : objectName + " piece " + std::to_string(i);
    pieces[i].block.fixed = pieces[i].ground;
  }
  return pieces;
}

}  // namespace

double materialDensity(std::string_view material, const std::map<std::string, double>& overrides) {
  const std::string name = material.empty() ? "stone" : std::string(material);
  if (auto it = overrides.find(name); it != overrides.end()) {
    if (!(std::isfinite(it->second) && it->second > 0))
      throw Error("statics: the density of material \"" + name + "\" must be a positive number");
    return it->second;
  }
  for (const DensityEntry& e : kDensities)
    if (e.name == name) return e.density;
  throw Error("statics: material \"" + name + "\" has no density; give one (corbel-cli statics --density " + name +
              "=KG_PER_M3)");
}

SceneAssembly assemblyFromScene(const Scene& scene, const SceneBlockOptions& options) {
  const auto byObject = scene.facesByObject();
  std::vector<ObjectId> structural = options.objects;
  if (structural.empty())
    for (const auto& [id, info] : scene.objects())
      if (info.kind == Kind::Block) structural.push_back(id);
  const std::set<ObjectId> carried(options.nonstructural.begin(), options.nonstructural.end());
  std::vector<ObjectId> all = structural;
  for (ObjectId id : options.nonstructural)
    if (std::find(all.begin(), all.end(), id) == all.end()) all.push_back(id);
  std::vector<Piece> pieces;
  for (ObjectId id : all) {
    if (!scene.hasObject(id)) throw Error("statics: the scene has no object " + std::to_string(id));
    auto f = byObject.find(id);
    if (f == byObject.end() || f->second.empty())
      throw Error("statics: object \"" + scene.objects().at(id).name + "\" has no faces in the scene");
    for (Piece& p : piecesOf(scene, id, f->second, carried.count(id) > 0)) pieces.push_back(std::move(p));
  }

  SceneAssembly out;
  std::vector<Piece> loads;
  for (Piece& p : pieces) {
    if (p.nonstructural && p.ground)
      throw Error("statics: \"" + p.block.name + "\" is tagged both \"ground\" and \"nonstructural\"");
    p.block.density = materialDensity(p.material, options.densities);
    if (p.nonstructural) {
      loads.push_back(std::move(p));
      continue;
    }
    out.origins.push_back({p.object, p.index, p.material});
    out.assembly.blocks.push_back(std::move(p.block));
  }
  if (out.assembly.blocks.empty())
    throw Error(all.empty() ? "statics: the scene has no blocks (no object of kind block)"
                            : "statics: every piece is nonstructural; nothing carries the loads");
  BBox model;
  for (const Block& b : out.assembly.blocks)
    for (const Vec3& v : b.vertices) model.add(v);
  for (const Piece& p : loads)
    for (const Vec3& v : p.block.vertices) model.add(v);
  const double tol = lengthTolerance(model);
  const bool anyFixed =
      std::any_of(out.assembly.blocks.begin(), out.assembly.blocks.end(), [](const Block& b) { return b.fixed; });
  if (!anyFixed && options.groundPlane) {
    BBox structure;
    for (const Block& b : out.assembly.blocks)
      for (const Vec3& v : b.vertices) structure.add(v);
    const double pad = std::max(1.0, 0.1 * structure.diagonal());
    out.assembly.blocks.push_back(boxBlock("ground plane", structure.lo - Vec3(pad, pad, pad),
                                           Vec3(structure.hi[0] + pad, structure.hi[1] + pad, structure.lo[2]), 2400.0,
                                           true));
    out.origins.push_back({0, -1, ""});
    out.groundPlaneAdded = true;
  }

  // Each nonstructural piece rests on the blocks under it (contacts whose normal, from the block
  // into the piece, points up). One block: its whole weight acts at the piece's centroid, as if
  // fixed to that block. Several: it is shared by contact area, each share at its contact's
  // centroid (a simply supported load).
  const std::vector<BlockProperties> props = validateAssembly(out.assembly, tol);
  const Vec3 up = -out.assembly.gravity / out.assembly.gravity.norm();
  for (Piece& load : loads) {
    Assembly local;
    std::vector<int> toGlobal;
    BBox lb;
    for (const Vec3& v : load.block.vertices) lb.add(v);
    for (std::size_t i = 0; i < out.assembly.blocks.size(); ++i)
      if (boxesTouch(props[i].bounds, lb, tol)) {
        local.blocks.push_back(out.assembly.blocks[i]);
        toGlobal.push_back(int(i));
      }
    const int self = int(local.blocks.size());
    load.block.fixed = false;
    local.blocks.push_back(load.block);
    const std::vector<BlockProperties> lp = validateAssembly(local, tol);
    const Contacts contacts = findContacts(local, lp, tol, 0.0);
    struct Support {
      int block;
      double area;
      Vec3 at;
    };
    std::vector<Support> supports;
    for (const Interface& itf : contacts.interfaces) {
      if (itf.a != self && itf.b != self) continue;
      const int other = itf.a == self ? itf.b : itf.a;
      const Vec3 intoLoad = itf.b == self ? itf.normal : -itf.normal;
      if (dot(intoLoad, up) > 1e-6) supports.push_back({toGlobal[std::size_t(other)], itf.area, itf.centroid});
    }
    if (supports.empty())
      throw Error("statics: nonstructural \"" + load.block.name +
                  "\" rests on no structural block (no contact below it)");
    const double weight = load.block.density * lp[std::size_t(self)].volume * out.assembly.g;
    const Vec3 force = -up * weight;
    out.nonstructuralWeight += weight;
    ++out.nonstructuralPieces;
    bool oneBlock = true;
    for (const Support& s : supports) oneBlock = oneBlock && s.block == supports.front().block;
    if (oneBlock) {
      out.assembly.blocks[std::size_t(supports.front().block)].pointLoads.push_back(
          {lp[std::size_t(self)].centroid, force});
      continue;
    }
    double total = 0;
    for (const Support& s : supports) total += s.area;
    for (const Support& s : supports)
      out.assembly.blocks[std::size_t(s.block)].pointLoads.push_back({s.at, force * (s.area / total)});
  }
  return out;
}

}  // namespace corbel::statics
