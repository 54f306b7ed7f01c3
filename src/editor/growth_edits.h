#pragma once
// The growth panel's changes to a growth object (core/growth_spec.h): pure functions the panel
// commits, so Step and Run are undoable and a scripted run replays them exactly.
#include "core/growth_spec.h"

#include <optional>

namespace corbel::editor {

// One step more than `spec` grows, or nullopt when there is none to take: it already grows
// until every unit stops (steps = -1), or its last build said every unit stopped after
// `stoppedAfter` ≤ spec.steps steps (-1: it did not say so).
std::optional<GrowthSpec> nextStep(const GrowthSpec& spec, int stoppedAfter);

}  // namespace corbel::editor
