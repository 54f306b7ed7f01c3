// Exact regions of the active plan (CGAL's Polygon_set_2): the plan as a region, a flat face
// over a region, and the plan rebuilt from a region after a Boolean change (forced steps,
// offset events, the winding rule).
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::extrude::staging {

EPolygon toPolygon(const std::vector<Vec2>& pts) {
  EPolygon p;
  for (const Vec2& q : pts) p.push_back(EK::Point_2(q[0], q[1]));
  if (p.size() >= 3 && p.is_simple() && p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

Vec2 toVec(const EK::Point_2& p) { return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = OpenMesh::dot(d, d);
  const double t = len2 > 0 ? std::clamp(OpenMesh::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return (a + d * t - p).norm();
}

void Stager::addFlatRegion(const EPolygonH& region, double h, bool up, const ShellFace& info) {
  RawFace f;
  f.info = info;
  f.info.normal = Vec3(0, 0, up ? 1 : -1);
  auto add = [&](const EPolygon& p, [[maybe_unused]] bool ccw) {
    std::vector<int> ids;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) ids.push_back(weld(toVec(*v), h));
    // CGAL gives outer boundaries counter-clockwise and holes clockwise from above: right as
    // seen from outside for a face looking up; a face looking down is seen from below.
    if (!up) std::reverse(ids.begin(), ids.end());
    for (std::size_t k = 0; k < ids.size(); ++k) f.segments.emplace_back(ids[k], ids[(k + 1) % ids.size()]);
  };
  add(region.outer_boundary(), true);
  for (auto hole = region.holes_begin(); hole != region.holes_end(); ++hole) add(*hole, false);
  addFace(std::move(f));
}

EPolygonSet planSet(const Plan& plan) {
  EPolygonSet set;
  for (const auto& loop : plan) {
    std::vector<Vec2> pts;
    for (const Active& a : loop) pts.push_back(a.start);
    const EPolygon p = toPolygon(pts);
    if (p.size() >= 3 && p.is_simple()) set.symmetric_difference(p);
  }
  return set;
}

// The active plan after a Boolean change: an edge lying on an edge of the old plan (same way
// round) keeps what that edge was; any other edge is what `other` says for its midpoint.
Plan Stager::rebuild(const Plan& old, const EPolygonSet& next, double h, const std::function<Active(const Vec2&)>& other,
                     bool atBase) {
  auto classify = [&](const Vec2& a, const Vec2& b) {
    const Vec2 mid = (a + b) * 0.5;
    Vec2 d = b - a;
    d.normalize();
    for (const auto& loop : old)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 &p = loop[i].start, &q = loop[(i + 1) % loop.size()].start;
        Vec2 e = q - p;
        if (e.norm() == 0) continue;
        e.normalize();
        if (OpenMesh::dot(d, e) > 1 - 1e-9 && distanceToSegment(mid, p, q) <= tol_.cluster) return loop[i];
      }
    return other(mid);
  };
  std::vector<EPolygonH> regions;
  next.polygons_with_holes(std::back_inserter(regions));
  Plan result;
  auto addLoop = [&](const EPolygon& p) {
    std::vector<Vec2> pts;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) pts.push_back(toVec(*v));
    std::vector<Active> l;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Active a = classify(pts[i], pts[(i + 1) % pts.size()]);
      a.start = pts[i];
      a.vertex = atBase ? -1 : weld(pts[i], h);  // the base's vertices are made by the first stage
      l.push_back(a);
    }
    if (l.size() >= 3) result.push_back(std::move(l));
  };
  for (const EPolygonH& r : regions) {
    addLoop(r.outer_boundary());
    for (auto hole = r.holes_begin(); hole != r.holes_end(); ++hole) addLoop(*hole);
  }
  return result;
}

}  // namespace corbel::extrude::staging
