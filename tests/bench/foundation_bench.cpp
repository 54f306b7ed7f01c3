// Foundation speeds: building the Scene from a Document, validating shells, project I/O, cutting
// faces into triangles and one headless frame. Run: build/tests/bench/corbel_bench_foundation
#include "core/export.h"
#include "core/geometry.h"
#include "core/massing.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "render/headless_context.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace corbel;

Document townOf(int n) {
  Document d;
  for (int i = 0; i < n; ++i) {
    BoxSpec b;
    b.origin = Vec3((i % 100) * 15.0, (i / 100) * 15.0, 0.0);
    b.size = Vec3(10, 8, 6 + i % 7);
    b.rotation_deg = (i * 7) % 40;
    d.add("Block", b);
  }
  return d;
}

void SceneFromDocument(benchmark::State& state) {
  const Document d = townOf(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Scene s;
    SceneSync sync;
    sync.update(d, s);
    benchmark::DoNotOptimize(s.mesh().n_faces());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(SceneFromDocument)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void EditOneObject(benchmark::State& state) {
  Document d = townOf(static_cast<int>(state.range(0)));
  Scene s;
  SceneSync sync;
  sync.update(d, s);
  int k = 0;
  for (auto _ : state) {
    std::get<BoxSpec>(d.objects[0].spec).size[2] = 5.0 + (++k % 10);
    benchmark::DoNotOptimize(sync.update(d, s));
  }
}
BENCHMARK(EditOneObject)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

void ValidateObject(benchmark::State& state) {
  BoxSpec b;
  b.repeat_x = b.repeat_y = static_cast<int>(state.range(0));
  b.spacing_x = b.spacing_y = 12;
  Scene s;
  s.replaceObject(1, Kind::Mass, "grid", buildBoxes(b));
  for (auto _ : state) benchmark::DoNotOptimize(s.validate(1).euler);
  state.SetItemsProcessed(state.iterations() * 6 * state.range(0) * state.range(0));
}
BENCHMARK(ValidateObject)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

void ProjectParse(benchmark::State& state) {
  const std::string text = serializeProject(townOf(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(parseProject(text).document.objects.size());
  state.SetBytesProcessed(state.iterations() * static_cast<long>(text.size()));
}
BENCHMARK(ProjectParse)->Arg(1000)->Unit(benchmark::kMillisecond);

void ProjectSaveAtomic(benchmark::State& state) {
  const Document d = townOf(static_cast<int>(state.range(0)));
  const std::string path = (std::filesystem::temp_directory_path() / "corbel-bench.corbel").string();
  for (auto _ : state) saveProject(d, path);
  std::remove(path.c_str());
}
BENCHMARK(ProjectSaveAtomic)->Arg(1000)->Unit(benchmark::kMillisecond);

void ExportGlb(benchmark::State& state) {
  Scene s;
  SceneSync().update(townOf(static_cast<int>(state.range(0))), s);
  const std::string path = (std::filesystem::temp_directory_path() / "corbel-bench.glb").string();
  for (auto _ : state) exportScene(s, path);
  std::remove(path.c_str());
}
BENCHMARK(ExportGlb)->Arg(1000)->Unit(benchmark::kMillisecond);

// Cutting one face into triangles (triangulatePolygon: the ear cut, then the flips), as every
// export, frame and pick does: a star-shaped polygon of n corners at random radii (concave,
// about half its corners reflex), in a plane tilted 30° like a roof.
std::vector<Vec3> tiltedStar(int n) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::uniform_real_distribution<double> radius(5.0, 10.0);
  std::vector<Vec3> p;
  const double pi = std::numbers::pi, tilt = pi / 6;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n, r = radius(rng);
    const double x = r * std::cos(a), y = r * std::sin(a);
    p.emplace_back(100 + x, 50 + y * std::cos(tilt), 3 + y * std::sin(tilt));
  }
  return p;
}

void Triangulate(benchmark::State& state) {
  const std::vector<Vec3> face = tiltedStar(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(triangulatePolygon(face).size());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(Triangulate)->Arg(4)->Arg(16)->Arg(256)->Arg(2048)->Unit(benchmark::kMicrosecond);

void HeadlessFrame(benchmark::State& state) {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  Scene s;
  SceneSync().update(townOf(static_cast<int>(state.range(0))), s);
  render::OrbitCamera camera;
  camera.frame(s.bounds(), 4.0 / 3.0);
  render::RenderSettings settings;
  // Arg 1 = 1: with shadows (the depth pass from the sun, then the 3 × 3-tap lookups).
  settings.shadows = state.range(1) != 0;
  render::OffscreenTarget target(1024, 768);
  for (auto _ : state) {
    target.bind();
    renderer.setScene(s, settings);
    renderer.draw(camera, 0, 0, 1024, 768, settings);
    benchmark::DoNotOptimize(target.read().rgba.data());
  }
}
BENCHMARK(HeadlessFrame)->Args({100, 0})->Args({1000, 0})->Args({1000, 1})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
