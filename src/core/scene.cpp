#include "core/scene.h"

#include "core/manifold_order.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <numeric>

namespace corbel {

std::string_view kindName(Kind kind) {
  switch (kind) {
    case Kind::Mass:
      return "mass";
    case Kind::Shell:
      return "shell";
    case Kind::Block:
      return "block";
    case Kind::Unit:
      return "unit";
    case Kind::Ornament:
      return "ornament";
    case Kind::Site:
      return "site";
    case Kind::Feature:
      return "feature";
  }
  return "unknown";
}

std::optional<Kind> kindFromName(std::string_view name) {
  for (int k = 0; k < kKindCount; ++k)
    if (kindName(static_cast<Kind>(k)) == name) return static_cast<Kind>(k);
  return std::nullopt;
}

std::vector<std::string> ValidityReport::problems() const {
  std::vector<std::string> out;
  auto add = [&](std::size_t n, const char* what) {
    if (n) out.push_back(std::to_string(n) + " " + what);
  };
  if (faces == 0) out.push_back("no faces");
  add(boundary_edges, "boundary edges (the surface has holes)");
  add(non_manifold_vertices, "non-manifold vertices");
  add(rejected_faces, "faces rejected because they would make an edge non-manifold");
  add(degenerate_faces, "degenerate (zero-area) faces");
  add(non_finite_points, "points with NaN or infinite coordinates");
  if (watertight() && faces > 0 && !(volume > 0)) out.push_back("closed surface faces inward (negative volume)");
  return out;
}

void Scene::touch() {
  static std::atomic<std::uint64_t> counter{0};
  revision_ = ++counter;
}

Scene::Scene() {
  touch();
  // Kernels never print: OpenMesh reports refused faces on omerr, we count them instead.
  // omerr() is one global stream whose disable() edits a target list without a lock, so
  // Scenes built at once on several threads (the batch extruder) must disable it only once.
  static std::once_flag quiet;
  std::call_once(quiet, [] { omerr().disable(); });
  bindProperties();
}

Scene::Scene(const Scene& other)
    : mesh_(other.mesh_),
      objects_(other.objects_),
      tags_(other.tags_),
      materials_(other.materials_),
      tagIndex_(other.tagIndex_),
      materialIndex_(other.materialIndex_) {
  bindProperties();
  touch();
}

Scene& Scene::operator=(const Scene& other) {
  if (this != &other) {
    mesh_ = other.mesh_;
    objects_ = other.objects_;
    tags_ = other.tags_;
    materials_ = other.materials_;
    tagIndex_ = other.tagIndex_;
    materialIndex_ = other.materialIndex_;
    touch();
    bindProperties();
  }
  return *this;
}

void Scene::bindProperties() {
  auto bind = [&](auto& handle, const char* name) {
    if (!mesh_.get_property_handle(handle, name)) mesh_.add_property(handle, name);
  };
  bind(object_, prop::kObject);
  bind(kind_, prop::kKind);
  bind(tag_, prop::kTag);
  bind(material_, prop::kMaterial);
}

int Scene::internTag(const std::string& name) {
  auto [it, fresh] = tagIndex_.try_emplace(name, static_cast<int>(tags_.size()));
  if (fresh) tags_.push_back(name);
  return it->second;
}

int Scene::internMaterial(const std::string& name) {
  auto [it, fresh] = materialIndex_.try_emplace(name, static_cast<int>(materials_.size()));
  if (fresh) materials_.push_back(name);
  return it->second;
}

std::vector<PolyMesh::FaceHandle> Scene::faces(ObjectId id) const {
  std::vector<PolyMesh::FaceHandle> out;
  for (auto f : mesh_.faces())
    if (faceObject(f) == id) out.push_back(f);
  return out;
}

std::map<ObjectId, std::vector<PolyMesh::FaceHandle>> Scene::facesByObject() const {
  std::map<ObjectId, std::vector<PolyMesh::FaceHandle>> out;
  for (auto f : mesh_.faces()) out[faceObject(f)].push_back(f);
  return out;
}

void Scene::collectGarbage() { mesh_.garbage_collection(); }

void Scene::removeObject(ObjectId id) {
  if (!objects_.count(id)) return;  // nothing to scan for
  bool any = false;
  for (auto f : mesh_.faces()) {
    if (faceObject(f) == id) {
      mesh_.delete_face(f, true);
      any = true;
    }
  }
  if (any) collectGarbage();
  objects_.erase(id);
  touch();
}


void Scene::replaceObject(ObjectId id, Kind kind, const std::string& name, const MeshData& data) {
  removeObject(id);
  std::vector<PolyMesh::VertexHandle> vh;
  vh.reserve(data.points.size());
  for (const Vec3& p : data.points) vh.push_back(mesh_.add_vertex(p));

  std::vector<int> tagMap(data.tags.size()), materialMap(data.materials.size());
  for (size_t i = 0; i < data.tags.size(); ++i) tagMap[i] = internTag(data.tags[i]);
  for (size_t i = 0; i < data.materials.size(); ++i) materialMap[i] = internMaterial(data.materials[i]);

  ObjectInfo info;
  info.kind = kind;
  info.name = name;
  const std::vector<int> order = manifoldFaceOrder(data, info.rejected_faces);
  std::vector<PolyMesh::VertexHandle> loop;
  for (int f : order) {
    loop.clear();
    for (int i : data.faces[f]) loop.push_back(vh[i]);
    const PolyMesh::FaceHandle fh = mesh_.add_face(loop);
    if (!fh.is_valid()) {
      ++info.rejected_faces;
      continue;
    }
    mesh_.property(object_, fh) = static_cast<std::int32_t>(id);
    mesh_.property(kind_, fh) = static_cast<std::uint8_t>(kind);
    const int t = static_cast<size_t>(f) < data.faceTag.size() ? data.faceTag[f] : 0;
    const int m = static_cast<size_t>(f) < data.faceMaterial.size() ? data.faceMaterial[f] : 0;
    mesh_.property(tag_, fh) = (t >= 0 && static_cast<size_t>(t) < tagMap.size()) ? tagMap[t] : 0;
    mesh_.property(material_, fh) = (m >= 0 && static_cast<size_t>(m) < materialMap.size()) ? materialMap[m] : 0;
  }
  // Points no face used would be isolated vertices: drop them.
  bool isolated = false;
  for (auto v : vh) {
    if (mesh_.is_isolated(v)) {
      mesh_.delete_vertex(v, false);
      isolated = true;
    }
  }
  if (isolated) collectGarbage();
  objects_[id] = std::move(info);
  touch();
}

void Scene::setObjectName(ObjectId id, const std::string& name) {
  auto it = objects_.find(id);
  if (it != objects_.end()) {
    it->second.name = name;
    touch();
  }
}

void Scene::clear() {
  mesh_.clean();
  objects_.clear();
  touch();
}

BBox Scene::bounds(ObjectId id) const {
  BBox box;
  for (auto f : mesh_.faces())
    if (faceObject(f) == id)
      for (auto v : mesh_.fv_range(f)) box.add(mesh_.point(v));
  return box;
}

BBox Scene::bounds() const {
  BBox box;
  for (auto v : mesh_.vertices()) box.add(mesh_.point(v));
  return box;
}

ValidityReport Scene::validate(ObjectId id) const {
  ValidityReport r;
  auto it = objects_.find(id);
  if (it == objects_.end()) return r;
  r.rejected_faces = it->second.rejected_faces;

  const std::vector<PolyMesh::FaceHandle> fs = faces(id);
  r.faces = fs.size();
  std::vector<char> vSeen(mesh_.n_vertices(), 0), eSeen(mesh_.n_edges(), 0);
  const BBox box = bounds(id);
  const double scale = std::max(box.diagonal(), 1e-300);
  // Zero area at the kernels' resolution: the extrusion kernel keeps faces down to its
  // clustering distance squared (1e-16 s²) and its natural steps leave soffits about 1e-10 s²;
  // below 1e-14 s² a face is taken to have collapsed.
  const double areaEps = 1e-14 * scale * scale;

  // Connected components by a flood fill over shared edges.
  std::vector<int> faceComponent(mesh_.n_faces(), -1);
  std::vector<PolyMesh::FaceHandle> stack;

  std::vector<Vec3> poly;
  for (auto f : fs) {
    poly.clear();
    for (auto v : mesh_.fv_range(f)) {
      poly.push_back(mesh_.point(v));
      if (!vSeen[v.idx()]) {
        vSeen[v.idx()] = 1;
        ++r.vertices;
        const Vec3& p = mesh_.point(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) ++r.non_finite_points;
        if (!mesh_.is_manifold(v)) ++r.non_manifold_vertices;
      }
    }
    for (auto e : mesh_.fe_range(f)) {
      if (!eSeen[e.idx()]) {
        eSeen[e.idx()] = 1;
        ++r.edges;
        if (mesh_.is_boundary(e)) ++r.boundary_edges;
      }
    }
    const double area = 0.5 * newellNormal(poly).norm();
    r.area += area;
    if (!(area > areaEps)) ++r.degenerate_faces;
    for (size_t i = 1; i + 1 < poly.size(); ++i)
      r.volume += OpenMesh::dot(poly[0], OpenMesh::cross(poly[i], poly[i + 1])) / 6.0;

    if (faceComponent[f.idx()] < 0) {
      const int c = static_cast<int>(r.components++);
      faceComponent[f.idx()] = c;
      stack.push_back(f);
      while (!stack.empty()) {
        auto g = stack.back();
        stack.pop_back();
        for (auto h : mesh_.ff_range(g)) {
          if (faceComponent[h.idx()] < 0) {
            faceComponent[h.idx()] = c;
            stack.push_back(h);
          }
        }
      }
    }
  }
  r.euler = static_cast<long>(r.vertices) - static_cast<long>(r.edges) + static_cast<long>(r.faces);
  return r;
}

}  // namespace corbel
