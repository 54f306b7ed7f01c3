#pragma once
// Masonry template: a column of drums laid in horizontal courses (Whiting et al. 2009, Sec. 2).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct ColumnSpec {
  int drums = 4;            // courses
  int sides = 8;            // of the regular polygon section; 4 is a square pier
  double radius = 0.3;      // circumradius of the section, m
  double height = 3.0;      // total, m
  double density = 2400.0;
};

// Drums stacked from z = 0 to `height`, the section centred on the z-axis with a flat side
// facing +x (its apothem is radius·cos(π/sides)). Throws corbel::Error for a bad spec.
std::vector<Block> columnBlocks(const ColumnSpec& spec);

}  // namespace corbel::statics
