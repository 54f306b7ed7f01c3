// Procedural extrusion speed, against CGAL's straight skeleton on the same footprints in the
// same run (so the figures are ratios), and end to end on the real footprints.
// Run: build/tests/bench/corbel_bench_extrude  (see docs/benchmarks.md)
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "extrude/batch.h"
#include "extrude/extrude.h"
#include "extrude/footprints.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/create_straight_skeleton_2.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

namespace {

using namespace corbel;
using namespace corbel::extrude;
constexpr double kDeg = std::numbers::pi / 180;

// The hip-roof batch of extrude-notes.md: rectangles, L, T and orthogonal 4–20 corners, half
// of them rotated.
std::vector<std::vector<Vec2>> hipBatch(int count) {
  std::mt19937 rng(6000);
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  std::vector<std::vector<Vec2>> out;
  while (static_cast<int>(out.size()) < count) {
    std::vector<Vec2> p;
    const double w = uni(6, 20), h = uni(6, 14);
    switch (out.size() % 4) {
      case 0: p = {{0, 0}, {w, 0}, {w, h}, {0, h}}; break;
      case 1: {
        const double a = uni(0.3, 0.7) * w, b = uni(0.3, 0.7) * h;
        p = {{0, 0}, {w, 0}, {w, b}, {a, b}, {a, h + b}, {0, h + b}};
        break;
      }
      case 2: {
        const double s = uni(0.2, 0.35) * w, t = uni(4, 10);
        p = {{s, 0}, {w - s, 0}, {w - s, t}, {w, t}, {w, t + h / 2}, {0, t + h / 2}, {0, t}, {s, t}};
        break;
      }
      default: {  // a skyline of 1–9 steps: 4–20 corners
        const int steps = pick(1, 9);
        std::vector<double> xs{0}, hs;
        for (int i = 0; i < steps; ++i) xs.push_back(xs.back() + uni(2, 6));
        for (int i = 0; i < steps; ++i) {
          double v;
          do v = std::round(uni(2, 10));
          while (!hs.empty() && v == hs.back());
          hs.push_back(v);
        }
        p = {{0, 0}, {xs.back(), 0}};
        for (int i = steps - 1; i >= 0; --i) {
          p.emplace_back(xs[i + 1], hs[i]);
          p.emplace_back(xs[i], hs[i]);
        }
      }
    }
    if (out.size() % 2 == 1) {
      const double a = uni(0, 2 * std::numbers::pi), c = std::cos(a), s = std::sin(a);
      for (Vec2& q : p) q = Vec2(c * q[0] - s * q[1], s * q[0] + c * q[1]);
    }
    out.push_back(p);
  }
  return out;
}

const std::vector<std::vector<Vec2>>& batch() {
  static const auto b = hipBatch(6000);
  return b;
}

ExtrusionSpec hipSpec(const std::vector<Vec2>& loop) {
  ExtrusionSpec s;
  s.profiles = {hipProfile(45 * kDeg)};
  s.loops = {{loop, std::vector<int>(loop.size(), 0)}};
  return s;
}

void Hip6000_Corbel_OneThread(benchmark::State& state) {
  std::vector<ExtrusionSpec> specs;
  for (const auto& l : batch()) specs.push_back(hipSpec(l));
  for (auto _ : state)
    for (const auto& s : specs) benchmark::DoNotOptimize(corbel::extrude::extrude(s).shell.faces.size());
  state.SetItemsProcessed(state.iterations() * static_cast<long>(specs.size()));
}
BENCHMARK(Hip6000_Corbel_OneThread)->Unit(benchmark::kMillisecond);

// The batch (each shell also built into a half-edge mesh and validated) on `jobs` threads:
// with Hip6000_Batch_OneJob, how far the batch scales over the cores.
void runBatch(benchmark::State& state, unsigned jobs) {
  std::vector<BatchItem> items;
  for (const auto& l : batch()) items.push_back({"", hipSpec(l), ""});
  BatchOptions o;
  o.jobs = jobs;
  for (auto _ : state) benchmark::DoNotOptimize(extrudeBatch(items, o).size());
  state.SetItemsProcessed(state.iterations() * static_cast<long>(items.size()));
}
void Hip6000_Corbel_AllCores(benchmark::State& state) { runBatch(state, 0); }
void Hip6000_Batch_OneJob(benchmark::State& state) { runBatch(state, 1); }
BENCHMARK(Hip6000_Corbel_AllCores)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hip6000_Batch_OneJob)->Unit(benchmark::kMillisecond)->UseRealTime();

void Hip6000_CgalStraightSkeleton(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<CGAL::Polygon_2<K>> polys;
  for (const auto& l : batch()) {
    CGAL::Polygon_2<K> p;
    for (const Vec2& q : l) p.push_back(K::Point_2(q[0], q[1]));
    polys.push_back(p);
  }
  for (auto _ : state)
    for (const auto& p : polys) {
      auto ss = CGAL::create_interior_straight_skeleton_2(p.vertices_begin(), p.vertices_end(), K());
      benchmark::DoNotOptimize(ss->size_of_faces());
    }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(polys.size()));
}
BENCHMARK(Hip6000_CgalStraightSkeleton)->Unit(benchmark::kMillisecond);

// GeoJSON → shells → glb for all 10,524 real footprints (the CLI's path).
void RealFootprints_EndToEnd(benchmark::State& state) {
  const std::string dir = CORBEL_FOOTPRINTS;
  const std::string out = (std::filesystem::temp_directory_path() / "corbel-bench-town.glb").string();
  for (auto _ : state) {
    std::vector<BatchItem> items;
    for (const char* name : {"kathmandu_np.geojson", "moosburg_de.geojson"})
      for (auto& fp : readGeoJsonFile(dir + "/" + name)) {
        ExtrusionSpec s;
        s.profiles = {hipProfile(45 * kDeg)};
        for (auto& l : fp.loops) s.loops.push_back({l, std::vector<int>(l.size(), 0)});
        items.push_back({fp.id, std::move(s), fp.problem});
      }
    BatchOptions o;
    o.keepMeshes = true;
    const auto results = extrudeBatch(items, o);
    Scene scene;
    ObjectId id = 1;
    for (const auto& r : results)
      if (r.ok) scene.replaceObject(id++, Kind::Shell, r.id, r.mesh);
    exportScene(scene, out);
  }
  std::filesystem::remove(out);
}
BENCHMARK(RealFootprints_EndToEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

// Editing: re-extrusion of a 50-corner plan with 3-segment profiles (wall, steep, shallow)
// and two natural steps (dormers at the top of the wall).
void ReExtrude50Corners(benchmark::State& state) {
  ExtrusionSpec s;
  Profile p;
  p.name = "wall+mansard";
  p.points = {{0, 0}, {0, 3}, {0.6, 4.5}, {3, 6}};
  s.profiles = {p};
  std::vector<Vec2> loop;
  for (int i = 0; i < 50; ++i) {
    const double a = 2 * std::numbers::pi * i / 50, r = (i % 2 ? 14.0 : 16.0) + 2 * std::sin(3 * a);
    loop.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  s.loops = {{loop, std::vector<int>(50, 0)}};
  Profile front, side;
  front.name = "dormer front";
  front.points = {{0, 0}, {0, 1}};
  side.name = "dormer side";
  side.points = {{0, 0}, {0, 1.2}, {1, 2.2}};
  s.profiles.push_back(front);
  s.profiles.push_back(side);
  for (int edge : {0, 25}) {
    PlanStep d;
    d.anchor = {0, edge, false, 0.5, 3.0};
    d.width = 1.2;
    d.depth = 0.1;
    d.frontProfile = 1;
    d.sideProfile = 2;
    s.steps.push_back(d);
  }
  if (!corbel::extrude::extrude(s).shell.warnings.empty()) state.SkipWithError("the benchmark plan has warnings");
  for (auto _ : state) benchmark::DoNotOptimize(corbel::extrude::extrude(s).shell.faces.size());
}
BENCHMARK(ReExtrude50Corners)->Unit(benchmark::kMicrosecond);

// The gallery: one building of each example, extruded from its spec.
void Gallery(benchmark::State& state, const char* file, int object) {
  const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + file).document;
  const ExtrusionSpec s = std::get<ExtrusionSpec>(d.objects[object].spec);
  for (auto _ : state) benchmark::DoNotOptimize(corbel::extrude::extrude(s).shell.faces.size());
}
BENCHMARK_CAPTURE(Gallery, house_fig1, "house.corbel", 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Gallery, temple_fig5, "temple.corbel", 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Gallery, terrace_with_bays, "terrace.corbel", 0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Gallery, courtyard_building, "extrusions.corbel", 0)->Unit(benchmark::kMicrosecond);

// The town block: 87 real footprints as one project, all its extrusions.
void Gallery_TownBlock(benchmark::State& state) {
  const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/town.corbel").document;
  for (auto _ : state)
    for (const DocObject& o : d.objects)
      if (const auto* s = std::get_if<ExtrusionSpec>(&o.spec)) benchmark::DoNotOptimize(corbel::extrude::extrude(*s).shell.faces.size());
}
BENCHMARK(Gallery_TownBlock)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
