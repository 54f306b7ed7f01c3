#include "growth/seeding.h"

#include "core/error.h"
#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace corbel::growth {
namespace {

[[noreturn]] void bad(const std::string& field, const std::string& reason) {
  throw InputError("generate_seeds." + field, reason);
}

// Whether a seed's box fits the site (the checks validateSite makes
// of a hand-placed seed).
bool fits(const Site& site, const Box& b) {
  if (!site.contains(b)) return false;
  for (std::size_t j = 0; j < site.cores.size(); ++j)
    if (interiorsOverlap(b, grownInPlan(site.coreBox(j), site.coreClearance), kEps)) return false;
  for (const Box& c : site.circulation)
    if (interiorsOverlap(b, grownInPlan(c, site.circulationClearance), kEps)) return false;
  for (std::size_t j = 0; j < site.seeds.size(); ++j)
    if (interiorsOverlap(b, site.seedBox(j), kEps)) return false;
  return true;
}

}  // namespace

int generateSeeds(Site& site, const SeedControls& c) {
  if (c.count < 0 || c.count > 100000) bad("count", "must lie in 0..100000");
  for (int k = 0; k < 2; ++k)
    if (!std::isfinite(c.size[k]) || c.size[k] < kMinPartWidth - kEps || c.size[k] > 1e4)
      bad("size", "a seed is at least 3 m x 3 m (Sec. 5.3)");
  if (!std::isfinite(c.spacing) || c.spacing < 0) bad("spacing", "must be a non-negative number of metres");
  if (!std::isfinite(c.areaLo) || !std::isfinite(c.areaHi) || !(c.areaLo > 0) || c.areaHi < c.areaLo)
    bad("target_area", "expected [lo, hi] with 0 < lo <= hi");
  for (int s : c.storeys)
    if (s < 0 || s >= site.storeys) bad("storeys", "storey " + std::to_string(s) + " is not in 0.." + std::to_string(site.storeys - 1));

  struct Candidate {
    Vec2 at;
    int storey;
  };
  std::vector<Candidate> candidates;
  const double g = site.circulationClearance;
  for (const Box& circ : site.circulation)
    for (int s = 0; s < site.storeys; ++s) {
      if (!c.storeys.empty() && std::find(c.storeys.begin(), c.storeys.end(), s) == c.storeys.end()) continue;
      // The circulation serves a storey whose floor level it spans.
      const double floor = site.base + s * site.storeyHeight;
      if (floor < circ.lo[2] - kEps || floor >= circ.hi[2] - kEps) continue;
      for (int axis = 0; axis < 2; ++axis) {       // sides facing ∓x (axis 0) and ∓y (axis 1)
        const int along = 1 - axis;
        const double width = c.size[along], depth = c.size[axis];
        const double step = c.spacing > 0 ? c.spacing : width;
        const double from = circ.lo[along], to = circ.hi[along] - width;
        for (double t = from; t <= to + kEps; t += step)
          for (int sign : {-1, 1}) {
            Vec2 at;
            at[along] = t;
            at[axis] = sign > 0 ? circ.hi[axis] + g : circ.lo[axis] - g - depth;
            candidates.push_back({at, s});
          }
      }
    }
  std::mt19937 rng(c.seed);
  std::shuffle(candidates.begin(), candidates.end(), rng);
  std::uniform_real_distribution<double> area(c.areaLo, c.areaHi);
  int added = 0;
  for (const Candidate& k : candidates) {
    if (added >= c.count) break;
    Seed seed;
    seed.at = k.at;
    seed.size = c.size;
    seed.storey = k.storey;
    seed.behaviour = c.behaviour;
    const double z0 = site.base + k.storey * site.storeyHeight;
    const Box box{{k.at[0], k.at[1], z0}, {k.at[0] + c.size[0], k.at[1] + c.size[1], z0 + site.storeyHeight}};
    if (!fits(site, box)) continue;
    seed.targetArea = c.areaLo == c.areaHi ? c.areaLo : area(rng);
    site.seeds.push_back(seed);
    ++added;
  }
  return added;
}

}  // namespace corbel::growth
