#pragma once
// A town cut into square tiles of a grid for separate builds (corbel-cli city-split,
// docs/city.md "Beyond one machine"): each building belongs to the one tile that holds the mean
// of its outer ring's corners, and each tile's source also carries, marked as margin, the
// buildings and streets near its own ones, so that its buildings are labelled (turned to their
// street, their widest gap found) as in a build of the whole town.
#include "city/import.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace corbel::city {

// The property that marks a margin building in a tile's source: labelled, not built.
inline constexpr const char* kMarginProperty = "corbel_margin";

// Whether a building's properties mark it as margin (kMarginProperty true or a number other than 0).
inline bool marksMargin(const nlohmann::json& p) {
  if (!p.is_object()) return false;
  const auto m = p.find(kMarginProperty);
  return m != p.end() && (m->is_boolean() ? m->get<bool>() : m->is_number() && m->get<double>() != 0);
}

struct SplitTile {
  long x = 0, y = 0;                 // the cell [x g, (x + 1) g) × [y g, (y + 1) g) of the local frame
  std::string name;                  // "X_Y"
  std::vector<std::size_t> own;      // buildings whose corners' mean lies in the cell
  std::vector<std::size_t> margin;   // others within `margin` m of the box around the own ones
  std::vector<std::size_t> streets;  // streets within `margin` m of that box
};

// The tiles that own a building, in (y, x) order, for a grid of `grid` m and a margin of `margin`
// m (the labels look 60 m for walls and 200 m for streets). `unplaced` gets the buildings with no
// outline (a reader's refusal), which no tile holds.
std::vector<SplitTile> splitTown(const Town& town, double grid, double margin, std::vector<std::size_t>* unplaced = nullptr);

// One tile's source as a GeoJSON FeatureCollection in the town's local frame: the frame named
// as corbel's "frame" member (an equirectangular frame) or a "crs" member (the PROJ definition),
// the attribution as a "source" member, every building with its id, properties and outline as
// read, margin buildings with kMarginProperty true.
nlohmann::json tileSource(const Town& town, const SplitTile& tile);

}  // namespace corbel::city
