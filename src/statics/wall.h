#pragma once
// Masonry template: a wall of blocks in horizontal courses, running bond, with rectangular
// window openings under one-piece lintels (Whiting et al. 2009, Sec. 2, Fig. 3).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct WindowSpec {
  double x = 1.0;      // left edge of the opening, m from the wall's start
  double width = 1.0;  // m
  int sill = 1;        // first open course (0: a door)
  int head = 3;        // the course over the opening, which holds its lintel
};

struct WallSpec {
  double length = 4.0;       // along x
  double thickness = 0.4;    // along y
  double height = 3.0;       // along z
  int courses = 6;
  double blockLength = 0.5;  // odd courses are shifted by half a block (running bond)
  std::vector<WindowSpec> windows;
  double density = 2400.0;
};

// Blocks in x ∈ [0, length], y ∈ [0, thickness], z ∈ [0, height]. Course c is cut at the bond's
// joints, at the edges of openings it crosses and at the ends of lintels it holds; a lintel
// spans its opening and half a block of bearing on each side as one block, and bond joints
// closer than a quarter block to a cut are dropped (no slivers). Throws corbel::Error for
// openings that leave the wall, overlap (with their lintels) or have no course above.
std::vector<Block> wallBlocks(const WallSpec& spec);

}  // namespace corbel::statics
