// Plain extruded blocks (city/blocks.h).
#include "city/blocks.h"

#include "extrude/nested_cdt.h"

#include <cmath>
#include <map>

namespace corbel::city {

namespace {

using extrude::nested::CDT;
using extrude::nested::K;
using extrude::nested::markNesting;

}  // namespace

MeshData extrudedBlock(const std::vector<std::vector<Vec2>>& loops, double bottom, double top,
                       const std::string& wallMaterial, const std::string& topMaterial) {
  MeshData m;
  if (!(top > bottom)) return m;
  CDT cdt;
  std::vector<Vec2> corners;
  std::map<std::pair<double, double>, int> index;  // a corner met twice is one vertex of the CDT
  for (const auto& loop : loops) {
    if (loop.size() < 3) continue;
    std::vector<CDT::Vertex_handle> vs;
    for (const Vec2& p : loop) {
      auto v = cdt.insert(K::Point_2(p[0], p[1]));
      const auto [it, fresh] = index.try_emplace({p[0], p[1]}, static_cast<int>(corners.size()));
      if (fresh) corners.push_back(p);
      v->info() = it->second;
      vs.push_back(v);
    }
    for (std::size_t k = 0; k < vs.size(); ++k)
      if (vs[k] != vs[(k + 1) % vs.size()]) cdt.insert_constraint(vs[k], vs[(k + 1) % vs.size()]);
  }
  if (corners.empty()) return m;
  markNesting(cdt);
  const int wall = m.addMaterial(wallMaterial), cap = m.addMaterial(topMaterial);
  const int wallTag = m.addTag("wall"), roofTag = m.addTag("roof"), baseTag = m.addTag("base");
  // Corner i is point 2i at the bottom and 2i + 1 at the top.
  for (const Vec2& p : corners) {
    m.addPoint(Vec3(p[0], p[1], bottom));
    m.addPoint(Vec3(p[0], p[1], top));
  }
  bool any = false;
  for (auto f : cdt.finite_face_handles()) {
    if (!f->info().inDomain()) continue;
    const int a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
    m.addFace({2 * a + 1, 2 * b + 1, 2 * c + 1}, roofTag, cap);  // CGAL's faces are counter-clockwise
    m.addFace({2 * a, 2 * c, 2 * b}, baseTag, wall);
    any = true;
  }
  if (!any) return MeshData{};
  // A wall per constrained edge, oriented by the side the footprint is on.
  for (auto e : cdt.finite_edges()) {
    if (!cdt.is_constrained(e)) continue;
    auto f = e.first;
    auto g = f->neighbor(e.second);
    const bool fIn = f->info().inDomain(), gIn = g->info().inDomain();
    if (fIn == gIn) continue;
    // In face f, the edge opposite vertex i runs ccw from vertex (i+1) to (i+2), the face on its left.
    int p = f->vertex(CDT::ccw(e.second))->info(), q = f->vertex(CDT::cw(e.second))->info();
    if (!fIn) std::swap(p, q);  // the footprint on the left of p -> q: outside on the right
    m.addFace({2 * p, 2 * q, 2 * q + 1, 2 * p + 1}, wallTag, wall);
  }
  return m;
}

std::pair<std::string, std::string> dominantMaterials(const MeshData& mesh) {
  std::map<int, double> walls, tops;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::vector<Vec3> poly;
    for (int v : mesh.faces[f]) poly.push_back(mesh.points[v]);
    if (poly.size() < 3) continue;
    const Vec3 n = newellNormal(poly);
    const double area = n.norm() / 2;
    if (area <= 0) continue;
    const double nz = n[2] / (2 * area);
    if (std::abs(nz) < 0.1) walls[mesh.faceMaterial[f]] += area;
    else if (nz > 0.1) tops[mesh.faceMaterial[f]] += area;
  }
  auto most = [&](const std::map<int, double>& m) {
    int best = 0;
    double area = -1;
    for (const auto& [k, a] : m)
      if (a > area) best = k, area = a;
    return mesh.materials.empty() ? std::string() : mesh.materials[best];
  };
  const std::string wall = most(walls);
  return {wall, tops.empty() ? wall : most(tops)};
}

}  // namespace corbel::city
