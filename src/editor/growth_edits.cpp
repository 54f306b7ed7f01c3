#include "editor/growth_edits.h"

namespace corbel::editor {

std::optional<GrowthSpec> nextStep(const GrowthSpec& spec, int stoppedAfter) {
  if (spec.steps < 0 || (stoppedAfter >= 0 && stoppedAfter <= spec.steps) || spec.steps >= limits::kMaxGrowthSteps)
    return std::nullopt;
  GrowthSpec next = spec;
  ++next.steps;
  return next;
}

}  // namespace corbel::editor
