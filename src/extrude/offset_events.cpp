// A profile offset event (Sec. 4.6): a recursive extrusion moves every listed edge out by its
// inside distance over the first unit of height and by its outside distance over the second
// (disabled edges stand still); its faces between the two heights, flattened, are the offset
// region R (Fig. 18). Outward, R joins the active plan and its underside is a soffit; inward,
// R is cut from the plan and its top is a ledge. The new plan's edges keep their profiles where
// they lie on the old plan; elsewhere they follow the inside, outside or side profile of the
// boundary they lie on. Booleans are CGAL's, exact.
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::extrude::staging {

Plan Stager::offset(const Plan& plan, double h, const OffsetEvent& ev, std::size_t index) {
  const bool outward = ev.edges.front().outside > 0;
  auto tupleOf = [&](const Active& a) -> const OffsetEdge* {
    for (const OffsetEdge& t : ev.edges)
      if (t.profile == a.profile) return &t;
    return nullptr;
  };
  SweepInput in;
  in.baseZ = 0;
  in.stopZ = 2;
  in.emitBase = false;
  std::vector<const Active*> flat;
  const EPolygonSet active = planSet(plan);
  for (const auto& loop : plan) {
    std::vector<SweepEdge> sl;
    for (const Active& a : loop) {
      const OffsetEdge* t = tupleOf(a);
      SweepEdge e;
      e.start = a.start;
      e.sourceLoop = -1;
      e.sourceEdge = static_cast<int>(flat.size());
      // Distances are outward; k = tan θ moves an edge inward per unit of height.
      e.steps.push_back({0.0, std::atan(t ? -t->inside : 0.0), 0, 0.0});
      e.steps.push_back({1.0, std::atan(t ? -t->outside : 0.0), 1, 0.0});
      sl.push_back(e);
      flat.push_back(&a);
    }
    in.loops.push_back(std::move(sl));
  }
  SweepOutput out = runSweep(in, " (in the offset event at height " + std::to_string(h) + ")");

  // R, and the pieces of its two boundaries by the edge they come from.
  struct Piece {
    Vec2 a, b;
    int edge;
    int boundary;  // 0 inside, 1 outside
  };
  std::vector<Piece> pieces;
  std::vector<RawFace> second;
  for (RawFace& f : out.raw) {
    const Active* a = flat[f.info.sourceEdge];
    if (f.info.segment != 1 || !tupleOf(*a)) continue;
    for (auto [u, v] : f.segments) {
      const Vec3 &p = out.points[u], &q = out.points[v];
      for (int b : {0, 1})
        if (std::abs(p[2] - (1 + b)) <= tol_.height && std::abs(q[2] - (1 + b)) <= tol_.height)
          pieces.push_back({Vec2(p[0], p[1]), Vec2(q[0], q[1]), f.info.sourceEdge, b});
    }
    second.push_back(std::move(f));
  }
  std::vector<ShellFace> faces;
  std::vector<std::string> ignored;
  traceFaces(out.points, second, tol_, faces, ignored);
  EPolygonSet region;
  for (const ShellFace& f : faces) {
    if (std::abs(f.normal[2]) < 1e-9) continue;  // vertical: the edge did not move
    for (const auto& loop : f.loops) {
      std::vector<Vec2> pts;
      for (int v : loop) pts.emplace_back(out.points[v][0], out.points[v][1]);
      const EPolygon p = toPolygon(pts);
      if (p.size() < 3 || !p.is_simple() || p.area() == 0) continue;
      EPolygonSet piece(p);
      region.join(piece);
    }
  }
  EPolygonSet next = active, flats = region;
  if (outward) {
    next.join(region);
    flats.difference(active);
  } else {
    next.difference(region);
    flats.intersection(active);
  }
  ShellFace info;
  info.angle = outward ? -std::numbers::pi / 2 : std::numbers::pi / 2;
  std::vector<EPolygonH> regions;
  flats.polygons_with_holes(std::back_inserter(regions));
  for (const EPolygonH& r : regions) addFlatRegion(r, h, !outward, info);

  // The new plan, edge by edge: edges off the old plan lie on a boundary piece.
  Plan result = rebuild(plan, next, h, [&](const Vec2& mid) {
    Active n;
    n.z0 = h;
    n.profile = ev.sideProfile;
    double best = tol_.cluster;
    for (const Piece& pc : pieces) {
      const double dist = distanceToSegment(mid, pc.a, pc.b);
      if (dist > best) continue;
      best = dist;
      const Active& src = *flat[pc.edge];
      const OffsetEdge* t = tupleOf(src);
      n.profile = pc.boundary == 0 ? t->insideProfile : t->outsideProfile;
      n.sourceLoop = src.sourceLoop;
      n.sourceEdge = src.sourceEdge;
      n.step = src.step;
    }
    return n;
  });
  if (result.empty())
    warnings_.push_back("offsets[" + std::to_string(index) + "]: the offset removed the whole plan at height " + std::to_string(h));
  return result;
}

}  // namespace corbel::extrude::staging
