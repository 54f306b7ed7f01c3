#include "growth/roofs.h"

#include "core/polygon_area.h"
#include "extrude/extrude.h"
#include "growth/tolerances.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <sstream>

namespace corbel::growth {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;

// Coordinates on a micrometre grid: sums of α steps that differ in the last bits meet exactly.
double snap(double x) { return std::round(x * 1e6) / 1e6; }

Polygon rectangle(double x0, double y0, double x1, double y1) {
  Polygon p;
  p.push_back(Point(snap(x0), snap(y0)));
  p.push_back(Point(snap(x1), snap(y0)));
  p.push_back(Point(snap(x1), snap(y1)));
  p.push_back(Point(snap(x0), snap(y1)));
  return p;
}

std::vector<Vec2> loopOf(const Polygon& p) {
  std::vector<Point> pts(p.vertices_begin(), p.vertices_end());
  // Drop collinear corners (where rectangles joined), repeatedly around the loop.
  bool changed = true;
  while (changed && pts.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < pts.size() && pts.size() > 3; ++i) {
      const Point& a = pts[(i + pts.size() - 1) % pts.size()];
      const Point& c = pts[(i + 1) % pts.size()];
      if (CGAL::collinear(a, pts[i], c)) {
        pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        --i;
      }
    }
  }
  std::vector<Vec2> out;
  for (const Point& q : pts) out.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  return out;
}

Profile makeProfile(std::string name, std::vector<Vec2> points, std::vector<std::string> tags) {
  Profile p;
  p.name = std::move(name);
  p.points = std::move(points);
  p.tags = std::move(tags);
  return p;
}

// A corner the region's boundaries pass twice (two lobes, or a hole and the outside, meeting at
// a point): the extrusion kernel needs simple loops that do not touch.
bool pinch(const PolygonWithHoles& pwh, Point& at) {
  std::vector<Point> pts(pwh.outer_boundary().vertices_begin(), pwh.outer_boundary().vertices_end());
  for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) pts.insert(pts.end(), h->vertices_begin(), h->vertices_end());
  std::sort(pts.begin(), pts.end());
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (pts[i] == pts[i - 1]) {
      at = pts[i];
      return true;
    }
  return false;
}

// The region cut by the line x = at.x() through a pinch (rectilinear lobes meet diagonally, so
// the line parts them), again until no piece is pinched (a few cuts at most).
void unpinch(const PolygonWithHoles& pwh, std::vector<PolygonWithHoles>& out, int depth = 0) {
  Point at;
  if (depth >= 8 || !pinch(pwh, at)) {
    out.push_back(pwh);
    return;
  }
  const auto box = pwh.outer_boundary().bbox();
  const double lo = std::floor(box.xmin()) - 1, hi = std::ceil(box.xmax()) + 1;
  const double y0 = std::floor(box.ymin()) - 1, y1 = std::ceil(box.ymax()) + 1;
  for (int side = 0; side < 2; ++side) {
    Polygon half;
    const K::FT x0 = side == 0 ? K::FT(lo) : at.x(), x1 = side == 0 ? at.x() : K::FT(hi);
    half.push_back(Point(x0, y0));
    half.push_back(Point(x1, y0));
    half.push_back(Point(x1, y1));
    half.push_back(Point(x0, y1));
    std::vector<PolygonWithHoles> pieces;
    CGAL::intersection(pwh, half, std::back_inserter(pieces));
    for (const PolygonWithHoles& p : pieces) unpinch(p, out, depth + 1);
  }
}

}  // namespace

double RoofRegion::area() const {
  double a = 0;
  for (const auto& l : loops) a += signedArea(l);
  return a;
}

std::vector<RoofRegion> exposedTops(const Site& site, const std::vector<Unit>& units) {
  std::vector<Box> all;
  for (const Unit& u : units) all.insert(all.end(), u.parts.begin(), u.parts.end());
  std::vector<Box> obstacles = all;
  for (std::size_t i = 0; i < site.cores.size(); ++i) obstacles.push_back(site.coreBox(i));
  obstacles.insert(obstacles.end(), site.circulation.begin(), site.circulation.end());

  std::map<double, std::vector<const Box*>> byHeight;
  for (const Box& b : all) byHeight[snap(b.hi[2])].push_back(&b);

  std::vector<RoofRegion> out;
  for (const auto& [z, tops] : byHeight) {
    PolygonSet set;
    for (const Box* b : tops) set.join(rectangle(b->lo[0], b->lo[1], b->hi[0], b->hi[1]));
    for (const Box& o : obstacles) {
      // Standing on the tops (floor at z) or passing through that height.
      if (!(o.lo[2] <= z + kEps && o.hi[2] > z + kEps)) continue;
      if (snap(o.hi[0]) <= snap(o.lo[0]) || snap(o.hi[1]) <= snap(o.lo[1])) continue;
      set.difference(rectangle(o.lo[0], o.lo[1], o.hi[0], o.hi[1]));
    }
    std::vector<PolygonWithHoles> sets, pieces;
    set.polygons_with_holes(std::back_inserter(sets));
    for (const PolygonWithHoles& p : sets) unpinch(p, pieces);
    std::vector<RoofRegion> level;
    for (const PolygonWithHoles& pwh : pieces) {
      RoofRegion r;
      r.z = z;
      r.loops.push_back(loopOf(pwh.outer_boundary()));
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) r.loops.push_back(loopOf(*h));
      level.push_back(std::move(r));
    }
    std::sort(level.begin(), level.end(), [](const RoofRegion& a, const RoofRegion& b) {
      const auto key = [](const RoofRegion& r) {
        Vec2 m = r.loops[0][0];
        for (const Vec2& p : r.loops[0]) m = Vec2(std::min(m[0], p[0]), std::min(m[1], p[1]));
        return std::pair(m[0], m[1]);
      };
      return key(a) < key(b);
    });
    out.insert(out.end(), level.begin(), level.end());
  }
  return out;
}

ExtrusionSpec roofSpec(const RoofRegion& region, const RoofSettings& s) {
  ExtrusionSpec spec;
  spec.baseZ = region.z;
  spec.material = s.wallMaterial;
  spec.roofMaterial = !s.material.empty() ? s.material : s.profile == RoofProfile::Flat ? "concrete" : "roof_tile";
  const double pitch = s.pitch * std::numbers::pi / 180;
  int lean = 0, upright = 0;
  if (s.profile == RoofProfile::Flat) {
    // The city's parapet (docs/city.md): walls to the coping, then in by the parapet's thickness
    // (closing the ring it leaves), the cut's inner edges rising straight up.
    const double top = s.slab + s.parapet;
    spec.profiles.push_back(makeProfile("parapet wall", {Vec2(0, 0), Vec2(0, top), Vec2(s.parapetThickness, top),
                                                         Vec2(s.parapetThickness + 1, top + 1)},
                                        {"parapet", "coping", "roof"}));
    spec.profiles.push_back(makeProfile("parapet inside", {Vec2(0, 0), Vec2(0, s.parapet + 1)}, {"parapet"}));
    OffsetEvent ev;
    ev.height = s.slab;
    ev.sideProfile = 1;
    ev.edges.push_back({0, -s.parapetThickness, -1000.0, 1, 1});
    spec.offsets.push_back(ev);
  } else {
    spec.profiles.push_back(makeProfile("roof slope", {Vec2(0, 0), Vec2(1.0 / std::tan(pitch), 1.0)}, {"roof"}));
    spec.profiles.push_back(makeProfile("gable end", {Vec2(0, 0), Vec2(0, 1.0)}, {"gable"}));
    lean = 0;
    upright = 1;
  }
  // The longer axis of the region's bounding box: gables stand across it, a shed rises along the
  // shorter one.
  Vec2 lo = region.loops[0][0], hi = lo;
  for (const Vec2& p : region.loops[0]) {
    lo = Vec2(std::min(lo[0], p[0]), std::min(lo[1], p[1]));
    hi = Vec2(std::max(hi[0], p[0]), std::max(hi[1], p[1]));
  }
  const int longAxis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  const int shortAxis = 1 - longAxis;
  for (const auto& loop : region.loops) {
    std::vector<int> profile(loop.size(), 0);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2 d = loop[(i + 1) % loop.size()] - loop[i];
      const Vec2 outward(d[1], -d[0]);  // outer loops counter-clockwise, holes clockwise
      const bool alongLong = std::abs(d[longAxis]) > std::abs(d[shortAxis]);
      switch (s.profile) {
        case RoofProfile::Flat:
        case RoofProfile::Hip: profile[i] = lean; break;
        case RoofProfile::Gable: profile[i] = alongLong ? lean : upright; break;
        case RoofProfile::Shed: profile[i] = alongLong && outward[shortAxis] < 0 ? lean : upright; break;
      }
    }
    spec.loops.emplace_back(loop, profile);
  }
  return spec;
}

Roofs buildRoofs(const Site& site, const std::vector<Unit>& units, const RoofSettings& settings) {
  Roofs out;
  out.regions = exposedTops(site, units);
  for (const RoofRegion& r : out.regions) {
    const ExtrusionSpec spec = roofSpec(r, settings);
    std::string problem;
    MeshData shell;
    try {
      const extrude::ExtrusionResult result = extrude::extrude(spec, nullptr, 10.0);
      if (extrude::unpairedEdges(result.shell) != 0) {
        problem = "the kernel's shell is not closed";
      } else if (const std::string crossed = extrude::crossedFace(result.shell); !crossed.empty()) {
        problem = "the kernel's shell is not valid: " + crossed;
      } else {
        shell = extrude::toMeshData(result.shell, spec, spec.material);
        out.mesh.append(shell);
      }
    } catch (const std::exception& e) {
      problem = e.what();
    }
    out.shells.push_back(std::move(shell));
    if (!problem.empty()) {
      std::ostringstream w;
      w << "roof over the " << r.area() << " m² region at height " << r.z << " (corner " << r.loops[0][0][0] << ", "
        << r.loops[0][0][1] << ") not built: " << problem;
      out.warnings.push_back(w.str());
    }
  }
  return out;
}

}  // namespace corbel::growth
