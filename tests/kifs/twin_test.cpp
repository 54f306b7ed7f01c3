// The shader is the CPU code's twin: a depth buffer rendered headless through OSMesa with
// shaders/kifs.frag.glsl agrees with CPU sphere tracing of the same rays (kifs/trace.h).
#include "kifs/trace.h"
#include "render/gl.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace corbel::kifs::test {
namespace {

render::KifsPass& sharedPass() {
  static render::HeadlessContext context;
  static render::KifsPass pass;
  return pass;
}

constexpr int kSize = 96;
constexpr double kDepthAgreement = 1e-4;  // of the scene size (the outer shell box's diagonal)
constexpr double kThreshold = 2.5e-5;     // the hit threshold at the camera's distance, of the scene size
constexpr double kGraze = 0.5;            // a passed minimum of estimate/threshold below 1 + kGraze
constexpr double kThresholdWobble = 0.05; // relative change of the hit threshold
constexpr double kRelaxWobble = 0.02;     // change of ω
constexpr double kOutliers = 1e-3;        // of the compared pixels, see below

struct Twin {
  int hits = 0, silhouette = 0, unstable = 0, compared = 0, maskMismatch = 0, depthOutliers = 0;
  int gpuHits = 0, offSurface = 0;  // GPU hits whose point the CPU estimate puts off the surface
  double worstDepth = 0;            // |t_gpu − t_cpu| / scene size, compared hit pixels, outliers aside
};

// Compares, for one preset, the GPU depth buffer with CPU sphere tracing of the same rays.
//
// 1. The function: at every GPU hit, the CPU estimate at the GPU's point is below the hit
//    threshold (times 1 + kGraze for float noise, plus the depth buffer's resolution there;
//    the least of three points that resolution apart, as the estimate jumps at id planes).
// 2. The march, on the pixels where it is well-conditioned. Excluded are
//    - silhouette pixels: a 4-neighbour's CPU hit status differs;
//    - grazing pixels, where a tiny change of the march changes its result: the CPU march passed
//      a minimum of estimate/threshold below 1 + kGraze; or it stopped where the estimate rises
//      again one threshold further (a graze, not a surface ahead); or the surface is seen so
//      edge-on that the threshold alone spans half the agreement along the ray; or its hit
//      status or depth changes when the threshold changes by ±kThresholdWobble or ω by
//      ±kRelaxWobble.
//    On the rest, hit masks must be identical and depths agree to kDepthAgreement of the scene
//    size, except for at most kOutliers of them: float (GPU) against double (CPU) steps still
//    part, rarely, in ways none of the tests above foresees.
Twin compare(const std::string& name) {
  const int w = kSize, h = kSize;
  render::KifsPass& pass = sharedPass();
  KifsParams p = preset(name);
  const render::OrbitCamera camera = render::kifsCamera(Building(p), 1.0, viewAzimuth(name));
  p = render::kifsForView(p, camera, h);
  const double size = glm::length(Building(p).worldBounds().size());
  p.trace.hitFactor = kThreshold * size / (p.trace.pixelAngle * camera.distance);
  p.trace.maxSteps = 2000;
  const Building b(p);
  std::vector<Building> wobbled;
  for (int k = 0; k < 4; ++k) {
    KifsParams q = p;
    if (k < 2) q.trace.hitFactor *= k == 0 ? 1 - kThresholdWobble : 1 + kThresholdWobble;
    else q.trace.overRelax = std::max(1.0, q.trace.overRelax + (k == 2 ? -kRelaxWobble : kRelaxWobble));
    wobbled.emplace_back(q);
  }
  const std::vector<float> depth = render::renderKifsDepth(pass, b, camera, w, h);

  const glm::dmat4 inv = glm::inverse(camera.projection(1.0) * camera.view());
  const Vec3 e = camera.eye();
  const glm::dvec3 eye(e[0], e[1], e[2]);
  auto threshold = [&](double t) { return p.trace.hitFactor * p.trace.pixelAngle * t; };
  // The GPU's window depth back to a distance along the pixel's ray.
  auto gpuT = [&](int x, int y, double d) {
    const glm::dvec4 world = inv * glm::dvec4(2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0, 2.0 * d - 1.0, 1.0);
    return glm::length(glm::dvec3(world) / world.w - eye);
  };
  std::vector<int> cpuHit(w * h), unstable(w * h);
  std::vector<double> cpuT(w * h);
  Twin out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      const Ray ray = pixelRay(inv, eye, x, y, w, h);
      const Hit hit = trace(b, ray);
      cpuHit[i] = hit.hit;
      cpuT[i] = hit.t;
      if (hit.closest < 1 + kGraze) unstable[i] = 1;
      if (hit.hit) {
        const double eps = threshold(hit.t);
        if (b.evaluate(ray.origin + (hit.t + eps) * ray.dir).surface >= hit.sample.surface) unstable[i] = 1;
        const glm::dvec3 n = normalAt(b, ray.origin + hit.t * ray.dir, 0.5 * eps);
        if (eps / std::abs(glm::dot(n, ray.dir)) > 0.5 * kDepthAgreement * size) unstable[i] = 1;
      }
      for (const Building& other : wobbled) {
        const Hit o = trace(other, ray);
        if (o.hit != hit.hit || std::abs(o.t - hit.t) > kDepthAgreement * size) unstable[i] = 1;
      }
      if (depth[i] < 1.0f) {  // 1: the GPU's stopping point, judged by the CPU's estimate
        ++out.gpuHits;
        const double t = gpuT(x, y, depth[i]);
        const double resolution = std::abs(gpuT(x, y, std::nextafter(depth[i], 2.0f)) - t);
        // Within the depth buffer's resolution (the estimate jumps at facade-id planes).
        double least = 1e300;
        for (double dt : {-2 * resolution, 0.0, 2 * resolution})
          least = std::min(least, b.evaluate(ray.origin + (t + dt) * ray.dir).surface);
        if (least > (1 + kGraze) * threshold(t) + 2 * resolution) ++out.offSurface;
      }
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      out.hits += cpuHit[i];
      bool edge = false;
      for (auto [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx >= 0 && ny >= 0 && nx < w && ny < h && cpuHit[ny * w + nx] != cpuHit[i]) edge = true;
      }
      if (edge) {
        ++out.silhouette;
        continue;
      }
      if (unstable[i]) {
        ++out.unstable;
        continue;
      }
      ++out.compared;
      const bool gpuHit = depth[i] < 1.0f;
      if (gpuHit != bool(cpuHit[i])) {
        ++out.maskMismatch;
        continue;
      }
      if (!gpuHit) continue;
      const double diff = std::abs(gpuT(x, y, depth[i]) - cpuT[i]) / size;
      if (diff > kDepthAgreement) ++out.depthOutliers;
      else out.worstDepth = std::max(out.worstDepth, diff);
    }
  return out;
}

class KifsTwin : public ::testing::TestWithParam<std::string> {};

TEST_P(KifsTwin, ShaderDepthAgreesWithCpuTracing) {
  const Twin t = compare(GetParam());
  std::cout << GetParam() << " " << kSize << "x" << kSize << ": " << t.hits << " CPU hits, " << t.silhouette
            << " silhouette, " << t.unstable << " grazing, " << t.compared << " compared: " << t.maskMismatch
            << " mask mismatches, " << t.depthOutliers << " depth outliers, worst depth difference " << t.worstDepth
            << " of the scene size; " << t.offSurface << " of " << t.gpuHits << " GPU hits off the CPU surface\n";
  EXPECT_GT(t.hits, kSize * kSize / 10);
  EXPECT_EQ(t.offSurface, 0);
  EXPECT_GT(t.compared, kSize * kSize / 2);
  EXPECT_LE(t.maskMismatch + t.depthOutliers, kOutliers * t.compared);
  EXPECT_LE(t.worstDepth, kDepthAgreement);
}

INSTANTIATE_TEST_SUITE_P(Presets, KifsTwin, ::testing::ValuesIn(buildingPresets()));

// Every active uniform of kifs.frag.glsl is written by a draw, in the program of every
// preset's variant (setKifsUniforms throws for the other direction: a name the variant uses
// that the shader lacks).
TEST(KifsTwin, EveryShaderUniformIsWritten) {
  render::KifsPass& pass = sharedPass();
  std::set<int> variants;
  for (const std::string& name : presetNames()) {
    const Building b(preset(name));
    variants.insert(render::kifsVariant(b).key());
    (void)render::renderKifsDepth(pass, b, render::kifsCamera(b, 1.0), 8, 8);
    const std::set<std::string> written(pass.writtenUniforms().begin(), pass.writtenUniforms().end());
    GLint count = 0;
    glGetProgramiv(pass.program(), GL_ACTIVE_UNIFORMS, &count);
    EXPECT_GT(count, 20);
    for (GLint i = 0; i < count; ++i) {
      char uniform[128] = {};
      GLsizei len = 0;
      GLint size = 0;
      GLenum type = 0;
      glGetActiveUniform(pass.program(), GLuint(i), sizeof uniform, &len, &size, &type, uniform);
      EXPECT_TRUE(written.count(uniform)) << name << ": uniform " << uniform << " is never written";
    }
  }
  EXPECT_GE(variants.size(), 6u);  // box, T, H, polar ring, arc, R1 and R2 ≠ I
}

// The fragment shader runs on the back faces of the grown bounds box, or on the whole viewport
// when the eye is inside it: either way every ray that meets the bounds marches (the test above
// checks this for the box; here the eye stands inside the building, where every ray does).
TEST(KifsTwin, EveryRayMarchesWhenTheEyeIsInsideTheBounds) {
  render::KifsPass& pass = sharedPass();
  const Building b(preset("box"));
  const int w = 24, h = 20;
  render::OrbitCamera camera = render::kifsCamera(b, double(w) / h);
  EXPECT_FALSE(render::kifsCover(b, camera, w, h).fullScreen);
  camera.distance = 2.0;  // the target is the box's centre
  ASSERT_TRUE(render::kifsCover(b, camera, w, h).fullScreen);
  const render::KifsCost cost = render::measureKifsCost(pass, b, camera, w, h);
  for (int i = 0; i < w * h; ++i) EXPECT_GE(cost.perPixel[i], 1) << "pixel " << i;
  EXPECT_GT(cost.hits, w * h / 2);
}

// The shader tests the ray against the outer shell's box before marching: pixels whose ray
// misses the box (by the CPU's slab test) evaluate nothing; the others evaluate at least once,
// and hits on average at least ten times (a step, the normal's four, the occlusion's five).
TEST(KifsTwin, RaysMissingTheBoundsEvaluateNothingOnTheGpu) {
  render::KifsPass& pass = sharedPass();
  const Building b(preset("t"));
  const int w = 48, h = 40;
  const render::OrbitCamera camera = render::kifsCamera(b, double(w) / h);
  const render::KifsCost cost = render::measureKifsCost(pass, b, camera, w, h);
  const glm::dmat4 inv = glm::inverse(camera.projection(double(w) / h) * camera.view());
  const Vec3 e = camera.eye();
  int outside = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double t0 = 0, t1 = 0;
      const bool inBox = rayBox(pixelRay(inv, glm::dvec3(e[0], e[1], e[2]), x, y, w, h), b.worldBounds(), t0, t1);
      const int n = cost.perPixel[std::size_t(y) * w + x];
      if (!inBox) {
        ++outside;
        EXPECT_EQ(n, 0) << "pixel " << x << "," << y;
      } else {
        EXPECT_GE(n, 1) << "pixel " << x << "," << y;
      }
    }
  EXPECT_GT(outside, w * h / 10);
  EXPECT_GT(cost.hits, w * h / 10);
  EXPECT_GE(cost.meanHit, 10.0);
  EXPECT_EQ(cost.heat.width, w);
}

// The shader's facade ids and storeys (Algorithm 2, Eq. 4) are the CPU's: at each GPU hit, read
// back with its depth, the CPU evaluated at that point gives the same ids and storey, wherever
// it gives them unchanged over the depth buffer's resolution along the ray (on an id or storey
// plane either side is right).
TEST(KifsTwin, ShaderIdsAndStoreysAreTheCpus) {
  render::KifsPass& pass = sharedPass();
  for (const std::string& name : {std::string("h"), std::string("curved"), std::string("box")}) {
    const Building b0(preset(name));
    const int w = 64, h = 64;
    const render::OrbitCamera camera = render::kifsCamera(b0, 1.0, viewAzimuth(name));
    const Building b(render::kifsForView(preset(name), camera, h));
    const render::KifsCost gpu = render::measureKifsCost(pass, b, camera, w, h);
    const glm::dmat4 inv = glm::inverse(camera.projection(1.0) * camera.view());
    const Vec3 e = camera.eye();
    const glm::dvec3 eye(e[0], e[1], e[2]);
    auto tOf = [&](int x, int y, double d) {
      const glm::dvec4 q = inv * glm::dvec4(2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0, 2.0 * d - 1.0, 1.0);
      return glm::length(glm::dvec3(q) / q.w - eye);
    };
    int compared = 0, mismatches = 0;
    std::set<int> idsSeen, storeysSeen;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * w + x;
        if (gpu.depth[i] >= 1.0f) continue;
        const Ray ray = pixelRay(inv, eye, x, y, w, h);
        const double t = tOf(x, y, gpu.depth[i]);
        const double res = std::abs(tOf(x, y, std::nextafter(gpu.depth[i], 2.0f)) - t);
        std::set<std::pair<int, int>> cpu;
        for (double dt : {-2 * res, 0.0, 2 * res}) {
          const Sample s = b.evaluate(ray.origin + (t + dt) * ray.dir);
          cpu.insert({s.idX + 4 * s.idZ, std::clamp(s.floor, -128, 127)});
        }
        if (cpu.size() != 1) continue;
        ++compared;
        idsSeen.insert(cpu.begin()->first);
        storeysSeen.insert(cpu.begin()->second);
        if (cpu.begin()->first != gpu.ids[i] || cpu.begin()->second != gpu.storeys[i]) ++mismatches;
      }
    EXPECT_EQ(mismatches, 0) << name << " of " << compared;
    EXPECT_GT(compared, w * h / 10) << name;
    EXPECT_GT(storeysSeen.size(), 3u) << name;
    if (name == "h") {
      EXPECT_GT(idsSeen.size(), 3u);
    }
  }
}

// The building composes with the rasterized Scene through gl_FragDepth: drawn after a Scene
// holding a wall through the building's middle, every pixel keeps the nearer of the two depths
// (each rendered alone).
TEST(KifsTwin, ComposesDepthCorrectlyWithTheScene) {
  render::KifsPass& pass = sharedPass();
  static render::Renderer renderer;
  const Building b(preset("box"));
  const int w = 64, h = 64;
  const render::OrbitCamera camera = render::kifsCamera(b, 1.0);
  Scene scene;  // a wall in the plane x = 0, wider and taller than the building
  MeshData wall;
  for (auto [y, z] : {std::pair{-20.0, -1.0}, std::pair{20.0, -1.0}, std::pair{20.0, 30.0}, std::pair{-20.0, 30.0}})
    wall.addPoint(Vec3(0.0, y, z));
  wall.addFace({0, 1, 2, 3});
  scene.replaceObject(1, Kind::Mass, "wall", wall);
  render::RenderSettings settings;
  settings.grid = settings.edges = settings.background = false;
  auto draw = [&](bool withScene, bool withKifs) {
    render::DepthTarget target(w, h);
    target.bind();
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (withScene) {
      renderer.setScene(scene, settings);
      renderer.draw(camera, 0, 0, w, h, settings);
    }
    if (withKifs) pass.draw(b, camera, 0, 0, w, h, render::KifsMode::Shaded);
    return target.readDepth();
  };
  const std::vector<float> both = draw(true, true), wallOnly = draw(true, false), kifsOnly = draw(false, true);
  int wallWins = 0, kifsWins = 0;
  for (int i = 0; i < w * h; ++i) {
    EXPECT_FLOAT_EQ(both[i], std::min(wallOnly[i], kifsOnly[i])) << "pixel " << i;
    wallWins += wallOnly[i] < kifsOnly[i];
    kifsWins += kifsOnly[i] < wallOnly[i];
  }
  EXPECT_GT(wallWins, 100);  // both in front somewhere: the test sees the depth test work
  EXPECT_GT(kifsWins, 100);
}

}  // namespace
}  // namespace corbel::kifs::test
