#pragma once
// The state of a simulation as a polygon soup for the Scene: every block that was not removed
// or broken, moved by its current pose, the parts of broken blocks and the dropped loads. The editor draws it live; the
// CLI renders frames from it. The design blocks themselves are never changed.
#include "core/mesh_data.h"
#include "sim/session.h"

#include <string>

namespace corbel::sim {

// Faces tagged "block", "ground" (fixed blocks) or "load", all in `material`.
MeshData posedMesh(const Session& session, const std::string& material = "stone");

}  // namespace corbel::sim
