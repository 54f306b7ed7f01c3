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

// A flying buttress (Fig. 4, Fig. 13): a quarter arc of voussoirs with radial joints about the
// centre (0, pierHeight), from a horizontal springing on top of its pier up to a vertical head
// joint against the wall. In its frame the wall's outer face is the plane x = 0 and the
// buttress reaches towards +x: the springing spans x ∈ [R − t/2, R + t/2] at z = pierHeight,
// the head z ∈ [pierHeight + R − t/2, pierHeight + R + t/2] at x = 0; the pier (courses,
// `pierWidth` wide) stands under the springing from z = 0.
struct FlyingButtressSpec {
  int blocks = 5;            // voussoirs of the quarter arc
  double radius = 1.5;       // of the arc's centreline: reach from the wall, and rise
  double thickness = 0.25;
  double depth = 0.5;        // along y, from y = 0
  double pierHeight = 1.5;   // the springing's height
  double pierWidth = 0.6;    // along x, centred under the springing
  int pierCourses = 3;
  double density = 2400.0;
};

std::vector<Block> flyingButtressBlocks(const FlyingButtressSpec& spec);

}  // namespace corbel::statics
