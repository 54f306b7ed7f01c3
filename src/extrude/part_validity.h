#pragma once
// A building's validity checked in parts: its shell and its features' parts (each a closed
// polyhedron with points of its own), reported as Scene::validate reports the mesh that has
// them all, without building that mesh's half-edge structure. A town's features outnumber its
// shells' faces many times over, and their parts come in a few shapes: each shape's
// connectivity (what a Scene makes of it, and the order it keeps the faces in) is found once
// per thread, and each part adds only its geometry (areas, volume, finite points).
#include "core/mesh_data.h"
#include "core/scene.h"
#include "extrude/features.h"

#include <string>
#include <vector>

namespace corbel::extrude {

// The report of Scene::validate for `shell` with every part of `features` appended (as
// appendFeatures appends them) and inserted as one object named `name`: every count, and the
// area and volume summed in the same order. A part whose shape a Scene would not keep whole
// (faces refused) has the whole mesh built and validated as before.
ValidityReport validateWithFeatures(const MeshData& shell, const std::vector<PlacedFeature>& features,
                                    const std::string& name);

}  // namespace corbel::extrude
