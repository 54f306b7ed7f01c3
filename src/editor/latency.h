#pragma once
// From a mouse or key event to the frame that shows what it changed: the editor's latency, as
// `--latency-log` records it for the benchmarks. A Document state made in a frame that had input
// is stamped with that frame's earliest event (the one that waited longest); when a frame
// presents the Scene built from that state, the time since the stamp is its latency. States
// superseded before the Scene showed them (a drag moves faster than the kernel builds) are
// never shown, so they have no latency; the next shown state does.
#include <cstdint>
#include <map>
#include <optional>

namespace corbel::editor {

class FrameLatency {
 public:
  // `state` was committed in a frame whose earliest input event happened at `eventTime` (s).
  void caused(std::uint64_t state, double eventTime);
  // A frame presented at `now` (s) the Scene of `shownState`: the latency (s) when that state
  // came from input and had not been presented before. Stamps of older states are forgotten.
  std::optional<double> presented(std::optional<std::uint64_t> shownState, double now);
  std::size_t pending() const { return stamps_.size(); }

 private:
  std::map<std::uint64_t, double> stamps_;
};

}  // namespace corbel::editor
