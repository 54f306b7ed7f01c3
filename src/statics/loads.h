#pragma once
// The loads an artist places on a masonry object (core/masonry_spec.h: MasonryLoad) applied to
// the blocks of its model (Whiting et al. 2009, Sec. 3.4: point loads stand for the weight of
// what a structure carries; a pressure on a face for wind). The equilibrium equations, the
// search and the simulation then see them as any other point load.
#include "core/masonry_spec.h"
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

// Where a load acts and with what force, resolved on an assembly: a point load at the block's
// centroid plus its offset; a pressure p on face f as the force p·A·(−n) at the face's area
// centroid (A its area, n its outward unit normal).
struct ResolvedLoad {
  int block = -1;
  PointLoad load;
};

// Resolves every load against the assembly's block names. Throws InputError at
// "masonry.loads[k]" when a load names a block the model does not have (or a fixed one: the
// ground takes any load), or a face the block does not have, or its force is not finite.
std::vector<ResolvedLoad> resolveLoads(const Assembly& assembly, const std::vector<MasonryLoad>& loads);

// Adds the resolved loads to their blocks' point loads.
void applyLoads(Assembly& assembly, const std::vector<MasonryLoad>& loads);

}  // namespace corbel::statics
