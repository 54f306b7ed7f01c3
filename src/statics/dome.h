#pragma once
// Masonry template: a hemispherical dome with an oculus, in rings of voussoirs (Whiting et al.
// 2009, Fig. 4, Fig. 10).
#include "statics/model.h"

#include <vector>

namespace corbel::statics {

struct DomeSpec {
  int rings = 8;            // courses from the springing to the oculus
  int segments = 16;        // voussoirs per ring
  double radius = 2.0;      // of the middle surface, m
  double thickness = 0.2;   // m
  double oculusDeg = 10.0;  // angle of the oculus from the pole, degrees: the top ring ends at 90° − this
  double density = 2400.0;
};

// Block (i, j) lies between latitudes φ_i = i·(90° − oculus)/rings, φ_{i+1} and longitudes
// θ_j = 2πj/segments, θ_{j+1}, from radius R − t/2 to R + t/2 about the origin. Its meridional
// joints lie in planes through the axis, its bed joints in planes through the centre (cones
// cut by two meridians), intrados and extrados are isosceles trapezoids: every face is plane.
// The springing ring stands on z = 0. Throws corbel::Error for a bad spec.
std::vector<Block> domeBlocks(const DomeSpec& spec);

// A drum: a round wall of `courses` courses, each of `segments` blocks, whose plan is the
// ring between two regular polygons of `segments` sides (inner and outer circumradius
// radius ∓ thickness / 2, so a dome of the same radius, thickness and segments sits on it
// face to face). Course c is turned by half a block when `bond` and c is odd (running bond
// round the drum). Block (c, j) spans the polygons' corners j and j + 1, z ∈ [c h, (c+1) h].
//
// Windows (stack bond only): with windowWidth > 0, segments j ≡ windowEvery / 2 (mod
// windowEvery) have an opening of that width through courses windowSill .. windowHead − 1,
// centred on the segment and cut square to its faces (by the two planes parallel to its
// radial mid-plane at ± windowWidth / 2). Each such course of the segment is two jambs; the
// segment's block in course windowHead spans the opening as its lintel, bearing on both.
struct DrumSpec {
  int courses = 4;
  int segments = 16;
  double radius = 2.0;     // of the middle surface, m
  double thickness = 0.3;  // m
  double height = 2.0;     // m
  bool bond = true;
  double windowWidth = 0;  // m; 0: no windows. At most 90 % of a segment's inner chord.
  int windowEvery = 2;     // a window in every windowEvery-th segment
  int windowSill = 1;      // first open course
  int windowHead = 3;      // the course over the openings (their lintels), below `courses`
  double density = 2400.0;
};

std::vector<Block> drumBlocks(const DrumSpec& spec);

}  // namespace corbel::statics
