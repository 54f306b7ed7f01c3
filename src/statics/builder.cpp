#include "statics/builder.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <cmath>
#include <numbers>

namespace corbel::statics {

StructureBuilder& StructureBuilder::add(const std::string& prefix, std::vector<Block> blocks, const Vec3& offset) {
  for (Block& b : placed(std::move(blocks), offset, prefix)) blocks_.push_back(std::move(b));
  return *this;
}

StructureBuilder& StructureBuilder::ground(const Vec2& lo, const Vec2& hi, double depth) {
  if (!(lo[0] < hi[0] && lo[1] < hi[1]) || !(depth > 0) || !std::isfinite(depth))
    throw Error("builder: the ground needs lo < hi and a positive depth");
  ground_.push_back(boxBlock("ground", Vec3(lo[0], lo[1], -depth), Vec3(hi[0], hi[1], 0.0), 1.0, true));
  return *this;
}

StructureBuilder& StructureBuilder::groundUnder(double margin) {
  if (blocks_.empty()) throw Error("builder: nothing to put ground under");
  BBox box;
  for (const Block& b : blocks_)
    for (const Vec3& v : b.vertices) box.add(v);
  return ground(Vec2(box.lo[0] - margin, box.lo[1] - margin), Vec2(box.hi[0] + margin, box.hi[1] + margin), margin);
}

StructureBuilder& StructureBuilder::tilt(double deg) {
  if (!std::isfinite(deg) || std::abs(deg) >= 90) throw Error("builder: the tilt must be within ±90°");
  const double t = deg * std::numbers::pi / 180.0;
  gravity_ = Vec3(std::sin(t), 0.0, -std::cos(t));
  return *this;
}

Assembly StructureBuilder::build() const {
  Assembly as;
  as.blocks = blocks_;
  as.blocks.insert(as.blocks.end(), ground_.begin(), ground_.end());
  as.gravity = gravity_;
  return as;
}

}  // namespace corbel::statics
