// Masonry statics: one penalty QP on walls of about 100, 1,000 and 5,000 blocks, and one
// iteration of the parameter search (one QP and its envelope gradient) on the paper's
// examples. Results: docs/benchmarks.md.
#include "compose/stone_extrusion.h"
#include "core/project_io.h"
#include "statics/analysis.h"
#include "statics/builder.h"
#include "statics/examples.h"
#include "statics/search.h"
#include "statics/sensitivity.h"
#include "statics/wall.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using namespace corbel::statics;

// A running-bond wall of half-metre blocks, about `blocks` of them, as wide as it is tall.
Assembly wall(int blocks) {
  WallSpec w;
  const int perCourse = int(std::lround(std::sqrt(blocks)));
  w.blockLength = 0.5;
  w.length = perCourse * w.blockLength;
  w.courses = perCourse;
  w.height = perCourse * 0.25;
  w.thickness = 0.4;
  StructureBuilder b;
  b.add("wall", wallBlocks(w));
  b.groundUnder(1.0);
  return b.build();
}

void WallQP(benchmark::State& state) {
  const Assembly as = wall(int(state.range(0)));
  AnalysisOptions o;
  o.solver.schurSolver = state.range(1) == 0   ? SchurSolver::BlockLdlt
                         : state.range(1) == 1 ? SchurSolver::Cholmod
                                               : SchurSolver::EigenLdlt;
  AnalysisResult r;
  for (auto _ : state) {
    r = analyse(as, o);
    benchmark::DoNotOptimize(r.y);
  }
  state.counters["blocks"] = double(as.blocks.size() - 1);
  state.counters["iterations"] = r.iterations;
  state.counters["optimal"] = r.status == SolveStatus::Optimal;
}
// Second argument, the Schur solver: 0 ours on 6×6 blocks, 1 CHOLMOD's supernodal LLᵀ, 2 Eigen's SimplicialLDLT.
// Wall time: large walls find their contacts and factor on two threads (docs/statics.md).
BENCHMARK(WallQP)
    ->ArgsProduct({{100, 1000, 5000}, {0, 1, 2}})
    ->ArgNames({"blocks", "solver"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// The QP's reach: 10,000 blocks (a cathedral front), our Schur solver only.
BENCHMARK(WallQP)->Args({10000, 0})->ArgNames({"blocks", "solver"})->UseRealTime()->Unit(benchmark::kMillisecond);

// An extrusion of the stone house example (assets/examples/stone-house.corbel), built in stone.
corbel::ExtrusionSpec stoneHouseSpec(const std::string& object) {
  const corbel::LoadedProject p =
      corbel::loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel");
  const corbel::DocObject* o = p.document.findByName(object);
  const auto* spec = o ? std::get_if<corbel::ExtrusionSpec>(&o->spec) : nullptr;
  if (!spec) throw std::runtime_error("stone-house.corbel has no extrusion \"" + object + "\"");
  return *spec;
}

// What the statics panel does after an edit of the stone house: the walls coursed from the
// extrusion, loaded by the roof, and analysed (one penalty QP).
void StoneHouseAnalyse(benchmark::State& state) {
  const corbel::ExtrusionSpec spec = stoneHouseSpec("Stone house");
  AnalysisResult r;
  std::size_t blocks = 0;
  for (auto _ : state) {
    const ParametricModel m = stoneModel(spec);
    const Assembly as = m.build(m.parameters);
    blocks = as.blocks.size() - 1;
    r = analyse(as, {});
    benchmark::DoNotOptimize(r.y);
  }
  state.counters["blocks"] = double(blocks);
}
BENCHMARK(StoneHouseAnalyse)->Unit(benchmark::kMillisecond);

// A whole search (Make It Stand) over the model's suggested free parameters from its saved values.
void WholeSearch(benchmark::State& state, const ParametricModel& m) {
  for (auto _ : state) {
    const auto r = corbel::statics::searchParameters(m, m.suggestedFree);
    benchmark::DoNotOptimize(r.measure);
    state.counters["evaluations"] = r.evaluations;
    state.counters["stands"] = r.status == corbel::statics::SearchStatus::Feasible;
  }
  state.counters["blocks"] = double(m.build(m.parameters).blocks.size() - 1);
}

// Make It Stand on the thin-walled house (its roof's thrust overturns the walls): the search
// over the wall thickness.
void StoneHouseMakeItStand(benchmark::State& state) {
  WholeSearch(state, stoneModel(stoneHouseSpec("Stone house, thin walls")));
}
BENCHMARK(StoneHouseMakeItStand)->Unit(benchmark::kMillisecond)->Iterations(1);

void SearchIteration(benchmark::State& state, const ParametricModel& model) {
  for (auto _ : state) {
    const MeasureEvaluation ev = evaluateMeasure(model, model.parameters, model.suggestedFree, {}, true);
    benchmark::DoNotOptimize(ev.gradient.data());
  }
}
void BarrelVaultIteration(benchmark::State& state) { SearchIteration(state, barrelVaultExample()); }
void TowerIteration(benchmark::State& state) { SearchIteration(state, towerExample()); }
BENCHMARK(BarrelVaultIteration)->Unit(benchmark::kMillisecond);
BENCHMARK(TowerIteration)->Unit(benchmark::kMillisecond);

// The vault's whole search from its start (buttress width 0.1 m, which does not stand).
void BarrelVaultSearch(benchmark::State& state) {
  const ParametricModel m = barrelVaultExample();
  for (auto _ : state) {
    const auto r = corbel::statics::searchParameters(m, m.suggestedFree);
    benchmark::DoNotOptimize(r.measure);
  }
}
BENCHMARK(BarrelVaultSearch)->Unit(benchmark::kMillisecond);

// Table 1's large models, whole searches from their defaults (which do not stand) with their
// four free parameters: the chapel (Fig. 9, 480 blocks) and the abbey nave (Fig. 1, 988).
void PaperModelSearch(benchmark::State& state) {
  WholeSearch(state, state.range(0) == 0 ? corbel::statics::chapelExample() : corbel::statics::abbeyExample());
}
// Argument: 0 the chapel, 1 the abbey.
BENCHMARK(PaperModelSearch)->Arg(0)->Arg(1)->ArgName("abbey")->Unit(benchmark::kMillisecond)->Iterations(1);

// One interactive update (Fig. 13): the radius widened from 2 m to 2.3 m (span 4 → 4.6 m), the buttress width
// searched again from the previous result.
void BarrelVaultUpdate(benchmark::State& state) {
  const ParametricModel m = barrelVaultExample();
  const auto previous = corbel::statics::searchParameters(m, m.suggestedFree);
  corbel::statics::SearchOptions o;
  o.strictCheck = state.range(0) != 0;
  for (auto _ : state) {
    const auto r = corbel::statics::updateAfterEdit(m, m.suggestedFree, previous.values, "radius", 2.3, o);
    benchmark::DoNotOptimize(r.measure);
    state.counters["evaluations"] = r.evaluations;
  }
}
// Argument: 1 with the strict LP check of the result, 0 without (what a drag loop needs).
BENCHMARK(BarrelVaultUpdate)->Arg(1)->Arg(0)->ArgName("strict")->Unit(benchmark::kMillisecond);

// The same update on the vault with flying buttresses (180 blocks): the vault widened from a
// radius of 2 m to 2.2 m, the flyers' reach searched again from the last result (no LP check).
void FlyingButtressUpdate(benchmark::State& state) {
  const ParametricModel m = flyingButtressVaultExample();
  const auto previous = corbel::statics::searchParameters(m, m.suggestedFree);
  corbel::statics::SearchOptions o;
  o.strictCheck = false;
  for (auto _ : state) {
    const auto r = corbel::statics::updateAfterEdit(m, m.suggestedFree, previous.values, "radius", 2.2, o);
    benchmark::DoNotOptimize(r.measure);
    state.counters["evaluations"] = r.evaluations;
  }
}
BENCHMARK(FlyingButtressUpdate)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
