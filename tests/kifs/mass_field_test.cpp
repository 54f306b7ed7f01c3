// The baked distance to a mass object's shell (kifs/mass_field.h): CGAL's exact signed distance
// is the oracle (itself checked against the box's closed form); the bake must stay below it
// everywhere sampled and within one cell diagonal of it inside the grid.
#include "kifs/mass_field.h"

#include "core/error.h"
#include "core/project_io.h"
#include "extrude/extrude.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace corbel::kifs {
namespace {

// An axis-aligned box as a kernel soup: six quads, counter-clockwise seen from outside.
MeshData boxSoup(const glm::dvec3& lo, const glm::dvec3& hi) {
  MeshData m;
  for (int c = 0; c < 8; ++c) m.addPoint(Vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z));
  m.addFace({0, 2, 3, 1});  // bottom (−z)
  m.addFace({4, 5, 7, 6});  // top
  m.addFace({0, 1, 5, 4});  // −y
  m.addFace({2, 6, 7, 3});  // +y
  m.addFace({0, 4, 6, 2});  // −x
  m.addFace({1, 3, 7, 5});  // +x
  return m;
}

double boxDistance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  const glm::dvec3 c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
  const glm::dvec3 q = glm::abs(p - c) - h;
  return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

// The first extrusion of an example project, its shell alone (no feature meshes).
MeshData exampleShell(const std::string& file) {
  const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + file).document;
  for (const DocObject& o : d.objects)
    if (const auto* spec = std::get_if<ExtrusionSpec>(&o.spec)) {
      const extrude::ExtrusionResult r = extrude::extrude(*spec);
      return extrude::toMeshData(r.shell, *spec, "plaster");
    }
  ADD_FAILURE() << file << " has no extrusion";
  return {};
}

// Points where the bake is tested: uniform over the grid grown by a fifth each way (so some lie
// outside it), and as many within two cells of the surface (random points of random triangles,
// moved along a random direction), where the sign changes and interpolation errs most.
std::vector<glm::dvec3> samplePoints(const TriangleSoup& tris, const MassField& f, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Aabb g = f.grid();
  const glm::dvec3 grow = 0.2 * g.size();
  std::vector<glm::dvec3> out;
  for (int i = 0; i < n; ++i) out.push_back(test::uniformIn(rng, g.lo - grow, g.hi + grow));
  std::uniform_int_distribution<std::size_t> pick(0, tris.triangles.size() - 1);
  for (int i = 0; i < n; ++i) {
    const auto t = tris.corners(pick(rng));
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    out.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]) + 2.0 * f.cell * u(rng) * test::unitVector(rng));
  }
  return out;
}

struct Shape {
  std::string name;
  MeshData soup;
};

std::vector<Shape> shapes() {
  return {{"box", boxSoup({-3, 1, 0}, {7, 7, 4})},
          {"hip-roofed house (stone-house.corbel)", exampleShell("stone-house.corbel")},
          {"Fig. 1 house (house.corbel)", exampleShell("house.corbel")}};
}

TEST(MassField, ExactDistanceIsTheBoxClosedForm) {
  const glm::dvec3 lo(-3, 1, 0), hi(7, 7, 4);
  const ShellDistance exact(trianglesOf(boxSoup(lo, hi)));
  std::mt19937_64 rng(7);
  for (int i = 0; i < 3000; ++i) {
    const glm::dvec3 p = test::uniformIn(rng, lo - 5.0, hi + 5.0);
    EXPECT_NEAR(exact.signedDistance(p), boxDistance(p, lo, hi), 1e-9) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(MassField, BakeIsALowerBoundWithinOneCellDiagonal) {
  for (const Shape& s : shapes()) {
    SCOPED_TRACE(s.name);
    const TriangleSoup tris = trianglesOf(s.soup);
    const ShellDistance exact(tris);
    for (int resolution : {16, 40}) {
      SCOPED_TRACE(resolution);
      const MassField f = bakeMassField(exact, resolution);
      const double diagonal = std::sqrt(3.0) * f.cell;
      EXPECT_NEAR(f.lowered, 0.5 * diagonal, 1e-12);
      int inside = 0, within = 0, outsideGrid = 0;
      for (const glm::dvec3& p : samplePoints(tris, f, 2000, 11 + resolution)) {
        const double e = exact.signedDistance(p), b = f.distance(p);
        // Lower bound: the samples were lowered and rounded down, so only the double
        // interpolation's rounding (≈ 1e-15 of the values) could push b above e.
        ASSERT_LE(b, e + 1e-12 * (1 + std::abs(e))) << p.x << " " << p.y << " " << p.z;
        const Aabb g = f.grid();
        if (glm::all(glm::greaterThanEqual(p, g.lo)) && glm::all(glm::lessThanEqual(p, g.hi))) {
          // Within one diagonal: half for the interpolation, half for the lowering, plus the
          // samples' rounding to float (one float ulp, 2⁻²³ of a value no larger than |e| + diagonal).
          EXPECT_GE(b, e - diagonal - std::ldexp(std::abs(e) + diagonal, -22)) << p.x << " " << p.y << " " << p.z;
          ++within;
        } else {
          ++outsideGrid;
        }
        if (e < 0) ++inside;
      }
      EXPECT_GT(inside, 300);  // the samples reach inside the solid and out of the grid
      EXPECT_GT(outsideGrid, 300);
      EXPECT_GT(within, 2000);
    }
  }
}

// The lowering is needed: without it the interpolated samples overshoot the exact distance
// somewhere (near the shell's edges and corners, where the distance bends).
TEST(MassField, UnloweredSamplesOvershoot) {
  for (const Shape& s : shapes()) {
    SCOPED_TRACE(s.name);
    const TriangleSoup tris = trianglesOf(s.soup);
    const ShellDistance exact(tris);
    MassField f = bakeMassField(exact, 16);
    for (float& v : f.values) v += static_cast<float>(f.lowered);
    int over = 0;
    for (const glm::dvec3& p : samplePoints(tris, f, 2000, 5))
      if (f.distance(p) > exact.signedDistance(p) + 1e-3 * f.cell) ++over;
    EXPECT_GT(over, 10);
  }
}

TEST(MassField, OpenShellIsRefused) {
  MeshData box = boxSoup({0, 0, 0}, {1, 1, 1});
  box.faces.pop_back();  // the +x side
  box.faceTag.pop_back();
  box.faceMaterial.pop_back();
  try {
    ShellDistance d(trianglesOf(box));
    FAIL() << "an open box was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not closed (4 open edges)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ShellDistance(TriangleSoup{}), Error);
}

TEST(MassField, ResolutionOutOfRangeIsNamed) {
  const ShellDistance d(trianglesOf(boxSoup({0, 0, 0}, {1, 1, 1})));
  for (int r : {0, -3, kMaxMassResolution + 1}) {
    try {
      bakeMassField(d, r);
      FAIL() << r;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("kifs.mass.resolution"), std::string::npos) << e.what();
    }
  }
}

// Parts of a shell: a point is inside when it is inside any part (the parity of one ray over all
// of them would call a point inside two overlapping parts outside, as in a chimney in a roof).
TEST(MassField, OverlappingPartsAreOneSolid) {
  MeshData soup = boxSoup({0, 0, 0}, {4, 4, 4});
  soup.append(boxSoup({1, 1, 1}, {2, 2, 6}));  // pokes out of the top
  soup.append(boxSoup({3, 3, 4}, {4, 4, 5}));  // stands on the top at a corner: shares coordinates, not corners
  const ShellDistance d(trianglesOf(soup));
  EXPECT_LT(d.signedDistance({3.5, 3.5, 4.5}), 0.0);
  EXPECT_LT(d.signedDistance({1.5, 1.5, 1.5}), 0.0);  // inside both: parity would call it outside
  EXPECT_LT(d.signedDistance({1.5, 1.5, 5.0}), 0.0);  // the part above the big box
  EXPECT_NEAR(d.signedDistance({1.5, 1.5, 7.0}), 1.0, 1e-12);
  EXPECT_NEAR(d.signedDistance({6.0, 2.0, 2.0}), 2.0, 1e-12);
}

}  // namespace
}  // namespace corbel::kifs
