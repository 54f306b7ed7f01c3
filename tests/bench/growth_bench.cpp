// The growth kernel on the Alpha-like example: one simulation step (early and mid-run), the
// view maps of a grown model, and a full run. Results: docs/growth.md.
#include "core/atomic_file.h"
#include "core/scene.h"
#include "editor/growth_edits.h"
#include "editor/growth_inspect.h"
#include "growth/engine.h"
#include "growth/kernel.h"
#include "growth/site.h"
#include "growth/tiling.h"
#include "render/gl_view_mapper.h"
#include "render/headless_context.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace corbel::growth;

const Site& alpha() {
  static const Site site = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  return site;
}

// One step after `before` steps (the engine is rebuilt outside the timing each time).
void BM_GrowthStep(benchmark::State& state) {
  const int before = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    auto engine = std::make_unique<GrowthEngine>(alpha());
    engine->run(before);
    const std::size_t commits = engine->commits();
    state.ResumeTiming();
    engine->step();
    state.PauseTiming();
    state.counters["moves"] = double(engine->commits() - commits);
    engine.reset();
    state.ResumeTiming();
  }
}
BENCHMARK(BM_GrowthStep)->Arg(0)->Arg(30)->Unit(benchmark::kMillisecond)->Iterations(20);

void BM_ExactViewMaps(benchmark::State& state) {
  GrowthEngine engine(alpha());
  engine.run(100000);
  const std::vector<ViewBox> boxes = engine.viewBoxes();
  ExactViewMapper mapper;
  for (auto _ : state) benchmark::DoNotOptimize(mapper.render(boxes, alpha().bounds()));
  state.counters["boxes"] = double(boxes.size());
}
BENCHMARK(BM_ExactViewMaps)->Unit(benchmark::kMillisecond);

// The gain in view of one candidate advance (Sec. 5.2) on the exact maps of grown Alpha: every
// vertical face of every part, one query each (items = queries).
void BM_GainQuery(benchmark::State& state) {
  GrowthEngine engine(alpha());
  engine.run(100000);
  std::vector<std::pair<Box, std::uint32_t>> regions;
  for (const Unit& u : engine.units())
    for (const Box& p : u.parts)
      for (Side s : kVerticalSides) regions.push_back({sweptRegion(p, s, alpha().alpha), std::uint32_t(u.id)});
  for (auto _ : state)
    for (const auto& [r, id] : regions) benchmark::DoNotOptimize(engine.views().gain(r, id));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(regions.size()));
}
BENCHMARK(BM_GainQuery)->Unit(benchmark::kMicrosecond);

void BM_RasterViewMaps(benchmark::State& state) {
  GrowthEngine engine(alpha());
  engine.run(100000);
  const std::vector<ViewBox> boxes = engine.viewBoxes();
  RasterViewMapper mapper(0.1);
  for (auto _ : state) benchmark::DoNotOptimize(mapper.render(boxes, alpha().bounds()));
}
BENCHMARK(BM_RasterViewMaps)->Unit(benchmark::kMillisecond);

void BM_GlViewMaps(benchmark::State& state) {
  GrowthEngine engine(alpha());
  engine.run(100000);
  const std::vector<ViewBox> boxes = engine.viewBoxes();
  corbel::render::HeadlessContext context;
  corbel::render::GlViewMapper mapper(0.1);
  for (auto _ : state) benchmark::DoNotOptimize(mapper.render(boxes, alpha().bounds()));
}
BENCHMARK(BM_GlViewMaps)->Unit(benchmark::kMillisecond);

// A full run with view maps from OSMesa at 0.25 m pixels.
void BM_FullRunGl(benchmark::State& state) {
  corbel::render::HeadlessContext context;
  corbel::render::GlViewMapper mapper(0.25);
  for (auto _ : state) {
    GrowthEngine engine(alpha(), {}, &mapper);
    state.counters["steps"] = engine.run(100000);
  }
}
BENCHMARK(BM_FullRunGl)->Unit(benchmark::kMillisecond);

void BM_FullRun(benchmark::State& state) {
  for (auto _ : state) {
    GrowthEngine engine(alpha());
    state.counters["steps"] = engine.run(100000);
    state.counters["moves"] = double(engine.commits());
  }
}
BENCHMARK(BM_FullRun)->Unit(benchmark::kMillisecond);

// Beta (100 m x 60 m, 6 storeys, 132 seeds) grown to completion: the goal is under 5 s.
// Arg 1: collide-and-extrude from CGAL's polygon difference instead of intervals.
void BM_FullRunBeta(benchmark::State& state) {
  static const Site beta = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-beta.json");
  GrowthOptions options;
  options.exactCollide = state.range(0) != 0;
  for (auto _ : state) {
    GrowthEngine engine(beta, options);
    state.counters["steps"] = engine.run(100000);
    state.counters["moves"] = double(engine.commits());
  }
}
BENCHMARK(BM_FullRunBeta)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Scale (issue 33): the Beta-like site tiled n × n (132 n² seeds; 3 × 3: 1,188 units on
// 300 m × 180 m) grown to the end. Wall time is what counts (the engine may use both cores).
void BM_FullRunBetaTiled(benchmark::State& state) {
  static const Site beta = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-beta.json");
  const Site site = tiledSite(beta, int(state.range(0)), int(state.range(0)));
  for (auto _ : state) {
    GrowthEngine engine(site, optionsFor(site, 1));
    state.counters["steps"] = engine.run(100000);
    state.counters["moves"] = double(engine.commits());
  }
  state.counters["units"] = double(site.seeds.size());
}
BENCHMARK(BM_FullRunBetaTiled)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// Collide-and-extrude's free columns (growth/collide.h) of every vertical face of grown Alpha
// that something lies within α of: arg 0 by intervals, 1 by CGAL's polygon difference (items =
// faces).
void BM_CollideColumns(benchmark::State& state) {
  GrowthEngine engine(alpha());
  engine.run(100000);
  std::vector<FaceObstacles> faces;
  for (std::size_t i = 0; i < engine.units().size(); ++i)
    for (int p = 0; p < int(engine.units()[i].parts.size()); ++p)
      for (Side s : kVerticalSides) {
        FaceObstacles f = engine.enforcer().obstaclesAhead(engine.units(), i, p, s, alpha().alpha);
        if (!f.obstacles.empty()) faces.push_back(std::move(f));
      }
  for (auto _ : state)
    for (const FaceObstacles& f : faces)
      benchmark::DoNotOptimize(state.range(0) ? freeColumns(f) : freeColumnsByIntervals(f));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(faces.size()));
  state.counters["faces"] = double(faces.size());
}
BENCHMARK(BM_CollideColumns)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The site editor (editor/growth_edits.h): one edit checked as the build would check it (parse,
// validate, the engine's constructor), which the panel does on every frame of a drag; Alpha (72
// seeds) and Beta (132). And the slice of grown Alpha's mesh (editor/growth_inspect.h).
corbel::GrowthSpec specOf(const std::string& name) {
  corbel::GrowthSpec spec;
  spec.site = corbel::readFile(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name, 1 << 24);
  return spec;
}

void BM_SiteEditCheck(benchmark::State& state) {
  const corbel::GrowthSpec spec = specOf(state.range(0) ? "growth-beta.json" : "growth-alpha.json");
  const auto hand = corbel::editor::handPlaced(spec.site);
  const Rect core = hand.cores.at(0);
  for (auto _ : state) {
    const auto r = corbel::editor::setCore(spec, 0, core);  // the same place: valid, full check
    if (!r.spec) state.SkipWithError(r.error.c_str());
    benchmark::DoNotOptimize(r.spec);
  }
  state.counters["seeds"] = double(parseSite(spec.site).seeds.size());
}
BENCHMARK(BM_SiteEditCheck)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SliceGrownAlpha(benchmark::State& state) {
  corbel::GrowthSpec spec = specOf("growth-alpha.json");
  spec.steps = -1;
  const GrownModel grown = grow(spec);
  corbel::MeshData mesh;
  for (const Unit& u : grown.units) mesh.append(unitMesh(u));
  for (auto _ : state) benchmark::DoNotOptimize(corbel::editor::sliceBelow(mesh, 9.0));
  state.counters["faces"] = double(mesh.faces.size());
}
BENCHMARK(BM_SliceGrownAlpha)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
