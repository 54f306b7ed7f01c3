#pragma once
// Geometric checks of a shell beyond closure (the Scene checks that): each face a simple
// polygon in its own plane, and the triangulated shell free of self-intersections. A face
// that runs up a hip past the roof's apex and back (a needle of no area) is closed and a
// 2-manifold, and only these see it.
#include "extrude/extrude.h"

#include <array>
#include <string>
#include <vector>

namespace corbel::extrude::test {

// "" or the first problem: a face loop (outer or hole) that is not simple when projected onto
// the coordinate plane its normal is most across (CGAL's is_simple_2), or two triangles of the
// shell's mesh (toMeshData, every face triangulated) that intersect (CGAL's self_intersections),
// except triangles that only touch at one point where the mesh has two vertices (a vertex of
// two fans split in two, as toMeshData does where a shell touches itself).
// `factor`: the tolerance factor the shell was built with (ExtrudeOptions), which widens δ2.
std::string shellGeometryProblem(const SweepOutput& shell, const ExtrusionSpec& spec, double factor = 1.0);

// The triangles (indices into pts) that the check cuts a polygon into, in the coordinate plane
// its normal is most across: ear clipping by exact orientation tests. No cut passes within
// `tolerance` of a corner of the polygon that is not its end (a corner that close blocks the
// ear: the triangle would be a sliver against that corner, and in space, where the polygon is
// planar only to rounding, it crosses the faces that meet there). Corners within `tolerance`
// of the line through their neighbours are never ears; what is left when no ear remains has no
// area and is dropped.
std::vector<std::array<int, 3>> cutIntoTriangles(const std::vector<Vec3>& pts, const std::vector<int>& polygon,
                                                 double tolerance);

}  // namespace corbel::extrude::test
