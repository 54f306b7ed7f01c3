#pragma once
// Mass properties of a block for the rigid-body simulation (Whiting et al. 2009, Sec. 5): the
// volume, centroid and inertia of its closed polyhedron, and the principal frame in which a
// rigid body's inertia is diagonal.
#include "statics/model.h"

#include <array>

namespace corbel::sim {

struct MassProperties {
  double volume = 0;   // m³
  Vec3 centroid{0.0};  // m
  // Principal moments of inertia about the centroid per unit density (m⁵; times the density
  // they are kg·m²), and the unit axes they belong to, right-handed (axes[0] × axes[1] = axes[2]).
  Vec3 principalMoments{0.0};
  std::array<Vec3, 3> principalAxes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  // The block's thinnest extent across any of its faces: the least, over faces, of the
  // distance from the face's plane to the farthest vertex.
  double leastWidth = 0;
};

// Exact for any closed polyhedron with outward faces (fans of tetrahedra from the first
// vertex). Throws corbel::Error naming the block when its volume is not positive.
MassProperties massProperties(const statics::Block& block);

}  // namespace corbel::sim
