#pragma once
// Which faces of a soup can go into a half-edge mesh, and in what order (Scene::replaceObject;
// the glb writer lays a soup's faces out in the same order, core/glb_writer.h).
#include "core/mesh_data.h"

#include <cstddef>
#include <vector>

namespace corbel {

// OpenMesh refuses some non-manifold faces but asserts (aborts) on others, so the soup is
// checked first: every directed edge used once, every undirected edge by at most two faces, and
// the faces around each vertex forming one fan. Returns the accepted faces in an order that
// grows each connected piece across shared edges (so OpenMesh never has to relink boundary gaps
// blindly); `rejected` is set to the number of faces left out.
std::vector<int> manifoldFaceOrder(const MeshData& data, std::size_t& rejected);

}  // namespace corbel
