#pragma once
// The growth simulation (Ch. 4, Fig. 4.1–4.2). Each step:
//  1. arbitration orders the growing units (pluggable; by default units with the largest view
//     deficit tend to go first, every growing unit moves once per step, ties broken at random
//     from the run's seed);
//  2. behaviour invocation: each unit's behaviour proposes candidate moves;
//  3. the constraint enforcer drops invalid moves (and trims advances at obstacles), and the
//     view-conflict rule drops moves that would take more than τ of another unit's best view;
//  4. the behaviour picks its best valid move, which is committed at once; at the end of the
//     step the form quantifiers (floor area, volume, view maps) are updated.
// A unit stops when it reaches its target (floor area or volume) or has had no valid move
// for `patience` steps. Runs are deterministic for a seed.
#include "growth/constraints.h"
#include "growth/rng.h"
#include "growth/site.h"
#include "growth/unit.h"
#include "growth/view_map.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace corbel::growth {

// Fixed: a unit already there (Site::fixed), which never moves.
enum class UnitStatus { Growing, Reached, Stuck, Fixed };

// A unit and its form quantifiers and behaviour state.
struct UnitState {
  Unit unit;
  double target = 0;  // floor area (m²) or volume (m³)
  bool byVolume = false;
  std::string behaviour;
  UnitStatus status = UnitStatus::Growing;
  double view = 0;      // current view (m²), from the last view maps
  double peakView = 0;  // the most it has had
  double goalView = 0;  // GrowthOptions::viewGoalRatio × target floor area
  int idleSteps = 0;    // consecutive steps without a valid move
  int moves = 0;
  // Shape variation (Sec. 5.3): the target is grown as `subUnits` sub-units one after another.
  int subUnits = 1;
  int subUnitsStarted = 1;
  int activePart = 0;
  Side activeSide = Side::PosX;  // the face the current sub-unit grows from
  double activeStart = 0;        // that face's coordinate when the sub-unit started
  bool wantsDoubleVolume = false;
  bool doubleVolumeDone = false;

  double progress() const { return byVolume ? unit.volume() : unit.floorArea(); }
};

// A run's options: the site's growth settings (GrowthSettings, growth/site.h) and the seed.
struct GrowthOptions : GrowthSettings {
  std::uint64_t seed = 1;
  // Collide-and-extrude from CGAL's polygon difference (growth/collide.h's freeColumns) rather
  // than its interval twin: the same splits, slower.
  bool exactCollide = false;
};
// The options of a run on `site`: its growth settings and the seed.
GrowthOptions optionsFor(const Site& site, std::uint64_t seed);

class GrowthEngine;

// A valid move with its gain in view.
struct ScoredMove {
  Move move;
  ViewGain view;
};

// What a behaviour sees of the run.
struct BehaviourContext {
  const GrowthEngine& engine;
  std::size_t unit;
  Rng& rng;
  UnitState& state;
};

// Unit behaviour (Ch. 4.1, Unit Behavior Manager): registered by name, chosen per seed.
class Behaviour {
 public:
  virtual ~Behaviour() = default;
  virtual std::vector<Move> propose(BehaviourContext& ctx) = 0;
  // The index of the move to commit among the valid ones (non-empty), or -1 for none.
  virtual int choose(BehaviourContext& ctx, const std::vector<ScoredMove>& valid) = 0;
  // After the engine committed the chosen move (as trimmed by the enforcer).
  virtual void committed(BehaviourContext&, const Move&) {}
};

// The default behaviour: view-guided growth (Sec. 5.2) with shape variation (Sec. 5.3).
std::shared_ptr<Behaviour> makeViewBehaviour();

class Arbitration {
 public:
  virtual ~Arbitration() = default;
  // An order of `growing` (indices into units) for this step.
  virtual std::vector<std::size_t> order(const std::vector<UnitState>& units, std::vector<std::size_t> growing,
                                         const GrowthOptions& options, Rng& rng) = 0;
};
// Every growing unit once per step, in a random order weighted by view deficit (exponential
// races: a unit with twice the weight is twice as likely to go before another).
std::unique_ptr<Arbitration> makeViewDeficitArbitration();
std::unique_ptr<Arbitration> makeRandomArbitration();
// Units in seed order (no randomness).
std::unique_ptr<Arbitration> makeSequentialArbitration();

struct CommitRecord {
  int step = 0;
  std::size_t unit = 0;
  Move move;
};

class GrowthEngine {
 public:
  // The site must stay alive; `mapper` (if given) too. Without one the exact CPU mapper is
  // used. Throws InputError for a seed naming no registered behaviour.
  GrowthEngine(const Site& site, GrowthOptions options = {}, ViewMapper* mapper = nullptr,
               std::map<std::string, std::shared_ptr<Behaviour>> extraBehaviours = {});
  // The enforcer indexes units_ by address (ConstraintEnforcer::index), so an engine stays put.
  GrowthEngine(const GrowthEngine&) = delete;
  GrowthEngine& operator=(const GrowthEngine&) = delete;

  void setArbitration(std::unique_ptr<Arbitration> a) { arbitration_ = std::move(a); }
  void onCommit(std::function<void(const GrowthEngine&, const CommitRecord&)> f) { onCommit_ = std::move(f); }

  // One simulation step; false when no unit is growing any more (then nothing changed).
  bool step();
  // Steps until every unit stopped or `maxSteps` steps ran; returns the steps run.
  int run(int maxSteps);
  bool done() const;

  const Site& site() const { return site_; }
  const GrowthOptions& options() const { return options_; }
  const ConstraintEnforcer& enforcer() const { return enforcer_; }
  const std::vector<UnitState>& states() const { return states_; }
  const std::vector<Unit>& units() const { return units_; }
  const ViewMaps& views() const { return views_; }
  int steps() const { return steps_; }
  std::size_t commits() const { return commits_; }
  // Per unit, whether it is still growing (status Growing), kept up to date as statuses change.
  const std::vector<bool>& growing() const { return growing_; }
  // The view maps' boxes: every part (id = unit id) and cores and circulation (kObstacleId).
  std::vector<ViewBox> viewBoxes() const;

 private:
  void updateQuantifiers();
  const Site& site_;
  GrowthOptions options_;
  ConstraintEnforcer enforcer_;
  std::unique_ptr<ViewMapper> ownMapper_;
  ViewMapper* mapper_;
  std::map<std::string, std::shared_ptr<Behaviour>> behaviours_;
  std::unique_ptr<Arbitration> arbitration_;
  std::function<void(const GrowthEngine&, const CommitRecord&)> onCommit_;
  std::vector<UnitState> states_;
  std::vector<bool> growing_;  // by unit: status == Growing
  std::vector<Unit> units_;  // the units alone, for the enforcer (kept equal to states_[i].unit)
  ViewMaps views_;
  Rng rng_;
  int steps_ = 0;
  std::size_t commits_ = 0;
};

}  // namespace corbel::growth
