#pragma once
// Block shapes the masonry templates are cut from: convex blocks, prisms, moves and mirrors.
#include "statics/model.h"

#include <string>
#include <vector>

namespace corbel::statics {

// A convex block from its vertices and faces, every face turned to face outwards (the
// vertex average is inside a convex block).
Block convexBlock(std::string name, std::vector<Vec3> vertices, std::vector<std::vector<int>> faces, double density);

// The prism swept by the planar convex polygon `base` along `extent`.
Block prismBlock(std::string name, const std::vector<Vec3>& base, const Vec3& extent, double density);

// A half-space n·p ≤ d.
struct HalfSpace {
  Vec3 n;
  double d = 0;
};

// The convex block bounded by the half-spaces (their intersection must be bounded and have
// volume): vertices where three planes meet inside all the others, one face per plane that
// touches the block in an area, counter-clockwise about its outward normal.
Block halfspaceBlock(std::string name, const std::vector<HalfSpace>& halfspaces, double density);

// Blocks moved by `offset`, their names prefixed by "prefix/" when the prefix is not empty.
std::vector<Block> placed(std::vector<Block> blocks, const Vec3& offset, const std::string& prefix = "");

// The blocks turned by `radians` about the z-axis (counter-clockwise seen from above).
std::vector<Block> rotatedZ(std::vector<Block> blocks, double radians);

// The mirror image in the plane x = 0 (faces reversed so they still face outwards).
std::vector<Block> mirroredX(std::vector<Block> blocks);

}  // namespace corbel::statics
