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
  // Per edge of walls.plan (the input loop, broken where a bay or recess opens an edge, with
  // the bay's cheeks and front between the pieces): the input edge it lies on and how far along
  // it the piece starts (m), or -1 and 0 for a bay's or recess's own walls.
  std::vector<int> edgeSource;
  std::vector<double> edgeOffset;
  std::vector<int> bayStep;        // the entry of spec.steps behind each bay or recess built
  // Bays and recesses lower than the walls (all rising to bayTop, m above the base; 0: none):
  // below bayTop (snapped to a course joint) the walls follow walls.plan, with them; above it
  // they follow upper.plan, without them, the wall spanning each one's mouth on a lintel
  // (mouths, on upper.plan's edges). upper.openings are the doors and windows over a mouth;
  // the others, in walls.openings, are carried on into the band above where they reach it.
  double bayTop = 0;
  CoursingSpec upper;
  std::vector<int> upperSource;     // as edgeSource and edgeOffset, for upper.plan
  std::vector<double> upperOffset;
  std::vector<WallOpening> mouths;
  std::vector<double> upperRoofArea, upperThrustArea;  // per edge of upper.plan
  std::vector<double> roofArea;    // per edge: m² of roof surface bearing on it
  std::vector<double> thrustArea;  // per edge: Σ A / (2 tan θ) over those faces, m²
  double roofPitchDeg = 0;         // the steepest roof face's pitch
  // The extrusion's buttresses (walls.buttresses, at their steps' depths): which entry of
  // spec.steps made each (repeats expanded).
  std::vector<int> buttressStep;
};

// Buttresses below this depth (m) are not built: a search on buttressDepth starting from 0
// adds them (proposedButtresses) once the depth reaches it.
inline constexpr double kMinButtressDepth = 0.05;

// Reads the extrusion: one plan loop, every edge's profile starting with a vertical wall of one
// common height; door and window anchors become openings (heads from the masonry section).
// Natural steps standing on the ground (anchor height 0), every instance of a repeat:
// - of rectangle shape reaching out of the wall (depth > 0): buttresses, solid piers of stone
//   `width` × `depth` about their anchor, as high as their front profile's first, vertical
//   segment (at most the wall head);
// - bays (any depth), and rectangles reaching in (recesses): walls of the plan. The edge's wall
//   is opened over the step's width and the step's cheeks and front close the plan around it
//   (out of it for a bay, into it for a recess), meeting the main wall at reflex corners, as
//   high as their profiles' first, vertical segments (front and sides alike, at most the main
//   walls'). Those lower than the main walls all rise to one height (bayTop), above which the
//   main wall spans their mouths on lintels.
// Roof faces (those above the wall segment facing up, in the extrusion with its bays and
// recesses) go to the edge that traced them: a main edge's spread along its pieces, a bay's
// to the bay's wall. Throws InputError at "masonry", "masonry.openings.NAME", "plan" or
// "steps[i]" naming what cannot be built in stone (forced steps, steps above the ground, bays
// higher than the walls, lower bays of different heights, bays past their edge's end or
// meeting another, openings and buttresses where a bay opens the wall).
StoneHouse stoneHouseOf(const ExtrusionSpec& spec);

// Where Make It Stand puts buttresses on an extrusion that has none (Kelly & Wonka's
// buttresses, Fig. 23, as natural steps): on each main wall (not a bay's) of length L and height h, ⌊L / h⌋ (at
// least one) evenly spaced piers one block long; a pier that would meet an opening (with a
// course and three quarters of a block of clearance for its head), or the lintel over a lower
// bay's mouth beside it, is replaced by one on each side of it; piers that would reach a corner's square or another pier are left out. Their
// depth is 0 (the caller sets it) and they reach the wall head.
std::vector<WallButtress> proposedButtresses(const StoneHouse& house, double blockLength, double courseHeight,
                                             double thickness);

// The loads on the wall heads for a covering weight q (N/m²): per edge, down = q·A/L and, unless
// the roof has ties, out = q·Σ A/(2 tan θ) / L (each rafter of weight w = qA, pinned to its
// partner at the ridge, pushes its foot out by w / (2 tan θ)). Faces pitched under 5° push
// nothing (a flat roof on beams). The model puts them on the blocks with loadHeadsOnPiers: a
// wall with buttresses up to its head carries its roof on them.
std::vector<HeadLoad> roofLoads(const StoneHouse& house, double coveringWeight, bool ties);

inline constexpr const char* kStoneModelName = "stone extrusion";

// The extrusion's stone model (named kStoneModelName): parameters thickness, courseHeight,
// blockLength, coveringWeight, density, ties (0 or 1), windPressure and windDirection from the
// masonry section, and buttressDepth: the deepest buttress step's depth, every buttress scaled
// with it; on an extrusion without buttresses it is 0 and a value of kMinButtressDepth or more
// adds proposedButtresses of that depth. The walls coursed, loaded by the roof (on the piers
// where a wall has buttresses up to its head: loadHeadsOnPiers) and the wind (loadWind), on a
// fixed ground slab. Free by default: thickness, and buttressDepth where the
// extrusion has buttresses (Make It Stand thickens the walls and deepens the buttresses); free
// buttressDepth yourself (e.g. 0.1 to 2 m) to let it add buttresses.
ParametricModel stoneModel(const ExtrusionSpec& spec);

// The masonry section at the model's values: thickness, course height, block length, covering
// weight, density, ties and wind taken from `values` (those it has), openings kept. What Make
// It Stand writes back, so its result stays the extrusion the artist keeps editing and is one
// edit of the Document.
StoneWalls stoneWallsAt(const StoneWalls& section, const ParameterSet& values);

// The extrusion at the model's values: its masonry section (stoneWallsAt) and its buttress
// steps at `buttressDepth` (scaled as the model does), or, where it has none and the value adds
// them, the proposed buttresses written as rectangle steps (anchored at the ground on their
// walls, a fraction along, with a profile "buttress": vertical to the wall head, then leaning
// in at 60°). What Make It Stand writes back: the result stays an extrusion the artist keeps
// editing.
ExtrusionSpec stoneSpecAt(const ExtrusionSpec& spec, const ParameterSet& values);

}  // namespace corbel::statics
