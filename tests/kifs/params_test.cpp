// Specifications of kifs/params.h beyond the named bad fields (distance_test.cpp): random
// parameter sets, finite but wild, are either refused with a kifs.* field named, or give a
// building whose estimates are never NaN and whose rays always end.
#include "core/error.h"
#include "kifs/trace.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::kifs::test {
namespace {

TEST(KifsParams, WildParametersAreRefusedOrBehave) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // A number of any sign and of magnitude 1e-12 .. 1e12, sometimes exactly 0.
  auto wild = [&] {
    if (u(rng) < 0.05) return 0.0;
    return (u(rng) < 0.3 ? -1.0 : 1.0) * std::pow(10.0, -12.0 + 24.0 * u(rng));
  };
  // Around a sensible value, most of the time.
  auto near = [&](double v) { return u(rng) < 0.7 ? v * (0.5 + u(rng)) : wild(); };
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    KifsParams p;
    p.iterations = u(rng) < 0.8 ? int(u(rng) * 12) : int(wild());
    p.scale = near(3.0);
    p.centre = {near(0.9), near(0.9), near(0.3)};
    p.r1.yDeg = near(10.0);
    p.r2 = {near(5.0), near(5.0), near(5.0)};
    p.bailout = near(1000.0);
    p.mass.footprint = Footprint(trial % 3);
    p.mass.halfWidth = near(8.0), p.mass.halfDepth = near(6.0), p.mass.height = near(20.0);
    p.mass.wing = near(2.0), p.mass.shell = near(1.0);
    p.facade.period = near(6.0), p.facade.r = {near(0.2), near(0.1), near(0.3)};
    p.facade.a1 = near(0.3), p.facade.a2 = near(1.0), p.facade.b1 = near(0.1), p.facade.b2 = near(0.1);
    p.floors.height = near(3.0), p.floors.y0 = near(0.5), p.floors.sy = near(1.0);
    p.curvilinear.enabled = trial % 4 == 0;
    p.curvilinear.sTheta = near(10.0), p.curvilinear.cTheta = near(0.3), p.curvilinear.sR = near(1.0);
    p.curvilinear.cR = near(-12.0), p.curvilinear.z0 = near(1.0);
    p.trace.maxSteps = 200;
    p.trace.pixelAngle = 1e-3;
    std::unique_ptr<Building> b;
    try {
      b = std::make_unique<Building>(p);
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("kifs.", 0), 0u) << e.what();
      continue;
    }
    ++accepted;
    const Aabb box = b->worldBounds();
    ASSERT_TRUE(std::isfinite(box.lo.x) && std::isfinite(box.hi.z)) << "trial " << trial;
    for (int i = 0; i < 20; ++i) {
      const glm::dvec3 q = uniformIn(rng, box.lo, box.hi);
      const Sample s = b->evaluate(q);
      ASSERT_FALSE(std::isnan(s.bound) || std::isnan(s.surface)) << "trial " << trial;
      ASSERT_LE(s.bound, s.surface) << "trial " << trial;
    }
    const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
    const Ray ray{centre + 2.0 * glm::length(box.size()) * glm::dvec3(1, -0.5, 0.4), glm::normalize(glm::dvec3(-1, 0.5, -0.4))};
    const Hit h = trace(*b, ray);
    EXPECT_LE(h.steps, p.trace.maxSteps);
    if (h.hit) {
      EXPECT_TRUE(std::isfinite(h.t));
    }
  }
  EXPECT_GT(accepted, 200);  // the sensible part of the space is reached
}

// Huge but finite angles and offsets: no hang, no NaN (an arc's bounds once looped on a += π/2).
TEST(KifsParams, HugeAnglesDoNotHang) {
  for (double c : {1e17, -1e17, 1e300}) {
    KifsParams p = preset("curved");
    p.curvilinear.cTheta = c;
    p.r2.yDeg = c;
    const Building b(p);
    const Sample s = b.evaluate(0.5 * (b.worldBounds().lo + b.worldBounds().hi));
    EXPECT_FALSE(std::isnan(s.bound)) << c;
  }
}

}  // namespace
}  // namespace corbel::kifs::test
