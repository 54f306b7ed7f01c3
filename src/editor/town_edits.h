#pragma once
// The Town panel's changes to a town object (core/town_spec.h), as pure functions on a
// Document that the panel commits (one undo step each), and picking a building of a built town
// under a ray of the 3D view.
#include "city/kernel.h"
#include "core/document.h"

#include <optional>
#include <string>

namespace corbel::editor {

// Sets one building's override (an empty one removes it); throws corbel::Error when there is
// no such town object.
void setTownOverride(Document& doc, ObjectId id, const std::string& building, const TownOverride& o);
// Replaces the object's town spec; throws corbel::Error when there is no such town object or a
// value is refused (checkTownSpec).
void setTownSpec(Document& doc, ObjectId id, const TownSpec& spec);

// The building of the object's last build whose faces the ray (origin, unit direction) meets
// first, or nullopt.
std::optional<std::string> pickBuilding(const city::TownCache& cache, ObjectId object, const Vec3& origin,
                                        const Vec3& dir);

// The .json styles in a folder (assets/styles), sorted by file name.
std::vector<std::string> stylesIn(const std::string& folder);

}  // namespace corbel::editor
