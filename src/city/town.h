#pragma once
// A styled town, built in chunks on all cores and handed building by building to a sink, so
// the caller can write each mesh out (a tile, a file) and drop it: the town's meshes are never
// all held by this code.
#include "city/labels.h"
#include "city/style.h"
#include "core/mesh_data.h"
#include "extrude/features.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace corbel::city {

// How much of a style is built: the masses and their roofs (parapets included), plus natural
// steps (dormers, chimneys), plus feature meshes (windows, doors: about 30 faces each, which at
// town scale outweigh the shells many times over).
enum class Detail { Massing, Steps, Full };

struct TownOptions {
  Detail detail = Detail::Full;
  std::uint64_t seed = 1;
  unsigned jobs = 0;               // 0 = all cores
  std::size_t chunk = 1024;        // buildings extruded per round before their meshes are handed on
  bool mergeCoplanar = false;      // export meshes: coplanar neighbours merged (builds each mesh twice)
  bool featuresApart = false;      // meshes without their features, placed in BuildingReport::features
  double timeLimitSeconds = 10.0;  // per building
  const std::map<std::string, BuildingOverride>* overrides = nullptr;  // by building id
};

struct BuildingReport {
  std::size_t index = 0;  // into town.buildings
  std::string id, type;
  bool ok = false;
  std::string error;  // clean-up refusal, styling fault or extrusion failure
  std::vector<std::string> notes, warnings;
  std::vector<extrude::FeaturePlacement> features;  // TownOptions::featuresApart: left out of the mesh
};

struct TownSummary {
  std::size_t buildings = 0, ok = 0, refused = 0, failed = 0;  // refused: before extrusion
  std::map<std::string, std::size_t> types;
  std::size_t faces = 0;
};

// Builds the buildings listed in `order` (all, in file order, when empty). The sink gets every
// building's report, with its mesh when it was built (moved out; null otherwise), in `order`.
// `progress` gets (done, total) after each chunk.
using BuildingSink = std::function<void(const BuildingReport&, MeshData*)>;
TownSummary buildTown(const Town& town, const std::vector<BuildingLabels>& labels, const Style& style,
                      const TownOptions& options, const BuildingSink& sink, const std::vector<std::size_t>& order = {},
                      const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace corbel::city
