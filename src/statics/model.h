#pragma once
// Rigid-block model of a masonry structure (Whiting et al. 2009, Sec. 3.1): closed polyhedra
// (convex or not) with a density, some of them fixed (the ground), loaded by gravity, live
// loads and point loads (the weight of nonstructural shapes they carry).
#include "core/geometry.h"

#include <string>
#include <vector>

namespace corbel::statics {

// A force applied at a point of a block (not necessarily on it), in N.
struct PointLoad {
  Vec3 at{0.0};
  Vec3 force{0.0};
};

// One rigid block. Faces are simple planar polygons (convex or not) given by vertex indices,
// counter-clockwise seen from outside (outward normals); together they must close the block's
// surface. The block itself need not be convex.
struct Block {
  std::string name;
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
  double density = 2400.0;  // kg/m³ (stone); ignored for fixed blocks
  bool fixed = false;       // the ground, an abutment: takes any reaction, has no equations
  Vec3 liveLoad{0.0};       // an extra force in N applied at the block's centroid (Sec. 3.4)
  std::vector<PointLoad> pointLoads;  // extra forces where they act (torque about the centroid)
};

struct Assembly {
  std::vector<Block> blocks;
  // Unit direction of gravity; a ground tilt is modelled by rotating it.
  Vec3 gravity{0.0, 0.0, -1.0};
  double g = 9.81;  // m/s²
};

// Mass properties of a validated block.
struct BlockProperties {
  double volume = 0;
  Vec3 centroid{0.0};
  BBox bounds;
  bool convex = true;             // the whole block lies behind each face's plane
  std::vector<bool> convexFaces;  // per face: a convex polygon (contacts take the fast clip)
};

// Checks that every block is a closed polyhedron with finite coordinates, planar simple faces
// (no two edges of a face cross or touch) and outward orientation, and that densities, loads
// and gravity are finite and positive where they must be. Throws corbel::Error naming the
// block and the fault.
// `tolerance` is the length below which two points count as one (see tolerances.h).
std::vector<BlockProperties> validateAssembly(const Assembly& assembly, double tolerance);

// An axis-aligned box as a block (for the ground, stacks and tests).
Block boxBlock(std::string name, const Vec3& lo, const Vec3& hi, double density = 2400.0, bool fixed = false);

}  // namespace corbel::statics
