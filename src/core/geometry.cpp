#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace corbel {

Vec3 newellNormal(const std::vector<Vec3>& polygon) {
  Vec3 n(0.0);
  const size_t count = polygon.size();
  for (size_t i = 0; i < count; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % count];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

namespace {

// Project onto the plane most aligned with the normal; returns 2D coordinates whose
// orientation is counter-clockwise when seen against the normal.
std::vector<Vec2> projectToPlane(const std::vector<Vec3>& polygon, const Vec3& normal) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const double flip = normal[axis] < 0 ? -1.0 : 1.0;
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  for (const Vec3& p : polygon) out.emplace_back(p[u], flip * p[v]);
  return out;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Points on the triangle's border (within eps) count as inside: they block the ear.
bool insideTriangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, double eps) {
  return cross(a, b, p) >= -eps && cross(b, c, p) >= -eps && cross(c, a, p) >= -eps;
}

// Whether corner q of the polygon lies within `slack` of the segment from corner a to corner b,
// in space.
bool withinOfSegment(const std::vector<Vec3>& polygon, int q, int a, int b, double slack) {
  const Vec3 ab = polygon[b] - polygon[a], aq = polygon[q] - polygon[a];
  const double len2 = ab.sqrnorm();
  const double t = len2 > 0 ? std::clamp(OpenMesh::dot(aq, ab) / len2, 0.0, 1.0) : 0.0;
  return (aq - ab * t).sqrnorm() <= slack * slack;
}

// The polygon in an orthonormal frame of its own plane (from its first corner), counter-clockwise
// about its normal: lengths and angles as in space, which the projection onto an axis plane
// squeezes along a steep face's slope.
std::vector<Vec2> inOwnPlane(const std::vector<Vec3>& polygon) {
  Vec3 normal = newellNormal(polygon);
  const double length = normal.norm();
  if (length > 0) normal /= length;
  int axis = 0;  // the axis least along the normal
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) < std::abs(normal[axis])) axis = k;
  Vec3 e1(0.0);
  e1[axis] = 1.0;
  e1 = OpenMesh::cross(normal, e1);
  if (e1.norm() > 0) e1.normalize();
  const Vec3 e2 = OpenMesh::cross(normal, e1);
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  for (const Vec3& p : polygon) out.emplace_back(OpenMesh::dot(p - polygon[0], e1), OpenMesh::dot(p - polygon[0], e2));
  return out;
}

// Lawson's flips turn a triangulation of the polygon into its constrained Delaunay
// triangulation: a diagonal whose two facing angles add up past pi (the far corner of one
// triangle lies inside the other's circumcircle) is swapped for the other diagonal of its quad.
// Ear cuts leave fans of slivers; Delaunay's triangles keep their cuts away from corners, so a
// polygon planar only to rounding folds less. A flip never makes a cut within `slack` of a corner
// nor a triangle turning by no more than `eps`; angles within 1e-10 rad of pi (corners on one
// circle, as round a regular polygon) never flip, and the flips stop after 16 per corner.
void flipToDelaunay(const std::vector<Vec3>& polygon, std::vector<std::array<int, 3>>& tris, double eps, double slack) {
  const int count = static_cast<int>(tris.size());
  if (count < 2) return;
  const std::vector<Vec2> own = inOwnPlane(polygon);
  // next[t][k]: the triangle across edge k of t (from corner k to corner k + 1), -1 on a side.
  std::vector<std::array<int, 3>> next(count, {-1, -1, -1});
  {
    struct Side {
      int lo, hi, t, k;
    };
    std::vector<Side> sides;
    sides.reserve(3 * count);
    for (int t = 0; t < count; ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = tris[t][k], b = tris[t][(k + 1) % 3];
        sides.push_back({std::min(a, b), std::max(a, b), t, k});
      }
    std::sort(sides.begin(), sides.end(),
              [](const Side& x, const Side& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
    for (std::size_t i = 0; i + 1 < sides.size(); ++i)
      if (sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi) {
        next[sides[i].t][sides[i].k] = sides[i + 1].t;
        next[sides[i + 1].t][sides[i + 1].k] = sides[i].t;
      }
  }
  auto edgeOf = [&](int t, int a, int b) {  // k where t runs a -> b, or -1
    for (int k = 0; k < 3; ++k)
      if (tris[t][k] == a && tris[t][(k + 1) % 3] == b) return k;
    return -1;
  };
  auto repoint = [&](int t, int from, int to) {  // t's neighbour `from` is `to` now
    if (t < 0) return;
    for (int k = 0; k < 3; ++k)
      if (next[t][k] == from) next[t][k] = to;
  };
  struct Pending {
    int t, a, b;
  };
  std::vector<Pending> pending;  // diagonals to check, each with a triangle running it
  for (int t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k)
      if (next[t][k] > t) pending.push_back({t, tris[t][k], tris[t][(k + 1) % 3]});
  std::size_t budget = 16 * polygon.size() + 64;
  while (!pending.empty() && budget > 0) {
    const auto [t, a, b] = pending.back();
    pending.pop_back();
    const int k = edgeOf(t, a, b);
    if (k < 0 || next[t][k] < 0) continue;  // flipped away since, or a side
    const int u = next[t][k], l = edgeOf(u, b, a);
    if (l < 0) continue;
    // t runs a, b, c and u runs b, a, d counter-clockwise: the quad is a, d, b, c.
    const int c = tris[t][(k + 2) % 3], d = tris[u][(l + 2) % 3];
    // The angles at c and d facing ab add up past pi where sin of their sum is negative:
    // sin(γ + δ) |ca| |cb| |da| |db| = cross_c dot_d + dot_c cross_d. Within 1e-10 stays.
    const Vec2 ca = own[a] - own[c], cb = own[b] - own[c], db = own[b] - own[d], da = own[a] - own[d];
    const double crossC = ca[0] * cb[1] - ca[1] * cb[0], dotC = ca[0] * cb[0] + ca[1] * cb[1];
    const double crossD = db[0] * da[1] - db[1] * da[0], dotD = db[0] * da[0] + db[1] * da[1];
    const double sine = crossC * dotD + dotC * crossD;
    if (sine >= 0 || sine * sine <= 1e-20 * ca.sqrnorm() * cb.sqrnorm() * da.sqrnorm() * db.sqrnorm()) continue;
    if (cross(own[c], own[a], own[d]) <= eps || cross(own[d], own[b], own[c]) <= eps) continue;
    if (withinOfSegment(polygon, a, c, d, slack) || withinOfSegment(polygon, b, c, d, slack)) continue;
    --budget;
    const int nbc = next[t][(k + 1) % 3], nca = next[t][(k + 2) % 3];
    const int nad = next[u][(l + 1) % 3], ndb = next[u][(l + 2) % 3];
    tris[t] = {c, a, d};
    next[t] = {nca, nad, u};
    tris[u] = {d, b, c};
    next[u] = {ndb, nbc, t};
    repoint(nad, u, t);
    repoint(nbc, t, u);
    pending.push_back({t, a, d});
    pending.push_back({u, d, b});
    pending.push_back({u, b, c});
    pending.push_back({t, c, a});
  }
}

}  // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec3>& polygon) {
  std::vector<std::array<int, 3>> tris;
  const int n = static_cast<int>(polygon.size());
  if (n < 3) return tris;
  tris.reserve(n - 2);
  if (n == 3) {
    tris.push_back({0, 1, 2});
    return tris;
  }
  const std::vector<Vec2> pts = projectToPlane(polygon, newellNormal(polygon));
  // Colinear corners of a polygon in a tilted plane come out a rounding error away from
  // flat; where no clean ear is left, turns within eps count as flat (never ears).
  double extent = 0.0, reach = 0.0;
  BBox box;
  {
    Vec2 lo = pts[0], hi = pts[0];
    for (const Vec2& p : pts) {
      lo.minimize(p);
      hi.maximize(p);
      reach = std::max({reach, std::abs(p[0]), std::abs(p[1])});
    }
    extent = (hi - lo).norm();
    for (const Vec3& p : polygon) box.add(p);
  }
  const double eps = 1e-12 * extent * std::max(extent, reach);
  // A modeller's polygon is planar only to its own rounding (the extrusion kernel merges
  // vertices up to 5e-8 of the plan's size apart), so a cut passing within `slack` of a corner,
  // in space, or an ear at a corner that close to its cut, leaves a sliver that can fold across
  // the faces that meet there. (Not scaled by the coordinates' size: a face cuts the same
  // wherever it is placed.)
  const double slack = 1e-7 * box.diagonal();
  auto nearSegment = [&](int q, int a, int b) { return withinOfSegment(polygon, q, a, b, slack); };
  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i) ring[i] = i;
  // The first ear of the ring (-1: none). A clean ear (`strict`) turns left however little, and
  // neither its corner nor any other lies within the slack of its cut; otherwise an ear is any
  // corner turning left by more than eps whose triangle holds no other corner.
  auto findEar = [&](bool strict) {
    const int m = static_cast<int>(ring.size());
    const double e = strict ? 0.0 : eps;
    for (int i = 0; i < m; ++i) {
      const int ia = ring[(i + m - 1) % m], ib = ring[i], ic = ring[(i + 1) % m];
      const double turn = cross(pts[ia], pts[ib], pts[ic]);
      if (turn <= e) continue;  // reflex or flat corner: not an ear
      if (strict && nearSegment(ib, ia, ic)) continue;
      bool empty = true;
      for (int j = 0; j < m && empty; ++j) {
        const int q = ring[j];
        if (q == ia || q == ib || q == ic) continue;
        if (insideTriangle(pts[q], pts[ia], pts[ib], pts[ic], e) || (strict && nearSegment(q, ia, ic))) empty = false;
      }
      if (empty) return i;
    }
    return -1;
  };
  while (ring.size() > 3) {
    const int m = static_cast<int>(ring.size());
    int best = findEar(true);
    if (best < 0) best = findEar(false);
    if (best < 0) {
      // No ear at all (degenerate input): clip the convex-most corner so we still terminate.
      double most = -std::numeric_limits<double>::infinity();
      for (int i = 0; i < m; ++i) {
        const double turn = cross(pts[ring[(i + m - 1) % m]], pts[ring[i]], pts[ring[(i + 1) % m]]);
        if (turn > most) {
          most = turn;
          best = i;
        }
      }
    }
    tris.push_back({ring[(best + m - 1) % m], ring[best], ring[(best + 1) % m]});
    ring.erase(ring.begin() + best);
  }
  tris.push_back({ring[0], ring[1], ring[2]});
  flipToDelaunay(polygon, tris, eps, slack);
  return tris;
}

}  // namespace corbel
