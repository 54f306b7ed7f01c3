#pragma once
// A masonry object (Whiting, Ochsendorf & Durand 2009): one of the statics kernel's parametric
// models, named by `model`, with the parameter values the user set (the others keep the
// model's defaults), the parameters freed for the search that makes it stand (Sec. 4) and the
// analysis settings. Core holds names and numbers; the statics kernel checks the names against
// the model when it builds the blocks, and says which one is wrong.
#include <string>
#include <vector>

namespace corbel {

struct MasonryParameter {
  std::string name;
  double value = 0.0;
  bool operator==(const MasonryParameter&) const = default;
};

// A parameter the search may move, within [lo, hi] (the user's bounds, Sec. 2).
struct MasonryFree {
  std::string name;
  double lo = 0.0, hi = 0.0;
  bool operator==(const MasonryFree&) const = default;
};

struct MasonrySpec {
  std::string model = "arch-on-columns";
  std::vector<MasonryParameter> parameters;  // loaded in name order (JSON objects keyed by name)
  std::vector<MasonryFree> free;
  double friction = 0.7;  // α of the friction pyramid (Sec. 3.1)
  double kern = 0.0;      // every contact polygon shrunk by this factor about its centroid (Sec. 3.4)
  std::string material = "stone";
  bool operator==(const MasonrySpec&) const = default;
};

namespace limits {
inline constexpr std::size_t kMaxMasonryParameters = 10000;
}

}  // namespace corbel
