// Collapse-simulation speed (docs/benchmarks.md): simulated seconds per wall-clock second on
// the chapel (Fig. 9, 480 blocks) and abbey nave (Fig. 1, 988 blocks) at the parameters their
// searches found (assets/examples/masonry-{chapel,abbey}.corbel), and on the barrel vault of
// Fig. 13 lengthened to about 500 and 1,000 blocks, standing and shaken.
#include "core/error.h"
#include "core/project_io.h"
#include "sim/session.h"
#include "statics/examples.h"
#include "statics/kernel.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace corbel;

// The vault with `rings` rings of 1 m (12 voussoirs each, on buttressed walls of 4 courses):
// 28 blocks a ring, so 18 rings make 505 blocks with the ground and 36 make 1,009. Buttresses
// 0.8 m wide: the statics example then stands (y/W² ≈ 1e-14).
statics::Assembly vault(int rings) {
  statics::ParametricModel m = statics::exampleByName("barrel-vault");
  statics::ParameterSet p = m.parameters;
  p.set("rings", rings);
  p.set("length", rings);
  p.set("buttressWidth", 0.8);
  return m.build(p);
}

// The one masonry object of an example project, as the project sets it.
statics::Assembly projectModel(const std::string& name) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-" + name + ".corbel");
  for (const DocObject& o : p.document.objects)
    if (const auto* spec = std::get_if<MasonrySpec>(&o.spec)) {
      const statics::ParametricModel m = statics::modelOf(*spec);
      return m.build(m.parameters);
    }
  throw Error(name + ": no masonry object");
}

// Simulates 0.1 s (24 steps) an iteration, with the default solver (the contact QP) unless
// said otherwise, from the design or after the paper's shake scaled
// to the model; the counter is simulated seconds per second of real time.
void simulate(benchmark::State& state, const statics::Assembly& as, const sim::SimSettings& settings, bool shaken) {
  sim::Session session(as, settings);
  if (shaken) {
    const sim::ShakeSpec paper = sim::paperShake(as);
    session.shake(Vec3(paper.velocity, 0, 0), paper.duration);
  }
  double simulated = 0;
  for (auto _ : state) {
    session.step(24);
    simulated += 24 * settings.timeStep;
  }
  state.counters["blocks"] = double(as.blocks.size());
  state.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}

// Argument: 1 for the shake.
void BM_SimulatePaperModel(benchmark::State& state, const std::string& name) {
  simulate(state, projectModel(name), {}, state.range(0) != 0);
}
void paperModelRuns(benchmark::internal::Benchmark* b) {
  b->ArgName("shake")->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
}
BENCHMARK_CAPTURE(BM_SimulatePaperModel, chapel, std::string("chapel"))->Apply(paperModelRuns);
BENCHMARK_CAPTURE(BM_SimulatePaperModel, abbey, std::string("abbey"))->Apply(paperModelRuns);
BENCHMARK_CAPTURE(BM_SimulatePaperModel, groin, std::string("groin"))->Apply(paperModelRuns);

// The same with Bullet's sequential impulses (200 iterations) in place of the contact QP.
void BM_SimulateWithBulletsSolver(benchmark::State& state, const std::string& name) {
  sim::SimSettings settings;
  settings.solver = sim::Solver::SequentialImpulse;
  simulate(state, projectModel(name), settings, state.range(0) != 0);
}
BENCHMARK_CAPTURE(BM_SimulateWithBulletsSolver, chapel, std::string("chapel"))->Apply(paperModelRuns);
BENCHMARK_CAPTURE(BM_SimulateWithBulletsSolver, groin, std::string("groin"))->Apply(paperModelRuns);

// Arguments: rings, 1 for the shake (sim::paperShake: 5.4 m/s within 1/45 s on 18 rings,
// 7.6 m/s within 1/32 s on 36), Bullet's solver's iterations (0: the contact QP).
void BM_SimulateVault(benchmark::State& state) {
  sim::SimSettings settings;
  if (state.range(2) > 0) {
    settings.solver = sim::Solver::SequentialImpulse;
    settings.solverIterations = int(state.range(2));
  }
  simulate(state, vault(int(state.range(0))), settings, state.range(1) != 0);
}
BENCHMARK(BM_SimulateVault)
    ->ArgNames({"rings", "shake", "iterations"})
    ->Args({18, 0, 0})
    ->Args({18, 1, 0})
    ->Args({36, 0, 0})
    ->Args({18, 0, 200})
    ->Args({18, 1, 200})
    ->Args({36, 0, 200})
    ->Args({36, 1, 200})
    ->Args({18, 0, 50})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
