#include "skeleton_oracle.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_straight_skeleton_from_polygon_with_holes_2.h>

#include <cmath>
#include <stdexcept>

namespace corbel::extrude::test {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
}  // namespace

SkeletonRoof cgalRoof(const std::vector<std::vector<Vec2>>& loops, double pitch) {
  auto toPoly = [](const std::vector<Vec2>& l) {
    Polygon p;
    for (const Vec2& v : l) p.push_back(K::Point_2(v[0], v[1]));
    return p;
  };
  PolygonWithHoles pwh(toPoly(loops[0]));
  for (std::size_t i = 1; i < loops.size(); ++i) pwh.add_hole(toPoly(loops[i]));
  auto ss = CGAL::create_interior_straight_skeleton_2(pwh, K());
  if (!ss) throw std::runtime_error("CGAL could not build the straight skeleton");
  const double t = std::tan(pitch);
  SkeletonRoof r;
  for (auto v = ss->vertices_begin(); v != ss->vertices_end(); ++v) r.maxHeight = std::max(r.maxHeight, v->time() * t);
  for (auto f = ss->faces_begin(); f != ss->faces_end(); ++f) {
    ++r.faces;
    std::vector<Vec3> poly;
    auto h = f->halfedge();
    auto start = h;
    do {
      const auto& p = h->vertex()->point();
      poly.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), h->vertex()->time() * t);
      h = h->next();
    } while (h != start);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      r.volume += OpenMesh::dot(poly[0], OpenMesh::cross(poly[i], poly[i + 1])) / 6.0;
    r.roofArea += 0.5 * newellNormal(poly).norm();
  }
  return r;
}

}  // namespace corbel::extrude::test
