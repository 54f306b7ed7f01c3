#pragma once
// Registers the town kernel with a SceneSync, so town objects of a Document (core/town_spec.h)
// become shells in the Scene: the footprints read and labelled, the style applied with the
// user's overrides, and the buildings extruded by buildTown. Each building's result is kept in
// a TownCache keyed by a hash of everything it is built from (its styled extrusion spec, which
// holds its footprint, labels, type, profiles and features, and the detail), so rebuilding after
// an override or a change of seed re-extrudes only the buildings whose inputs changed.
#include "city/import.h"
#include "city/labels.h"
#include "city/style.h"
#include "city/town.h"
#include "core/scene_sync.h"
#include "core/town_spec.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace corbel::city {

// The town's inputs, read from a TownSpec: footprints, labels and style.
struct TownInputs {
  Town town;
  std::vector<BuildingLabels> labels;
  Style style;
};
// Reads the spec's footprints and style (files or embedded text); faults throw InputError
// naming "town.footprints" or "town.style" and the fault inside.
TownInputs readTownInputs(const TownSpec& spec);
// The spec's overrides against a style; an unknown type or profile throws InputError naming
// "town.overrides[\"id\"].type" (or .profiles.SIDE).
std::map<std::string, BuildingOverride> resolveOverrides(const Style& style, const TownSpec& spec);
Detail detailFromName(const std::string& name);

// One building of a built town, as the editor lists and picks it.
struct BuiltBuilding {
  std::string id;
  std::string type;   // as styled ("" when it could not be)
  std::string error;  // why it was not built ("" = built)
  std::uint64_t hash = 0;  // of its inputs
  BBox bounds;             // of its mesh (empty when not built)
  std::size_t firstFace = 0, faceCount = 0;  // its faces in the object's mesh
};

class TownCache {
 public:
  // Builds a town object: every building whose input hash is not cached is extruded (in chunks
  // of `chunk`, reporting progress and honouring cancellation between chunks; what was built
  // before a cancel stays cached). Throws InputError for bad inputs, Cancelled when cancelled.
  // The result's warnings name each building not built ("building ID: why") and what the
  // styling changed to build one (an overhang taken off a sharp corner, rows thinned).
  BuildResult build(const DocObject& object, Progress* progress, std::size_t chunk = 8);
  // The buildings of the object's last completed build, in footprint order.
  std::vector<BuiltBuilding> buildings(ObjectId object) const;
  // The cached mesh of one building of the object's last build (empty when none).
  MeshData mesh(ObjectId object, const std::string& id) const;
  // The style and footprints of the object's last build (null before one).
  std::shared_ptr<const TownInputs> inputs(ObjectId object) const;
  // The tag textures (docs/city.md) of every town object's style as last read, for
  // ExportOptions and RenderSettings::tagTextures: a snapshot, which holds those styles.
  TagTextures tagTextures() const;
  std::size_t extrusions() const { return extrusions_.load(); }  // buildings extruded so far

 private:
  struct Entry {
    std::uint64_t hash = 0;
    bool ok = false;
    std::string type, error;
    MeshData mesh;
  };
  struct InputsEntry {
    std::string key;
    std::shared_ptr<const TownInputs> inputs;
  };
  std::shared_ptr<const TownInputs> inputsFor(ObjectId object, const TownSpec& spec);
  mutable std::mutex mutex_;
  std::map<std::pair<ObjectId, std::string>, Entry> entries_;
  std::map<ObjectId, InputsEntry> inputs_;
  std::map<ObjectId, std::vector<BuiltBuilding>> last_;
  std::atomic<std::size_t> extrusions_{0};
};

// One building of a town object's last build, placed as the object is (world space): the mass a
// KIFS follower names with kifs.mass.building (kifs/follow.h). Throws corbel::Error "has no
// building \"ID\"" or "building \"ID\" was not built: WHY"; before the town's first build,
// "is not built yet".
MeshData buildingMesh(const TownCache& cache, const DocObject& town, const std::string& id);
// The same as a function holding the cache (the type of kifs::TownBuildings).
std::function<MeshData(const DocObject&, const std::string&)> buildingMeshes(std::shared_ptr<const TownCache> cache);

// Registers the builder of town objects; the cache (made when null) is shared with the caller
// (the editor lists and picks buildings from it, the tests count its extrusions).
std::shared_ptr<TownCache> registerKernel(SceneSync& sync, std::shared_ptr<TownCache> cache = nullptr);

}  // namespace corbel::city
