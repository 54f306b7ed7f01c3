#pragma once
// The mass-model kernel: BoxSpec → closed shell. A pure function, like every kernel.
#include "core/document.h"
#include "core/mesh_data.h"

namespace corbel {

// Six quads per box (tags "wall", "roof", "base"), outward-facing, one closed component
// per repeated copy.
MeshData buildBoxes(const BoxSpec& spec);

}  // namespace corbel
