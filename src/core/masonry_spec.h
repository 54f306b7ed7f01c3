#pragma once
// A masonry object (Whiting, Ochsendorf & Durand 2009): one of the statics kernel's parametric
// models, named by `model`, with the parameter values the user set (the others keep the
// model's defaults), the parameters freed for the search that makes it stand (Sec. 4) and the
// analysis settings. Core holds names and numbers; the statics kernel checks the names against
// the model when it builds the blocks, and says which one is wrong.
#include "core/geometry.h"

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

// A load the artist placed on one block (Sec. 3.4: the weight of what the structure carries, a
// bell, a statue, people; wind as a pressure on a face). The block is named as the model names
// it ("voussoir 4", "left/drum 2"), so the load stays on it when parameters change its size;
// the statics kernel says which load names a block or face the model does not have.
struct MasonryLoad {
  std::string name;  // what it is ("bell"), for the panel and the messages
  std::string block;
  // A point load: `force` in N acting at the block's centroid plus `offset` (m), so it moves
  // with the block when the block is resized. Weight of m kg: (0, 0, −9.81 m).
  Vec3 offset{0.0};
  Vec3 force{0.0};
  // A load per area instead, when face ≥ 0: `pressure` Pa on that face of the block (its
  // index in the block), pushing into the face at the face's centroid (wind).
  int face = -1;
  double pressure = 0.0;
  bool operator==(const MasonryLoad&) const = default;
};

struct MasonrySpec {
  std::string model = "arch-on-columns";
  std::vector<MasonryParameter> parameters;  // loaded in name order (JSON objects keyed by name)
  std::vector<MasonryFree> free;
  double friction = 0.7;  // α of the friction pyramid (Sec. 3.1)
  // Use α/√2, so the pyramid lies inside the friction cone (Sec. 3.1): safe, but a design
  // that relies on friction near α is called not standing.
  bool conservativeFriction = false;
  double kern = 0.0;      // every contact polygon shrunk by this factor about its centroid (Sec. 3.4)
  std::vector<MasonryLoad> loads;
  // The model's own ground slab. Off for an object that rests on others (an arch on columns):
  // it is neither drawn nor analysed alone, only with the objects it stands on
  // (statics/composite.h puts one ground under them all).
  bool ground = true;
  std::string material = "stone";
  bool operator==(const MasonrySpec&) const = default;
};

namespace limits {
inline constexpr std::size_t kMaxMasonryParameters = 10000;
inline constexpr std::size_t kMaxMasonryLoads = 10000;
}

}  // namespace corbel
