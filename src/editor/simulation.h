#pragma once
// The statics panel's "Simulate" section without GL or ImGui (Whiting et al. 2009, Sec. 5,
// Fig. 14): a collapse simulation (sim::Session) of one masonry spec, played a bounded slice of
// wall time per frame so the window stays responsive (on a worker thread once a single step
// costs more than the slice), shaken or robbed of a block, and drawn in place of the design's
// blocks. It owns a copy of the design; the Document and its undo history
// are never touched, and reset() returns to the design state.
#include "core/placement.h"
#include "core/masonry_spec.h"
#include "core/mesh_data.h"
#include "core/scene.h"
#include "sim/session.h"

#include <cstdint>
#include <functional>
#include <future>
#include <string>
#include <vector>

namespace corbel::editor {

// The most wall time a frame spends stepping while playing: a 60 Hz frame keeps ~6 ms for the
// rest of the editor. A model that needs more per simulated frame plays slower than real time.
inline constexpr double kSimFrameBudget = 0.010;  // s

class Simulation {
 public:
  // A monotonic clock in seconds; the default reads std::chrono::steady_clock.
  using Clock = std::function<double()>;

  // Builds the spec's model (statics::modelOf) and a session with the spec's friction. Throws
  // corbel::Error (InputError for a bad spec) when the model cannot be built or simulated.
  explicit Simulation(const MasonrySpec& spec, Clock clock = {});
  ~Simulation();  // waits for the worker's steps
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // The spec the simulation was made from: it shows only while the object still has it.
  const MasonrySpec& spec() const { return spec_; }
  const statics::Assembly& design() const { return session_.design(); }
  const sim::SimSettings& settings() const { return session_.settings(); }

  // Everything below waits for steps running on the worker first, except advance(), which
  // collects them only once they are done, and the state readers, which show the last state
  // collected.
  void play();
  void pause();
  void togglePlay() { playing() ? pause() : play(); }
  bool playing() const { return playing_; }

  // `steps` fixed steps at once, playing or not (the Step button, scripted runs).
  void step(int steps = 1);
  // One frame while playing: steps to catch up with `wallSeconds` of real time since the last
  // frame, one at a time, and stops once `budget` seconds of wall time have gone on stepping
  // (at least one step is taken when any is due). A backlog the budget could not cover is
  // dropped, so a slow model runs slower than real time instead of falling ever further behind.
  // Once one step has taken longer than the whole budget, the frame's steps go to a worker
  // thread instead and the frame returns at once; a later frame collects them when they are
  // done (the view meanwhile shows the last state). Returns the steps that this call took or
  // collected; none while paused.
  int advance(double wallSeconds, double budget = kSimFrameBudget);
  // Waits for the worker's steps and collects them (scripted runs, tests).
  void finish();
  bool stepping() const { return batch_.valid(); }  // steps are running on the worker

  // The design state, paused; the perturbations are forgotten.
  void reset();
  // The paper's ground shake (4 m/s within 1/60 s on 10 m), scaled to the model (sim::paperShake).
  void shake();
  // Takes the named block out of the world (Fig. 14b). Throws corbel::Error for an unknown,
  // fixed or already removed block.
  void removeBlock(const std::string& name);

  // The blocks that can still be removed (not fixed, not removed), by name in design order.
  std::vector<std::string> removableBlocks() const;
  // The default choice for the remove-block tool: the removable block whose highest point is
  // highest (an arch's keystone), or "" when there is none.
  std::string topBlock() const;

  // The state as of the last steps collected.
  double time() const { return shown_.time; }
  long steps() const { return shown_.steps; }
  const std::vector<sim::Pose>& poses() const { return shown_.poses; }
  // The largest displacement of any block's farthest vertex since reset, m.
  double largestDisplacement() const { return shown_.largest; }
  int fallenCount() const { return shown_.fallen; }
  // What is drawn in place of the design's blocks: the blocks where they are now, without the
  // removed ones, in the spec's material.
  const MeshData& mesh() const { return shown_.mesh; }
  // Counts every change to what mesh() gives (a step, reset, a removal), for redrawing.
  std::uint64_t revision() const { return revision_; }

  // The block a ray from `origin` along `direction` first enters, where the blocks are now
  // (removed ones left out), or -1: picking a block in the 3D view. Fixed blocks count, so a
  // click on the ground does not reach a block behind it.
  int blockAt(const Vec3& origin, const Vec3& direction) const;

 private:
  // What the readers show, taken from the session between steps.
  struct State {
    double time = 0;
    long steps = 0;
    std::vector<sim::Pose> poses;
    std::vector<bool> removed;
    double largest = 0;
    int fallen = 0;
    MeshData mesh;
  };
  State capture() const;
  void show(State state);  // the readers' state from now on

  MasonrySpec spec_;
  sim::Session session_;  // touched by the worker while batch_ runs, by nobody else
  Clock clock_;
  bool playing_ = false;
  State shown_;
  std::uint64_t revision_ = 0;
  double pending_ = 0;        // wall time not yet turned into steps (under one step)
  double stepCost_ = 0;       // wall time of the last step timed, s
  std::future<State> batch_;  // steps on the worker, with the state they end in
};

// Draws the simulation in `scene` (the viewport's copy of the Scene, never the one that follows
// the Document): object `id`'s faces become the simulation's blocks; it keeps its name and kind.
void showSimulation(Scene& scene, ObjectId id, const Simulation& simulation, const Placement& placement = {});

}  // namespace corbel::editor
