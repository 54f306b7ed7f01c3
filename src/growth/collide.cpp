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
#include <iterator>

namespace corbel::growth {

namespace {

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

}  // namespace corbel::growth
