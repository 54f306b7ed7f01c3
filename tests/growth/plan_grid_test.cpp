// The plan grid (growth/plan_grid.h) against a scan of every rectangle, and the enforcer's
// indexed queries against its own full scan: the grid may only make queries cheaper, never
// change an answer or the order in which obstacles and supports are visited.
#include "growth/plan_grid.h"

#include "core/error.h"
#include "growth/engine.h"
#include "growth/rng.h"
#include "growth/tiling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace corbel::growth {
namespace {

// Closed rectangles meet when they overlap or touch.
bool meet(const Rect& a, const Rect& b) { return a.u0 <= b.u1 && b.u0 <= a.u1 && a.v0 <= b.v1 && b.v0 <= a.v1; }

Rect randomRect(Rng& rng, double lo, double hi) {
  const double u = lo + rng.uniform() * (hi - lo), v = lo + rng.uniform() * (hi - lo);
  return {u, v, u + rng.uniform() * 12, v + rng.uniform() * 12};
}

TEST(PlanGrid, AQueryHoldsEveryRectangleItMeetsOnceAndInOrder) {
  Rng rng(7);
  PlanGrid grid({0, 0, 100, 60}, 8);
  std::vector<Rect> rects;
  // Some lie partly or wholly outside the grid's bounds; some share edges exactly.
  for (int k = 0; k < 400; ++k) rects.push_back(randomRect(rng, -10, 110));
  for (int k = 0; k < 40; ++k) rects.push_back({8.0 * (k % 12), 16, 8.0 * (k % 12) + 8, 24});
  for (std::size_t k = 0; k < rects.size(); ++k) grid.insert(k, rects[k]);
  // Move some and erase some: the grid must forget where they were.
  for (std::size_t k = 0; k < rects.size(); k += 7) {
    rects[k] = randomRect(rng, -10, 110);
    grid.insert(k, rects[k]);
  }
  std::vector<bool> erased(rects.size(), false);
  for (std::size_t k = 3; k < rects.size(); k += 11) {
    grid.erase(k);
    erased[k] = true;
  }
  std::vector<std::uint64_t> got;
  for (int q = 0; q < 500; ++q) {
    const Rect r = q % 50 == 0 ? Rect{16, 0, 24, 16} : randomRect(rng, -20, 120);  // touching cell edges
    grid.query(r, got);
    ASSERT_TRUE(std::is_sorted(got.begin(), got.end()));
    ASSERT_EQ(std::adjacent_find(got.begin(), got.end()), got.end());
    for (std::size_t k = 0; k < rects.size(); ++k) {
      const bool listed = std::binary_search(got.begin(), got.end(), std::uint64_t(k));
      if (erased[k]) {
        EXPECT_FALSE(listed) << k;
      } else if (meet(rects[k], r)) {
        EXPECT_TRUE(listed) << "query " << q << " misses " << k;
      }
    }
  }
}

// Every query the behaviour and the engine make, on the engine's own (indexed) units and on a
// copy of them (which the enforcer scans): equal, item for item, at several points of a run of
// the Beta-like site tiled 2 × 1 (copies meet along x = 100 m).
TEST(PlanGrid, TheIndexedEnforcerAnswersAsTheFullScanDoes) {
  const Site beta = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-beta.json");
  const Site site = tiledSite(beta, 2, 1);
  GrowthEngine engine(site, optionsFor(site, 3));
  const ConstraintEnforcer& e = engine.enforcer();
  int compared = 0;
  for (int round = 0; round < 3; ++round) {
    engine.run(round == 0 ? 5 : 25);
    const std::vector<Unit>& live = engine.units();
    const std::vector<Unit> copy = live;
    std::vector<bool> growing;
    for (const UnitState& s : engine.states()) growing.push_back(s.status == UnitStatus::Growing);
    for (std::size_t i = 0; i < live.size(); i += 3) {
      EXPECT_EQ(e.plausible(live, i), e.plausible(copy, i));
      for (int p = 0; p < int(live[i].parts.size()); ++p)
        for (Side s : kAllSides) {
          EXPECT_EQ(e.freeDistance(live, i, p, s, 1e3), e.freeDistance(copy, i, p, s, 1e3));
          EXPECT_EQ(e.lookAhead(live, i, p, s, 1e3, 3.0, growing), e.lookAhead(copy, i, p, s, 1e3, 3.0, growing));
          for (double d : {site.alpha, site.storeyHeight}) {
            const Verdict a = e.check(live, i, Move::advance(p, s, d)), b = e.check(copy, i, Move::advance(p, s, d));
            EXPECT_EQ(a.ok, b.ok);
            EXPECT_EQ(a.move, b.move);
            EXPECT_EQ(a.reason, b.reason);
          }
          if (sideAxis(s) == 2) continue;
          const FaceObstacles a = e.obstaclesAhead(live, i, p, s, 0.5), b = e.obstaclesAhead(copy, i, p, s, 0.5);
          EXPECT_EQ(a.face, b.face);
          EXPECT_EQ(a.obstacles, b.obstacles);
          ++compared;
        }
    }
  }
  EXPECT_GT(compared, 1000);
  // A copy of the enforcer scans: it answers as the original does, and stays right after the
  // engine moves on (its own grid is not kept up).
  const ConstraintEnforcer copy = e;
  engine.run(10);
  for (std::size_t i = 0; i < engine.units().size(); i += 7)
    for (Side s : kVerticalSides)
      EXPECT_EQ(copy.freeDistance(engine.units(), i, 0, s, 1e3), e.freeDistance(engine.units(), i, 0, s, 1e3));
}

TEST(Tiling, CopiesSitSideBySideAndABadRequestIsNamed) {
  const Site beta = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/growth-beta.json");
  const Site t = tiledSite(beta, 3, 2);
  EXPECT_EQ(t.seeds.size(), 6 * beta.seeds.size());
  EXPECT_EQ(t.cores.size(), 6 * beta.cores.size());
  EXPECT_EQ(t.circulation.size(), 6 * beta.circulation.size());
  EXPECT_DOUBLE_EQ(t.area(), 6 * 100.0 * 60.0);
  // The last copy (2, 1) is moved by (200, 60) m.
  EXPECT_EQ(t.seeds.back().at, beta.seeds.back().at + Vec2(200, 60));
  EXPECT_NO_THROW(validateSite(t));
  try {
    tiledSite(beta, 0, 2);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tiles"), std::string::npos);
  }
  Site l = beta;
  l.plan = {Vec2(0, 0), Vec2(100, 0), Vec2(100, 60), Vec2(50, 60), Vec2(50, 30), Vec2(0, 30)};
  EXPECT_THROW(tiledSite(l, 2, 2), InputError);
}

}  // namespace
}  // namespace corbel::growth
