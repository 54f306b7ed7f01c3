#pragma once
// Masonry template: a buttress (or a plain pier) of horizontal courses whose width tapers
// linearly from the base to the top (Whiting et al. 2009, Sec. 2, Fig. 4).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct ButtressSpec {
  double height = 3.0;
  double baseWidth = 1.0;  // along x, of the lowest course
  double topWidth = 1.0;   // of the highest course; equal widths make a pier
  double depth = 1.0;      // along y
  int courses = 6;
  double density = 2400.0;
};

// Course i is the box x ∈ [0, w_i], y ∈ [0, depth], z ∈ [i h, (i+1) h] with h = height/courses
// and w_i interpolated linearly from baseWidth (i = 0) to topWidth (i = courses − 1): the face
// x = 0 is flat (it stands against a wall), the other side steps in. Throws corbel::Error.
std::vector<Block> buttressBlocks(const ButtressSpec& spec);

}  // namespace corbel::statics
