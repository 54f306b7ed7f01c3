#pragma once
// Collapsing staircases (Sec. 7.3.1, Fig. 7.10-7.11): the constructive proof that Face Split
// and Face Advance reach every rectilinear unit from the canonical one, as an algorithm.
//
// A staircase is three consecutive edges A, B, C of the outline with A and C facing the same
// way (one convex and one reflex corner at B's ends). Collapsing it moves C back onto A's
// line (or A onto C's), merging them into one edge; B disappears, and so does the edge after
// C (before A) when it was exactly as long as B. Each collapse is the reverse of one forward
// step on a ShapeTree: split the merged edge at one or two points and advance one piece.
// Repeating until four edges remain leaves a rectangle; the recorded steps, replayed
// backwards from the canonical unit, rebuild the shape.
#include "growth/shapetree.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace corbel::growth {

// The forward step that undoes one collapse: on the edge from → to (facing `facing`) of the
// collapsed outline, split at `cuts` (distances from `from`, increasing), then advance piece
// `piece` (0-based among the cut pieces) by `alpha`.
struct CollapseStep {
  GridPoint from, to;
  Facing facing = Facing::None;
  std::vector<GridCoord> cuts;
  int piece = 0;
  GridCoord alpha = 0;
  GridRect swept;  // the rectangle the collapse removed (alpha > 0) or filled (alpha < 0)
};

struct CollapseTrace {
  GridRect rectangle;               // what is left
  std::vector<CollapseStep> steps;  // in collapse order
};

struct CollapseOptions {
  std::uint64_t seed = 1;   // which staircase to collapse when several can be
  bool removeOnly = false;  // only collapses that cut area away (for the sea, Alg. 2)
};

// Collapses a simple clockwise rectilinear outline to a rectangle; nullopt when no staircase
// can be collapsed without the outline touching itself (the property tests look for this).
std::optional<CollapseTrace> collapseStaircases(const std::vector<GridPoint>& outline,
                                                const CollapseOptions& options = {});

// The canonical unit: a 1 × 1 square at the rectangle's south-west corner, advanced east and
// north to the rectangle, then the steps replayed last to first. Its outline equals the
// collapsed one's; every op is in the tree's history, so undoing all of it returns the square.
ShapeTree rebuildFromCanonical(const CollapseTrace& trace, std::string* why = nullptr);

// The same cycle of corners starting at its least corner (for comparing outlines).
std::vector<GridPoint> canonicalCycle(std::vector<GridPoint> corners);

}  // namespace corbel::growth
