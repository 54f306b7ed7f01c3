// Seeded random sites (box and polygon envelopes, cores, corridors, seeds anywhere): every
// site is either refused with an InputError or grown with every constraint holding after
// every committed move, checked independently of the enforcer.
#include "core/error.h"
#include "growth/engine.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

Site randomSite(Rng& rng) {
  Site s;
  const double w = 20 + 40 * rng.uniform(), d = 15 + 30 * rng.uniform();
  s.storeys = 1 + rng.below(4);
  s.storeyHeight = 2.8 + 0.6 * rng.uniform();
  s.alpha = 0.2 + 0.3 * rng.uniform();
  s.cantilever = 2 + 4 * rng.uniform();
  s.coreClearance = rng.uniform() * 1.5;
  if (rng.uniform() < 0.5) {
    s.plan = rectanglePlan(0, 0, w, d);
  } else {  // a convex pentagon: one corner cut off
    const double cut = 0.2 + 0.5 * rng.uniform();
    s.plan = {Vec2(0, 0), Vec2(w, 0), Vec2(w, d * (1 - cut)), Vec2(w * (1 - cut), d), Vec2(0, d)};
  }
  for (int i = 0, n = rng.below(3); i < n; ++i) {
    const double x = rng.uniform() * (w - 4), y = rng.uniform() * (d - 4);
    s.cores.push_back({x, y, x + 3 + rng.uniform(), y + 3 + rng.uniform()});
  }
  for (int i = 0, n = rng.below(3); i < n; ++i) {
    const double x = rng.uniform() * (w - 8), y = rng.uniform() * (d - 3);
    for (int k = 0; k < s.storeys; ++k)
      s.circulation.push_back(test::box(x, y, k * s.storeyHeight, x + 6, y + 2, (k + 1) * s.storeyHeight));
  }
  // Mostly tidy seeds (on the ground, or at a corridor's end, clear of each other and of the
  // cores), sometimes anywhere at all.
  const bool tidy = rng.uniform() < 0.75;
  for (int i = 0, n = 2 + rng.below(10); i < n; ++i) {
    Seed seed = test::seedAt(rng.uniform() * (w - 4), rng.uniform() * (d - 4), rng.below(s.storeys),
                             20 + 80 * rng.uniform(), 3 + rng.uniform(), 3 + rng.uniform());
    if (tidy && seed.storey > 0) {
      if (s.circulation.empty())
        seed.storey = 0;
      else {
        const Box& c = s.circulation[rng.below(int(s.circulation.size()))];
        seed.at = Vec2(c.hi[0], c.lo[1]);
        seed.storey = int(std::lround((c.lo[2] - s.base) / s.storeyHeight));
      }
    }
    if (rng.uniform() < 0.2) std::swap(seed.targetArea, seed.targetVolume), seed.targetVolume *= s.storeyHeight;
    if (rng.uniform() < 0.2) seed.locked[rng.below(6)] = true;
    s.seeds.push_back(seed);
    if (!tidy) continue;
    const Box b = s.seedBox(s.seeds.size() - 1);
    bool clash = !s.contains(b);
    for (std::size_t j = 0; j + 1 < s.seeds.size(); ++j) clash = clash || test::overlaps(b, s.seedBox(j));
    for (std::size_t j = 0; j < s.cores.size(); ++j)
      clash = clash || test::gapInPlan(b, s.coreBox(j)) < s.coreClearance + 1e-6;
    for (const Box& c : s.circulation) clash = clash || test::overlaps(b, c);
    if (clash) s.seeds.pop_back();
  }
  return s;
}

TEST(RandomSites, RefusedWithAReasonOrGrownValidly) {
  Rng rng(2026);
  int grown = 0, refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Site site = randomSite(rng);
    std::unique_ptr<GrowthEngine> engine;
    try {
      GrowthOptions o;
      o.seed = std::uint64_t(trial);
      engine = std::make_unique<GrowthEngine>(site, o);
    } catch (const InputError& e) {
      EXPECT_FALSE(e.where.empty()) << e.what();
      ++refused;
      continue;
    }
    std::string firstBad;
    std::size_t checked = 0;
    engine->onCommit([&](const GrowthEngine& e, const CommitRecord&) {
      if (!firstBad.empty() || checked++ % 7) return;  // every 7th commit, and the end
      const auto bad = test::independentViolations(site, e.units());
      if (!bad.empty()) firstBad = bad.front();
    });
    engine->run(400);
    const auto bad = test::independentViolations(site, engine->units());
    if (firstBad.empty() && !bad.empty()) firstBad = bad.front();
    EXPECT_TRUE(firstBad.empty()) << "trial " << trial << ": " << firstBad;
    EXPECT_TRUE(engine->done()) << "trial " << trial;
    ++grown;
  }
  // Random seeds often land in each other or in the air; enough sites must still grow.
  RecordProperty("grown", grown);
  RecordProperty("refused", refused);
  EXPECT_GT(grown, 50);
  EXPECT_GT(refused, 10);
}

}  // namespace
}  // namespace corbel::growth
