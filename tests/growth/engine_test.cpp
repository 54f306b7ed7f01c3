// The growth loop (Fig. 4.1–4.2): reproducible for a seed, constraints after every committed
// move (checked independently of the enforcer), per-unit termination, bad setups refused.
#include "growth/engine.h"
#include "core/error.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

using test::box;

// A three-storey site with two cores, a corridor per storey and 14 seeds.
Site testSite() {
  Site s = test::openSite(48, 30, 3);
  s.cores = {{10, 13, 14, 17}, {34, 13, 38, 17}};
  s.coreClearance = 0.5;
  s.cantilever = 4.0;
  for (int k = 0; k < 3; ++k) s.circulation.push_back(box(14.5, 14, 3.0 * k, 33.5, 16, 3.0 * k + 3));
  double targets[] = {45, 60, 90, 35, 70};
  int t = 0;
  for (int k = 0; k < 3; ++k)
    for (double x : {16.0, 22.0, 28.0}) {
      if (k == 2 && x == 22.0) continue;
      s.seeds.push_back(test::seedAt(x, 16, k, targets[t++ % 5]));
      s.seeds.push_back(test::seedAt(x, 11, k, targets[t++ % 5]));
    }
  return s;
}

bool sameUnits(const std::vector<Unit>& a, const std::vector<Unit>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].parts != b[i].parts) return false;
  return true;
}

TEST(Engine, RunsAreReproducibleForASeed) {
  const Site site = testSite();
  GrowthOptions o;
  o.seed = 7;
  GrowthEngine a(site, o), b(site, o);
  a.run(400);
  b.run(400);
  EXPECT_GT(a.commits(), 100u);
  EXPECT_TRUE(sameUnits(a.units(), b.units()));
  EXPECT_EQ(a.steps(), b.steps());
  o.seed = 8;
  GrowthEngine c(site, o);
  c.run(400);
  EXPECT_FALSE(sameUnits(a.units(), c.units())) << "the seed should matter";
}

TEST(Engine, ConstraintsHoldAfterEveryCommittedMove) {
  const Site site = testSite();
  GrowthEngine engine(site);
  std::size_t checked = 0;
  std::vector<std::string> first;
  engine.onCommit([&](const GrowthEngine& e, const CommitRecord&) {
    ++checked;
    if (first.empty()) first = test::independentViolations(site, e.units());
  });
  engine.run(2000);
  EXPECT_TRUE(engine.done());
  EXPECT_EQ(checked, engine.commits());
  EXPECT_TRUE(first.empty()) << first.front();
  EXPECT_TRUE(engine.enforcer().violations(engine.units()).empty());
}

TEST(Engine, UnitsStopAtTheirTargetOrWhenStuck) {
  const Site site = testSite();
  GrowthEngine engine(site);
  engine.run(2000);
  ASSERT_TRUE(engine.done());
  int reached = 0;
  for (const UnitState& s : engine.states()) {
    EXPECT_NE(s.status, UnitStatus::Growing);
    if (s.status == UnitStatus::Reached) {
      ++reached;
      EXPECT_GE(s.progress(), s.target - 1e-6);
      // One advance adds at most α × (the longest part side) × 2 storeys, or a storey's volume.
      EXPECT_LT(s.progress(), s.target + 40) << s.unit.id;
    }
  }
  EXPECT_GT(reached, int(site.seeds.size()) / 2);
  // A lone unit in the open reaches its target.
  Site open = test::openSite(40, 40, 1);
  open.seeds.push_back(test::seedAt(18, 18, 0, 70));
  GrowthEngine lone(open);
  lone.run(1000);
  EXPECT_EQ(lone.states()[0].status, UnitStatus::Reached);
  EXPECT_GE(lone.units()[0].floorArea(), 70);
}

// A behaviour proposing random moves of every kind: the enforcer alone keeps the model valid.
class RandomBehaviour : public Behaviour {
 public:
  std::vector<Move> propose(BehaviourContext& ctx) override {
    std::vector<Move> moves;
    const Unit& u = ctx.state.unit;
    for (int i = 0; i < 6; ++i) {
      const int part = ctx.rng.below(int(u.parts.size()));
      const double r = ctx.rng.uniform();
      if (r < 0.15) {
        const int axis = ctx.rng.below(2);
        const Box& b = u.parts[part];
        moves.push_back(Move::split(part, axis, b.lo[axis] + ctx.rng.uniform() * b.size(axis)));
      } else if (r < 0.25) {
        moves.push_back(Move::advance(part, ctx.rng.below(2) ? Side::Top : Side::Bottom, 3.0));
      } else {
        moves.push_back(Move::advance(part, kVerticalSides[ctx.rng.below(4)], 0.2 + 0.3 * ctx.rng.uniform()));
      }
    }
    return moves;
  }
  int choose(BehaviourContext& ctx, const std::vector<ScoredMove>& valid) override {
    return ctx.rng.below(int(valid.size()));
  }
};

TEST(Engine, RandomMovesThroughTheEnforcerKeepEveryConstraint) {
  Site site = testSite();
  for (Seed& s : site.seeds) s.behaviour = "random";
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    GrowthOptions o;
    o.seed = seed;
    GrowthEngine engine(site, o, nullptr, {{"random", std::make_shared<RandomBehaviour>()}});
    engine.setArbitration(makeRandomArbitration());
    std::vector<std::string> bad;
    engine.onCommit([&](const GrowthEngine& e, const CommitRecord&) {
      if (bad.empty()) bad = test::independentViolations(site, e.units());
    });
    engine.run(150);
    EXPECT_GT(engine.commits(), 300u);
    EXPECT_TRUE(bad.empty()) << "seed " << seed << ": " << bad.front();
  }
}

TEST(Engine, ViewDeficitArbitrationIsAFairWeightedOrder) {
  std::vector<UnitState> units(3);
  units[0].goalView = 100, units[0].view = 100;  // no deficit
  units[1].goalView = 100, units[1].view = 50;
  units[2].goalView = 100, units[2].view = 0;  // largest deficit
  auto arb = makeViewDeficitArbitration();
  Rng rng(3);
  int firsts[3] = {0, 0, 0};
  for (int i = 0; i < 3000; ++i) {
    std::vector<std::size_t> order = arb->order(units, {0, 1, 2}, GrowthOptions{}, rng);
    ASSERT_EQ(order.size(), 3u);  // every growing unit gets its turn
    std::vector<std::size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, (std::vector<std::size_t>{0, 1, 2}));
    ++firsts[order[0]];
  }
  // Weights 0.1, 0.6, 1.1: first with probability w / Σw = 0.056, 0.333, 0.611.
  EXPECT_NEAR(firsts[0] / 3000.0, 0.1 / 1.8, 0.02);
  EXPECT_NEAR(firsts[1] / 3000.0, 0.6 / 1.8, 0.03);
  EXPECT_NEAR(firsts[2] / 3000.0, 1.1 / 1.8, 0.03);
}

TEST(Engine, BadSetupsGetClearErrors) {
  Site site = test::openSite(30, 30, 3);
  site.seeds.push_back(test::seedAt(5, 5, 2, 40));  // storey 2, nothing under or beside it
  try {
    GrowthEngine engine(site);
    FAIL() << "an unsupported seed was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "seeds[0]");
    EXPECT_NE(std::string(e.what()).find("not supported"), std::string::npos);
  }
  site.seeds[0].storey = 0;
  site.seeds[0].behaviour = "dance";
  try {
    GrowthEngine engine(site);
    FAIL() << "an unknown behaviour was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "seeds[0].behaviour");
  }
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

TEST(Engine, AlphaExampleEndsWithEveryConstraintHolding) {
  const Site site = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  for (std::uint64_t seed : {1u, 5u}) {
    GrowthOptions o;
    o.seed = seed;
    GrowthEngine engine(site, o);
    engine.run(100000);
    EXPECT_TRUE(engine.done());
    const std::vector<std::string> bad = test::independentViolations(site, engine.units());
    EXPECT_TRUE(bad.empty()) << bad.front();
  }
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// Sec. 5.3: growth by view alone stretches units; the view behaviour keeps every part within
// 1 : maxAspect in plan (seeds start square), on both example sites.
TEST(Engine, ViewBehaviourKeepsPartsWithinTheAspectLimit) {
  for (const char* name : {"growth-alpha.json", "growth-beta.json"}) {
    const Site site = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name);
    GrowthEngine engine(site);
    engine.run(100000);
    for (const Unit& u : engine.units())
      for (const Box& p : u.parts)
        EXPECT_LE(std::max(p.size(0), p.size(1)), engine.options().maxAspect * std::min(p.size(0), p.size(1)) + 1e-9)
            << name << " unit " << u.id;
  }
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// Sec. 5.3, locked faces: a unit whose -x, -y and +y faces are locked keeps those planes for
// the whole run, whatever its behaviour does.
TEST(Engine, LockedFacesKeepTheirPlanes) {
  Site site = test::openSite(40, 40, 2);
  Seed seed = test::seedAt(5, 10, 0, 80);
  seed.locked[int(Side::NegX)] = seed.locked[int(Side::NegY)] = seed.locked[int(Side::PosY)] = true;
  site.seeds = {seed};
  GrowthEngine engine(site);
  engine.run(1000);
  ASSERT_GT(engine.commits(), 5u);
  for (const Box& p : engine.units()[0].parts) {
    EXPECT_DOUBLE_EQ(p.lo[0], 5);
    EXPECT_GE(p.lo[1], 10);
    EXPECT_LE(p.hi[1], 13);
  }
  EXPECT_GT(engine.units()[0].bounds().hi[0], 8.0);  // it grew where it could: +x
}

TEST(Engine, VolumeTargetsCountDoubleVolumes) {
  Site site = test::openSite(40, 40, 2);
  Seed seed = test::seedAt(18, 18, 0, 0);
  seed.targetVolume = 240;
  site.seeds = {seed};
  GrowthEngine engine(site);
  engine.run(1000);
  const UnitState& s = engine.states()[0];
  EXPECT_EQ(s.status, UnitStatus::Reached);
  EXPECT_TRUE(s.byVolume);
  EXPECT_GE(engine.units()[0].volume(), 240 - 1e-9);
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// Collide-and-extrude (Sec. 5.3, Fig. 5.3): unit 2 sits against the south half of unit 1's
// +x face; unit 1 (free to grow only in +x) splits at the obstacle's edge and its north piece
// extrudes past it.
TEST(Engine, ACollidingFaceSplitsAndExtrudesPastTheObstacle) {
  Site site = test::openSite(40, 40, 1);
  Seed a = test::seedAt(0, 0, 0, 60, 6, 6);
  a.locked[int(Side::NegX)] = a.locked[int(Side::NegY)] = a.locked[int(Side::PosY)] = true;
  Seed b = test::seedAt(6, 0, 0, 9);  // 3 x 3, at its target from the start
  site.seeds = {a, b};
  GrowthEngine engine(site);
  ASSERT_EQ(engine.states()[1].status, UnitStatus::Reached);
  engine.run(1000);
  const Unit& u = engine.units()[0];
  ASSERT_GE(u.parts.size(), 2u);
  bool past = false;
  for (const Box& p : u.parts) {
    EXPECT_FALSE(test::overlaps(p, engine.units()[1].parts[0]));
    if (p.hi[0] > 6 + 1e-9) {
      past = true;
      EXPECT_GE(p.lo[1], 3 - 1e-9);  // only the free north piece went past x = 6
    }
  }
  EXPECT_TRUE(past);
  EXPECT_GT(u.floorArea(), 36);
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// Fig. 5.3, interlocking: unit 1's +x face (12 m) meets two units that leave only its middle
// 4 m free (y 4–8). It splits at y = 8 and then y = 4, and the middle piece extrudes between
// the two obstacles, past them.
TEST(Engine, AFaceBlockedAtBothEndsExtrudesItsFreeMiddle) {
  Site site = test::openSite(40, 40, 1);
  Seed a = test::seedAt(0, 0, 0, 100, 6, 12);
  a.locked[int(Side::NegX)] = a.locked[int(Side::NegY)] = a.locked[int(Side::PosY)] = true;
  site.seeds = {a, test::seedAt(6, 0, 0, 12, 3, 4), test::seedAt(6, 8, 0, 12, 3, 4)};
  GrowthEngine engine(site);
  ASSERT_EQ(engine.states()[1].status, UnitStatus::Reached);
  ASSERT_EQ(engine.states()[2].status, UnitStatus::Reached);
  std::vector<double> cuts;
  engine.onCommit([&](const GrowthEngine&, const CommitRecord& r) {
    if (r.unit == 0 && r.move.type == Move::Type::Split) cuts.push_back(r.move.at);
  });
  engine.run(1000);
  ASSERT_GE(cuts.size(), 2u);
  EXPECT_DOUBLE_EQ(cuts[0], 8);
  EXPECT_DOUBLE_EQ(cuts[1], 4);
  bool past = false;
  for (const Box& p : engine.units()[0].parts)
    if (p.hi[0] > 9 + 1e-9) {
      past = true;
      EXPECT_GE(p.lo[1], 4 - 1e-9);
      EXPECT_LE(p.hi[1], 8 + 1e-9);
    }
  EXPECT_TRUE(past);
  EXPECT_TRUE(test::independentViolations(site, engine.units()).empty());
}

// The interval twin against CGAL's polygon difference over whole runs: the same units, part for
// part, on Alpha and on the test site with another seed.
TEST(Engine, CollideByIntervalsGrowsWhatCgalsDifferenceGrows) {
  const Site alpha = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-alpha.json");
  for (std::uint64_t seed : {1u, 3u}) {
    GrowthOptions o;
    o.seed = seed;
    GrowthEngine fast(alpha, o);
    o.exactCollide = true;
    GrowthEngine exact(alpha, o);
    fast.run(100000);
    exact.run(100000);
    EXPECT_TRUE(sameUnits(fast.units(), exact.units())) << "seed " << seed;
    EXPECT_EQ(fast.commits(), exact.commits());
  }
}

// Fig. 5.4 on a hand-made site: a one-storey unit on storey 2, fixed to a stair tower, grows +x
// (its other faces locked) toward an external staircase of storey 0 (x 10–14, y 2–6, roof at
// z = 3, one storey below the unit's floor). Once its face is within α of the staircase it
// takes the staircase's whole top as a two-storey part from the roof up to its ceiling.
Site stairSite() {
  Site site = test::openSite(30, 20, 3);
  site.circulation = {test::box(3, 2, 0, 6, 5, 9), test::box(10, 2, 0, 14, 6, 3)};
  Seed a = test::seedAt(6, 2, 2, 40);
  for (Side s : {Side::NegX, Side::NegY, Side::PosY, Side::Bottom, Side::Top}) a.locked[int(s)] = true;
  site.seeds = {a};
  return site;
}

TEST(Engine, AUnitTakesAStaircasesWholeTopAsItsStairBase) {
  const Site site = stairSite();
  GrowthEngine engine(site);
  std::vector<Move> bases;
  double faceAt = 0;
  std::vector<std::string> bad;
  engine.onCommit([&](const GrowthEngine& e, const CommitRecord& r) {
    if (r.move.type == Move::Type::StairBase) {
      bases.push_back(r.move);
      faceAt = e.units()[0].parts[0].hi[0];
    }
    if (bad.empty()) bad = test::independentViolations(site, e.units());
  });
  engine.run(1000);
  EXPECT_TRUE(bad.empty()) << bad.front();
  ASSERT_EQ(bases.size(), 1u);
  EXPECT_EQ(bases[0].staircase, 1);
  EXPECT_GE(faceAt, 10 - site.alpha - 1e-9);
  EXPECT_LE(faceAt, 10 + 1e-9);
  // By hand: from the face to the staircase's far side, its width, roof to ceiling.
  EXPECT_EQ(bases[0].box, (Box{{faceAt, 2, 3}, {14, 6, 9}}));
  const Unit& u = engine.units()[0];
  EXPECT_DOUBLE_EQ(u.bounds().lo[2], 3);  // double-storey: storeys 1 and 2
  EXPECT_DOUBLE_EQ(u.bounds().hi[2], 9);
}

// The same unit, but a unit of storey 1 already stands on part of the staircase's top (x 12–14):
// only a partial occupancy would be left, so the unit never takes any of it.
TEST(Engine, AStaircasesTopIsNeverTakenInPart) {
  Site site = stairSite();
  Seed b = test::seedAt(12, 2.5, 1, 9);
  b.locked.fill(true);
  site.seeds.push_back(b);
  GrowthEngine engine(site);
  ASSERT_EQ(engine.states()[1].status, UnitStatus::Reached);
  int bases = 0;
  std::vector<std::string> bad;
  engine.onCommit([&](const GrowthEngine& e, const CommitRecord& r) {
    bases += r.move.type == Move::Type::StairBase;
    if (bad.empty()) bad = test::independentViolations(site, e.units());
  });
  engine.run(1000);
  EXPECT_TRUE(bad.empty()) << bad.front();
  EXPECT_EQ(bases, 0);
  for (const Box& p : engine.units()[0].parts) EXPECT_DOUBLE_EQ(p.lo[2], 6);  // nothing on the roof at z = 3
  // It did reach the staircase (and stopped there: nothing holds it up beyond x = 10).
  EXPECT_GE(engine.units()[0].bounds().hi[0], 10 - site.alpha - 1e-9);
}

}  // namespace
}  // namespace corbel::growth

namespace corbel::growth {
namespace {

// The look-ahead before a stair base: unit 2 (storey 1, on a second staircase's roof, 0.2 m east
// of the first staircase's top) is growing, so its next advance could take the top's east end;
// unit 1 waits at the staircase and takes the whole top only once unit 2 has stopped (it can
// make no move: every face locked, so it is stuck after `patience` steps, here 10).
TEST(Engine, AStairBaseWaitsUntilNoGrowingNeighbourCouldReachTheTop) {
  Site site = stairSite();
  site.circulation.push_back(test::box(14.2, 2.5, 0, 17.2, 5.5, 3));
  Seed b = test::seedAt(14.2, 2.5, 1, 100);
  b.locked.fill(true);
  site.seeds.push_back(b);
  GrowthOptions o;
  o.patience = 10;  // unit 2 grows (in name) for 10 steps; unit 1 arrives in 3
  GrowthEngine engine(site, o);
  int baseStep = 0, stuckStep = 0, arrivedStep = 0;
  Box base;
  engine.onCommit([&](const GrowthEngine& e, const CommitRecord& r) {
    if (r.move.type == Move::Type::StairBase) {
      baseStep = r.step;
      base = r.move.box;
    }
    if (!arrivedStep && e.units()[0].parts[0].hi[0] >= 10 - site.alpha - 1e-9) arrivedStep = r.step;
  });
  while (engine.step())
    if (!stuckStep && engine.states()[1].status == UnitStatus::Stuck) stuckStep = engine.steps();
  ASSERT_GT(arrivedStep, 0);
  ASSERT_GT(stuckStep, arrivedStep);  // unit 1 was at the staircase while unit 2 still grew
  ASSERT_GT(baseStep, 0);
  EXPECT_GE(baseStep, stuckStep - 1);  // in the step unit 2 stopped (if it went first) or after
  EXPECT_EQ(base, (Box{{engine.units()[0].parts[0].hi[0], 2, 3}, {14, 6, 9}}));  // the whole top
  EXPECT_TRUE(test::independentViolations(site, engine.units()).empty());
}

}  // namespace
}  // namespace corbel::growth
