#pragma once
// A small composition layer: place templates' blocks in one assembly, name them, put ground
// under them (the "production rules" of Whiting et al. 2009, Sec. 2, as C++ calls).
#include "statics/model.h"

#include <string>
#include <vector>

namespace corbel::statics {

class StructureBuilder {
 public:
  // Adds a template's blocks moved by `offset`, named "prefix/…".
  StructureBuilder& add(const std::string& prefix, std::vector<Block> blocks, const Vec3& offset = Vec3(0.0));
  // A fixed ground slab: top face at z = 0 over [lo, hi] in x and y, `depth` deep.
  StructureBuilder& ground(const Vec2& lo, const Vec2& hi, double depth = 1.0);
  // A fixed ground slab under everything added so far, `margin` wider on each side.
  StructureBuilder& groundUnder(double margin = 1.0);
  // Gravity direction tilted by `deg` about the y-axis, towards +x.
  StructureBuilder& tilt(double deg);
  // The assembly (blocks in the order added, then the ground).
  Assembly build() const;
  std::size_t size() const { return blocks_.size(); }

 private:
  std::vector<Block> blocks_;
  std::vector<Block> ground_;
  Vec3 gravity_{0.0, 0.0, -1.0};
};

}  // namespace corbel::statics
