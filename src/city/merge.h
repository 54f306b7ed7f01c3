#pragma once
// One tileset over the tilesets of a town's tiles, built apart (corbel-cli city-merge,
// docs/city.md "Beyond one machine"): each part's root becomes a child of a new root, its
// content addresses put under the part's folder; the parts keep their own transforms onto the
// globe, so the new root has none and its box is in Earth-centred coordinates (ECEF).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace corbel::city {

struct TilesetPart {
  std::string folder;     // relative to the merged tileset.json, e.g. "tilesets/3_4"
  nlohmann::json tileset; // the part's tileset.json
};

// The merged tileset.json (version 1.1). The root's box is the ECEF-axis box around the corners
// of every part's root box placed by its transform, grown by 1 cm; its geometric error (and the tileset's) is
// that box's diagonal. Throws corbel::Error naming a part whose root is not a box placed by a
// transform.
nlohmann::json mergeTilesets(const std::vector<TilesetPart>& parts);

}  // namespace corbel::city
