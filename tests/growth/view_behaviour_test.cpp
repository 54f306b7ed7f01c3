// The view behaviour's choices (Sec. 5.2–5.3), each against a hand-worked case: the move with
// the best gain, the intrusion penalty, the aspect preference, the double-volume chance, the
// number of sub-units, and the view-conflict threshold τ the engine applies before a behaviour
// chooses. Views are orthographic areas (growth/view_map.h), so the figures below are areas of
// faces by hand.
#include "growth/engine.h"
#include "support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace corbel::growth {
namespace {

using test::box;

// One ground-storey unit, 3 m wide (x) and 6 m deep (y), alone on an open 40 × 40 m site.
Site oneUnitSite(double target) {
  Site s = test::openSite(40, 40, 2);
  s.seeds.push_back(test::seedAt(10, 10, 0, target, 3, 6));
  return s;
}

ScoredMove advance(Side side, double gain, std::map<std::uint32_t, double> taken = {}) {
  ScoredMove m;
  m.move = Move::advance(0, side, 0.3);
  m.view.gain = gain;
  m.view.taken = std::move(taken);
  return m;
}

// What the view behaviour chooses among `valid` for the engine's first unit.
int chosen(const GrowthOptions& options, const std::vector<ScoredMove>& valid, double target = 60) {
  const Site site = oneUnitSite(target);
  GrowthEngine engine(site, options);
  UnitState state = engine.states()[0];
  Rng rng(7);
  BehaviourContext ctx{engine, 0, rng, state};
  return makeViewBehaviour()->choose(ctx, valid);
}

TEST(ViewBehaviour, ChoosesTheMoveWithTheBestGain) {
  GrowthOptions o;
  o.aspectChance = 0;  // every step by view
  EXPECT_EQ(chosen(o, {advance(Side::PosX, 2), advance(Side::NegX, 5), advance(Side::PosY, 3)}), 1);
  EXPECT_EQ(chosen(o, {advance(Side::PosX, 4), advance(Side::NegX, 1), advance(Side::PosY, 3)}), 0);
}

// Gain 5 m² taking 6 m² from unit 2 against gain 3 m² taking nothing: at a penalty of 0.5 per
// m² taken the first scores 5 − 3 = 2 < 3; at 0.2 it scores 5 − 1.2 = 3.8 > 3.
TEST(ViewBehaviour, TheIntrusionPenaltyWeighsTheViewTakenFromOthers) {
  GrowthOptions o;
  o.aspectChance = 0;
  const std::vector<ScoredMove> moves{advance(Side::PosX, 5, {{2, 6.0}}), advance(Side::NegY, 3)};
  o.intrusionPenalty = 0.5;
  EXPECT_EQ(chosen(o, moves), 1);
  o.intrusionPenalty = 0.2;
  EXPECT_EQ(chosen(o, moves), 0);
}

// The 3 × 6 part advanced 0.3 m along x becomes 3.3 × 6 (aspect 6 / 3.3 = 1.82), along y
// 3 × 6.3 (2.1): a step that favours aspect takes x, whatever the view says.
TEST(ViewBehaviour, AnAspectStepTakesTheMoveThatLeavesThePartSquarest) {
  GrowthOptions o;
  const std::vector<ScoredMove> moves{advance(Side::PosY, 10), advance(Side::PosX, 1)};
  o.aspectChance = 1;  // uniform() < 1 always
  EXPECT_EQ(chosen(o, moves), 1);
  o.aspectChance = 0;
  EXPECT_EQ(chosen(o, moves), 0);
}

// Sub-units: 2 or 3 are drawn, then fewer while a sub-unit would be under two 3 × 3 m parts
// (18 m²): 30 m² → 1 (30 / 2 = 15), 40 m² → 2 (40 / 3 = 13.3, 40 / 2 = 20), 100 m² → 2 or 3.
TEST(ViewBehaviour, SubUnitCountsFollowTheTargetArea) {
  auto counts = [](double target) {
    std::map<int, int> seen;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      GrowthOptions o;
      o.seed = seed;
      const Site site = oneUnitSite(target);
      ++seen[GrowthEngine(site, o).states()[0].subUnits];
    }
    return seen;
  };
  EXPECT_EQ(counts(30), (std::map<int, int>{{1, 40}}));
  EXPECT_EQ(counts(40), (std::map<int, int>{{2, 40}}));
  const std::map<int, int> large = counts(100);
  EXPECT_EQ(large.size(), 2u);
  EXPECT_GT(large.count(2) ? large.at(2) : 0, 0);
  EXPECT_GT(large.count(3) ? large.at(3) : 0, 0);
}

// Each unit wants a double volume with the chance given: none at 0, all at 1, and at the
// default 0.35 the share of 1,000 draws within 4.5 standard deviations (σ = √(1000·0.35·0.65)
// = 15.1) of 350.
TEST(ViewBehaviour, TheDoubleVolumeChanceIsTheShareOfUnitsThatWantOne) {
  Site site = test::openSite(200, 200, 2);
  for (int i = 0; i < 40; ++i) site.seeds.push_back(test::seedAt(5.0 * (i % 20) * 2, 20.0 * (i / 20), 0, 60));
  auto wanting = [&](double chance, int runs) {
    int n = 0;
    for (int r = 1; r <= runs; ++r) {
      GrowthOptions o;
      o.seed = std::uint64_t(r);
      o.doubleVolumeChance = chance;
      const GrowthEngine engine(site, o);
      for (const UnitState& s : engine.states()) n += s.wantsDoubleVolume;
    }
    return n;
  };
  EXPECT_EQ(wanting(0.0, 5), 0);
  EXPECT_EQ(wanting(1.0, 5), 200);
  const int share = wanting(0.35, 25);
  EXPECT_NEAR(share, 350, 4.5 * 15.1);
}

// A unit that wants a double volume, at half its target (9 of 16 m²), proposes to rise a whole
// storey and takes it before any face advance: its part becomes 6 m high. Without the wish it
// stays 3 m high.
TEST(ViewBehaviour, AUnitThatWantsADoubleVolumeRisesAStoreyAtHalfItsTarget) {
  Site site = test::openSite(40, 40, 2);
  site.seeds.push_back(test::seedAt(10, 10, 0, 16));
  for (double chance : {1.0, 0.0}) {
    GrowthOptions o;
    o.doubleVolumeChance = chance;
    GrowthEngine engine(site, o);
    ASSERT_EQ(engine.states()[0].wantsDoubleVolume, chance > 0);
    engine.step();
    const Box b = engine.units()[0].bounds();
    EXPECT_DOUBLE_EQ(b.size(2), chance > 0 ? 6.0 : 3.0) << "chance " << chance;
  }
}

// A behaviour that proposes one fixed move and records what the engine let through.
class Probe : public Behaviour {
 public:
  explicit Probe(Move m) : move_(m) {}
  std::vector<Move> propose(BehaviourContext&) override { return {move_}; }
  int choose(BehaviourContext&, const std::vector<ScoredMove>& valid) override {
    offered = int(valid.size());
    if (!valid.empty()) taken = valid[0].view.taken;
    return -1;
  }
  int offered = 0;
  std::map<std::uint32_t, double> taken;

 private:
  Move move_;
};

// Unit 1, 3 × 3 × 3 m at the origin, alone in view on every side: 4 faces × 9 m² = 36 m².
// Unit 2 (x 5–8, y 3.2–6.2) advancing its −y face by 0.3 m comes in front of unit 1's +x face
// for y 2.9–3.0: 0.1 × 3 = 0.3 m² taken, 0.83 % of unit 1's best view. At τ = 1 % the move is
// offered; at τ = 0.5 % the engine drops it.
TEST(ViewBehaviour, AMoveTakingMoreThanTauOfAnotherUnitsBestViewIsDropped) {
  Site site = test::openSite(40, 40, 1);
  site.seeds.push_back(test::seedAt(0, 0, 0, 9));  // reached at once: it only watches
  site.seeds.push_back(test::seedAt(5, 3.2, 0, 60));
  site.seeds[1].behaviour = "probe";
  for (double tau : {0.01, 0.005}) {
    auto probe = std::make_shared<Probe>(Move::advance(0, Side::NegY, 0.3));
    GrowthOptions o;
    o.tau = tau;
    GrowthEngine engine(site, o, nullptr, {{"probe", probe}});
    EXPECT_NEAR(engine.states()[0].peakView, 36.0, 1e-9);
    engine.step();
    if (tau == 0.01) {
      EXPECT_EQ(probe->offered, 1);
      ASSERT_EQ(probe->taken.size(), 1u);
      EXPECT_NEAR(probe->taken.at(1), 0.3, 1e-9);
    } else {
      EXPECT_EQ(probe->offered, 0);
    }
  }
}

}  // namespace
}  // namespace corbel::growth
