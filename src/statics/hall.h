#pragma once
// Masonry template: a square hall under a drum (Whiting et al. 2009, Fig. 10 a, b, d): four
// walls of the wall template, one window centred in each, and on their tops a course of flat
// corner slabs (squinches) that turns the square into an octagon on which a round drum sits.
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct SquareHallSpec {
  double radius = 3.0;         // of the walls' middle square (half its side), m
  double wallThickness = 0.8;  // m
  double height = 4.0;         // of the walls, m
  int courses = 4;             // of the walls; their blocks are about a course long
  double windowWidth = 1.0;    // of the window centred in each wall, m; 0: none
  double slabThickness = 0.4;  // of the course of slabs on the walls, m
  // The corner slabs' inner faces are the planes |x| + |y| = cornerLine (the octagon's
  // diagonal sides); squinchLine gives the one under a drum.
  double cornerLine = 4.0;
  double density = 2400.0;
};

// The walls, x and y in [−a, a] with a = radius + wallThickness / 2, z ∈ [0, height], laid
// pinwheel-fashion: each wall runs from the inner face of the one before it (turning
// counter-clockwise) to the outer corner, so every corner square belongs to one wall and the
// four are quarter turns of each other. Windows run from the second course to a lintel in the
// top one. Then the slab course, z ∈ [height, height + slabThickness], over the walls' outer
// square less the octagon |x|, |y| ≤ b, |x| + |y| ≤ cornerLine (b = radius − wallThickness / 2):
// four corner slabs (|x| + |y| ≥ cornerLine in a quadrant, meeting on the axes where
// cornerLine < a) and four side slabs on the walls' middles between their lines (trapezoids,
// or triangles where cornerLine ≤ a). Every block is convex. Throws corbel::Error
// for a bad spec (windows that do not fit, an octagon that is no octagon).
std::vector<Block> squareHallBlocks(const SquareHallSpec& spec);

// The largest cornerLine under which the ring between the regular polygons of `segments`
// sides (corners at angles 2πk/segments, circumradius drumInner inside, drumOuter outside)
// lies wholly on the hall's walls and corner slabs: the least |x| + |y| of the ring where it
// is off the walls (|x|, |y| < b). Throws corbel::Error when the ring does not lie inside the
// walls' outer square or `segments` is not a multiple of 4.
double squinchLine(const SquareHallSpec& hall, double drumInner, double drumOuter, int segments);

}  // namespace corbel::statics
