// Specifications of kifs/trace.h: pixel rays go through their pixel centres, the sphere tracer
// never passes through solid that a dense march finds (with and without over-relaxation),
// misses the bounds box without evaluating anything, and normals are the gradient.
#include "kifs/trace.h"
#include "test_support.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace corbel::kifs::test {
namespace {

struct View {
  glm::dvec3 eye;
  glm::dmat4 viewProj, inverse;
};

// A camera looking at the building's box from azimuth `az` (degrees) and 25° above.
View viewOf(const Building& b, double az, double fovDeg = 40.0) {
  const Aabb box = b.worldBounds();
  const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
  const double dist = 1.6 * glm::length(box.size());
  const double a = glm::radians(az), e = glm::radians(25.0);
  View v;
  v.eye = centre + dist * glm::dvec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  v.viewProj = glm::perspective(glm::radians(fovDeg), 1.0, 0.01 * dist, 20 * dist) *
               glm::lookAt(v.eye, centre, glm::dvec3(0, 0, 1));
  v.inverse = glm::inverse(v.viewProj);
  return v;
}

TEST(KifsTrace, PixelRaysPassThroughPixelCentres) {
  const Building b(preset("box"));
  const View v = viewOf(b, -60);
  const int w = 7, h = 5;
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      const Ray r = pixelRay(v.inverse, v.eye, px, py, w, h);
      EXPECT_NEAR(glm::length(r.dir), 1.0, 1e-12);
      for (double t : {5.0, 50.0}) {
        const glm::dvec4 clip = v.viewProj * glm::dvec4(r.origin + t * r.dir, 1.0);
        EXPECT_NEAR((clip.x / clip.w + 1) * 0.5 * w, px + 0.5, 1e-9);
        EXPECT_NEAR((clip.y / clip.w + 1) * 0.5 * h, py + 0.5, 1e-9);
      }
    }
}

// The first solid point along the ray by a uniform march of step `dt` (an independent oracle);
// negative when there is none inside the bounds box.
double denseFirstSolid(const Building& b, const Ray& r, double dt) {
  double t0 = 0, t1 = 0;
  if (!rayBox(r, b.worldBounds(), t0, t1)) return -1;
  for (double t = std::max(t0, 0.0); t <= t1; t += dt)
    if (b.evaluate(r.origin + t * r.dir).surface <= 0) return t;
  return -1;
}

// Sphere tracing never steps over solid: where the dense march meets the building at t, the
// tracer stops at or before t. With over-relaxation (ω = 1.6, falling back to plain steps) and
// without (ω = 1), for every preset.
TEST(KifsTrace, NeverPassesThroughSolid) {
  for (const std::string& name : buildingPresets())
    for (double omega : {1.0, 1.6}) {
      KifsParams p = preset(name);
      p.trace.overRelax = omega;
      p.trace.hitFactor = 0.05;
      p.trace.maxSteps = 5000;
      const int size = 24;
      p.trace.pixelAngle = pixelAngle(40.0, size);
      const Building b(p);
      const View v = viewOf(b, viewAzimuth(name));
      const double dt = 2e-3;
      int hits = 0;
      for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
          const Ray r = pixelRay(v.inverse, v.eye, px, py, size, size);
          const Hit hit = trace(b, r);
          const double dense = denseFirstSolid(b, r, dt);
          if (dense < 0) continue;
          ++hits;
          ASSERT_TRUE(hit.hit) << name << " ω " << omega << ": pixel " << px << "," << py << " missed solid at t = " << dense
                               << " after " << hit.steps << " steps";
          EXPECT_LE(hit.t, dense + 1e-9) << name << " ω " << omega << ": pixel " << px << "," << py;
        }
      EXPECT_GT(hits, size * size / 10) << name;
    }
}

TEST(KifsTrace, RaysMissingTheBoundsEvaluateNothing) {
  const Building b(preset("box"));
  const Aabb box = b.worldBounds();
  const Ray away{box.hi + glm::dvec3(10.0), glm::normalize(glm::dvec3(1, 0.2, 0.3))};
  const Hit h = trace(b, away);
  EXPECT_FALSE(h.hit);
  EXPECT_EQ(h.steps, 0);
}

// Where the outer shell cuts solid fractal, the surface is the wall's plane and its normal the
// wall's outward normal (points on the +x wall with fractal solid behind them).
TEST(KifsTrace, NormalsOfShellCutsAreTheWallNormals) {
  KifsParams p = preset("box");
  p.facade.b2 = -0.2;  // the wall cuts the fractal 0.2 inside its face, not along it
  const Building b(p);
  std::mt19937_64 rng(4);
  int checked = 0;
  for (int i = 0; i < 10000; ++i) {
    const glm::dvec3 onWall = uniformIn(rng, glm::dvec3(p.mass.halfWidth, -5.0, 1.0), glm::dvec3(p.mass.halfWidth, 5.0, 23.0));
    bool solidBehind = true;  // the outer shell's distance is the estimate all around
    for (double depth : {0.0, 1e-6, 2e-6, 4e-6})
      solidBehind = solidBehind && std::abs(b.evaluate(onWall - glm::dvec3(depth, 0, 0)).surface + depth) < 1e-15;
    if (!solidBehind) continue;
    ++checked;
    const glm::dvec3 n = normalAt(b, onWall - glm::dvec3(2e-6, 0, 0), 1e-6);
    EXPECT_NEAR(n.x, 1.0, 1e-9) << "at y " << onWall.y << " z " << onWall.z;
  }
  EXPECT_GT(checked, 100);
}

// Normals by finite differences face the rays that found them, but where the fractal's detail is
// finer than their offsets (a sign error would leave a small minority facing).
TEST(KifsTrace, HitsFaceTheirRays) {
  KifsParams p = preset("box");
  p.trace.pixelAngle = pixelAngle(40.0, 32);
  const Building b(p);
  const View v = viewOf(b, -60);
  int hits = 0, facing = 0;
  for (int py = 0; py < 32; ++py)
    for (int px = 0; px < 32; ++px) {
      const Ray r = pixelRay(v.inverse, v.eye, px, py, 32, 32);
      const Hit h = trace(b, r);
      if (!h.hit) continue;
      ++hits;
      const glm::dvec3 n = normalAt(b, r.origin + h.t * r.dir, 0.5 * p.trace.pixelAngle * h.t);
      facing += glm::dot(n, r.dir) < 0;
    }
  EXPECT_GT(hits, 100);
  EXPECT_GE(facing, hits * 8 / 10) << hits;
}

}  // namespace
}  // namespace corbel::kifs::test
