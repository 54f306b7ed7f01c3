#include "editor/latency.h"

#include <algorithm>

namespace corbel::editor {

void FrameLatency::caused(std::uint64_t state, double eventTime) {
  auto [it, added] = stamps_.emplace(state, eventTime);
  if (!added) it->second = std::min(it->second, eventTime);
}

std::optional<double> FrameLatency::presented(std::optional<std::uint64_t> shownState, double now) {
  if (!shownState) return std::nullopt;
  std::optional<double> latency;
  if (const auto it = stamps_.find(*shownState); it != stamps_.end()) latency = now - it->second;
  // Presented, or superseded by what was: state ids only grow (History::commit).
  stamps_.erase(stamps_.begin(), stamps_.upper_bound(*shownState));
  return latency;
}

}  // namespace corbel::editor
