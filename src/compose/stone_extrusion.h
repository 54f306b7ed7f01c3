#pragma once
// An extrusion built in stone (core/stone_walls.h): the walls of a procedural extrusion (Kelly
// & Wonka 2011) coursed into blocks (coursing.h), with openings at its door and window anchors,
// and its roof carried as loads on the wall heads, as a parametric model the statics kernel
// analyses and searches like any masonry template (Whiting et al. 2009).
#include "core/extrusion_spec.h"
#include "statics/coursing.h"
#include "statics/parameters.h"

#include <vector>

namespace corbel::statics {

// What the extrusion's shell gives the walls: the plan, the wall height and, per plan edge, the
// roof resting on that edge's wall head.
struct StoneHouse {
  CoursingSpec walls;        // without the masonry section's numbers (set by stoneModel's build)
  std::vector<double> roofArea;    // per edge: m² of roof surface bearing on it
  std::vector<double> thrustArea;  // per edge: Σ A / (2 tan θ) over those faces, m²
  double roofPitchDeg = 0;         // the steepest roof face's pitch
};

// Reads the extrusion: one plan loop with convex corners, every edge's profile starting with a
// vertical wall of one common height; roof faces (those above the wall segment facing up) go to
// the edge that traced them; door and window anchors become openings (heads from the masonry
// section). Throws InputError at "masonry", "masonry.openings.NAME", "plan" or "steps" naming
// what cannot be built in stone.
StoneHouse stoneHouseOf(const ExtrusionSpec& spec);

// The loads on the wall heads for a covering weight q (N/m²): per edge, down = q·A/L and, unless
// the roof has ties, out = q·Σ A/(2 tan θ) / L (each rafter of weight w = qA, pinned to its
// partner at the ridge, pushes its foot out by w / (2 tan θ)). Faces pitched under 5° push
// nothing (a flat roof on beams).
std::vector<HeadLoad> roofLoads(const StoneHouse& house, double coveringWeight, bool ties);

inline constexpr const char* kStoneModelName = "stone extrusion";

// The extrusion's stone model (named kStoneModelName): parameters thickness, courseHeight, blockLength, coveringWeight,
// density, ties (0 or 1), windPressure and windDirection from the masonry section; the walls
// coursed, loaded by the roof and the wind (loadWind), on a fixed ground slab. Free by default: thickness (Make It Stand thickens the walls).
ParametricModel stoneModel(const ExtrusionSpec& spec);

// The masonry section at the model's values: thickness, course height, block length, covering
// weight, density, ties and wind taken from `values` (those it has), openings kept. What Make
// It Stand writes back, so its result stays the extrusion the artist keeps editing and is one
// edit of the Document.
StoneWalls stoneWallsAt(const StoneWalls& section, const ParameterSet& values);

}  // namespace corbel::statics
