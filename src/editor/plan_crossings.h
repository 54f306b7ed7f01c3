#pragma once
// Where a plan's edges cross or touch, for the editor to mark them (in the plan pane and in the
// 3D view) while the kernel refuses the plan. Floating point and for display only: the
// kernel's own check (extrude/plan_check.h, CGAL's exact predicates) decides validity. No GL.
#include "core/geometry.h"

#include <vector>

namespace corbel::editor {

struct PlanCrossing {
  int loopA = 0, edgeA = 0, loopB = 0, edgeB = 0;  // edge i runs from points[i] to points[i + 1]
  Vec2 at{0.0, 0.0};                               // where they meet (the middle of an overlap)
};

// Every pair of edges of `loops` (closed polygons) that meet, other than neighbours of one
// loop at their shared corner; an edge that turns back along its neighbour counts.
std::vector<PlanCrossing> planCrossings(const std::vector<std::vector<Vec2>>& loops);

}  // namespace corbel::editor
