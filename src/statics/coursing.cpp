#include "statics/coursing.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
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
  // At a reflex corner the square lies beyond the face's end (its squares above are 0): the
  // wall that does not hold it stops at the outer corner.
  bool startReflex = false, endReflex = false;
  double startKeep = 0.0, endKeep = 0.0;  // openings and buttresses stay this far from the ends
  Vec2 at(double u, double v) const { return p0 + d * u + n * v; }
};

// A cut across a course: where it meets the course's bottom and top (m along the face).
struct Cut {
  double bottom = 0.0, top = 0.0;
  double lo() const { return std::min(bottom, top); }
  double hi() const { return std::max(bottom, top); }
};

using Poly2 = std::vector<Vec2>;

double signedArea(const Poly2& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross2(p[i], p[(i + 1) % p.size()]);
  return a / 2;
}

// The part of a convex polygon where a·p ≤ c (Sutherland–Hodgman against one line).
Poly2 clipped(const Poly2& poly, const Vec2& a, double c) {
  Poly2 out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
    const double fp = dot(a, p) - c, fq = dot(a, q) - c;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
  }
  return out;
}

// Drops repeated points and points on the line through their neighbours (within `tol`).
Poly2 cleaned(Poly2 p, double tol) {
  for (bool changed = true; changed && p.size() >= 3;) {
    changed = false;
    for (std::size_t i = 0; i < p.size() && p.size() >= 3; ++i) {
      const Vec2 &a = p[(i + p.size() - 1) % p.size()], &b = p[i], &c = p[(i + 1) % p.size()];
      const double len = (c - a).norm();
      if ((b - a).norm() <= tol || std::abs(cross2(b - a, c - a)) <= tol * std::max(len, tol)) {
        p.erase(p.begin() + std::ptrdiff_t(i));
        changed = true;
      }
    }
  }
  return p;
}

// The convex hull, counter-clockwise (Andrew's monotone chain), points on its edges dropped.
Poly2 hullOf(Poly2 pts, double tol) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  Poly2 h(2 * pts.size());
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = k;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec2& p = pass == 0 ? pts[i] : pts[pts.size() - 1 - i];
      while (k >= start + 2 && cross2(h[k - 1] - h[k - 2], p - h[k - 2]) <= 0) --k;
      h[k++] = p;
    }
    --k;  // the last point starts the other chain
  }
  h.resize(k);
  return cleaned(h, tol);
}

// A semicircular arch over an opening, in the wall face's coordinates (u along the edge, z up):
// the voussoirs' joints and the arch's zone of courses [first, first + courses).
struct ArchHead {
  Vec2 centre{0.0, 0.0};
  Poly2 inner, outer;  // joint k's intrados and extrados points, k = 0..N
  int first = 0, courses = 0;
  double lo = 0.0, hi = 0.0;  // the zone's sides (m along the face)
};

ArchHead archHead(double from, double to, double springing, int headCourse, double ch, double depth, double bearing) {
  ArchHead a;
  const double ri = (to - from) / 2, ro = ri + depth, mid = (from + to) / 2;
  a.centre = Vec2(mid, springing);
  int n = std::max(5, int(std::lround(std::numbers::pi * (ri + ro) / 2 / (0.75 * ch))));
  if (n % 2 == 0) ++n;
  for (int k = 0; k <= n; ++k) {
    const double th = std::numbers::pi * k / n;
    const double cs = k == 0 ? 1.0 : k == n ? -1.0 : std::cos(th), sn = (k == 0 || k == n) ? 0.0 : std::sin(th);
    a.inner.push_back(a.centre + Vec2(ri * cs, ri * sn));
    a.outer.push_back(a.centre + Vec2(ro * cs, ro * sn));
  }
  a.first = headCourse;
  a.courses = int(std::ceil((ro + ch / 4) / ch - 1e-9));
  a.lo = mid - ro - bearing;
  a.hi = mid + ro + bearing;
  return a;
}

// The spandrel pieces of the arch's zone in the course [z0, z1] (z from the wall's foot): the
// course's slab within the zone, outside the extrados, cut along each joint's ray; runs of
// neighbouring pieces whose union is convex are joined.
std::vector<Poly2> spandrelPieces(const ArchHead& a, double z0, double z1, double tol) {
  std::vector<Poly2> pieces;
  const std::size_t n = a.outer.size() - 1;
  const double tiny = tol * (a.hi - a.lo + z1 - z0);
  for (std::size_t k = 0; k < n; ++k) {
    Poly2 p = {Vec2(a.lo, z0), Vec2(a.hi, z0), Vec2(a.hi, z1), Vec2(a.lo, z1)};
    const Vec2 d0 = a.outer[k] - a.centre, d1 = a.outer[k + 1] - a.centre, chord = a.outer[k + 1] - a.outer[k];
    p = clipped(p, -leftNormal(d0), -dot(leftNormal(d0), a.centre));  // left of joint k's ray
    p = clipped(p, leftNormal(d1), dot(leftNormal(d1), a.centre));    // right of joint k + 1's
    p = clipped(p, leftNormal(chord), dot(leftNormal(chord), a.outer[k]));  // beyond the extrados
    p = cleaned(p, tol);
    if (p.size() < 3 || signedArea(p) <= tiny) continue;
    if (!pieces.empty()) {
      Poly2 both = pieces.back();
      both.insert(both.end(), p.begin(), p.end());
      const Poly2 h = hullOf(both, tol);
      const double sum = signedArea(pieces.back()) + signedArea(p);
      if (std::abs(signedArea(h) - sum) <= 1e-9 * sum) {
        pieces.back() = h;
        continue;
      }
    }
    pieces.push_back(std::move(p));
  }
  return pieces;
}

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
    if (turn < -1e-9) {
      // A reflex corner: the square between the outer corner P, the inner corner Q and P's feet
      // on the two inner faces is convex, and so is either wall's end with it, while the plan
      // turns by at most a right angle.
      if (dot(in.d, out.d) < -1e-9)
        throw Error("coursing: the plan turns right by more than a right angle at corner " + std::to_string(k) +
                    "; reflex corners are coursed up to 90°");
      in.endSquare = out.startSquare = 0.0;
      in.endCorner = out.startCorner = true;
      in.endReflex = out.startReflex = true;
      in.endKeep = out.startKeep = sliver;
      continue;
    }
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
    in.endKeep = out.startKeep = a;
  }

  // Openings: snapped to courses, checked against their wall and each other.
  struct Placed {
    const WallOpening* o;
    int sill, head;
    std::vector<Cut> headCuts;  // the cuts of the head course, left to right (lintel, flat arch)
    int top = 0;                // the last course its head occupies
    double lo = 0.0, hi = 0.0;  // how far along the face its head reaches
    std::optional<ArchHead> arch;
  };
  std::vector<Placed> placed;
  for (const WallOpening& o : spec.openings) {
    const std::string who = "coursing: opening \"" + o.name + "\"";
    if (o.edge < 0 || std::size_t(o.edge) >= ne) throw Error(who + ": no edge " + std::to_string(o.edge));
    if (!std::isfinite(o.from) || !std::isfinite(o.to) || !(o.to > o.from) || !std::isfinite(o.bottom) ||
        !std::isfinite(o.top) || !(o.top > o.bottom))
      throw Error(who + ": needs from < to and bottom < top");
    Placed p{&o, int(std::lround(o.bottom / ch)), int(std::lround(o.top / ch)), {}, 0, 0.0, 0.0, std::nullopt};
    p.sill = std::max(p.sill, 0);
    if (o.top <= 0) p.sill = p.head = 0;  // below the foot: only its head, in the first course
    else if (p.head <= p.sill) p.head = p.sill + 1;
    if (!o.throughHead && p.head >= courses)
      throw Error(who + ": its head reaches the wall head (no course above it for a lintel or arch)");
    if (o.throughHead) {
      if (p.sill >= courses) throw Error(who + ": it starts above the wall head");
      p.head = courses;  // open to the head; the band above goes on with it
      p.top = courses - 1;
      p.lo = o.from;
      p.hi = o.to;
    } else if (o.head == OpeningHead::SemicircularArch) {
      const double depth = o.archDepth > 0 ? o.archDepth : ch;
      if (!std::isfinite(depth)) throw Error(who + ": the arch's depth is not a number");
      p.arch = archHead(o.from, o.to, p.head * ch, p.head, ch, depth, bearing);
      p.top = p.head + p.arch->courses - 1;
      p.lo = p.arch->lo;
      p.hi = p.arch->hi;
      if (p.top >= courses)
        throw Error(who + ": its semicircular arch rises above the wall head (" + std::to_string(p.arch->courses) +
                    " courses from its springing, " + std::to_string(courses - p.head) + " left)");
    } else if (o.head == OpeningHead::Lintel) {
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
    if (!p.arch && !o.throughHead) {
      p.top = p.head;
      p.lo = p.headCuts.front().lo();
      p.hi = p.headCuts.back().hi();
    }
    const EdgeFrame& f = edges[std::size_t(o.edge)];
    if (p.lo < f.startKeep - tol || p.hi > f.length - f.endKeep + tol)
      throw Error(who + ": the opening and its " + (o.head == OpeningHead::Lintel ? "lintel's bearings" : "arch") +
                  " leave its wall or reach a corner's square");
    for (const Placed& q : placed) {
      if (q.o->edge != o.edge) continue;
      if (p.lo < q.hi && q.lo < p.hi && p.sill <= q.top && q.sill <= p.top)
        throw Error(who + " overlaps opening \"" + q.o->name + "\" (with their heads)");
    }
    placed.push_back(std::move(p));
  }

  // Buttresses: snapped to courses, checked against their wall, each other and the openings.
  struct Pier {
    const WallButtress* b;
    int courses;  // it stands in courses [0, courses)
  };
  std::vector<Pier> piers;
  for (const WallButtress& w : spec.buttresses) {
    const std::string who = "coursing: buttress \"" + w.name + "\"";
    if (w.edge < 0 || std::size_t(w.edge) >= ne) throw Error(who + ": no edge " + std::to_string(w.edge));
    if (!std::isfinite(w.from) || !std::isfinite(w.to) || !(w.to > w.from) || !std::isfinite(w.top) ||
        !std::isfinite(w.depth) || !(w.depth > 0))
      throw Error(who + ": needs from < to, a depth > 0 and a finite top");
    const EdgeFrame& f = edges[std::size_t(w.edge)];
    if (w.from < f.startKeep - tol || w.to > f.length - f.endKeep + tol)
      throw Error(who + ": it leaves its wall or reaches a corner's square");
    const Pier pier{&w, std::clamp(int(std::lround(w.top / ch)), 1, courses)};
    for (const Pier& q : piers)
      if (q.b->edge == w.edge && w.from < q.b->to - tol && q.b->from < w.to - tol)
        throw Error(who + " overlaps buttress \"" + q.b->name + "\"");
    for (const Placed& p : placed)
      if (p.o->edge == w.edge && w.from < p.hi && p.lo < w.to && p.sill < pier.courses)
        throw Error(who + " overlaps opening \"" + p.o->name + "\" (with its head)");
    piers.push_back(pier);
  }

  CoursedWalls out;
  out.courses = courses;
  out.courseHeight = ch;
  for (int c = 0; c < courses; ++c) {
    const double z0 = spec.base + c * ch, z1 = spec.base + (c + 1) * ch;
    const bool odd = (c + spec.firstCourse) % 2 != 0;
    const std::string course = std::to_string(c + spec.firstCourse);
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
        } else if (p.arch && c >= p.head && c <= p.top) {
          // The arch's zone: its voussoirs and spandrel pieces are laid below.
          cuts.push_back({p.lo, p.lo});
          cuts.push_back({p.hi, p.hi});
          spans.push_back({p.lo, p.hi, true});
        } else if (c == p.head) {
          cuts.insert(cuts.end(), p.headCuts.begin(), p.headCuts.end());
          spans.push_back({p.headCuts.front().lo(), p.headCuts.back().hi(), false});
        }
      }
      // Through-stones: the wall behind a buttress is one block with it on even courses, and on
      // the head course over a pier that reaches it.
      auto bonded = [&](const Pier& p) { return !odd || (c == courses - 1 && p.courses == courses); };
      std::vector<const WallButtress*> throughs;
      for (const Pier& p : piers) {
        if (std::size_t(p.b->edge) != e || c >= p.courses || !bonded(p)) continue;
        cuts.push_back({p.b->from, p.b->from});
        cuts.push_back({p.b->to, p.b->to});
        spans.push_back({p.b->from, p.b->to, false});
        throughs.push_back(p.b);
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
            "wall " + std::to_string(e) + " course " + course + " block " + std::to_string(k);
        const int index = int(out.blocks.size());
        const bool first = k == 0, last = k + 2 == cuts.size();
        const bool atStart = first && ownsStart, atEnd = last && ownsEnd;  // the block holds a corner's square
        if (atStart || atEnd) {
          if (atStart && atEnd) throw Error("coursing: wall " + std::to_string(e) + " is one block between two corners");
          // The block holding a corner: between the course's planes, the wall's faces, the
          // other wall's outer face and its joint at the corner square, and the cut on the far
          // side (slanted at an arch's skewback). Convex: a convex plan prism cut by a plane.
          const EdgeFrame& other = atStart ? edges[(e + ne - 1) % ne] : edges[(e + 1) % ne];
          auto horizontal = [](const Vec2& nrm, double d) { return HalfSpace{Vec3(nrm[0], nrm[1], 0.0), d}; };
          std::vector<HalfSpace> hs = {{Vec3(0, 0, -1), -z0}, {Vec3(0, 0, 1), z1},
                                       horizontal(-f.n, -dot(f.n, f.p0)), horizontal(f.n, dot(f.n, f.p0) + t)};
          if (atStart ? f.startReflex : f.endReflex) {
            // A reflex corner P: the square's sides are the other wall's end joint through P
            // (across its face) and its inner face.
            const Vec2 corner = atStart ? f.p0 : other.p0;
            if (atStart)  // (p − P)·d_prev ≥ 0
              hs.push_back(horizontal(-other.d, -dot(other.d, corner)));
            else  // (p − P)·d_next ≤ 0
              hs.push_back(horizontal(other.d, dot(other.d, corner)));
            hs.push_back(horizontal(other.n, dot(other.n, corner) + t));
          } else {
            hs.push_back(horizontal(-other.n, -dot(other.n, other.p0)));
            if (atStart)  // u_prev ≥ L_prev − a
              hs.push_back(horizontal(-other.d, -(dot(other.d, other.p0) + other.length - f.startSquare)));
            else  // u_next ≤ a
              hs.push_back(horizontal(other.d, dot(other.d, other.p0) + f.endSquare));
          }
          // The far cut: u − s·z ≤ c (a start corner) or ≥ c (an end one), u = d·(p − p0), s = (top − bottom) / (z1 − z0).
          const Cut& cut = atStart ? r : l;
          const double slope = (cut.top - cut.bottom) / (z1 - z0), c0 = cut.bottom - slope * z0 + dot(f.d, f.p0);
          const Vec3 along(f.d[0], f.d[1], -slope);
          hs.push_back(atStart ? HalfSpace{along, c0} : HalfSpace{-along, -c0});
          out.blocks.push_back(halfspaceBlock(name, hs, spec.density));
          if (c == courses - 1 && (atStart ? f.startReflex : f.endReflex)) {
            // The square lies beyond both outer faces: the block's head is its own edge's.
            out.heads.push_back(atStart ? HeadSpan{index, int(e), 0.0, r.top} : HeadSpan{index, int(e), l.top, f.length});
          } else if (c == courses - 1) {
            if (atStart) {
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
        const WallButtress* through = nullptr;
        for (const WallButtress* w : throughs)
          if (std::abs(l.bottom - w->from) <= tol && std::abs(r.bottom - w->to) <= tol) through = w;
        const double out0 = through ? -through->depth : 0.0;  // the block's outer face, v
        auto onFace = [&](double u, double z) {
          const Vec2 p = f.at(u, out0);
          return Vec3(p[0], p[1], z);
        };
        const std::vector<Vec3> face = {onFace(l.bottom, z0), onFace(r.bottom, z0), onFace(r.top, z1), onFace(l.top, z1)};
        out.blocks.push_back(prismBlock(through ? name + " through \"" + through->name + "\"" : name, face,
                                        Vec3(f.n[0], f.n[1], 0.0) * (t - out0), spec.density));
        if (c == courses - 1) out.heads.push_back({index, int(e), l.top, r.top});
      }
      // Buttresses on their other courses: a block of their own against the wall's outer face.
      for (const Pier& p : piers) {
        if (std::size_t(p.b->edge) != e || c >= p.courses || bonded(p)) continue;
        const WallButtress& w = *p.b;
        auto outside = [&](double u, double z) {
          const Vec2 q = f.at(u, -w.depth);
          return Vec3(q[0], q[1], z);
        };
        out.blocks.push_back(prismBlock("wall " + std::to_string(e) + " buttress \"" + w.name + "\" course " + course,
                                        {outside(w.from, z0), outside(w.to, z0), outside(w.to, z1), outside(w.from, z1)},
                                        Vec3(f.n[0], f.n[1], 0.0) * w.depth, spec.density));
      }
      // Semicircular arches whose zone this course crosses: the voussoirs (once, in the
      // springing course) and the course's spandrel pieces.
      const Vec3 across(f.n[0] * t, f.n[1] * t, 0.0);
      auto prism = [&](const std::string& name, const Poly2& poly) {
        std::vector<Vec3> face;
        for (const Vec2& q : poly) {
          const Vec2 at = f.at(q[0], 0.0);
          face.emplace_back(at[0], at[1], spec.base + q[1]);
        }
        out.blocks.push_back(prismBlock(name, face, across, spec.density));
      };
      for (const Placed& p : placed) {
        if (std::size_t(p.o->edge) != e || !p.arch || c < p.head || c > p.top) continue;
        const ArchHead& a = *p.arch;
        const std::string prefix = "wall " + std::to_string(e) + " arch \"" + p.o->name + "\" ";
        if (c == p.head)
          for (std::size_t k = 0; k + 1 < a.inner.size(); ++k)
            prism(prefix + "voussoir " + std::to_string(k), {a.inner[k], a.outer[k], a.outer[k + 1], a.inner[k + 1]});
        const std::vector<Poly2> pieces = spandrelPieces(a, c * ch, (c + 1) * ch, tol);
        for (std::size_t k = 0; k < pieces.size(); ++k) {
          const int index = int(out.blocks.size());
          prism(prefix + "course " + course + " spandrel " + std::to_string(k), pieces[k]);
          if (c != courses - 1) continue;
          double lo = std::numeric_limits<double>::infinity(), hi = -lo;
          for (const Vec2& q : pieces[k])
            if (std::abs(q[1] - (c + 1) * ch) <= tol) lo = std::min(lo, q[0]), hi = std::max(hi, q[0]);
          if (hi - lo > tol) out.heads.push_back({index, int(e), lo, hi});
        }
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

void loadWind(const CoursingSpec& spec, CoursedWalls& walls, double pressure, const Vec2& towards) {
  if (!std::isfinite(pressure) || pressure < 0) throw Error("coursing: the wind pressure must be a number ≥ 0");
  if (!(towards.norm() > 0) || !std::isfinite(towards.norm())) throw Error("coursing: the wind has no direction");
  if (pressure == 0) return;
  const Vec2 w = towards / towards.norm();
  const std::size_t np = spec.plan.size(), ne = spec.closed ? np : np - 1;
  BBox box;
  for (const Vec2& p : spec.plan) box.add(Vec3(p[0], p[1], 0.0));
  const double tol = 1e-9 * std::max(1.0, box.diagonal() + spec.height);
  for (std::size_t e = 0; e < ne; ++e) {
    const Vec2 p0 = spec.plan[e], v = spec.plan[(e + 1) % np] - p0;
    const double length = v.norm();
    const Vec2 d = v / length, o = -leftNormal(d);  // the outer face's outward normal
    const double meets = -dot(o, w);
    if (meets <= 1e-12) continue;
    for (Block& b : walls.blocks)
      for (const auto& face : b.faces) {
        // The face in the outer face's coordinates (u along the edge, z up), if it lies there.
        Poly2 poly;
        bool onFace = true;
        for (int i : face) {
          const Vec3& q = b.vertices[std::size_t(i)];
          const Vec2 r = Vec2(q[0], q[1]) - p0;
          onFace = onFace && std::abs(dot(r, o)) <= tol;
          poly.emplace_back(dot(r, d), q[2]);
        }
        if (!onFace || poly.size() < 3) continue;
        std::vector<Vec3> loop;
        for (int i : face) loop.push_back(b.vertices[std::size_t(i)]);
        const Vec3 normal = newellNormal(loop);
        if (!(normal.norm() > 0) || dot(normal.normalized(), Vec3(o[0], o[1], 0.0)) < 1 - 1e-9) continue;
        // Only its part on the edge's stretch (a block holding a reflex corner's square reaches
        // past the face's end along the face's line, behind the other wall).
        poly = clipped(clipped(poly, Vec2(-1.0, 0.0), 0.0), Vec2(1.0, 0.0), length);
        if (poly.size() < 3) continue;
        const double area = std::abs(signedArea(poly));
        if (!(area > tol * tol)) continue;
        // Area centroid by a fan of triangles from the first vertex.
        Vec2 cu(0.0, 0.0);
        double total = 0;
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
          const double a = cross2(poly[k] - poly[0], poly[k + 1] - poly[0]) / 2;
          cu += (poly[0] + poly[k] + poly[k + 1]) * (a / 3);
          total += a;
        }
        cu /= total;
        const Vec2 at = p0 + d * cu[0];
        PointLoad l;
        l.at = Vec3(at[0], at[1], cu[1]);
        l.force = Vec3(-o[0], -o[1], 0.0) * (pressure * area * meets);
        b.pointLoads.push_back(l);
      }
  }
}

}  // namespace corbel::statics
