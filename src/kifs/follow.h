#pragma once
// KIFS buildings that follow a mass object (footprint "object", docs/kifs.md): the object that
// kifs.mass.object names in the Document, its shell as the Scene holds it (placed: world
// space), baked into a MassField for the building's d_o and d_i.
#include "core/document.h"
#include "core/scene.h"
#include "kifs/distance.h"
#include "kifs/mass_field.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace corbel {
class Progress;
}

namespace corbel::kifs {

// An object's faces in the Scene, cut into triangles (world space).
TriangleSoup sceneTriangles(const Scene& scene, ObjectId id);

// One building of a town object as its kernel last built it, placed (world space): the mass of
// a follower whose kifs.mass.building names it. Throws corbel::Error saying why there is none
// ("has no building \"w9\"", "building \"w9\" was not built: ..."). The Scene holds a town as
// one object, so the caller that has the town kernel's cache supplies this (city::buildingMesh).
using TownBuildings = std::function<MeshData(const DocObject& town, const std::string& building)>;

// The triangles a follower stands on: its mass object's in the Scene, or with
// kifs.mass.building the one building of the town it follows. Throws corbel::Error beginning
// "kifs.mass.building: " when a building is named on an object that is not a town, when there
// are no town buildings to ask (`buildings` empty) or when `buildings` throws.
TriangleSoup massTriangles(const DocObject& mass, const KifsSpec& follower, const Scene& scene,
                           const TownBuildings& buildings);

// The object's KIFS spec when it is a KIFS object that follows a mass (footprint "object"),
// else nullptr.
const KifsSpec* followingSpec(const DocObject& o);

// The object a KIFS object with footprint "object" follows. Throws corbel::Error beginning
// "kifs.mass.object: " when the name is empty, names no object, names the object itself or
// leads back to it through KIFS objects that follow others (a cycle), or names a KIFS object
// that follows another (a mass is a shell: an extrusion, a box, a unit, a meshed KIFS object).
const DocObject& followedObject(const Document& doc, const DocObject& kifsObject);

// That object's shell baked at kifs.mass.resolution. Throws corbel::Error beginning
// "kifs.mass.object: \"NAME\" " when the Scene holds no faces of it (hidden objects are built
// too; a failed build has none) or its faces do not close ("is not closed (N open edges)").
std::shared_ptr<const MassField> followedMass(const Document& doc, const Scene& scene, const DocObject& kifsObject,
                                              Progress* progress = nullptr, const TownBuildings& buildings = {});

// The same bake from the mass object's triangles taken from the Scene beforehand (sceneTriangles),
// so that a worker thread can bake while the Scene changes (the editor's followers).
std::shared_ptr<const MassField> bakeFollowedMass(const DocObject& mass, const TriangleSoup& triangles,
                                                  const KifsParams& params, Progress* progress = nullptr);

// A KIFS object's building: its spec's parameters (paramsOf) and, with footprint "object", the
// mass it follows, in world space (the object's own placement does not apply).
Building buildingOf(const Document& doc, const Scene& scene, const DocObject& kifsObject, Progress* progress = nullptr,
                    const TownBuildings& buildings = {});

}  // namespace corbel::kifs
