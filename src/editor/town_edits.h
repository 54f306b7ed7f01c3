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
// Sets one edge's profile in a building's override (loop and edge of the cleaned footprint);
// an empty profile gives that edge back to its orientation's choice (and an override left
// empty is removed). Throws corbel::Error when there is no such town object.
void setTownEdgeProfile(Document& doc, ObjectId id, const std::string& building, int loop, int edge,
                        const std::string& profile);
// The edge (loop, edge) of a plan nearest to p and within maxDistance of it, or nullopt; on a
// tie the first in loop order.
std::optional<std::pair<int, int>> nearestEdge(const std::vector<std::vector<Vec2>>& loops, const Vec2& p,
                                               double maxDistance);
// Replaces the object's town spec; throws corbel::Error when there is no such town object or a
// value is refused (checkTownSpec).
void setTownSpec(Document& doc, ObjectId id, const TownSpec& spec);

// Streets of a town (Fig. 26), each edit checked by checkTownSpec (a refusal throws
// corbel::Error naming the street, "town.streets[0].points[2]: repeats the point before it", and
// leaves the Document as it was).
// A straight street of three control points along the town's south side, 20 m clear of the
// bounds of what the object's last build made (or 0..70 m on y = -20 before any build).
TownStreet defaultStreet(const city::TownCache& cache, ObjectId object);
// Adds a street; returns its index.
std::size_t addStreet(Document& doc, ObjectId id, const TownStreet& street);
void setStreet(Document& doc, ObjectId id, std::size_t street, const TownStreet& value);
void moveStreetPoint(Document& doc, ObjectId id, std::size_t street, std::size_t point, const Vec2& to);
void removeStreet(Document& doc, ObjectId id, std::size_t street);
// Where a ray of the 3D view meets the ground plane z = 0 (nullopt when it looks up or along it).
std::optional<Vec2> groundPoint(const Vec3& origin, const Vec3& dir);

// The building of the object's last build whose faces the ray (origin, unit direction) meets
// first, or nullopt.
std::optional<std::string> pickBuilding(const city::TownCache& cache, ObjectId object, const Vec3& origin,
                                        const Vec3& dir);

// The .json styles in a folder (assets/styles), sorted by file name.
std::vector<std::string> stylesIn(const std::string& folder);

}  // namespace corbel::editor
