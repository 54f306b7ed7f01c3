#pragma once
// Meshes repeated across a scene (a town's windows, sills and doors), each kept once with the
// rigid placements of its copies; the glb writer places them with EXT_mesh_gpu_instancing
// (docs/export.md, "Instances").
#include "core/mesh_data.h"

#include <string>
#include <vector>

namespace corbel {

// A rotation and a translation in corbel's frame (z up): p_scene = translation + ex x + ey y +
// ez z for a point (x, y, z) of the mesh; ex, ey, ez are orthonormal and right-handed.
struct RigidPlacement {
  Vec3 translation{0, 0, 0};
  Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
};

struct InstancedMesh {
  std::string name;  // the glTF node's and mesh's name
  MeshData mesh;     // in its own frame
  std::vector<RigidPlacement> placements;
};

}  // namespace corbel
