// Shell → Scene geometry. Faces with holes cannot be one OpenMesh face, so they are
// triangulated with CGAL's constrained Delaunay triangulation (extrude/nested_cdt.h).
#include "extrude/extrude.h"

#include "extrude/nested_cdt.h"

#include <cmath>
#include <map>
#include <numbers>

namespace corbel::extrude {

namespace {

using nested::CDT;
using nested::K;
using nested::markNesting;

std::string defaultTag(const ShellFace& f) {
  if (f.base) return "base";
  if (f.segment == -2) return "roof";
  if (f.angle >= std::numbers::pi / 2 - 1e-9) return "ledge";
  if (f.angle > 1e-9) return "roof";
  if (f.angle < -1e-9) return "soffit";
  return "wall";
}

std::string tagOf(const ShellFace& f, const ExtrusionSpec& spec) {
  std::string tag;
  if (f.profile >= 0 && f.profile < static_cast<int>(spec.profiles.size()) && f.segment >= 0) {
    const Profile& p = spec.profiles[f.profile];
    if (static_cast<std::size_t>(f.segment) < p.tags.size()) tag = p.tags[f.segment];
  }
  return tag.empty() ? defaultTag(f) : tag;
}

// Roof material on sloped inward faces and caps; flat ledges and steps keep the walls'.
bool roofMaterial(const ShellFace& f) {
  const bool slope = f.angle > 1e-9 && f.angle < std::numbers::pi / 2 - 1e-9;
  return !f.base && (f.segment == -2 || slope);
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Neighbouring faces in one plane with the same tag and material become one face (their
// shared edges cancel when traced); the first face of each group keeps its provenance.
std::vector<ShellFace> mergedFaces(const SweepOutput& shell, const ExtrusionSpec& spec) {
  const std::size_t n = shell.faces.size();
  std::vector<int> parent(n);
  for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
  std::map<std::pair<int, int>, int> owner;
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& loop : shell.faces[i].loops)
      for (std::size_t k = 0; k < loop.size(); ++k) owner[{loop[k], loop[(k + 1) % loop.size()]}] = static_cast<int>(i);
  BBox box;
  for (const Vec3& p : shell.points) box.add(p);
  const Tolerances tol = Tolerances::forScale(box.diagonal());
  for (const auto& [uv, i] : owner) {
    auto it = owner.find({uv.second, uv.first});
    if (it == owner.end() || it->second == i) continue;
    const ShellFace &a = shell.faces[i], &b = shell.faces[it->second];
    const double da = OpenMesh::dot(a.normal, shell.points[a.loops[0][0]]);
    const double db = OpenMesh::dot(b.normal, shell.points[b.loops[0][0]]);
    if (OpenMesh::dot(a.normal, b.normal) < 1 - 1e-12 || std::abs(da - db) > tol.cluster) continue;
    if (a.base != b.base || roofMaterial(a) != roofMaterial(b) || tagOf(a, spec) != tagOf(b, spec)) continue;
    parent[findRoot(parent, i)] = findRoot(parent, it->second);
  }
  std::map<int, RawFace> groups;
  std::vector<int> order;
  for (std::size_t i = 0; i < n; ++i) {
    const int r = findRoot(parent, static_cast<int>(i));
    auto [it, fresh] = groups.try_emplace(r);
    if (fresh) {
      it->second.info = shell.faces[i];
      it->second.info.loops.clear();
      order.push_back(r);
    }
    for (const auto& loop : shell.faces[i].loops)
      for (std::size_t k = 0; k < loop.size(); ++k) it->second.segments.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  }
  std::vector<RawFace> raw;
  for (int r : order) raw.push_back(std::move(groups[r]));
  std::vector<ShellFace> faces;
  std::vector<std::string> ignored;
  traceFaces(shell.points, raw, tol, faces, ignored);
  return faces;
}

}  // namespace

MeshData toMeshData(const SweepOutput& shell, const ExtrusionSpec& spec, const std::string& material, bool mergeCoplanar) {
  MeshData out;
  out.points = shell.points;
  const int mat = out.addMaterial(material);
  const int roofMat = spec.roofMaterial.empty() ? mat : out.addMaterial(spec.roofMaterial);
  const std::vector<ShellFace> merged = mergeCoplanar ? mergedFaces(shell, spec) : std::vector<ShellFace>();
  for (const ShellFace& f : mergeCoplanar ? merged : shell.faces) {
    const int t = out.addTag(tagOf(f, spec));
    const int m = roofMaterial(f) ? roofMat : mat;
    if (f.loops.size() == 1) {
      out.addFace(f.loops[0], t, m);
      continue;
    }
    // Triangulate in the face's plane.
    Vec3 u = std::abs(f.normal[2]) < 0.9 ? OpenMesh::cross(Vec3(0, 0, 1), f.normal) : Vec3(1, 0, 0);
    u.normalize();
    const Vec3 w = OpenMesh::cross(f.normal, u);
    CDT cdt;
    for (const auto& loop : f.loops) {
      std::vector<CDT::Vertex_handle> vh;
      for (int v : loop) {
        auto h = cdt.insert(K::Point_2(OpenMesh::dot(shell.points[v], u), OpenMesh::dot(shell.points[v], w)));
        h->info() = v;
        vh.push_back(h);
      }
      for (std::size_t i = 0; i < vh.size(); ++i)
        if (vh[i] != vh[(i + 1) % vh.size()]) cdt.insert_constraint(vh[i], vh[(i + 1) % vh.size()]);
    }
    markNesting(cdt);
    for (auto fh : cdt.finite_face_handles()) {
      if (!fh->info().inDomain()) continue;
      std::vector<int> tri;
      for (int i = 0; i < 3; ++i) tri.push_back(fh->vertex(i)->info());
      out.addFace(tri, t, m);  // CDT faces are counter-clockwise in the (u, w) frame: outward
    }
  }
  splitPinchedVertices(out);
  return out;
}

}  // namespace corbel::extrude
