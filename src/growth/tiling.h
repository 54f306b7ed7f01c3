#pragma once
// A site repeated side by side: a site of many times the units, for measuring how growth
// scales (tests/bench/growth_bench.cpp tiles the Beta-like site 3 × 3).
#include "growth/site.h"

namespace corbel::growth {

// `site` repeated `nx` × `ny` times along +x and +y: the envelope is the rectangle of the
// copies, and each copy's cores, circulation and seeds are moved by its offset (seeds in copy
// order, so unit ids run copy by copy). The envelope must be a rectangle (InputError
// "envelope" otherwise; "tiles" for counts under 1 or over 100).
Site tiledSite(const Site& site, int nx, int ny);

}  // namespace corbel::growth
