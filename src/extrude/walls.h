#pragma once
// Walls at the kernel's door. A wall (PlanLoop::walls) may span several input edges once an
// edit has split one; anchors measure along the whole wall. Before the sweep, each wall's run
// of edges becomes as few kernel edges as its shape allows: consecutive edges in one line on
// one profile join (a split that changed nothing leaves no trace in the shell), and every
// anchor moves onto the joined edge that holds its point, in that edge's own terms.
#include "core/extrusion_spec.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::extrude {

struct KernelWalls {
  ExtrusionSpec spec;  // one edge per joined stretch of a wall
  // Per loop, per kernel corner: the input corner it is (so per kernel edge, the input edge it
  // starts with).
  std::vector<std::vector<int>> inputCorner;
  // "loops[L].points[P]" (or ".profile[P]") of the kernel spec, in the input's numbering.
  std::string inputPath(const std::string& where) const;
};

// nullopt when every wall is one edge: the spec goes to the kernel as it is. `colinear`: how
// far (m) a corner may lie off the line of its neighbours and still be joined.
std::optional<KernelWalls> kernelWalls(const ExtrusionSpec& spec, double colinear);

}  // namespace corbel::extrude
