#include "growth/collide.h"

#include "core/polygon_area.h"
#include "growth/tolerances.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace corbel::growth {

namespace {

// "3 m", "4.5 m": a length for a message.
std::string metres(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g m", x);
  return text;
}

// Exact constructions: the difference's corners are the inputs' coordinates, exactly.
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;

Polygon rectangle(const Rect& r) {
  Polygon p;
  p.push_back(Point(r.u0, r.v0));
  p.push_back(Point(r.u1, r.v0));
  p.push_back(Point(r.u1, r.v1));
  p.push_back(Point(r.u0, r.v1));
  return p;
}

// The obstacle clipped to the face, or false when they share no area.
bool clipped(const Rect& face, const Rect& o, Rect& out) {
  out = {std::max(face.u0, o.u0), std::max(face.v0, o.v0), std::min(face.u1, o.u1), std::min(face.v1, o.v1)};
  return out.u1 > out.u0 && out.v1 > out.v0;
}

bool positiveFace(const Rect& f) { return f.u1 > f.u0 && f.v1 > f.v0; }

PolygonSet freeSet(const FaceObstacles& f) {
  PolygonSet set(rectangle(f.face));
  for (const Rect& o : f.obstacles) {
    Rect c;
    if (clipped(f.face, o, c)) set.difference(rectangle(c));
  }
  return set;
}

std::vector<Vec2> corners(const Polygon& p) {
  std::vector<Vec2> out;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
    out.push_back(Vec2(CGAL::to_double(v->x()), CGAL::to_double(v->y())));
  return out;
}

}  // namespace

double FreePolygon::area() const {
  double a = signedArea(outer);
  for (const auto& h : holes) a += signedArea(h);  // holes run clockwise: negative
  return a;
}

std::vector<FreePolygon> freeRegion(const FaceObstacles& f) {
  std::vector<FreePolygon> out;
  if (!positiveFace(f.face)) return out;
  std::vector<PolygonWithHoles> pieces;
  freeSet(f).polygons_with_holes(std::back_inserter(pieces));
  for (const PolygonWithHoles& p : pieces) {
    FreePolygon fp;
    fp.outer = corners(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) fp.holes.push_back(corners(*h));
    out.push_back(std::move(fp));
  }
  return out;
}

std::vector<Interval> freeColumns(const FaceObstacles& f) {
  std::vector<Interval> out;
  if (!positiveFace(f.face)) return out;
  const PolygonSet set = freeSet(f);
  std::vector<PolygonWithHoles> pieces;
  set.polygons_with_holes(std::back_inserter(pieces));
  // The region is rectilinear: between consecutive corner coordinates every cell is wholly
  // inside or wholly outside it.
  std::vector<K::FT> us{K::FT(f.face.u0), K::FT(f.face.u1)}, vs{K::FT(f.face.v0), K::FT(f.face.v1)};
  auto collect = [&](const Polygon& p) {
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) {
      us.push_back(v->x());
      vs.push_back(v->y());
    }
  };
  for (const PolygonWithHoles& p : pieces) {
    collect(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) collect(*h);
  }
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  for (std::size_t i = 0; i + 1 < us.size(); ++i) {
    const K::FT um = (us[i] + us[i + 1]) / 2;
    bool free = true;
    for (std::size_t j = 0; j + 1 < vs.size() && free; ++j)
      free = set.oriented_side(Point(um, (vs[j] + vs[j + 1]) / 2)) == CGAL::ON_POSITIVE_SIDE;
    if (!free) continue;
    const double lo = CGAL::to_double(us[i]), hi = CGAL::to_double(us[i + 1]);
    if (!out.empty() && out.back().hi == lo)
      out.back().hi = hi;
    else
      out.push_back({lo, hi});
  }
  return out;
}

std::vector<Interval> freeColumnsByIntervals(const FaceObstacles& f) {
  std::vector<Interval> out;
  if (!positiveFace(f.face)) return out;
  std::vector<Interval> blocked;
  for (const Rect& o : f.obstacles) {
    Rect c;
    if (clipped(f.face, o, c)) blocked.push_back({c.u0, c.u1});
  }
  std::sort(blocked.begin(), blocked.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  double at = f.face.u0;
  for (const Interval& b : blocked) {
    if (b.lo > at) out.push_back({at, b.lo});
    at = std::max(at, b.hi);
  }
  if (f.face.u1 > at) out.push_back({at, f.face.u1});
  return out;
}

std::vector<CollideSplit> collideSplits(const Rect& face, const std::vector<Interval>& columns, double least) {
  std::vector<CollideSplit> ends, middles;
  const double u0 = face.u0, u1 = face.u1;
  auto fits = [&](double at) { return at - u0 >= least - kEps && u1 - at >= least - kEps; };
  for (const Interval& c : columns) {
    if (c.hi - c.lo < least - kEps) continue;
    const bool blockedBefore = c.lo > u0, blockedAfter = c.hi < u1;
    if (blockedAfter && fits(c.hi)) (blockedBefore ? middles : ends).push_back({c.hi, false, c});
    if (blockedBefore && fits(c.lo)) (blockedAfter ? middles : ends).push_back({c.lo, true, c});
  }
  ends.insert(ends.end(), middles.begin(), middles.end());
  return ends;
}

std::optional<Box> stairBasePart(const Box& b, Side s, const Box& c, double storeyHeight, double reach,
                                 std::string* why) {
  auto no = [&](const char* reason) -> std::optional<Box> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const int k = sideAxis(s);
  if (k == 2) return no("a stair base is reached through a vertical face");
  const int along = 1 - k;
  if (std::abs(b.size(2) - storeyHeight) > kEps) return no("the part is not one storey high");
  if (std::abs(c.hi[2] - (b.lo[2] - storeyHeight)) > kEps)
    return no("the staircase's roof is not one storey below the part's floor");
  const double gap = sideSign(s) > 0 ? c.lo[k] - b.hi[k] : b.lo[k] - c.hi[k];
  if (gap < -kEps || gap > reach + kEps) return no("the face has not reached the staircase");
  if (overlapLength(b.lo[along], b.hi[along], c.lo[along], c.hi[along]) < kMinDoorWidth - kEps)
    return no("the staircase faces the part along less than a door's width");
  Box part;
  part.lo[2] = c.hi[2];
  part.hi[2] = b.hi[2];
  part.lo[along] = c.lo[along];
  part.hi[along] = c.hi[along];
  part.lo[k] = sideSign(s) > 0 ? b.hi[k] : c.lo[k];
  part.hi[k] = sideSign(s) > 0 ? c.hi[k] : b.lo[k];
  return part;
}

std::optional<Extruded> collideAndExtrude(const Unit& u, int part, Side s, double d, const std::vector<Box>& obstacles,
                                          double least, std::string* why) {
  auto refuse = [&](const std::string& reason) -> std::optional<Extruded> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (part < 0 || part >= int(u.parts.size())) return refuse("no such part");
  if (!std::isfinite(d) || d == 0) return refuse("no distance");
  const int a = sideAxis(s);
  if (a == 2) return refuse("floors and ceilings move by whole storeys (moveFloorOrCeiling)");
  if (sideTouchesOwnPart(u, part, s)) return refuse("this side meets another part of the unit; push that part's side");
  const Box& b = u.parts[std::size_t(part)];
  const double sign = sideSign(s);
  Extruded out{u, 0};
  if (d < 0) {
    if (b.size(a) + d < least - kEps) return refuse("the part would be under " + std::to_string(least) + " m deep");
    Box& moved = out.unit.parts[std::size_t(part)];
    (sign > 0 ? moved.hi[a] : moved.lo[a]) += sign * d;
    out.added = d * b.size(1 - a) * b.size(2);
    return out;
  }
  // What lies in the swept region: each obstacle's stretch of the face and its distance from it.
  const int t = 1 - a;
  const Box swept = sweptRegion(b, s, d);
  struct Hit {
    double lo, hi, distance;
  };
  std::vector<Hit> hits;
  auto consider = [&](const Box& o) {
    if (!interiorsOverlap(swept, o, kEps)) return;
    const double gap = sign > 0 ? o.lo[a] - b.hi[a] : b.lo[a] - o.hi[a];
    hits.push_back({std::max(o.lo[t], b.lo[t]), std::min(o.hi[t], b.hi[t]), std::max(gap, 0.0)});
  };
  for (const Box& o : obstacles) consider(o);
  for (std::size_t i = 0; i < u.parts.size(); ++i)
    if (int(i) != part) consider(u.parts[i]);
  std::vector<double> cuts{b.lo[t], b.hi[t]};
  for (const Hit& h : hits) cuts.insert(cuts.end(), {h.lo, h.hi});
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double x, double y) { return std::abs(x - y) <= kEps; }), cuts.end());
  struct Run {
    double lo, hi, reach;
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double reach = d;
    for (const Hit& h : hits)
      if (overlapLength(h.lo, h.hi, cuts[i], cuts[i + 1]) > kEps) reach = std::min(reach, h.distance);
    if (!runs.empty() && std::abs(runs.back().reach - reach) <= kEps) runs.back().hi = cuts[i + 1];
    else runs.push_back({cuts[i], cuts[i + 1], reach});
  }
  // Narrow runs join the neighbour that reaches less (the joined run reaches the lesser).
  while (runs.size() > 1) {
    std::size_t narrow = runs.size();
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (runs[i].hi - runs[i].lo < least - kEps && (narrow == runs.size() || runs[i].hi - runs[i].lo < runs[narrow].hi - runs[narrow].lo))
        narrow = i;
    if (narrow == runs.size()) break;
    std::size_t with = narrow == 0 ? 1 : narrow - 1;
    if (narrow > 0 && narrow + 1 < runs.size() && runs[narrow + 1].reach < runs[narrow - 1].reach) with = narrow + 1;
    const std::size_t lo = std::min(narrow, with), hi = std::max(narrow, with);
    runs[lo] = {runs[lo].lo, runs[hi].hi, std::min(runs[lo].reach, runs[hi].reach)};
    runs.erase(runs.begin() + std::ptrdiff_t(hi));
    for (std::size_t i = 1; i < runs.size(); ++i)  // neighbours that now reach alike are one run
      if (std::abs(runs[i].reach - runs[i - 1].reach) <= kEps) {
        runs[i - 1].hi = runs[i].hi;
        runs.erase(runs.begin() + std::ptrdiff_t(i));
        break;
      }
  }
  if (std::all_of(runs.begin(), runs.end(), [](const Run& r) { return r.reach <= kEps; }))
    return refuse("something stands right at the face along its whole width");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    Box piece = b;
    piece.lo[t] = runs[i].lo;
    piece.hi[t] = runs[i].hi;
    if (runs[i].reach > kEps) (sign > 0 ? piece.hi[a] : piece.lo[a]) += sign * runs[i].reach;
    out.added += (runs[i].hi - runs[i].lo) * runs[i].reach * b.size(2);
    if (i == 0) out.unit.parts[std::size_t(part)] = piece;
    else out.unit.parts.push_back(piece);
  }
  return out;
}

std::optional<Extruded> moveFloorOrCeiling(const Unit& u, int part, Side s, int storeys, double storeyHeight,
                                           const std::vector<Box>& obstacles, double ground, std::string* why) {
  auto refuse = [&](const std::string& reason) -> std::optional<Extruded> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (part < 0 || part >= int(u.parts.size())) return refuse("no such part");
  if (sideAxis(s) != 2) return refuse("a wall is pushed, not moved by storeys");
  if (!(std::isfinite(storeyHeight) && storeyHeight > 0)) return refuse("the storey height must be positive");
  if (storeys == 0) return refuse("a floor or ceiling moves by whole storeys of " + metres(storeyHeight));
  if (sideTouchesOwnPart(u, part, s)) return refuse("this side meets another part of the unit");
  const Box& b = u.parts[std::size_t(part)];
  const double d = storeys * storeyHeight;  // outward
  const double height = b.size(2) + d;
  const double whole = height / storeyHeight;
  if (std::abs(whole - std::round(whole)) > 1e-6 || std::round(whole) < 1 || std::round(whole) > 2)
    return refuse("the room would be " + metres(height) + " high; a part is one or two storeys (" +
                  metres(storeyHeight) + " each)");
  Extruded out{u, d * b.size(0) * b.size(1)};
  Box& moved = out.unit.parts[std::size_t(part)];
  (s == Side::Top ? moved.hi[2] : moved.lo[2]) += sideSign(s) * d;
  if (moved.lo[2] < ground - kEps) return refuse("the floor would go below the ground (" + metres(ground) + ")");
  double lo = INFINITY, hi = -INFINITY;
  for (const Box& p : out.unit.parts) {
    lo = std::min(lo, p.lo[2]);
    hi = std::max(hi, p.hi[2]);
  }
  if (hi - lo > 2 * storeyHeight + kEps) return refuse("a unit spans at most two storeys");
  if (d > 0) {
    const Box swept = sweptRegion(b, s, d);
    for (const Box& o : obstacles)
      if (interiorsOverlap(swept, o, kEps)) return refuse(std::string("something stands ") + (s == Side::Top ? "above the ceiling" : "below the floor"));
    for (std::size_t i = 0; i < u.parts.size(); ++i)
      if (int(i) != part && interiorsOverlap(swept, u.parts[i], kEps))
        return refuse(std::string("another part of the unit is ") + (s == Side::Top ? "above" : "below"));
  }
  return out;
}

}  // namespace corbel::growth
