#include "growth/engine.h"

#include "core/error.h"
#include "growth/collide.h"
#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace corbel::growth {

namespace {

class ViewDeficitArbitration : public Arbitration {
 public:
  std::vector<std::size_t> order(const std::vector<UnitState>& units, std::vector<std::size_t> growing,
                                 const GrowthOptions& options, Rng& rng) override {
    (void)options;  // the goal view is set per unit from viewGoalRatio
    std::vector<std::pair<double, std::size_t>> keyed;
    for (std::size_t i : growing) {
      const UnitState& s = units[i];
      const double deficit = std::clamp((s.goalView - s.view) / std::max(s.goalView, 1e-9), 0.0, 1.0);
      const double weight = 0.1 + deficit;  // never zero: every unit keeps its turn
      keyed.push_back({-std::log(1.0 - rng.uniform()) / weight, i});
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::size_t> out;
    for (auto& [k, i] : keyed) out.push_back(i);
    return out;
  }
};

class RandomArbitration : public Arbitration {
 public:
  std::vector<std::size_t> order(const std::vector<UnitState>&, std::vector<std::size_t> growing, const GrowthOptions&,
                                 Rng& rng) override {
    for (std::size_t i = growing.size(); i > 1; --i) std::swap(growing[i - 1], growing[rng.below(int(i))]);
    return growing;
  }
};

class SequentialArbitration : public Arbitration {
 public:
  std::vector<std::size_t> order(const std::vector<UnitState>&, std::vector<std::size_t> growing, const GrowthOptions&,
                                 Rng&) override {
    return growing;
  }
};

class ViewBehaviour : public Behaviour {
 public:
  std::vector<Move> propose(BehaviourContext& ctx) override {
    UnitState& s = ctx.state;
    const Site& site = ctx.engine.site();
    const Unit& u = s.unit;
    std::vector<Move> moves;
    pending_.clear();
    // Shape variation: the next sub-unit starts from a split of the face with the largest
    // clearance (Sec. 5.3, "Choice of Splitting Face").
    // A unit that found no valid move last step also tries a new sub-unit.
    const bool due = s.subUnitsStarted < s.subUnits && s.progress() >= s.target * s.subUnitsStarted / s.subUnits;
    if (due || s.idleSteps > 0) {
      double best = -1;
      Move split;
      Side splitSide = Side::PosX;
      const std::vector<bool>& growing = ctx.engine.growing();
      for (int p = 0; p < int(u.parts.size()); ++p)
        for (Side side : kVerticalSides) {
          if (u.locked[int(side)] || sideTouchesOwnPart(u, p, side)) continue;
          const int along = 1 - sideAxis(side);
          const Box& b = u.parts[p];
          // Both pieces at least 3 m wide and within the aspect limit.
          const double least = std::max(kMinPartWidth, b.size(1 - along) / ctx.engine.options().maxAspect);
          if (b.size(along) < 2 * least) continue;
          // Look-ahead: room for 3 m even if the growing neighbours come 3 m closer meanwhile.
          const double clearance =
              ctx.engine.enforcer().lookAhead(ctx.engine.units(), ctx.unit, p, side, 1e3, kMinPartWidth, growing);
          if (clearance > best + kEps) {
            best = clearance;
            const double t = b.lo[along] + least + ctx.rng.uniform() * (b.size(along) - 2 * least);
            split = Move::split(p, along, t);
            splitSide = side;
          }
        }
      if (best >= kMinPartWidth) {
        moves.push_back(split);
        pending_.push_back({split, splitSide, -1});
      } else if (due) {
        s.subUnitsStarted = s.subUnits;  // no room for another sub-unit: grow what there is
      }
    }
    proposeCollideSplits(ctx, moves);
    if (s.progress() < s.target) proposeStairBases(ctx, moves);
    // Double volume once the unit has half its target (Sec. 5.3, "Choice of Unit Height").
    if (s.wantsDoubleVolume && !s.doubleVolumeDone && s.progress() >= 0.5 * s.target)
      for (int p = 0; p < int(u.parts.size()); ++p)
        for (Side side : {Side::Top, Side::Bottom})
          if (!u.locked[int(side)]) moves.push_back(Move::advance(p, side, site.storeyHeight));
    // Face advances, except those that would stretch a part past maxAspect (the elongated,
    // unusable units of Sec. 5.3).
    for (int p = 0; p < int(u.parts.size()); ++p)
      for (Side side : kVerticalSides) {
        if (u.locked[int(side)] || sideTouchesOwnPart(u, p, side)) continue;
        const Box& b = u.parts[p];
        const double along = b.size(sideAxis(side)) + site.alpha, across = b.size(1 - sideAxis(side));
        if (along > ctx.engine.options().maxAspect * across + kEps) continue;
        moves.push_back(Move::advance(p, side, site.alpha));
      }
    return moves;
  }

  int choose(BehaviourContext& ctx, const std::vector<ScoredMove>& valid) override {
    UnitState& s = ctx.state;
    const Unit& u = s.unit;
    for (int i = 0; i < int(valid.size()); ++i)
      if (valid[i].move.type == Move::Type::StairBase) return i;  // a rare chance, taken whole
    for (int i = 0; i < int(valid.size()); ++i)
      if (valid[i].move.type == Move::Type::Split) return i;
    for (int i = 0; i < int(valid.size()); ++i)
      if (sideAxis(valid[i].move.side) == 2) return i;
    // A new sub-unit first grows out of its face until it is 3 m deep.
    const Box& active = u.parts[std::min<std::size_t>(s.activePart, u.parts.size() - 1)];
    if (s.subUnitsStarted > 1 && std::abs(sideCoord(active, s.activeSide) - s.activeStart) < kMinPartWidth)
      for (int i = 0; i < int(valid.size()); ++i)
        if (valid[i].move.part == s.activePart && valid[i].move.side == s.activeSide) return i;
    const bool aspect = ctx.rng.uniform() < ctx.engine.options().aspectChance;
    int best = -1;
    double bestScore = 0;
    for (int i = 0; i < int(valid.size()); ++i) {
      const ScoredMove& m = valid[i];
      const Box& b = u.parts[m.move.part];
      double score;
      if (aspect) {
        // The move that leaves the part closest to square.
        Box grown = b;
        const int k = sideAxis(m.move.side);
        grown.hi[k] += m.move.distance;
        score = -std::max(grown.size(0), grown.size(1)) / std::min(grown.size(0), grown.size(1));
      } else {
        double taken = 0;
        for (const auto& [id, a] : m.view.taken) taken += a;
        score = m.view.gain - ctx.engine.options().intrusionPenalty * taken;
      }
      // The sub-unit being grown goes first; other parts only when it is stuck.
      if (m.move.part == s.activePart) score += 1e6;
      score += 1e-9 * ctx.rng.uniform();  // random ties
      if (best < 0 || score > bestScore) {
        best = i;
        bestScore = score;
      }
    }
    return best;
  }

  void committed(BehaviourContext& ctx, const Move& m) override {
    UnitState& s = ctx.state;
    if (m.type == Move::Type::Split) {
      Pending why{m, Side::PosX, -1};
      for (const Pending& p : pending_)
        if (p.move == m) why = p;
      s.subUnits = std::max(s.subUnits, ++s.subUnitsStarted);
      // The piece that grows the new sub-unit (the low piece keeps the index): either, or the
      // free one after a collision.
      const bool high = why.piece < 0 ? ctx.rng.uniform() < 0.5 : why.piece == 1;
      s.activePart = high ? int(s.unit.parts.size()) - 1 : m.part;
      s.activeSide = why.side;
      s.activeStart = sideCoord(s.unit.parts[s.activePart], s.activeSide);
    } else if (m.type == Move::Type::StairBase || sideAxis(m.side) == 2) {
      s.doubleVolumeDone = true;
    }
    pending_.clear();
  }

 private:
  // Collide-and-extrude (Sec. 5.3, Fig. 5.3): when obstacles cover only part of a face of the
  // growing part, the face is split at an obstacle's edge so a free piece can extrude past it.
  // The free region is face − obstacles (growth/collide.h: CGAL's polygon difference, or the
  // interval twin the tests hold to it); a split frees a piece whose whole height is free.
  void proposeCollideSplits(BehaviourContext& ctx, std::vector<Move>& moves) {
    const UnitState& s = ctx.state;
    const Unit& u = s.unit;
    const int p = std::min<int>(s.activePart, int(u.parts.size()) - 1);
    const Box& b = u.parts[p];
    const double alpha = ctx.engine.site().alpha;
    for (Side side : kVerticalSides) {
      if (u.locked[int(side)] || sideTouchesOwnPart(u, p, side)) continue;
      if (ctx.engine.enforcer().freeDistance(ctx.engine.units(), ctx.unit, p, side, alpha) >= alpha) continue;
      const int along = 1 - sideAxis(side);
      const double least = std::max(kMinPartWidth, b.size(sideAxis(side)) / ctx.engine.options().maxAspect);
      const FaceObstacles f = ctx.engine.enforcer().obstaclesAhead(ctx.engine.units(), ctx.unit, p, side, alpha);
      if (f.obstacles.empty()) continue;  // only the envelope is in the way
      const std::vector<Interval> columns =
          ctx.engine.options().exactCollide ? freeColumns(f) : freeColumnsByIntervals(f);
      const std::vector<CollideSplit> splits = collideSplits(f.face, columns, least);
      if (splits.empty()) continue;
      moves.push_back(Move::split(p, along, splits.front().at));
      pending_.push_back({moves.back(), side, splits.front().freeHigh ? 1 : 0});
    }
  }

  // Fig. 5.4: a face of the growing part that has reached an external staircase whose roof is
  // one storey below the part's floor may take the staircase's whole top, if the look-ahead
  // finds all of it clear even after the growing neighbours' next advance.
  void proposeStairBases(BehaviourContext& ctx, std::vector<Move>& moves) {
    const UnitState& s = ctx.state;
    const Unit& u = s.unit;
    const Site& site = ctx.engine.site();
    if (site.circulation.empty() || int(u.parts.size()) >= kMaxParts) return;
    const int p = std::min<int>(s.activePart, int(u.parts.size()) - 1);
    const Box& b = u.parts[p];
    const std::vector<bool>& growing = ctx.engine.growing();
    std::vector<std::size_t> near;
    for (Side side : kVerticalSides) {
      if (u.locked[int(side)] || sideTouchesOwnPart(u, p, side)) continue;
      // Only a staircase within α of the face can be reached (stairBasePart's rule).
      ctx.engine.enforcer().circulationNear(grown(footprint(sweptRegion(b, side, site.alpha)), 1e-6), near);
      for (std::size_t c : near) {
        const std::optional<Box> part = stairBasePart(b, side, site.circulation[c], site.storeyHeight, site.alpha);
        if (!part) continue;
        const int k = sideAxis(side);
        Box face = *part;  // the new part's face on the plane of b's side
        face.lo[k] = face.hi[k] = sideCoord(b, side);
        const double depth = part->size(k);
        if (ctx.engine.enforcer().lookAheadFrom(ctx.engine.units(), ctx.unit, face, side, depth, site.alpha, growing) >=
            depth - kEps)
          moves.push_back(Move::stairBase(p, side, int(c)));
      }
    }
  }

  struct Pending {
    Move move;
    Side side;  // the face the new sub-unit grows from
    int piece;  // 0 low, 1 high, -1 either
  };
  std::vector<Pending> pending_;  // this turn's proposed splits, from propose to committed
};

}  // namespace

std::shared_ptr<Behaviour> makeViewBehaviour() { return std::make_shared<ViewBehaviour>(); }
std::unique_ptr<Arbitration> makeViewDeficitArbitration() { return std::make_unique<ViewDeficitArbitration>(); }
std::unique_ptr<Arbitration> makeRandomArbitration() { return std::make_unique<RandomArbitration>(); }
std::unique_ptr<Arbitration> makeSequentialArbitration() { return std::make_unique<SequentialArbitration>(); }

GrowthOptions optionsFor(const Site& site, std::uint64_t seed) {
  GrowthOptions o;
  static_cast<GrowthSettings&>(o) = site.growth;
  o.seed = seed;
  return o;
}

GrowthEngine::GrowthEngine(const Site& site, GrowthOptions options, ViewMapper* mapper,
                           std::map<std::string, std::shared_ptr<Behaviour>> extraBehaviours)
    : site_(site),
      options_(options),
      enforcer_(site),
      mapper_(mapper),
      behaviours_(std::move(extraBehaviours)),
      arbitration_(makeViewDeficitArbitration()),
      rng_(options.seed) {
  validateSite(site);
  if (!mapper_) {
    ownMapper_ = std::make_unique<ExactViewMapper>();
    mapper_ = ownMapper_.get();
  }
  behaviours_.try_emplace("view", makeViewBehaviour());
  for (std::size_t i = 0; i < site.seeds.size(); ++i) {
    const Seed& seed = site.seeds[i];
    if (!behaviours_.count(seed.behaviour))
      throw InputError("seeds[" + std::to_string(i) + "].behaviour", "no behaviour named \"" + seed.behaviour + "\"");
    UnitState s;
    s.unit.id = int(i) + 1;
    s.unit.parts = {site.seedBox(i)};
    s.unit.locked = seed.locked;
    s.byVolume = seed.targetVolume > 0;
    s.target = s.byVolume ? seed.targetVolume : seed.targetArea;
    s.behaviour = seed.behaviour;
    const double floorTarget = s.byVolume ? s.target / site.storeyHeight : s.target;
    s.goalView = options_.viewGoalRatio * floorTarget;
    s.subUnits = options_.minSubUnits + rng_.below(options_.maxSubUnits - options_.minSubUnits + 1);
    while (s.subUnits > 1 && floorTarget / s.subUnits < 2 * kMinPartWidth * kMinPartWidth) --s.subUnits;
    s.wantsDoubleVolume = rng_.uniform() < options_.doubleVolumeChance;
    if (s.progress() >= s.target) s.status = UnitStatus::Reached;
    growing_.push_back(s.status == UnitStatus::Growing);
    states_.push_back(std::move(s));
    units_.push_back(states_.back().unit);
  }
  for (const Site::FixedUnit& f : site.fixed) {
    UnitState s;
    s.unit.id = int(states_.size()) + 1;
    s.unit.parts = f.parts;
    s.unit.locked.fill(true);
    s.status = UnitStatus::Fixed;
    s.behaviour = "fixed";
    growing_.push_back(false);
    states_.push_back(std::move(s));
    units_.push_back(states_.back().unit);
  }
  enforcer_.index(units_);
  for (std::size_t i = 0; i < site.seeds.size(); ++i)
    if (!enforcer_.plausible(units_, i))
      throw InputError("seeds[" + std::to_string(i) + "]",
                       "is not supported: it rests on nothing and is fixed to no core or circulation within the "
                       "cantilever limit");
  updateQuantifiers();
}

std::vector<ViewBox> GrowthEngine::viewBoxes() const {
  std::vector<ViewBox> boxes;
  for (const Unit& u : units_)
    for (const Box& p : u.parts) boxes.push_back({p, std::uint32_t(u.id)});
  for (std::size_t i = 0; i < site_.cores.size(); ++i) boxes.push_back({site_.coreBox(i), kObstacleId});
  for (const Box& c : site_.circulation) boxes.push_back({c, kObstacleId});
  return boxes;
}

void GrowthEngine::updateQuantifiers() {
  views_ = mapper_->render(viewBoxes(), site_.bounds());
  for (UnitState& s : states_) {
    s.view = views_.view(std::uint32_t(s.unit.id));
    s.peakView = std::max(s.peakView, s.view);
  }
}

bool GrowthEngine::done() const {
  return std::none_of(states_.begin(), states_.end(),
                      [](const UnitState& s) { return s.status == UnitStatus::Growing; });
}

bool GrowthEngine::step() {
  std::vector<std::size_t> growing;
  for (std::size_t i = 0; i < states_.size(); ++i)
    if (states_[i].status == UnitStatus::Growing) growing.push_back(i);
  if (growing.empty()) return false;
  ++steps_;
  for (std::size_t i : arbitration_->order(states_, growing, options_, rng_)) {
    UnitState& s = states_[i];
    Behaviour& behaviour = *behaviours_.at(s.behaviour);
    BehaviourContext ctx{*this, i, rng_, s};
    std::vector<ScoredMove> valid;
    for (const Move& m : behaviour.propose(ctx)) {
      const Verdict v = enforcer_.check(units_, i, m);
      if (!v.ok) continue;
      ScoredMove sm{v.move, {}};
      if (v.move.type == Move::Type::Advance) {
        sm.view = views_.gain(sweptRegion(units_[i].parts[v.move.part], v.move.side, v.move.distance),
                              std::uint32_t(s.unit.id));
        // View conflict (Sec. 5.2): no unit may lose more than τ of its best view.
        bool conflict = false;
        for (const auto& [id, a] : sm.view.taken) {
          const UnitState& o = states_[id - 1];
          if (o.view - a < (1 - options_.tau) * o.peakView - kEps) conflict = true;
        }
        if (conflict) continue;
      }
      valid.push_back(sm);
    }
    const int pick = valid.empty() ? -1 : behaviour.choose(ctx, valid);
    if (pick < 0) {
      if (++s.idleSteps >= options_.patience) {
        s.status = UnitStatus::Stuck;
        growing_[i] = false;
      }
      continue;
    }
    s.idleSteps = 0;
    const Move m = valid[pick].move;
    applyMove(units_[i], m);
    enforcer_.reindex(i);
    s.unit = units_[i];
    ++s.moves;
    ++commits_;
    behaviour.committed(ctx, m);
    if (s.progress() >= s.target - kEps) {
      s.status = UnitStatus::Reached;
      growing_[i] = false;
    }
    if (onCommit_) onCommit_(*this, {steps_, i, m});
  }
  updateQuantifiers();
  return true;
}

int GrowthEngine::run(int maxSteps) {
  int n = 0;
  while (n < maxSteps && step()) ++n;
  return n;
}

}  // namespace corbel::growth
