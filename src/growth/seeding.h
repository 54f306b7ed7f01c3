#pragma once
// Seeds generated within user controls (Ng, Ch. 3.1: seed units are "placed at exits along
// the circulation"): candidates are the places just outside every side of every staircase or
// corridor, on each storey it serves, slid along the side; a seeded shuffle picks among them,
// and a candidate is taken when it fits the site as a hand-placed seed must (inside the
// envelope, clear of cores, circulation and the seeds already placed).
#include "growth/site.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::growth {

struct SeedControls {
  int count = 10;                 // at most this many seeds are added
  Vec2 size{3.0, 3.0};            // plan size of each seed, at least 3 m × 3 m
  double spacing = 0.0;           // step between candidates along a side (0: the seed's width)
  double areaLo = 40, areaHi = 80;  // each seed's target floor area is drawn from [lo, hi] m²
  std::vector<int> storeys;       // storeys to seed (empty: every storey the circulation serves)
  unsigned seed = 1;              // the shuffle's seed: the same controls give the same seeds
  std::string behaviour = "view";
};

// Adds up to controls.count seeds to site.seeds (after those already there) and returns how
// many it added (fewer when the circulation has fewer free exits). Throws InputError naming
// the control at fault ("generate_seeds.count: ...") for bad controls.
int generateSeeds(Site& site, const SeedControls& controls);

// The "generate_seeds" controls of a site file as parseSite reads them (defaults for missing
// keys), or nullopt when it has none. Throws InputError naming a control the file gets wrong.
std::optional<SeedControls> seedControlsOf(const std::string& siteJsonText);

}  // namespace corbel::growth
