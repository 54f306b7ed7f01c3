#include "city/street.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_set_2.h>

#include "core/error.h"
#include "extrude/extrude.h"

#include <algorithm>
#include <cmath>

namespace corbel::city {

std::vector<Vec2> catmullRom(const std::vector<Vec2>& c, int perSpan) {
  if (c.size() < 2) throw InputError("street", "a street needs at least two points");
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const Vec2& p0 = c[i == 0 ? 0 : i - 1];
    const Vec2& p1 = c[i];
    const Vec2& p2 = c[i + 1];
    const Vec2& p3 = c[std::min(i + 2, c.size() - 1)];
    for (int k = 0; k < perSpan; ++k) {
      const double t = double(k) / perSpan, t2 = t * t, t3 = t2 * t;
      out.push_back(0.5 *
                    (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3));
    }
  }
  out.push_back(c.back());
  return out;
}

namespace {

// One side's frontage strip split among seeds by the skeleton (Fig. 26): the strip (fronts, then
// backs reversed; counter-clockwise) is a plan whose edges are walls far higher than the plots
// are deep, with one small square hole per seed whose edges rise at 45°. The sweep grows every
// seed at one speed until it meets its neighbours or the strip's walls, so the plan projection
// of a seed's four roof faces, with the seed itself, is the part of the strip it reaches
// first. Returns one counter-clockwise ring per seed, or an empty list (with `why`) when the
// kernel or the check that the plots add up to the strip fails.
std::vector<std::vector<Vec2>> skeletonPlots(const std::vector<Vec2>& strip, const std::vector<Vec2>& seeds,
                                             const std::vector<Vec2>& tangents, double reachHeight, std::string& why) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  extrude::ExtrusionSpec spec;
  extrude::Profile wall, slope;
  wall.name = "plot wall";
  wall.points = {{0, 0}, {0, reachHeight}, {1, reachHeight + 1}};
  slope.name = "plot seed";
  slope.points = {{0, 0}, {1, 1}};
  spec.profiles = {wall, slope};
  spec.loops.push_back({strip, std::vector<int>(strip.size(), 0)});
  const double a = 0.05;  // the seed's half side, m
  std::vector<std::vector<Vec2>> squares;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const Vec2 t = tangents[k], nrm(-t[1], t[0]);
    // Clockwise: a hole.
    std::vector<Vec2> sq{seeds[k] - a * t - a * nrm, seeds[k] - a * t + a * nrm, seeds[k] + a * t + a * nrm,
                         seeds[k] + a * t - a * nrm};
    squares.push_back(sq);
    spec.loops.push_back({sq, std::vector<int>(4, 1)});
  }
  extrude::ExtrusionResult r;
  try {
    r = extrude::extrude(spec, nullptr, 5.0);
  } catch (const std::exception& e) {
    why = std::string("the skeleton of the strip failed: ") + e.what();
    return {};
  }
  std::vector<CGAL::Polygon_set_2<EK>> sets(seeds.size());
  for (const extrude::ShellFace& f : r.shell.faces) {
    if (f.base || f.sourceLoop < 1 || f.sourceLoop > static_cast<int>(seeds.size())) continue;
    CGAL::Polygon_2<EK> poly;
    for (int v : f.loops[0]) poly.push_back(EK::Point_2(r.shell.points[v][0], r.shell.points[v][1]));
    if (poly.size() < 3 || !poly.is_simple()) continue;
    if (poly.orientation() == CGAL::CLOCKWISE) poly.reverse_orientation();
    sets[std::size_t(f.sourceLoop - 1)].join(poly);
  }
  std::vector<std::vector<Vec2>> plots;
  double total = 0;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    CGAL::Polygon_2<EK> sq;
    for (auto it = squares[k].rbegin(); it != squares[k].rend(); ++it) sq.push_back(EK::Point_2((*it)[0], (*it)[1]));
    sets[k].join(sq);
    std::vector<CGAL::Polygon_with_holes_2<EK>> parts;
    sets[k].polygons_with_holes(std::back_inserter(parts));
    if (parts.size() != 1 || parts[0].number_of_holes() != 0) {
      why = "the skeleton gave seed " + std::to_string(k) + " " + std::to_string(parts.size()) + " pieces";
      return {};
    }
    std::vector<Vec2> ring;
    for (const auto& p : parts[0].outer_boundary().container())
      ring.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    total += CGAL::to_double(parts[0].outer_boundary().area());
    plots.push_back(std::move(ring));
  }
  double stripArea = 0;
  for (std::size_t i = 0; i < strip.size(); ++i)
    stripArea += strip[i][0] * strip[(i + 1) % strip.size()][1] - strip[i][1] * strip[(i + 1) % strip.size()][0];
  stripArea /= 2;
  if (std::abs(total - stripArea) > 1e-6 * stripArea) {
    why = "the skeleton's plots cover " + std::to_string(total) + " m² of a " + std::to_string(stripArea) + " m² strip";
    return {};
  }
  return plots;
}

}  // namespace

Town streetTown(const std::vector<Vec2>& control, const PlotOptions& o) {
  for (std::size_t i = 0; i + 1 < control.size(); ++i)
    if (control[i] == control[i + 1])
      throw InputError("street[" + std::to_string(i + 1) + "]", "repeats the point before it");
  Town town;
  town.frame.how = "a street drawn in metres";
  const std::vector<Vec2> line = catmullRom(control);
  town.streets.push_back({"street", line});
  // Arc length and the unit normal (to the left) at every sample.
  const std::size_t n = line.size();
  std::vector<double> s(n, 0.0);
  std::vector<Vec2> normal(n);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + (line[i] - line[i - 1]).norm();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 d = line[std::min(i + 1, n - 1)] - line[i == 0 ? 0 : i - 1];
    normal[i] = Vec2(-d[1], d[0]).normalized();
  }
  // The centreline point and normal at arc length t (linear between samples).
  auto at = [&](double t, Vec2& p, Vec2& nm) {
    const std::size_t k = std::min<std::size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin(), n - 1);
    const std::size_t a = k == 0 ? 0 : k - 1;
    const double f = s[k] > s[a] ? (t - s[a]) / (s[k] - s[a]) : 0.0;
    p = line[a] + (line[k] - line[a]) * f;
    nm = (normal[a] * (1 - f) + normal[k] * f).normalized();
  };
  const double length = s.back();
  const int count = std::max(1, static_cast<int>(std::floor(length / o.plotWidth)));
  const double front = o.streetWidth / 2 + o.setback, back = front + o.depth;
  for (int side = 0; side < (o.bothSides ? 2 : 1); ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    std::string skeletonNote;
    if (o.method == PlotMethod::Skeleton) {
      // The side's whole strip: fronts and backs at every spline sample, each back kept short of
      // where its normal crosses a neighbour's (80 %, as below).
      std::vector<double> reach(n, back);
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const Vec2 d = line[i + 1] - line[i], a = normal[i] * sign, b = normal[i + 1] * sign;
        const double den = a[0] * b[1] - a[1] * b[0];
        if (std::abs(den) < 1e-12) continue;
        const double t = (d[0] * b[1] - d[1] * b[0]) / den;
        if (t > 0) reach[i] = std::min(reach[i], 0.8 * t), reach[i + 1] = std::min(reach[i + 1], 0.8 * t);
      }
      const double shallowest = *std::min_element(reach.begin(), reach.end());
      std::vector<Vec2> fronts, backs;
      for (std::size_t i = 0; i < n; ++i) {
        fronts.push_back(line[i] + normal[i] * sign * front);
        backs.push_back(line[i] + normal[i] * sign * reach[i]);
      }
      std::vector<Vec2> strip = fronts;
      strip.insert(strip.end(), backs.rbegin(), backs.rend());
      if (side == 1) std::reverse(strip.begin(), strip.end());
      std::vector<Vec2> seeds, tangents;
      for (int k = 0; k < count; ++k) {
        Vec2 p, nm;
        at(length * (k + 0.5) / count, p, nm);
        nm *= sign;
        const std::size_t near =
            std::min<std::size_t>(std::lower_bound(s.begin(), s.end(), length * (k + 0.5) / count) - s.begin(), n - 1);
        seeds.push_back(p + nm * (0.5 * (front + std::min(reach[near], reach[near == 0 ? 0 : near - 1]))));
        tangents.push_back(Vec2(nm[1], -nm[0]));
      }
      std::vector<std::vector<Vec2>> rings;
      if (shallowest - front < 3)
        skeletonNote = "the street bends too sharply for the skeleton's strip";
      else
        rings = skeletonPlots(strip, seeds, tangents, 10 * (o.depth + o.plotWidth + front), skeletonNote);
      if (!rings.empty()) {
        for (int k = 0; k < count; ++k) {
          Building b;
          b.id = std::string(side == 0 ? "left/" : "right/") + std::to_string(k);
          b.properties = {{"side", side == 0 ? "left" : "right"}, {"index", k}, {"plot", true}};
          b.loops.push_back(std::move(rings[std::size_t(k)]));
          b.notes.push_back("plot grown from its seed by the skeleton of the frontage (Fig. 26)");
          cleanBuilding(b);
          town.buildings.push_back(std::move(b));
        }
        continue;
      }
    }
    for (int k = 0; k < count; ++k) {
      const double t0 = length * k / count, t1 = length * (k + 1) / count;
      // Stations: the plot's two ends and every spline sample between them.
      std::vector<double> ts{t0};
      for (double t : s)
        if (t > t0 + 1e-9 && t < t1 - 1e-9) ts.push_back(t);
      ts.push_back(t1);
      std::vector<Vec2> ps, ns;
      for (double t : ts) {
        Vec2 p, nm;
        at(t, p, nm);
        ps.push_back(p);
        ns.push_back(nm * sign);
      }
      // On the inside of a bend the normals meet: the plot's back stays short of where two
      // neighbouring normals cross (at 80 % of that distance), so it never folds over itself.
      double fold = INFINITY;
      for (std::size_t i = 0; i + 1 < ps.size(); ++i) {
        const Vec2 d = ps[i + 1] - ps[i];
        const double den = ns[i][0] * ns[i + 1][1] - ns[i][1] * ns[i + 1][0];
        if (std::abs(den) < 1e-12) continue;
        const double t = (d[0] * ns[i + 1][1] - d[1] * ns[i + 1][0]) / den;
        if (t > 0) fold = std::min(fold, t);
      }
      const double reach = std::min(back, 0.8 * fold);
      std::vector<Vec2> fronts, backs;
      for (std::size_t i = 0; i < ps.size(); ++i) {
        fronts.push_back(ps[i] + ns[i] * front);
        backs.push_back(ps[i] + ns[i] * reach);
      }
      // Fronts then backs back again: counter-clockwise on the left side, clockwise on the right.
      std::vector<Vec2> ring = fronts;
      ring.insert(ring.end(), backs.rbegin(), backs.rend());
      if (side == 1) std::reverse(ring.begin(), ring.end());
      Building b;
      b.id = std::string(side == 0 ? "left/" : "right/") + std::to_string(k);
      b.properties = {{"side", side == 0 ? "left" : "right"}, {"index", k}, {"plot", true}};
      b.loops.push_back(std::move(ring));
      if (!skeletonNote.empty()) b.notes.push_back("plot cut along the street's normals instead: " + skeletonNote);
      if (reach - front < 3)
        b.problem = "the street bends too sharply here: a plot would be " + std::to_string(reach - front) +
                    " m deep before its back folds";
      else
        cleanBuilding(b);
      town.buildings.push_back(std::move(b));
    }
  }
  return town;
}

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_2 pt(const Vec2& v) { return {v[0], v[1]}; }

struct Box2 {
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  void add(const Vec2& p) { lo = lo.minimize(p), hi = hi.maximize(p); }
  bool meets(const Box2& o) const { return lo[0] < o.hi[0] && o.lo[0] < hi[0] && lo[1] < o.hi[1] && o.lo[1] < hi[1]; }
};

Box2 boxOf(const std::vector<Vec2>& ring) {
  Box2 b;
  for (const Vec2& p : ring) b.add(p);
  return b;
}

// Whether segments ab and cd cross properly (each strictly on both sides of the other's line).
bool crosses(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const auto o1 = CGAL::orientation(pt(a), pt(b), pt(c)), o2 = CGAL::orientation(pt(a), pt(b), pt(d));
  const auto o3 = CGAL::orientation(pt(c), pt(d), pt(a)), o4 = CGAL::orientation(pt(c), pt(d), pt(b));
  return o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR &&
         o3 != o4;
}

// Whether p lies strictly inside the simple ring.
bool inside(const std::vector<Vec2>& ring, const Vec2& p) {
  std::vector<K::Point_2> r;
  for (const Vec2& v : ring) r.push_back(pt(v));
  return CGAL::bounded_side_2(r.begin(), r.end(), pt(p), K()) == CGAL::ON_BOUNDED_SIDE;
}

// Whether two simple rings' interiors overlap: their edges cross, or a corner (or the middle
// of an edge, for rings that share corners) of one lies strictly inside the other. Touching
// along an edge or at a corner is not an overlap. Exact predicates (CGAL).
bool overlaps(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (crosses(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
  for (const auto* pair : {&a, &b}) {
    const auto& from = *pair;
    const auto& into = pair == &a ? b : a;
    for (std::size_t i = 0; i < from.size(); ++i)
      if (inside(into, from[i]) || inside(into, (from[i] + from[(i + 1) % from.size()]) * 0.5)) return true;
  }
  return false;
}

// Whether a polyline crosses a ring or runs inside it.
bool crossesLine(const std::vector<Vec2>& ring, const std::vector<Vec2>& line) {
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    if (inside(ring, line[i])) return true;
    for (std::size_t j = 0; j < ring.size(); ++j)
      if (crosses(line[i], line[i + 1], ring[j], ring[(j + 1) % ring.size()])) return true;
  }
  return !line.empty() && inside(ring, line.back());
}

// The least distance from p to a polyline.
double distanceToLine(const std::vector<Vec2>& line, const Vec2& p) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 d = line[i + 1] - line[i];
    const double len2 = d.sqrnorm();
    const double t = len2 > 0 ? std::clamp(((p - line[i]) | d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (line[i] + d * t - p).norm());
  }
  return best;
}

// Whether a plot lies on a street's roadway: the centreline runs into it, or a corner or the
// middle of an edge of it is nearer the centreline than half the street's width.
bool onRoad(const std::vector<Vec2>& ring, const std::vector<Vec2>& line, double halfWidth) {
  if (crossesLine(ring, line)) return true;
  for (std::size_t i = 0; i < ring.size(); ++i)
    for (const Vec2& q : {ring[i], (ring[i] + ring[(i + 1) % ring.size()]) * 0.5})
      if (distanceToLine(line, q) < halfWidth - 1e-9) return true;
  return false;
}

}  // namespace

void addStreets(Town& town, const std::vector<TownStreet>& streets) {
  const std::size_t footprints = town.buildings.size();
  std::vector<Box2> boxes;
  for (const Building& b : town.buildings) boxes.push_back(b.loops.empty() ? Box2{} : boxOf(b.loops[0]));
  std::vector<std::vector<Vec2>> lines;  // the streets' centrelines, in order
  std::vector<std::size_t> firstPlot;
  for (std::size_t k = 0; k < streets.size(); ++k) {
    const TownStreet& st = streets[k];
    std::vector<Vec2> control;
    for (const auto& p : st.points) control.emplace_back(p[0], p[1]);
    for (std::size_t i = 1; i < control.size(); ++i)
      if (control[i] == control[i - 1])
        throw InputError("streets[" + std::to_string(k) + "].points[" + std::to_string(i) + "]",
                         "repeats the point before it");
    PlotOptions o;
    o.streetWidth = st.width;
    o.setback = st.setback;
    o.depth = st.depth;
    o.plotWidth = st.plotWidth;
    o.bothSides = st.bothSides;
    o.method = st.skeletonPlots ? PlotMethod::Skeleton : PlotMethod::Normals;
    Town one = streetTown(control, o);
    const std::string name = "street " + std::to_string(k + 1);
    lines.push_back(one.streets.front().points);
    town.streets.push_back({name, one.streets.front().points});
    firstPlot.push_back(town.buildings.size());
    for (Building& b : one.buildings) {
      b.id = name + "/" + b.id;
      b.properties["street"] = name;
      boxes.push_back(b.loops.empty() ? Box2{} : boxOf(b.loops[0]));
      town.buildings.push_back(std::move(b));
    }
  }
  firstPlot.push_back(town.buildings.size());
  // Conflicts: against every footprint and every plot of an earlier street, and every other
  // street's centreline.
  for (std::size_t k = 0; k < streets.size(); ++k)
    for (std::size_t i = firstPlot[k]; i < firstPlot[k + 1]; ++i) {
      Building& plot = town.buildings[i];
      if (!plot.problem.empty() || plot.loops.empty()) continue;
      const auto& ring = plot.loops[0];
      for (std::size_t j = 0; j < firstPlot[k] && plot.problem.empty(); ++j) {
        const Building& other = town.buildings[j];
        if (other.loops.empty() || !boxes[i].meets(boxes[j]) || !overlaps(ring, other.loops[0])) continue;
        plot.problem = (j < footprints ? "the plot overlaps footprint " : "the plot overlaps plot ") + other.id;
      }
      for (std::size_t m = 0; m < lines.size() && plot.problem.empty(); ++m) {
        if (m == k) continue;
        Box2 road = boxOf(lines[m]);
        road.lo -= Vec2(streets[m].width / 2), road.hi += Vec2(streets[m].width / 2);
        if (boxes[i].meets(road) && onRoad(ring, lines[m], streets[m].width / 2))
          plot.problem = "the plot lies across street " + std::to_string(m + 1);
      }
    }
}

}  // namespace corbel::city
