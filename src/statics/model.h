#pragma once
// Rigid-block model of a masonry structure (Whiting et al. 2009, Sec. 3.1): closed convex
// polyhedra with a density, some of them fixed (the ground), loaded by gravity and live loads.
#include "core/geometry.h"

#include <string>
#include <vector>

namespace corbel::statics {

// One rigid block. Faces are convex polygons given by vertex indices, counter-clockwise seen
// from outside (outward normals); together they must close the block's surface.
struct Block {
  std::string name;
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
  double density = 2400.0;  // kg/m³ (stone); ignored for fixed blocks
  bool fixed = false;       // the ground, an abutment: takes any reaction, has no equations
  Vec3 liveLoad{0.0};       // an extra force in N applied at the block's centroid (Sec. 3.4)
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
};

// Checks that every block is a closed convex polyhedron with finite coordinates, planar convex
// faces and outward orientation, and that densities, loads and gravity are finite and
// positive where they must be. Throws corbel::Error naming the block and the fault.
// `tolerance` is the length below which two points count as one (see tolerances.h).
std::vector<BlockProperties> validateAssembly(const Assembly& assembly, double tolerance);

// An axis-aligned box as a block (for the ground, stacks and tests).
Block boxBlock(std::string name, const Vec3& lo, const Vec3& hi, double density = 2400.0, bool fixed = false);

}  // namespace corbel::statics
