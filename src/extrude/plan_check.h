#pragma once
// Plan validity with CGAL's exact predicates: an orientation decides the topology here, so a
// floating-point sign error must not slip through.
#include "core/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::extrude {

// The first fault of a plan, naming the loop and point: a crossing or touching of two
// edges, or a loop whose orientation does not match its nesting (outer loops and islands
// counter-clockwise, holes clockwise).
std::optional<std::string> checkPlanTopology(const std::vector<std::vector<Vec2>>& loops);

// Nesting depth of each loop (0 = outer, 1 = hole, 2 = island, ...); loops must not cross.
std::vector<int> nestingDepths(const std::vector<std::vector<Vec2>>& loops);

}  // namespace corbel::extrude
