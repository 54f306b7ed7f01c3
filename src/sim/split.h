#pragma once
// Breaking a block (Whiting et al. 2009, Fig. 14b): a closed convex block cut by a plane into
// the two closed convex blocks either side of it.
#include "statics/model.h"

#include <array>

namespace corbel::sim {

// The parts of `block` on the side of the plane through `point` that `normal` points away
// from (first) and towards (second), each closed with the cut face. Both keep the block's
// density and name with " (part 1)" and " (part 2)". Throws corbel::Error naming the block
// when the plane does not cut it into two parts of positive volume.
std::array<statics::Block, 2> splitBlock(const statics::Block& block, const Vec3& point, const Vec3& normal);

// The cut Session::breakBlock makes: through the centroid, at 45° between the block's longest
// and its shortest principal direction, the plane a shear crack would take. Two wedges meeting
// on it can only hold each other up by friction above tan 45° = 1.
Vec3 shearCrackNormal(const statics::Block& block);

}  // namespace corbel::sim
