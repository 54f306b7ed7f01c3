// KIFS speeds (docs/kifs.md, "Speed"): CPU distance evaluations per second for each preset, CPU
// rays per second, the shader's frame time through OSMesa (llvmpipe) at 256², 512² and 640² and
// meshing at 64³ and 128³. Run: build/tests/bench/corbel_bench_kifs
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "extrude/kernel.h"
#include "kifs/follow.h"
#include "kifs/kernel.h"
#include "kifs/mesher.h"
#include "kifs/trace.h"
#include "render/gl.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"

#include <benchmark/benchmark.h>

#include <optional>
#include <random>

namespace {

using namespace corbel;

const std::vector<std::string> kPresets = {"box", "menger", "t", "h", "polar", "curved"};

void KifsDistance(benchmark::State& state) {
  const kifs::Building b(kifs::preset(kPresets[state.range(0)]));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::dvec3> points(4096);
  const kifs::Aabb box = b.worldBounds();
  for (auto& p : points) p = box.lo + glm::dvec3(u(rng), u(rng), u(rng)) * box.size();
  for (auto _ : state)
    for (const auto& p : points) benchmark::DoNotOptimize(b.evaluate(p).bound);
  state.SetItemsProcessed(state.iterations() * points.size());
  state.SetLabel(kPresets[state.range(0)]);
}
BENCHMARK(KifsDistance)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

void KifsCpuFrame(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const kifs::KifsParams params = kifs::preset("box");
  const render::OrbitCamera camera = render::kifsCamera(kifs::Building(params), 1.0);
  const kifs::Building b(render::kifsForView(params, camera, n));
  const glm::dmat4 inv = glm::inverse(camera.projection(1.0) * camera.view());
  const Vec3 e = camera.eye();
  for (auto _ : state)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        benchmark::DoNotOptimize(kifs::trace(b, kifs::pixelRay(inv, glm::dvec3(e[0], e[1], e[2]), x, y, n, n)).t);
  state.SetItemsProcessed(state.iterations() * n * n);
}
BENCHMARK(KifsCpuFrame)->Arg(128)->Unit(benchmark::kMillisecond);

// One shaded frame of a preset (sky, grid, building; read back), as corbel-cli kifs draws it.
void KifsShaderFrame(benchmark::State& state) {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  static render::KifsPass pass;
  const int n = static_cast<int>(state.range(0));
  const kifs::KifsParams params = kifs::preset(kPresets[state.range(1)]);
  const render::OrbitCamera camera = render::kifsCamera(kifs::Building(params), 1.0);
  const kifs::Building b(render::kifsForView(params, camera, n));
  render::RenderSettings settings;
  settings.edges = false;
  const Scene scene;
  // The first draw compiles the shader (llvmpipe JIT): not part of a frame.
  (void)render::renderKifsImage(renderer, pass, b, scene, camera, n, n, render::KifsMode::Shaded, settings);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        render::renderKifsImage(renderer, pass, b, scene, camera, n, n, render::KifsMode::Shaded, settings).rgba[0]);
  state.SetLabel(kPresets[state.range(1)]);
}
BENCHMARK(KifsShaderFrame)
    ->Args({256, 0})
    ->Args({512, 0})
    ->Args({640, 0})
    ->Args({512, 3})
    ->Args({512, 4})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()  // "CPU" counts llvmpipe's threads: steadier on a shared machine
    ->UseRealTime();

// One shaded 640² frame of assets/examples/kifs-on-house.corbel: the box preset's facade on the
// Fig. 1 house (a follower: d_o from the baked mass, a 3D texture), the house drawn under it,
// as corbel-cli render draws the example; beside the box preset's frame above.
void KifsFollowerFrame(benchmark::State& state) {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  static render::KifsPass pass;
  const int n = static_cast<int>(state.range(0));
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/kifs-on-house.corbel");
  SceneSync sync;
  extrude::registerKernel(sync);
  kifs::registerKernel(sync);
  Scene scene;
  sync.update(p.document, scene);
  const DocObject* follower = nullptr;
  for (const DocObject& o : p.document.objects)
    if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->mass.footprint == "object") follower = &o;
  if (!follower) {
    state.SkipWithError("kifs-on-house.corbel has no follower");
    return;
  }
  const kifs::Building whole = kifs::buildingOf(p.document, scene, *follower);
  const render::OrbitCamera camera = render::kifsCamera(whole, 1.0);
  const kifs::Building b(render::kifsForView(whole.params(), camera, n), whole.mass());
  render::RenderSettings settings;
  settings.edges = false;
  (void)render::renderKifsImage(renderer, pass, b, scene, camera, n, n, render::KifsMode::Shaded, settings);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        render::renderKifsImage(renderer, pass, b, scene, camera, n, n, render::KifsMode::Shaded, settings).rgba[0]);
}
BENCHMARK(KifsFollowerFrame)->Arg(640)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

// Where the 640² box frame goes: each part ends with glFinish and only it is timed. 0 the
// target and the renderer's sky and grid, 1 the KIFS pass (march and shading), 2 the MSAA
// resolve and read-back.
void KifsFramePart(benchmark::State& state) {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  static render::KifsPass pass;
  const int n = 640, part = static_cast<int>(state.range(0));
  const kifs::KifsParams params = kifs::preset("box");
  const render::OrbitCamera camera = render::kifsCamera(kifs::Building(params), 1.0);
  const kifs::Building b(render::kifsForView(params, camera, n));
  render::RenderSettings settings;
  settings.edges = false;
  const Scene scene;
  (void)render::renderKifsImage(renderer, pass, b, scene, camera, n, n, render::KifsMode::Shaded, settings);
  for (auto _ : state) {
    state.PauseTiming();
    std::optional<render::OffscreenTarget> target;
    for (int stage = 0; stage < 3; ++stage) {
      if (stage == part) state.ResumeTiming();
      if (stage == 0) {
        target.emplace(n, n);
        target->bind();
        renderer.setScene(scene, settings);
        renderer.draw(camera, 0, 0, n, n, settings);
      } else if (stage == 1) {
        pass.draw(b, camera, 0, 0, n, n, render::KifsMode::Shaded);
      } else {
        benchmark::DoNotOptimize(target->read().rgba[0]);
      }
      glFinish();
      if (stage == part) state.PauseTiming();
    }
    target.reset();
    state.ResumeTiming();
  }
  state.SetLabel(part == 0 ? "sky and grid" : part == 1 ? "KIFS pass" : "read-back");
}
BENCHMARK(KifsFramePart)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void KifsMesh(benchmark::State& state) {
  const kifs::Building b(kifs::preset("box"));
  for (auto _ : state) benchmark::DoNotOptimize(kifs::meshBuilding(b, static_cast<int>(state.range(0))).faces.size());
}
BENCHMARK(KifsMesh)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
