// Shell → Scene geometry. Faces with holes cannot be one OpenMesh face, so they are
// triangulated with CGAL's constrained Delaunay triangulation (the only CGAL triangulation
// translation unit of the kernel).
#include "extrude/extrude.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <map>
#include <numbers>

namespace corbel::extrude {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;
  bool inDomain() const { return nesting % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Nesting levels by flood fill across constrained edges (the CGAL manual's polygon-with-holes
// recipe, written for our types).
void markDomains(CDT& cdt) {
  for (auto f : cdt.all_face_handles()) f->info().nesting = -1;
  std::vector<CDT::Face_handle> border{cdt.infinite_face()};
  int level = 0;
  while (!border.empty()) {
    std::vector<CDT::Face_handle> next;
    for (auto start : border) {
      if (start->info().nesting != -1) continue;
      std::vector<CDT::Face_handle> stack{start};
      while (!stack.empty()) {
        auto f = stack.back();
        stack.pop_back();
        if (f->info().nesting != -1) continue;
        f->info().nesting = level;
        for (int i = 0; i < 3; ++i) {
          auto n = f->neighbor(i);
          if (n->info().nesting != -1) continue;
          if (cdt.is_constrained(CDT::Edge(f, i))) next.push_back(n);
          else stack.push_back(n);
        }
      }
    }
    border = std::move(next);
    ++level;
  }
}

std::string defaultTag(const ShellFace& f) {
  if (f.base) return "base";
  if (f.segment == -2) return "roof";
  if (f.angle >= std::numbers::pi / 2 - 1e-9) return "ledge";
  if (f.angle > 1e-9) return "roof";
  if (f.angle < -1e-9) return "soffit";
  return "wall";
}

}  // namespace

MeshData toMeshData(const SweepOutput& shell, const ExtrusionSpec& spec, const std::string& material) {
  MeshData out;
  out.points = shell.points;
  const int mat = out.addMaterial(material);
  const int roofMat = spec.roofMaterial.empty() ? mat : out.addMaterial(spec.roofMaterial);
  for (const ShellFace& f : shell.faces) {
    std::string tag;
    if (f.profile >= 0 && f.profile < static_cast<int>(spec.profiles.size()) && f.segment >= 0) {
      const Profile& p = spec.profiles[f.profile];
      if (static_cast<std::size_t>(f.segment) < p.tags.size()) tag = p.tags[f.segment];
    }
    if (tag.empty()) tag = defaultTag(f);
    const int t = out.addTag(tag);
    // Roof material on sloped inward faces and caps; flat ledges and steps keep the walls'.
    const bool slope = f.angle > 1e-9 && f.angle < std::numbers::pi / 2 - 1e-9;
    const int m = (!f.base && (f.segment == -2 || slope)) ? roofMat : mat;
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
    markDomains(cdt);
    for (auto fh : cdt.finite_face_handles()) {
      if (!fh->info().inDomain()) continue;
      std::vector<int> tri;
      for (int i = 0; i < 3; ++i) tri.push_back(fh->vertex(i)->info());
      out.addFace(tri, t, m);  // CDT faces are counter-clockwise in the (u, w) frame: outward
    }
  }
  return out;
}

}  // namespace corbel::extrude
