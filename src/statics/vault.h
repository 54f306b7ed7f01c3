#pragma once
// Masonry template: the barrel vault, a semicircular arch extruded along y and laid in rings
// (courses along the axis) of radially jointed voussoirs (Whiting et al. 2009, Fig. 4, Fig. 13).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct BarrelVaultSpec {
  int blocks = 12;          // voussoirs per ring
  int rings = 5;            // courses along the axis
  double radius = 1.0;      // centreline radius, m
  double thickness = 0.15;  // m
  double length = 5.0;      // along y, m
  double density = 2400.0;
};

// Ring r spans y ∈ [r L/rings, (r+1) L/rings]; its voussoirs are those of the semicircular
// arch (arch.h) springing at x = ±R on z = 0. Rings share their joints (stack bond), so ring
// faces meet voussoir to voussoir. Throws corbel::Error for a bad spec.
std::vector<Block> barrelVaultBlocks(const BarrelVaultSpec& spec);

// The vault on fixed ground at z = 0.
Assembly barrelVault(const BarrelVaultSpec& spec);

}  // namespace corbel::statics
