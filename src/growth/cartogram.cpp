// The rectangular cartogram (Sec. 7.3.2-7.3.3). See cartogram.h.
#include "growth/cartogram.h"

#include "growth/collapse.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <tuple>

namespace corbel::growth {

namespace {

// Distance along an edge's travel from its start to the grid coordinate c on its axis.
GridCoord along(const ShapeEdge& e, GridCoord c) {
  const bool horizontal = e.facing == Facing::North || e.facing == Facing::South;
  const GridCoord start = horizontal ? e.from.x : e.from.y;
  const GridCoord dir = horizontal ? travelOf(e.facing).x : travelOf(e.facing).y;
  return (c - start) * dir;
}

GridPoint pointAt(const ShapeEdge& e, GridCoord d) {
  const GridPoint t = travelOf(e.facing);
  return {e.from.x + t.x * d, e.from.y + t.y * d};
}

GridCoord distance(GridPoint a, GridPoint b) { return std::llabs(a.x - b.x) + std::llabs(a.y - b.y); }

}  // namespace

BoundaryTrace traceBoundary(const Floorplan& plan) {
  BoundaryTrace out;
  const std::size_t n = plan.units().size();
  std::vector<std::vector<ShapeEdge>> edges(n);
  std::map<LeafRef, std::pair<int, int>> where;  // leaf → (unit, index in edges)
  for (std::size_t u = 0; u < n; ++u) {
    edges[u] = plan.unit(int(u)).edges();
    for (std::size_t k = 0; k < edges[u].size(); ++k) where[{int(u), edges[u][k].node}] = {int(u), int(k)};
  }
  // e_t: a north edge on the top line (the west-most of them).
  int su = -1, sk = -1;
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t k = 0; k < edges[u].size(); ++k) {
      const ShapeEdge& e = edges[u][k];
      if (e.facing != Facing::North) continue;
      if (su < 0 || e.line() > edges[std::size_t(su)][std::size_t(sk)].line() ||
          (e.line() == edges[std::size_t(su)][std::size_t(sk)].line() &&
           e.lo() < edges[std::size_t(su)][std::size_t(sk)].lo()))
        su = int(u), sk = int(k);
    }
  if (su < 0) return out;
  int u = su, k = sk;
  GridPoint p = edges[std::size_t(u)][std::size_t(k)].from;
  std::vector<GridPoint> pts{p};
  for (int guard = 0; guard < 1000000; ++guard) {
    const ShapeEdge& e = edges[std::size_t(u)][std::size_t(k)];
    const GridCoord d = distance(e.from, p), len = distance(e.from, e.to);
    const std::vector<Incidence> links = plan.linksOf({u, e.node});
    const Incidence* covered = nullptr;
    const Incidence* ahead = nullptr;
    GridCoord aheadAt = len;
    for (const Incidence& l : links) {
      const GridCoord a = along(e, l.from), b = along(e, l.to);
      const GridCoord u0 = std::min(a, b), u1 = std::max(a, b);
      if (u0 <= d && d < u1)
        covered = &l;
      else if (u0 > d && u0 < aheadAt)
        ahead = &l, aheadAt = u0;
    }
    auto jump = [&](const Incidence& l) {
      const LeafRef other = l.a == LeafRef{u, e.node} ? l.b : l.a;
      std::tie(u, k) = where.at(other);
    };
    if (links.empty()) {
      ++out.cases[int(TraceCase::NoIncidence)];
    } else if (covered) {
      ++out.cases[int(TraceCase::StartCovered)];
      jump(*covered);
      continue;
    } else if (ahead) {
      ++out.cases[int(TraceCase::ContactAhead)];
      p = pointAt(e, aheadAt);
      pts.push_back(p);
      jump(*ahead);
      continue;
    } else {
      ++out.cases[int(TraceCase::ContactsBehind)];
    }
    // The rest of the edge is boundary; go on with the unit's next edge.
    p = e.to;
    k = (k + 1) % int(edges[std::size_t(u)].size());
    if (u == su && k == sk && p == edges[std::size_t(su)][std::size_t(sk)].from) break;
    pts.push_back(p);
  }
  out.corners = cleanOutline(pts);
  // The four paths between extremal edges (Fig. 7.12).
  const auto& c = out.corners;
  GridCoord x0 = c[0].x, x1 = x0, y0 = c[0].y, y1 = y0;
  for (GridPoint q : c) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  auto best = [&](auto onLine, auto key) {
    int b = -1;
    for (int i = 0; i < int(c.size()); ++i)
      if (onLine(c[std::size_t(i)]) && (b < 0 || key(c[std::size_t(i)]) > key(c[std::size_t(b)]))) b = i;
    return b;
  };
  const int topEast = best([&](GridPoint q) { return q.y == y1; }, [](GridPoint q) { return q.x; });
  const int rightNorth = best([&](GridPoint q) { return q.x == x1; }, [](GridPoint q) { return q.y; });
  const int rightSouth = best([&](GridPoint q) { return q.x == x1; }, [](GridPoint q) { return -q.y; });
  const int bottomEast = best([&](GridPoint q) { return q.y == y0; }, [](GridPoint q) { return q.x; });
  const int bottomWest = best([&](GridPoint q) { return q.y == y0; }, [](GridPoint q) { return -q.x; });
  const int leftSouth = best([&](GridPoint q) { return q.x == x0; }, [](GridPoint q) { return -q.y; });
  const int leftNorth = best([&](GridPoint q) { return q.x == x0; }, [](GridPoint q) { return q.y; });
  const int topWest = best([&](GridPoint q) { return q.y == y1; }, [](GridPoint q) { return -q.x; });
  out.paths = {{{topEast, rightNorth}, {rightSouth, bottomEast}, {bottomWest, leftSouth}, {leftNorth, topWest}}};
  return out;
}

namespace {

// Position on the bounding box's perimeter, clockwise from its north-west corner.
GridCoord perimeterAt(const GridRect& b, GridPoint p) {
  const GridCoord w = b.x1 - b.x0, h = b.y1 - b.y0;
  if (p.y == b.y1) return p.x - b.x0;
  if (p.x == b.x1) return w + (b.y1 - p.y);
  if (p.y == b.y0) return w + h + (b.x1 - p.x);
  return 2 * w + h + (p.y - b.y0);
}

bool onBox(const GridRect& b, GridPoint p) { return p.x == b.x0 || p.x == b.x1 || p.y == b.y0 || p.y == b.y1; }

}  // namespace

std::vector<GridRect> seaRectangles(const Floorplan& plan, const BoundaryTrace& trace, std::size_t* bySubtraction) {
  if (bySubtraction) *bySubtraction = 0;
  if (plan.units().empty() || trace.corners.empty()) return {};
  const GridRect box = plan.bounds();
  const auto& c = trace.corners;
  const int n = int(c.size());
  std::vector<int> onIdx;
  for (int i = 0; i < n; ++i)
    if (onBox(box, c[std::size_t(i)])) onIdx.push_back(i);
  std::vector<GridRect> sea;
  const GridCoord w = box.x1 - box.x0, h = box.y1 - box.y0, per = 2 * (w + h);
  const GridPoint corners[4] = {{box.x0, box.y1}, {box.x1, box.y1}, {box.x1, box.y0}, {box.x0, box.y0}};
  const GridCoord cornerAt[4] = {0, w, w + h, 2 * w + h};
  for (std::size_t a = 0; a < onIdx.size(); ++a) {
    const int i = onIdx[a], j = onIdx[(a + 1) % onIdx.size()];
    const int steps = ((j - i) % n + n) % n;
    const GridPoint P = c[std::size_t(i)], Q = c[std::size_t(j)];
    if (steps == 1 && (P.x == Q.x ? (P.x == box.x0 || P.x == box.x1) : (P.y == box.y0 || P.y == box.y1))) continue;
    // The pocket: the outline from P to Q, then back along the box counter-clockwise.
    std::vector<GridPoint> pocket;
    for (int s = 0; s <= steps; ++s) pocket.push_back(c[std::size_t((i + s) % n)]);
    const GridCoord tq = perimeterAt(box, Q), tp = perimeterAt(box, P);
    const GridCoord span = ((tq - tp) % per + per) % per;  // how far back from Q to P
    std::vector<std::pair<GridCoord, GridPoint>> passed;
    for (int k = 0; k < 4; ++k) {
      const GridCoord back = ((tq - cornerAt[k]) % per + per) % per;
      if (back > 0 && back < span) passed.push_back({back, corners[k]});
    }
    std::sort(passed.begin(), passed.end(), [](auto& x, auto& y) { return x.first < y.first; });
    for (auto& q : passed) pocket.push_back(q.second);
    std::reverse(pocket.begin(), pocket.end());  // clockwise
    pocket = cleanOutline(pocket);
    if (pocket.size() < 4 || signedArea2(pocket) == 0) continue;
    if (const auto t = collapseStaircases(pocket, {1, true})) {
      sea.push_back(t->rectangle);
      for (const CollapseStep& s : t->steps) sea.push_back(s.swept);
    }
  }
  // Whatever sea is left (courtyards, or a pocket that would not collapse) by subtraction.
  std::vector<GridRect> rest{box};
  auto cut = [&](const GridRect& r) {
    std::vector<GridRect> next;
    for (const GridRect& q : rest)
      for (const GridRect& piece : subtractRect(q, r)) next.push_back(piece);
    rest = std::move(next);
  };
  for (const ShapeTree& t : plan.units())
    for (const GridRect& r : t.boxes()) cut(r);
  for (const GridRect& r : sea) cut(r);
  if (bySubtraction) *bySubtraction = rest.size();
  sea.insert(sea.end(), rest.begin(), rest.end());
  return sea;
}

Cartogram Cartogram::of(const Floorplan& plan) {
  std::vector<std::pair<GridRect, int>> all;
  for (std::size_t u = 0; u < plan.units().size(); ++u)
    for (const GridRect& r : plan.unit(int(u)).boxes()) all.push_back({r, int(u)});
  for (const GridRect& r : seaRectangles(plan, traceBoundary(plan))) all.push_back({r, -1});
  std::vector<GridCoord> gx, gy;
  for (const auto& [r, u] : all) gx.insert(gx.end(), {r.x0, r.x1}), gy.insert(gy.end(), {r.y0, r.y1});
  std::sort(gx.begin(), gx.end());
  gx.erase(std::unique(gx.begin(), gx.end()), gx.end());
  std::sort(gy.begin(), gy.end());
  gy.erase(std::unique(gy.begin(), gy.end()), gy.end());
  auto ix = [&](const std::vector<GridCoord>& v, GridCoord x) {
    return int(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  };
  Cartogram c;
  for (GridCoord x : gx) c.xs.push_back(double(x));
  for (GridCoord y : gy) c.ys.push_back(double(y));
  for (const auto& [r, u] : all) c.rects.push_back({ix(gx, r.x0), ix(gy, r.y0), ix(gx, r.x1), ix(gy, r.y1), u});
  return c;
}

PlanRect Cartogram::geometry(int i) const {
  const Rect& r = rects[std::size_t(i)];
  return {xs[std::size_t(r.x0)], ys[std::size_t(r.y0)], xs[std::size_t(r.x1)], ys[std::size_t(r.y1)]};
}

std::vector<PlanRect> Cartogram::geometry() const {
  std::vector<PlanRect> out;
  for (int i = 0; i < int(rects.size()); ++i) out.push_back(geometry(i));
  return out;
}

int Cartogram::subUnits() const {
  return int(std::count_if(rects.begin(), rects.end(), [](const Rect& r) { return r.unit >= 0; }));
}

std::array<double, 2> cornerAt(const std::vector<PlanRect>& rects, CornerRef c) {
  const PlanRect& r = rects[std::size_t(c.rect)];
  switch (c.corner) {
    case 0:
      return {r.x0, r.y0};
    case 1:
      return {r.x1, r.y0};
    case 2:
      return {r.x1, r.y1};
    default:
      return {r.x0, r.y1};
  }
}

Relations relationsOf(const std::vector<PlanRect>& rects) {
  // Vertices: distinct corner positions; edges: rectangle sides cut at every vertex on them.
  std::map<std::array<double, 2>, int> id;
  std::vector<std::array<double, 2>> pos;
  for (int i = 0; i < int(rects.size()); ++i)
    for (int k = 0; k < 4; ++k) {
      const auto p = cornerAt(rects, {i, k});
      if (id.emplace(p, int(pos.size())).second) pos.push_back(p);
    }
  const int v = int(pos.size());
  const std::size_t nv = std::size_t(v);
  std::vector<std::vector<int>> plusX(nv), plusY(nv), vertical(nv), horizontal(nv);
  for (const PlanRect& r : rects) {
    auto side = [&](std::array<double, 2> a, std::array<double, 2> b, bool isHorizontal) {
      std::vector<std::pair<double, int>> on;
      for (int q = 0; q < v; ++q) {
        const auto& p = pos[std::size_t(q)];
        if (isHorizontal ? (p[1] == a[1] && p[0] >= a[0] && p[0] <= b[0])
                         : (p[0] == a[0] && p[1] >= a[1] && p[1] <= b[1]))
          on.push_back({isHorizontal ? p[0] : p[1], q});
      }
      std::sort(on.begin(), on.end());
      for (std::size_t s = 0; s + 1 < on.size(); ++s) {
        const int lo = on[s].second, hi = on[s + 1].second;
        if (isHorizontal) {
          plusX[std::size_t(lo)].push_back(hi);  // only toward +x for ≺x
          horizontal[std::size_t(lo)].push_back(hi), horizontal[std::size_t(hi)].push_back(lo);
        } else {
          plusY[std::size_t(lo)].push_back(hi);
          vertical[std::size_t(lo)].push_back(hi), vertical[std::size_t(hi)].push_back(lo);
        }
      }
    };
    side({r.x0, r.y0}, {r.x1, r.y0}, true);
    side({r.x0, r.y1}, {r.x1, r.y1}, true);
    side({r.x0, r.y0}, {r.x0, r.y1}, false);
    side({r.x1, r.y0}, {r.x1, r.y1}, false);
  }
  // Reachability with free moves along one axis and forward moves along the other.
  auto reach = [&](const std::vector<std::vector<int>>& forward, const std::vector<std::vector<int>>& free, int axis) {
    std::vector<std::vector<char>> out(std::size_t(v), std::vector<char>(std::size_t(v), 0));
    for (int s = 0; s < v; ++s) {
      std::vector<char> seen(std::size_t(v), 0);
      std::deque<int> queue{s};
      seen[std::size_t(s)] = 1;
      while (!queue.empty()) {
        const int a = queue.front();
        queue.pop_front();
        for (const auto* list : {&forward[std::size_t(a)], &free[std::size_t(a)]})
          for (int b : *list)
            if (!seen[std::size_t(b)]) seen[std::size_t(b)] = 1, queue.push_back(b);
      }
      for (int q = 0; q < v; ++q)
        out[std::size_t(s)][std::size_t(q)] =
            seen[std::size_t(q)] && pos[std::size_t(q)][std::size_t(axis)] > pos[std::size_t(s)][std::size_t(axis)];
    }
    return out;
  };
  const auto vx = reach(plusX, vertical, 0), vz = reach(plusY, horizontal, 1);
  // Expand to every rectangle corner.
  const std::size_t m = rects.size() * 4;
  Relations rel;
  rel.x.assign(m, std::vector<char>(m, 0));
  rel.z.assign(m, std::vector<char>(m, 0));
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < m; ++b) {
      const int pa = id.at(cornerAt(rects, {int(a / 4), int(a % 4)})),
                pb = id.at(cornerAt(rects, {int(b / 4), int(b % 4)}));
      rel.x[a][b] = vx[std::size_t(pa)][std::size_t(pb)];
      rel.z[a][b] = vz[std::size_t(pa)][std::size_t(pb)];
    }
  return rel;
}

namespace {

std::array<int, 2> cornerLines(const Cartogram& c, CornerRef k) {
  const Cartogram::Rect& r = c.rects[std::size_t(k.rect)];
  return {k.corner == 0 || k.corner == 3 ? r.x0 : r.x1, k.corner <= 1 ? r.y0 : r.y1};
}

// Sets the fixed lines and spreads the others proportionally between them; false when the
// fixed values do not increase with the line index.
bool respace(std::vector<double>& lines, const std::map<int, double>& fixed, std::string* why) {
  if (fixed.empty()) return true;
  double last = -INFINITY;
  for (const auto& [i, x] : fixed) {
    if (!(x > last)) {
      if (why) *why = "two corresponded corners would swap or meet along an axis";
      return false;
    }
    last = x;
  }
  std::vector<double> out = lines;
  auto first = fixed.begin();
  for (int i = 0; i < first->first; ++i)
    out[std::size_t(i)] = lines[std::size_t(i)] + (first->second - lines[std::size_t(first->first)]);
  for (auto it = fixed.begin(); it != fixed.end(); ++it) {
    out[std::size_t(it->first)] = it->second;
    auto nx = std::next(it);
    if (nx == fixed.end()) {
      for (std::size_t i = std::size_t(it->first) + 1; i < lines.size(); ++i)
        out[i] = lines[i] + (it->second - lines[std::size_t(it->first)]);
      break;
    }
    const double a0 = lines[std::size_t(it->first)], a1 = lines[std::size_t(nx->first)];
    for (int i = it->first + 1; i < nx->first; ++i)
      out[std::size_t(i)] = it->second + (nx->second - it->second) * (lines[std::size_t(i)] - a0) / (a1 - a0);
  }
  lines = std::move(out);
  return true;
}

}  // namespace

bool respectsRelations(const std::vector<PlanRect>& rects, const std::vector<Correspondence>& targets,
                       std::string* why) {
  const Relations rel = relationsOf(rects);
  for (const Correspondence& p : targets)
    for (const Correspondence& q : targets) {
      const std::size_t a = std::size_t(4 * p.corner.rect + p.corner.corner),
                        b = std::size_t(4 * q.corner.rect + q.corner.corner);
      if ((rel.x[a][b] && !(p.x < q.x)) || (rel.z[a][b] && !(p.y < q.y))) {
        if (why) *why = "a correspondence reverses ≺x or ≺z between two corners";
        return false;
      }
    }
  return true;
}

bool realizable(const Cartogram& c, const std::vector<Correspondence>& targets, std::string* why) {
  return respectsRelations(c.geometry(), targets, why);
}

bool realize(Cartogram& c, const std::vector<Correspondence>& targets, std::string* why) {
  if (!realizable(c, targets, why)) return false;
  std::map<int, double> fx, fy;
  for (const Correspondence& t : targets) {
    const auto [ix, iy] = cornerLines(c, t.corner);
    for (auto [m, i, v] : {std::tuple{&fx, ix, t.x}, std::tuple{&fy, iy, t.y}}) {
      const auto [it, fresh] = m->emplace(i, v);
      if (!fresh && it->second != v) {
        if (why) *why = "two corners on one line are sent to different places";
        return false;
      }
    }
  }
  std::vector<double> xs = c.xs, ys = c.ys;
  if (!respace(xs, fx, why) || !respace(ys, fy, why)) return false;
  c.xs = std::move(xs);
  c.ys = std::move(ys);
  return true;
}

}  // namespace corbel::growth
