#pragma once
// A growth site in the Document (Ng, growth-based housing forms, Ch. 3–5): the site exactly as
// its site file has it (docs/growth.md), the run's random seed and how many steps to grow.
// The growth kernel owns the site's meaning: it parses and validates `site` when it builds the
// object and names a bad field by its path in the project file ("growth.site.seeds[3].at").
#include <cstdint>
#include <string>

namespace corbel {

struct GrowthSpec {
  std::string site = "{}";  // the site's JSON object (docs/growth.md, "Site file"), as compact text
  std::uint64_t seed = 1;   // the run is deterministic for a seed
  int steps = 0;            // simulation steps to grow; -1: until every unit stops
  // Grow around the Document's unit objects (frozen units, completed forms): they are units
  // already there, which the seeds avoid and the roofs, doors and windows finish (Freeze sets it).
  bool aroundUnits = false;
  bool operator==(const GrowthSpec&) const = default;
};

namespace limits {
inline constexpr long kMaxGrowthSteps = 1000000;
}

}  // namespace corbel
