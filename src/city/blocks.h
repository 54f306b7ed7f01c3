#pragma once
// The far view of a town's building (3D Tiles, docs/city.md "Tilesets"): its footprint extruded
// straight up between two heights, no roof, no features; walls in one material, the top in
// another.
#include "core/mesh_data.h"

#include <string>
#include <vector>

namespace corbel::city {

// A closed prism over the footprint `loops` (outer counter-clockwise, holes clockwise, metres)
// from z = bottom to z = top: a quad per edge, and the top and bottom faces triangulated
// (CGAL constrained Delaunay, courtyards left open). Faces are counter-clockwise seen from
// outside. Empty when the loops enclose nothing or top <= bottom.
MeshData extrudedBlock(const std::vector<std::vector<Vec2>>& loops, double bottom, double top,
                       const std::string& wallMaterial, const std::string& topMaterial);

// The material covering the most area of the mesh's upright faces (|n.z| < 0.1) and of its
// upward faces (n.z > 0.1): a block's wall and top materials (walls' for a mesh without a top).
std::pair<std::string, std::string> dominantMaterials(const MeshData& mesh);

}  // namespace corbel::city
