#include "statics/coursing.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace corbel::statics {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
Vec2 leftNormal(const Vec2& d) { return Vec2(-d[1], d[0]); }

// One edge's wall in plan: its outer face from p0 along d for `length`, inward normal n, and how
// far its inner face's ends lie from its outer corners (0 at a free end).
struct EdgeFrame {
  Vec2 p0{0.0, 0.0}, d{1.0, 0.0}, n{0.0, 1.0};
  double length = 0.0;
  double startSquare = 0.0, endSquare = 0.0;  // a_s, a_e: the corner squares' extent along the face
  bool startCorner = false, endCorner = false;
  Vec2 at(double u, double v) const { return p0 + d * u + n * v; }
};

// A cut across a course: where it meets the course's bottom and top (m along the face).
struct Cut {
  double bottom = 0.0, top = 0.0;
  double lo() const { return std::min(bottom, top); }
  double hi() const { return std::max(bottom, top); }
};

}  // namespace

CoursedWalls courseWalls(const CoursingSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(spec.height) || !positive(spec.courseHeight) || !positive(spec.blockLength) ||
      !positive(spec.thickness) || !positive(spec.density) || !std::isfinite(spec.base))
    throw Error("coursing: height, course height, block length, thickness and density must be positive numbers");
  const std::size_t np = spec.plan.size();
  if (np < (spec.closed ? 3u : 2u)) throw Error("coursing: the plan needs at least 3 corners (2 for an open wall)");
  const int courses = std::max(1, int(std::lround(spec.height / spec.courseHeight)));
  if (courses > 10000) throw Error("coursing: more than 10000 courses");
  const double ch = spec.height / courses, b = spec.blockLength, t = spec.thickness;
  const double bearing = b / 2, sliver = b / 4;
  const std::size_t ne = spec.closed ? np : np - 1;

  // Edge frames and corner squares.
  BBox box;
  for (const Vec2& p : spec.plan) box.add(Vec3(p[0], p[1], 0.0));
  const double tol = 1e-9 * std::max(1.0, box.diagonal() + spec.height);
  std::vector<EdgeFrame> edges(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    EdgeFrame& f = edges[e];
    f.p0 = spec.plan[e];
    const Vec2 v = spec.plan[(e + 1) % np] - f.p0;
    f.length = v.norm();
    if (!(f.length > 100 * tol)) throw Error("coursing: edge " + std::to_string(e) + " has no length");
    if (f.length / b > 100000) throw Error("coursing: too many blocks along edge " + std::to_string(e));
    f.d = v / f.length;
    f.n = leftNormal(f.d);
  }
  for (std::size_t k = 0; k < np; ++k) {
    if (!spec.closed && (k == 0 || k == np - 1)) continue;  // free wall ends
    EdgeFrame& in = edges[(k + ne - 1) % ne];
    EdgeFrame& out = edges[k % ne];
    const double turn = cross2(in.d, out.d);
    if (turn < -1e-9) throw Error("coursing: the plan turns right at corner " + std::to_string(k) +
                                  " (a reflex corner); only convex corners are coursed");
    double a = 0;
    if (turn > 1e-9) {
      // The inner faces' lines meet at Q = P + n_in t + s d_in = P + n_out t + r d_out.
      const Vec2 rhs = (out.n - in.n) * t;  // s d_in − r d_out = rhs
      const double s = cross2(rhs, -out.d) / cross2(in.d, -out.d);
      const Vec2 q = in.n * t + in.d * s;   // Q − P
      a = dot(q, out.d);
    }
    if (a >= in.length || a >= out.length)
      throw Error("coursing: the walls at corner " + std::to_string(k) + " are thicker than the edges are long");
    in.endSquare = out.startSquare = a;
    in.endCorner = out.startCorner = a > tol;
  }

  // Openings: snapped to courses, checked against their wall and each other.
  struct Placed {
    const WallOpening* o;
    int sill, head;
    std::vector<Cut> headCuts;  // the cuts of the head course, left to right
  };
  std::vector<Placed> placed;
  for (const WallOpening& o : spec.openings) {
    const std::string who = "coursing: opening \"" + o.name + "\"";
    if (o.edge < 0 || std::size_t(o.edge) >= ne) throw Error(who + ": no edge " + std::to_string(o.edge));
    if (!std::isfinite(o.from) || !std::isfinite(o.to) || !(o.to > o.from) || !std::isfinite(o.bottom) ||
        !std::isfinite(o.top) || !(o.top > o.bottom))
      throw Error(who + ": needs from < to and bottom < top");
    Placed p{&o, int(std::lround(o.bottom / ch)), int(std::lround(o.top / ch)), {}};
    p.sill = std::max(p.sill, 0);
    if (p.head <= p.sill) p.head = p.sill + 1;
    if (p.head >= courses)
      throw Error(who + ": its head reaches the wall head (no course above it for a lintel or arch)");
    if (o.head == OpeningHead::Lintel) {
      p.headCuts = {{o.from - bearing, o.from - bearing}, {o.to + bearing, o.to + bearing}};
    } else {
      // Joints through the apex C of the equilateral triangle under the span.
      const double span = o.to - o.from, mid = 0.5 * (o.from + o.to), depth = span * std::sqrt(3.0) / 2;
      int n = std::max(3, int(std::lround(span / (0.5 * ch))));
      if (n % 2 == 0) ++n;
      for (int k = 0; k <= n; ++k) {
        const double x = o.from + span * k / n;
        p.headCuts.push_back({x, mid + (x - mid) * (depth + ch) / depth});
      }
    }
    const EdgeFrame& f = edges[std::size_t(o.edge)];
    if (p.headCuts.front().lo() < f.startSquare - tol || p.headCuts.back().hi() > f.length - f.endSquare + tol)
      throw Error(who + ": the opening and its " + (o.head == OpeningHead::Lintel ? "lintel's bearings" : "arch") +
                  " leave its wall or reach a corner's square");
    for (const Placed& q : placed) {
      if (q.o->edge != o.edge) continue;
      const double lo = p.headCuts.front().lo(), hi = p.headCuts.back().hi();
      const double qlo = q.headCuts.front().lo(), qhi = q.headCuts.back().hi();
      if (lo < qhi && qlo < hi && p.sill <= q.head && q.sill <= p.head)
        throw Error(who + " overlaps opening \"" + q.o->name + "\" (with their heads)");
    }
    placed.push_back(std::move(p));
  }

  CoursedWalls out;
  out.courses = courses;
  out.courseHeight = ch;
  for (int c = 0; c < courses; ++c) {
    const double z0 = spec.base + c * ch, z1 = spec.base + (c + 1) * ch;
    const bool odd = c % 2 != 0;
    for (std::size_t e = 0; e < ne; ++e) {
      const EdgeFrame& f = edges[e];
      const bool ownsStart = f.startCorner && odd, ownsEnd = f.endCorner && !odd;
      struct Span {
        double lo, hi;
        bool open;
      };
      std::vector<Cut> cuts = {{ownsStart ? 0.0 : f.startSquare, ownsStart ? 0.0 : f.startSquare},
                               {ownsEnd ? f.length : f.length - f.endSquare, ownsEnd ? f.length : f.length - f.endSquare}};
      std::vector<Span> spans;  // no bond joints inside these
      for (const Placed& p : placed) {
        if (std::size_t(p.o->edge) != e) continue;
        if (c >= p.sill && c < p.head) {
          cuts.push_back({p.o->from, p.o->from});
          cuts.push_back({p.o->to, p.o->to});
          spans.push_back({p.o->from, p.o->to, true});
        } else if (c == p.head) {
          cuts.insert(cuts.end(), p.headCuts.begin(), p.headCuts.end());
          spans.push_back({p.headCuts.front().lo(), p.headCuts.back().hi(), false});
        }
      }
      // Keep-outs for bond joints: every cut so far and the inner corner lines.
      std::vector<Cut> avoid = cuts;
      avoid.push_back({f.startSquare, f.startSquare});
      avoid.push_back({f.length - f.endSquare, f.length - f.endSquare});
      for (int k = 0;; ++k) {
        const double x = (k + (odd ? 0.5 : 0.0)) * b;
        if (x >= f.length) break;
        if (x <= f.startSquare || x >= f.length - f.endSquare) continue;
        bool keep = true;
        for (const Cut& a : avoid) keep = keep && (x >= a.hi() + sliver - tol || x <= a.lo() - sliver + tol);
        for (const Span& s : spans) keep = keep && !(x > s.lo && x < s.hi);
        if (keep) cuts.push_back({x, x});
      }
      std::sort(cuts.begin(), cuts.end(), [](const Cut& p, const Cut& q) {
        return p.bottom + p.top < q.bottom + q.top;
      });
      cuts.erase(std::unique(cuts.begin(), cuts.end(),
                             [&](const Cut& p, const Cut& q) {
                               return std::abs(p.bottom - q.bottom) <= tol && std::abs(p.top - q.top) <= tol;
                             }),
                 cuts.end());
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const Cut& l = cuts[k];
        const Cut& r = cuts[k + 1];
        const double mid = 0.25 * (l.bottom + l.top + r.bottom + r.top);
        bool isOpen = false;
        for (const Span& s : spans) isOpen = isOpen || (s.open && mid > s.lo && mid < s.hi);
        if (isOpen) continue;
        const std::string name =
            "wall " + std::to_string(e) + " course " + std::to_string(c) + " block " + std::to_string(k);
        const int index = int(out.blocks.size());
        const bool first = k == 0, last = k + 2 == cuts.size();
        if ((first && ownsStart) || (last && ownsEnd)) {
          if (first && last) throw Error("coursing: wall " + std::to_string(e) + " is one block between two corners");
          // The block holding a corner: between the course's planes, the wall's faces, the
          // other wall's outer face and its joint at the corner square, and the cut on the far
          // side (slanted at an arch's skewback). Convex: a convex plan prism cut by a plane.
          const EdgeFrame& other = first ? edges[(e + ne - 1) % ne] : edges[(e + 1) % ne];
          auto horizontal = [](const Vec2& nrm, double d) { return HalfSpace{Vec3(nrm[0], nrm[1], 0.0), d}; };
          std::vector<HalfSpace> hs = {{Vec3(0, 0, -1), -z0}, {Vec3(0, 0, 1), z1},
                                       horizontal(-f.n, -dot(f.n, f.p0)), horizontal(f.n, dot(f.n, f.p0) + t),
                                       horizontal(-other.n, -dot(other.n, other.p0))};
          if (first)  // u_prev ≥ L_prev − a
            hs.push_back(horizontal(-other.d, -(dot(other.d, other.p0) + other.length - f.startSquare)));
          else  // u_next ≤ a
            hs.push_back(horizontal(other.d, dot(other.d, other.p0) + f.endSquare));
          // The far cut: u − s·z ≤ c (first) or ≥ c (last), u = d·(p − p0), s = (top − bottom) / (z1 − z0).
          const Cut& cut = first ? r : l;
          const double slope = (cut.top - cut.bottom) / (z1 - z0), c0 = cut.bottom - slope * z0 + dot(f.d, f.p0);
          const Vec3 along(f.d[0], f.d[1], -slope);
          hs.push_back(first ? HalfSpace{along, c0} : HalfSpace{-along, -c0});
          out.blocks.push_back(halfspaceBlock(name, hs, spec.density));
          if (c == courses - 1) {
            if (first) {
              const EdgeFrame& prev = edges[(e + ne - 1) % ne];
              out.heads.push_back({index, int((e + ne - 1) % ne), prev.length - f.startSquare, prev.length});
              out.heads.push_back({index, int(e), 0.0, r.top});
            } else {
              out.heads.push_back({index, int(e), l.top, f.length});
              out.heads.push_back({index, int((e + 1) % ne), 0.0, f.endSquare});
            }
          }
          continue;
        }
        auto onFace = [&](double u, double z) {
          const Vec2 p = f.at(u, 0.0);
          return Vec3(p[0], p[1], z);
        };
        const std::vector<Vec3> face = {onFace(l.bottom, z0), onFace(r.bottom, z0), onFace(r.top, z1), onFace(l.top, z1)};
        out.blocks.push_back(prismBlock(name, face, Vec3(f.n[0] * t, f.n[1] * t, 0.0), spec.density));
        if (c == courses - 1) out.heads.push_back({index, int(e), l.top, r.top});
      }
    }
  }
  return out;
}

void loadWallHeads(const CoursingSpec& spec, CoursedWalls& walls, const std::vector<HeadLoad>& perEdge) {
  const std::size_t np = spec.plan.size(), ne = spec.closed ? np : np - 1;
  if (perEdge.size() != ne)
    throw Error("coursing: " + std::to_string(perEdge.size()) + " head loads for " + std::to_string(ne) + " edges");
  const double top = spec.base + walls.courses * walls.courseHeight;
  for (const HeadSpan& h : walls.heads) {
    const HeadLoad& load = perEdge[std::size_t(h.edge)];
    if (!std::isfinite(load.down) || !std::isfinite(load.out)) throw Error("coursing: a head load is not finite");
    if (load.down == 0 && load.out == 0) continue;
    const Vec2 p0 = spec.plan[std::size_t(h.edge)], p1 = spec.plan[(std::size_t(h.edge) + 1) % np];
    const Vec2 d = (p1 - p0) / (p1 - p0).norm(), n = leftNormal(d);
    const Vec2 at = p0 + d * (0.5 * (h.from + h.to)) + n * (spec.thickness / 2);
    const double len = h.to - h.from;
    PointLoad l;
    l.at = Vec3(at[0], at[1], top);
    l.force = Vec3(-n[0] * load.out * len, -n[1] * load.out * len, -load.down * len);
    walls.blocks[std::size_t(h.block)].pointLoads.push_back(l);
  }
}

}  // namespace corbel::statics
