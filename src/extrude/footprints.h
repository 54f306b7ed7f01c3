#pragma once
// Building footprints from GeoJSON (RFC 7946): a FeatureCollection of Polygon or
// MultiPolygon features in projected coordinates (meters, taken as they are).
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace corbel::extrude {

struct Footprint {
  std::string id;                           // feature id, "source_id" property or index; "#k" per polygon part
  std::vector<std::vector<Vec2>> loops;     // outer counter-clockwise, holes clockwise
  nlohmann::json properties;
  std::vector<std::string> notes;           // clean-up done (duplicate points removed, rings reoriented)
  std::string problem;                      // why this footprint cannot be used ("" = usable)
};

// Reads every polygon of the file. A fault of the file as a whole throws InputError with the
// JSON path; a fault of one feature is kept in that footprint's `problem`, so a batch goes on.
std::vector<Footprint> readGeoJson(const std::string& text);
std::vector<Footprint> readGeoJsonFile(const std::string& path);

}  // namespace corbel::extrude
