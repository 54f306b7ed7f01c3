// geometry.h: triangulatePolygon and newellNormal, checked against the 2D shoelace formula of
// polygons built in a plane's own frame and then placed in tilted planes in space.
#include "core/geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using corbel::Vec2;
using corbel::Vec3;

// Signed shoelace area: positive for counter-clockwise loops.
double shoelace(const std::vector<Vec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

// An orthonormal frame (origin, e1, e2) of a plane; e1 x e2 is its normal.
struct Plane {
  Vec3 origin, e1, e2;
  Vec3 normal() const { return OpenMesh::cross(e1, e2); }
  Vec3 place(const Vec2& q) const { return origin + e1 * q[0] + e2 * q[1]; }
};

// Rotations of the XY frame about two axes: the planes used for every polygon below.
std::vector<Plane> planes() {
  std::vector<Plane> out;
  out.push_back({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});   // XY, normal +Z
  out.push_back({Vec3(3, -2, 5), Vec3(0, 1, 0), Vec3(0, 0, 1)});  // YZ, normal +X
  out.push_back({Vec3(-1, 4, 2), Vec3(0, 0, 1), Vec3(1, 0, 0)});  // ZX, normal +Y
  out.push_back({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0)});  // normal -Z
  for (double tilt : {17.0, 45.0, 73.0, 131.0}) {
    for (double spin : {0.0, 29.0, 200.0}) {
      const double t = tilt * std::numbers::pi / 180, s = spin * std::numbers::pi / 180;
      // Rotate X about Z by spin, then tilt the plane about the rotated X axis.
      const Vec3 e1(std::cos(s), std::sin(s), 0);
      const Vec3 side(-std::sin(s), std::cos(s), 0);
      const Vec3 e2 = side * std::cos(t) + Vec3(0, 0, 1) * std::sin(t);
      out.push_back({Vec3(1.5, -0.25, 7), e1, e2});
    }
  }
  return out;
}

std::vector<Vec3> place(const Plane& pl, const std::vector<Vec2>& poly) {
  std::vector<Vec3> out;
  for (const Vec2& q : poly) out.push_back(pl.place(q));
  return out;
}

std::vector<Vec2> reversed(std::vector<Vec2> p) { return {p.rbegin(), p.rend()}; }

std::vector<Vec2> regular(int n, double r) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

std::vector<Vec2> lShape() { return {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}}; }
std::vector<Vec2> uShape() { return {{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}; }
std::vector<Vec2> comb(int teeth) {
  // A spine (y in [0, 1], x in [0, 2 teeth - 1]) with `teeth` teeth of width 1 reaching y = 4.
  std::vector<Vec2> p{{0, 0}, {2.0 * teeth - 1, 0}};
  for (int t = teeth - 1; t >= 0; --t) {
    p.emplace_back(2.0 * t + 1, 4);
    p.emplace_back(2.0 * t, 4);
    if (t > 0) {
      p.emplace_back(2.0 * t, 1);
      p.emplace_back(2.0 * t - 1, 1);
    }
  }
  return p;
}
// Square with extra points on its sides (colinear with their neighbours).
std::vector<Vec2> squareWithMidpoints() { return {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}; }
// L shape with several colinear points along its long edges and its notch.
std::vector<Vec2> lWithColinear() {
  return {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {3, 1},
          {2, 1}, {1, 1}, {1, 2}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
}
// A triangle whose bottom edge carries many points: every ear but two has a flat corner.
std::vector<Vec2> fan() {
  std::vector<Vec2> p;
  for (int i = 0; i <= 6; ++i) p.emplace_back(i, 0);
  p.emplace_back(3, 2);
  return p;
}
// Random star-shaped polygon: sorted angles, random radii (simple, usually concave).
std::vector<Vec2> star(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(0.3, 2.0);
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.5 * (rng() % 100) / 100.0) / n;
    const double r = radius(rng);
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

// Checks one triangulation: n-2 triangles, all positively oriented about the polygon's normal,
// areas summing to the shoelace area, each boundary edge used once in its own direction and
// each diagonal twice in opposite directions (a proper triangulation of the loop).
void expectValidTriangulation(const std::vector<Vec2>& poly2, const Plane& pl, const std::string& what) {
  SCOPED_TRACE(what);
  const std::vector<Vec3> poly = place(pl, poly2);
  const int n = static_cast<int>(poly.size());
  const double signedArea = shoelace(poly2);
  const double area = std::abs(signedArea);
  const Vec3 unitNormal = pl.normal() * (signedArea > 0 ? 1.0 : -1.0);
  const auto tris = corbel::triangulatePolygon(poly);
  ASSERT_EQ(static_cast<int>(tris.size()), n - 2);
  double sum = 0.0;
  std::map<std::pair<int, int>, int> directed;
  auto uses = [&](int a, int b) {
    auto it = directed.find(std::make_pair(a, b));
    return it == directed.end() ? 0 : it->second;
  };
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(t[k], 0);
      ASSERT_LT(t[k], n);
    }
    const Vec3 c = OpenMesh::cross(poly[t[1]] - poly[t[0]], poly[t[2]] - poly[t[0]]);
    const double orient = OpenMesh::dot(c, unitNormal);
    EXPECT_GT(orient, 1e-9 * area) << "triangle " << t[0] << "," << t[1] << "," << t[2] << " is not positive";
    sum += 0.5 * c.norm();
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  EXPECT_NEAR(sum, area, 1e-12 * area);
  // The loop runs counter-clockwise about its own normal, so each boundary edge i -> i+1 is
  // used once in that direction by a positively oriented triangle.
  for (int i = 0; i < n; ++i) {
    const int a = i, b = (i + 1) % n;
    EXPECT_EQ(uses(a, b), 1) << "boundary edge " << a << "->" << b;
    EXPECT_EQ(uses(b, a), 0) << "boundary edge " << b << "->" << a << " used backwards";
  }
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << "directed edge " << e.first << "->" << e.second << " used " << count << " times";
    const bool boundary = (e.second == (e.first + 1) % n) || (e.first == (e.second + 1) % n);
    if (!boundary) {
      EXPECT_EQ(uses(e.second, e.first), 1) << "diagonal " << e.first << "-" << e.second << " without its twin";
    }
  }
}

void checkAllPlanes(const std::vector<Vec2>& poly, const std::string& name) {
  const auto pls = planes();
  for (std::size_t i = 0; i < pls.size(); ++i) {
    expectValidTriangulation(poly, pls[i], name + " in plane " + std::to_string(i));
    expectValidTriangulation(reversed(poly), pls[i], name + " (clockwise) in plane " + std::to_string(i));
  }
}

TEST(Geometry, ShoelaceOracleSanity) {
  // The oracle itself on hand-computed cases.
  EXPECT_DOUBLE_EQ(shoelace({{0, 0}, {2, 0}, {2, 3}, {0, 3}}), 6.0);
  EXPECT_DOUBLE_EQ(shoelace(lShape()), 4.0 + 2.0);
  EXPECT_DOUBLE_EQ(shoelace(uShape()), 20.0 - 9.0);
  EXPECT_DOUBLE_EQ(shoelace(reversed(lShape())), -6.0);
  EXPECT_DOUBLE_EQ(shoelace(comb(4)), 7.0 * 1.0 + 4 * 3.0);
}

TEST(Geometry, TriangulatesConvexPolygons) {
  checkAllPlanes({{0, 0}, {1, 0}, {0, 1}}, "triangle");
  checkAllPlanes({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, "rectangle");
  for (int n : {5, 6, 7, 12, 40}) checkAllPlanes(regular(n, 2.5), "regular " + std::to_string(n) + "-gon");
}

TEST(Geometry, TriangulatesConcavePolygons) {
  checkAllPlanes(lShape(), "L");
  checkAllPlanes(uShape(), "U");
  for (int teeth : {2, 3, 6}) checkAllPlanes(comb(teeth), "comb " + std::to_string(teeth));
  std::mt19937 rng(1234);
  for (int i = 0; i < 20; ++i) checkAllPlanes(star(rng, 5 + i), "star " + std::to_string(i));
}

TEST(Geometry, TriangulatesPolygonsWithColinearPoints) {
  checkAllPlanes(squareWithMidpoints(), "square with midpoints");
  checkAllPlanes(lWithColinear(), "L with colinear points");
  checkAllPlanes(fan(), "triangle with points on one side");
}

// A quad whose fourth corner D lies 4.5e-7 m from the diagonal AC, 1e-7 of its size, and off
// the plane of A, B, C by as much (as a modeller's faces are planar only to rounding; the
// extrusion's random6505 made one on a 43 m hip): of its two triangulations, the one cutting AC
// leaves a sliver ACD that folds out of the face, whatever corner the loop starts at. The other,
// cutting BD, has no corner nearer than 1 m to a side.
TEST(Geometry, TriangulationCutsNoSliverWhereAnotherEarIsLeft) {
  const Vec3 A(0, 0, 0), B(20, 0, 0), C(20, 20, 0), D(10, 10 + 4.5e-7, 4.5e-7);
  const std::vector<Vec3> quad{A, B, C, D};
  for (int start = 0; start < 4; ++start) {
    std::vector<Vec3> poly;
    std::vector<int> index;  // of quad
    for (int k = 0; k < 4; ++k) {
      poly.push_back(quad[(start + k) % 4]);
      index.push_back((start + k) % 4);
    }
    const auto tris = corbel::triangulatePolygon(poly);
    ASSERT_EQ(tris.size(), 2u);
    for (const auto& t : tris) {
      std::set<int> corners{index[t[0]], index[t[1]], index[t[2]]};
      EXPECT_TRUE(corners.count(1) && corners.count(3)) << "start " << start << ": the cut is not BD";
    }
  }
}

double distanceToSegment(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(OpenMesh::dot(q - a, ab) / OpenMesh::dot(ab, ab), 0.0, 1.0);
  return (q - (a + ab * t)).norm();
}

// A notch whose reflex corner lies 1e-13 m beyond the cut of the first convex corner's ear: in
// exact arithmetic that ear holds no corner, but its cut passes within rounding of the notch,
// and in space (a face planar only to rounding) such a sliver crosses the faces meeting there.
// The triangles must tile the polygon (their areas add up to the shoelace area) and no cut may
// pass within the slack (1e-7 of the polygon's size, 2.83 m) of a corner it does not end at: the
// fan from the notch does that.
TEST(Geometry, NoCutPassesWithinTheSlackOfAnotherCorner) {
  const std::vector<Vec3> pts{{0, -1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1e-13, 0}, {-1, 1, 0}, {-1, 0, 0}};
  const auto tris = corbel::triangulatePolygon(pts);
  std::vector<Vec2> flat;
  for (const Vec3& p : pts) flat.emplace_back(p[0], p[1]);
  double sum = 0;
  for (const auto& t : tris) {
    const double area = 0.5 * OpenMesh::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]])[2];
    EXPECT_GT(area, 0.0);
    sum += area;
    for (int k = 0; k < 3; ++k)
      for (int q = 0; q < static_cast<int>(pts.size()); ++q) {
        const int a = t[k], b = t[(k + 1) % 3];
        if (q == t[0] || q == t[1] || q == t[2]) continue;
        EXPECT_GT(distanceToSegment(pts[q], pts[a], pts[b]), 1e-7 * std::sqrt(8.0))
            << "the cut " << a << "-" << b << " passes corner " << q;
      }
  }
  EXPECT_EQ(tris.size(), 4u);
  EXPECT_NEAR(sum, shoelace(flat), 1e-12);
}

// Whether q lies inside the circle through a, b, c by more than `margin` of its radius: the
// circle's centre from the two perpendicular bisectors (Cramer's rule), its radius from a.
bool insideCircumcircle(const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c, double margin) {
  const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const double d = 2 * (bx * cy - by * cx);
  const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
  const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
  const double r = std::hypot(ux, uy);
  return std::hypot(q[0] - a[0] - ux, q[1] - a[1] - uy) < r * (1 - margin);
}

// The triangles of `poly2` placed in plane `pl`, as index triples into poly2.
std::vector<std::array<int, 3>> cut(const std::vector<Vec2>& poly2, const Plane& pl) {
  return corbel::triangulatePolygon(place(pl, poly2));
}

// Points at sorted random angles on an ellipse: a convex polygon with no four corners on one
// circle, so its Delaunay triangulation is unique.
std::vector<Vec2> ellipse(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::vector<double> a(n);
  for (double& x : a) x = angle(rng);
  std::sort(a.begin(), a.end());
  std::vector<Vec2> p;
  for (double x : a) p.emplace_back(3.0 * std::cos(x), 1.2 * std::sin(x));
  return p;
}

// An ear cut alone leaves fans of slivers (on a convex polygon, every ear from one end); the
// cut is the Delaunay triangulation, whose defining property is checked directly: no corner of
// the polygon lies inside any triangle's circumcircle (Delaunay 1934). Each polygon is cut in
// every plane, both ways round, so no start corner or projection favours it.
TEST(Geometry, TheCutOfAConvexPolygonIsDelaunay) {
  std::mt19937 rng(77);
  for (int n : {5, 8, 13, 24, 40}) {
    const std::vector<Vec2> poly = ellipse(rng, n);
    const auto pls = planes();
    for (std::size_t i = 0; i < pls.size(); ++i)
      for (const auto& p : {poly, reversed(poly)}) {
        SCOPED_TRACE(std::to_string(n) + " corners in plane " + std::to_string(i));
        const Plane& pl = pls[i];
        for (const auto& t : cut(p, pl))
          for (int q = 0; q < n; ++q) {
            if (q == t[0] || q == t[1] || q == t[2]) continue;
            EXPECT_FALSE(insideCircumcircle(p[q], p[t[0]], p[t[1]], p[t[2]], 1e-9))
                << "corner " << q << " lies inside the circle of " << t[0] << "," << t[1] << "," << t[2];
          }
      }
  }
}

// On a polygon that is not convex, the constrained Delaunay triangulation is the one whose every
// diagonal is locally Delaunay: the far corner of the triangle on one side lies outside the
// circumcircle of the triangle on the other (Lee & Lin 1986; Chew 1989).
TEST(Geometry, TheCutOfAConcavePolygonIsConstrainedDelaunay) {
  std::vector<std::pair<std::string, std::vector<Vec2>>> shapes{
      {"L", lShape()}, {"U", uShape()}, {"comb", comb(4)}, {"L with colinear points", lWithColinear()}};
  std::mt19937 rng(4321);
  for (int i = 0; i < 12; ++i) shapes.push_back({"star " + std::to_string(i), star(rng, 6 + 3 * i)});
  for (const auto& [name, shape] : shapes)
    for (const auto& pl : planes())
      for (const auto& p : {shape, reversed(shape)}) {
        SCOPED_TRACE(name);
        const auto tris = cut(p, pl);
        std::map<std::pair<int, int>, int> third;  // directed edge -> the corner opposite it
        for (const auto& t : tris)
          for (int k = 0; k < 3; ++k) third[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
        for (const auto& t : tris)
          for (int k = 0; k < 3; ++k) {
            const auto twin = third.find({t[(k + 1) % 3], t[k]});
            if (twin == third.end()) continue;  // a side of the polygon
            EXPECT_FALSE(insideCircumcircle(p[twin->second], p[t[0]], p[t[1]], p[t[2]], 1e-9))
                << "diagonal " << t[k] << "-" << t[(k + 1) % 3] << " is not locally Delaunay";
          }
      }
}

TEST(Geometry, TriangulationOfFewerThanThreePointsIsEmpty) {
  EXPECT_TRUE(corbel::triangulatePolygon({}).empty());
  EXPECT_TRUE(corbel::triangulatePolygon({Vec3(0, 0, 0), Vec3(1, 0, 0)}).empty());
}

TEST(Geometry, NewellNormalIsTwiceTheAreaTimesTheUnitNormal) {
  const std::vector<std::pair<std::string, std::vector<Vec2>>> shapes = {
      {"rectangle", {{0, 0}, {3, 0}, {3, 2}, {0, 2}}},
      {"L", lShape()},
      {"U", uShape()},
      {"comb", comb(5)},
      {"square with midpoints", squareWithMidpoints()},
      {"hexagon", regular(6, 1.7)}};
  for (const auto& pl : planes()) {
    for (const auto& [name, shape] : shapes) {
      for (const auto& poly2 : {shape, reversed(shape)}) {
        SCOPED_TRACE(name);
        const Vec3 n = corbel::newellNormal(place(pl, poly2));
        const Vec3 expected = pl.normal() * (2.0 * shoelace(poly2));
        const double scale = 2.0 * std::abs(shoelace(poly2));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(n[k], expected[k], 1e-12 * scale * 10) << "component " << k;
      }
    }
  }
}

TEST(Geometry, NewellNormalOfAxisAlignedSquareByHand) {
  // Unit square in the plane x = 2, counter-clockwise seen from +X: normal (2*1, 0, 0).
  const Vec3 n = corbel::newellNormal({Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(2, 1, 1), Vec3(2, 0, 1)});
  EXPECT_DOUBLE_EQ(n[0], 2.0);
  EXPECT_DOUBLE_EQ(n[1], 0.0);
  EXPECT_DOUBLE_EQ(n[2], 0.0);
}

TEST(Geometry, BBoxAccumulates) {
  corbel::BBox b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.diagonal(), 0.0);
  b.add(Vec3(1, -2, 3));
  b.add(Vec3(-1, 2, 0));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.lo, Vec3(-1, -2, 0));
  EXPECT_EQ(b.hi, Vec3(1, 2, 3));
  EXPECT_EQ(b.center(), Vec3(0, 0, 1.5));
  EXPECT_DOUBLE_EQ(b.diagonal(), std::sqrt(4.0 + 16.0 + 9.0));
  corbel::BBox c;
  c.add(corbel::BBox{});  // adding an empty box changes nothing
  EXPECT_TRUE(c.empty());
  c.add(b);
  EXPECT_EQ(c.lo, b.lo);
  EXPECT_EQ(c.hi, b.hi);
}

}  // namespace
