#include "statics/interfaces.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <tuple>

#include "statics/parallel.h"
#include "statics/tolerances.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace corbel::statics {
namespace {

struct Plane2 {
  Vec3 origin, u, v, n;
  Vec2 to2(const Vec3& p) const { return Vec2(dot(p - origin, u), dot(p - origin, v)); }
  Vec3 to3(const Vec2& q) const { return origin + u * q[0] + v * q[1]; }
};

double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

double signedArea(const std::vector<Vec2>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) s += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5 * s;
}

}  // namespace

// `subject` without repeated points (within `tol`) and without points on the line of their
// neighbours; empty when fewer than 3 are left.
std::vector<Vec2> simplified(std::vector<Vec2> subject, double tol) {
  // Drop repeated and collinear points.
  bool changed = true;
  while (changed && subject.size() >= 3) {
    changed = false;
    for (std::size_t k = 0; k < subject.size() && subject.size() >= 3; ++k) {
      const Vec2 p = subject[(k + subject.size() - 1) % subject.size()], q = subject[k],
                 r = subject[(k + 1) % subject.size()];
      const double pr = (r - p).norm();
      const bool repeated = (q - p).norm() <= tol;
      const bool collinear = pr > tol && std::abs(cross2(r - p, q - p)) / pr <= tol;
      if (repeated || collinear) {
        subject.erase(subject.begin() + long(k));
        changed = true;
        break;
      }
    }
  }
  return subject.size() >= 3 ? subject : std::vector<Vec2>{};
}

std::vector<Vec2> clipConvex(std::vector<Vec2> subject, const std::vector<Vec2>& clip, double tol) {
  for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
    const Vec2 e = b - a;
    const double len = e.norm();
    auto side = [&](const Vec2& p) { return cross2(e, p - a) / len; };  // > 0 inside (left)
    std::vector<Vec2> out;
    for (std::size_t k = 0; k < subject.size(); ++k) {
      const Vec2 p = subject[k], q = subject[(k + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      const bool pin = sp >= -tol, qin = sq >= -tol;
      if (pin) out.push_back(p);
      if (pin != qin && std::abs(sp - sq) > 0) {
        const double t = sp / (sp - sq);
        if (t > 0 && t < 1) out.push_back(p + (q - p) * t);
      }
    }
    subject = std::move(out);
  }
  return simplified(std::move(subject), tol);
}

namespace {

using ExactK = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<ExactK>;

ExactPolygon exactPolygon(const std::vector<Vec2>& p) {
  ExactPolygon out;
  for (const Vec2& q : p) out.push_back(ExactK::Point_2(q[0], q[1]));
  return out;
}

// The intersection of two simple counter-clockwise polygons, either of them non-convex, by
// CGAL's exact Boolean operations: one outer boundary per connected piece (a piece's holes do
// not matter to the contact: forces at its outer vertices span the same convex hull), each
// without repeated or collinear points. Shared edges that floating point left a few ulps
// apart give slivers, which the caller drops by area.
std::vector<std::vector<Vec2>> intersectGeneral(const std::vector<Vec2>& pa, const std::vector<Vec2>& pb, double tol) {
  const ExactPolygon a = exactPolygon(pa), b = exactPolygon(pb);
  std::vector<std::vector<Vec2>> out;
  if (!a.is_simple() || !b.is_simple()) return out;  // validateAssembly refuses such faces first
  std::vector<CGAL::Polygon_with_holes_2<ExactK>> pieces;
  CGAL::intersection(a, b, std::back_inserter(pieces));
  for (const auto& piece : pieces) {
    std::vector<Vec2> poly;
    for (auto v = piece.outer_boundary().vertices_begin(); v != piece.outer_boundary().vertices_end(); ++v)
      poly.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
    poly = simplified(std::move(poly), tol);
    if (!poly.empty()) out.push_back(std::move(poly));
  }
  return out;
}

// The distance between segments pq and rs in the plane.
double segmentDistance2(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  auto toSegment = [](const Vec2& x, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double len2 = d.dot(d);
    const double t = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (x - (a + d * t)).norm();
  };
  const double o1 = cross2(q - p, r - p), o2 = cross2(q - p, s - p), o3 = cross2(s - r, p - r),
               o4 = cross2(s - r, q - r);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return 0.0;
  return std::min({toSegment(p, r, s), toSegment(q, r, s), toSegment(r, p, q), toSegment(s, p, q)});
}

// Whether the boundaries of two polygons come within `tol` of each other.
bool boundariesMeet(const std::vector<Vec2>& pa, const std::vector<Vec2>& pb, double tol) {
  for (std::size_t i = 0; i < pa.size(); ++i)
    for (std::size_t j = 0; j < pb.size(); ++j)
      if (segmentDistance2(pa[i], pa[(i + 1) % pa.size()], pb[j], pb[(j + 1) % pb.size()]) <= tol) return true;
  return false;
}

struct FaceGeom {
  Vec3 n;                 // unit outward normal
  std::vector<Vec3> pts;  // counter-clockwise about n
};

std::vector<FaceGeom> faceGeometry(const Block& b) {
  std::vector<FaceGeom> out;
  for (const auto& f : b.faces) {
    FaceGeom g;
    for (int i : f) g.pts.push_back(b.vertices[i]);
    g.n = newellNormal(g.pts).normalized();
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace

bool boxesTouch(const BBox& a, const BBox& b, double tol) {
  for (int k = 0; k < 3; ++k)
    if (a.lo[k] > b.hi[k] + tol || b.lo[k] > a.hi[k] + tol) return false;
  return true;
}

namespace {
// Assemblies of at least this many blocks look for contacts on two threads, in chunks of
// kSweepChunk blocks of the sweep.
constexpr int kParallelBlocks = 2000;
constexpr int kSweepChunk = 256;
}  // namespace

Contacts findContacts(const Assembly& assembly, const std::vector<BlockProperties>& props, double tolerance,
                      double kernShrink) {
  Contacts result;
  const int nb = int(assembly.blocks.size());
  std::vector<std::vector<FaceGeom>> faces(nb);
  for (int i = 0; i < nb; ++i) faces[i] = faceGeometry(assembly.blocks[i]);
  // Spatial filter: blocks sorted by the low x of their boxes; a sweep keeps only pairs whose
  // boxes overlap (within the tolerance).
  std::vector<int> order(nb);
  for (int i = 0; i < nb; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int x, int y) { return props[x].bounds.lo[0] < props[y].bounds.lo[0]; });
  // The pairs of the sweep's blocks oi, written to `result`; run on two threads for a large
  // assembly (each on its own share of oi), whose findings the sorts below put in one order.
  auto sweep = [&](int oi, Contacts& result) {
    const int i = order[oi];
    for (int oj = oi + 1; oj < nb; ++oj) {
      const int j = order[oj];
      if (props[j].bounds.lo[0] > props[i].bounds.hi[0] + tolerance) break;
      if (assembly.blocks[i].fixed && assembly.blocks[j].fixed) continue;
      if (!boxesTouch(props[i].bounds, props[j].bounds, tolerance)) continue;
      const int a = std::min(i, j), b = std::max(i, j);
      bool touchedWithoutArea = false;
      for (std::size_t ia = 0; ia < faces[a].size(); ++ia) {
        const FaceGeom& fa = faces[a][ia];
        for (std::size_t ib = 0; ib < faces[b].size(); ++ib) {
          const FaceGeom& fb = faces[b][ib];
          if (dot(fa.n, fb.n) > -(1.0 - kOppositeCosine)) continue;
          bool coplanar = true;
          for (const Vec3& q : fb.pts) coplanar = coplanar && std::abs(dot(q - fa.pts[0], fa.n)) <= tolerance;
          if (!coplanar) continue;
          // A frame in a's face plane, u along its first edge.
          Plane2 pl;
          pl.origin = fa.pts[0];
          pl.n = fa.n;
          pl.u = fa.pts[1] - fa.pts[0];
          pl.u -= pl.n * dot(pl.u, pl.n);
          pl.u.normalize();
          pl.v = cross(pl.n, pl.u);
          std::vector<Vec2> pa, pb;
          for (const Vec3& q : fa.pts) pa.push_back(pl.to2(q));
          // b's face runs clockwise about a's normal: reverse it.
          for (auto it = fb.pts.rbegin(); it != fb.pts.rend(); ++it) pb.push_back(pl.to2(*it));
          const double minArea = tolerance * std::max(props[a].bounds.diagonal(), props[b].bounds.diagonal());
          const bool convexPair = props[a].convexFaces[ia] && props[b].convexFaces[ib];
          std::vector<std::vector<Vec2>> pieces;
          if (convexPair) {
            std::vector<Vec2> poly = clipConvex(pa, pb, tolerance);
            if (!poly.empty()) pieces.push_back(std::move(poly));
          } else {
            pieces = intersectGeneral(pa, pb, tolerance);
          }
          bool sliver = false;  // a piece with some area, too little to carry force
          std::erase_if(pieces, [&](const std::vector<Vec2>& q) {
            const double area = signedArea(q);
            sliver = sliver || (area > 0 && area <= minArea);
            return area <= minArea;
          });
          if (pieces.empty()) {
            if (convexPair) {
              // Coplanar faces meeting along an edge or at a point: clip against b's face grown
              // outwards by a few tolerances, so shared edges and corners survive the clip.
              std::vector<Vec2> grown = pb;
              Vec2 c(0.0);
              for (const Vec2& q : pb) c += q;
              c /= double(pb.size());
              for (Vec2& q : grown) {
                const Vec2 d = q - c;
                const double len = d.norm();
                if (len > 0) q += d * (4 * tolerance / len);
              }
              if (sliver || !clipConvex(pa, grown, 0).empty()) touchedWithoutArea = true;
            } else if (sliver || boundariesMeet(pa, pb, 4 * tolerance)) {
              touchedWithoutArea = true;
            }
            continue;
          }
          for (const std::vector<Vec2>& poly : pieces) {
            const double area = signedArea(poly);
            Interface itf;
            itf.a = a;
            itf.b = b;
            itf.faceA = int(ia);
            itf.faceB = int(ib);
            itf.normal = fa.n;
            itf.area = area;
            Vec2 c(0.0);
            for (std::size_t k = 0; k < poly.size(); ++k) {
              const Vec2 p = poly[k], q = poly[(k + 1) % poly.size()];
              c += (p + q) * cross2(p, q);
            }
            c /= 6.0 * area;
            itf.centroid = pl.to3(c);
            for (const Vec2& q : poly) {
              itf.polygon.push_back(pl.to3(q));
              itf.points.push_back(pl.to3(c + (q - c) * (1.0 - kernShrink)));
            }
            itf.t1 = (itf.polygon[1] - itf.polygon[0]).normalized();
            itf.t1 -= itf.normal * dot(itf.t1, itf.normal);
            itf.t1.normalize();
            itf.t2 = cross(itf.normal, itf.t1);
            result.interfaces.push_back(std::move(itf));
          }
        }
      }
      if (touchedWithoutArea) result.zeroArea.push_back({a, b});
    }
  };
  // Two threads by parallel.h's rule; the sweep's rows differ in cost, so they take chunks in
  // turn rather than halves.
  const unsigned threads = twoThreads(nb, 0, kParallelBlocks) ? 2u : 1u;
  if (threads == 1) {
    for (int oi = 0; oi < nb; ++oi) sweep(oi, result);
  } else {
    // Chunks of the sweep handed out in turn; each thread's findings kept apart, then joined.
    std::atomic<int> next{0};
    std::vector<Contacts> found(threads);
    auto work = [&](unsigned t) {
      for (int c; (c = next.fetch_add(kSweepChunk)) < nb;)
        for (int oi = c; oi < std::min(nb, c + kSweepChunk); ++oi) sweep(oi, found[t]);
    };
    std::thread helper(work, 1u);
    work(0);
    helper.join();
    for (Contacts& f : found) {
      for (Interface& itf : f.interfaces) result.interfaces.push_back(std::move(itf));
      result.zeroArea.insert(result.zeroArea.end(), f.zeroArea.begin(), f.zeroArea.end());
    }
  }
  // Stable: the pieces of one pair of non-convex faces keep CGAL's order (one thread finds them).
  std::stable_sort(result.interfaces.begin(), result.interfaces.end(), [](const Interface& x, const Interface& y) {
    return std::tie(x.a, x.b, x.faceA, x.faceB) < std::tie(y.a, y.b, y.faceA, y.faceB);
  });
  std::sort(result.zeroArea.begin(), result.zeroArea.end(),
            [](const ZeroAreaContact& x, const ZeroAreaContact& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  return result;
}

}  // namespace corbel::statics
