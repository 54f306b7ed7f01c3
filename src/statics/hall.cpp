#include "statics/hall.h"

#include "core/error.h"
#include "statics/shapes.h"
#include "statics/wall.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

// A quarter turn counter-clockwise about the z-axis, exact: (x, y) → (−y, x).
std::vector<Block> quarterTurned(std::vector<Block> blocks, int turns) {
  for (Block& b : blocks)
    for (int k = 0; k < ((turns % 4) + 4) % 4; ++k) {
      for (Vec3& v : b.vertices) v = Vec3(-v[1], v[0], v[2]);
      b.liveLoad = Vec3(-b.liveLoad[1], b.liveLoad[0], b.liveLoad[2]);
    }
  return blocks;
}

}  // namespace

std::vector<Block> squareHallBlocks(const SquareHallSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(spec.radius) || !positive(spec.wallThickness) || spec.wallThickness >= spec.radius)
    throw Error("hall: radius and wall thickness must be positive, the walls thinner than the radius");
  if (!positive(spec.height) || !positive(spec.slabThickness))
    throw Error("hall: height and slab thickness must be positive");
  if (spec.courses < 3 || spec.courses > 1000)
    throw Error("hall: the number of courses must be in 3..1000 (a window needs three)");
  if (!(std::isfinite(spec.windowWidth) && spec.windowWidth >= 0))
    throw Error("hall: the window width must be a number ≥ 0");
  if (!positive(spec.density)) throw Error("hall: the density must be a positive number");
  const double a = spec.radius + spec.wallThickness / 2, b = spec.radius - spec.wallThickness / 2, c = spec.cornerLine;
  // The octagon needs its diagonal sides to cut the square's corners, not pass them.
  if (!(std::isfinite(c) && c > b && c < 2 * b))
    throw Error("hall: the corner slabs' line |x| + |y| = " + std::to_string(c) +
                " must lie between the walls' inner face (" + std::to_string(b) + ") and the inner corner (" +
                std::to_string(2 * b) + ")");
  WallSpec wall;
  wall.length = a + b;
  wall.thickness = spec.wallThickness;
  wall.height = spec.height;
  wall.courses = spec.courses;
  wall.blockLength = spec.height / spec.courses;
  if (spec.windowWidth > 0) wall.windows.push_back({b - spec.windowWidth / 2, spec.windowWidth, 1, spec.courses - 1});
  std::vector<Block> out;
  // The south wall runs from the west wall's inner face (x = −b) to the south-east corner.
  const std::vector<Block> south = placed(wallBlocks(wall), Vec3(-b, -a, 0.0));
  for (int k = 0; k < 4; ++k)
    for (Block& blk : quarterTurned(south, k)) {
      blk.name = "wall " + std::to_string(k) + "/" + blk.name;
      out.push_back(std::move(blk));
    }
  // The slab course, built in the first quadrant's frame and turned.
  const double z0 = spec.height, z1 = spec.height + spec.slabThickness;
  const Vec3 X(1.0, 0.0, 0.0), Y(0.0, 1.0, 0.0), Z(0.0, 0.0, 1.0);
  const HalfSpace below{-Z, -z0}, above{Z, z1};
  std::vector<Block> quadrant;
  // The corner slab of the first quadrant; where its line passes inside the walls' outer
  // corner (c < a) it meets its neighbours on the axes.
  std::vector<HalfSpace> corner = {below, above, {X, a}, {Y, a}, {-(X + Y), -c}};
  if (c < a * (1 - 1e-9)) corner.insert(corner.end(), {{-X, 0.0}, {-Y, 0.0}});
  quadrant.push_back(halfspaceBlock("corner slab", corner, spec.density));
  // The side slab on the east wall's middle, between the corner slabs' lines (a triangle with
  // its apex on the axis where c ≤ a).
  quadrant.push_back(
      halfspaceBlock("side slab", {below, above, {-X, -b}, {X, a}, {X + Y, c}, {X - Y, c}}, spec.density));
  for (int k = 0; k < 4; ++k)
    for (Block& blk : quarterTurned(quadrant, k)) {
      blk.name = "slabs " + std::to_string(k) + "/" + blk.name;
      out.push_back(std::move(blk));
    }
  return out;
}

double squinchLine(const SquareHallSpec& hall, double drumInner, double drumOuter, int segments) {
  if (segments < 4 || segments % 4)
    throw Error("hall: the drum's segments must be a multiple of 4 to sit on a square hall");
  const double a = hall.radius + hall.wallThickness / 2, b = hall.radius - hall.wallThickness / 2;
  if (!(drumOuter <= a))
    throw Error("hall: the drum (outer radius " + std::to_string(drumOuter) +
                " m) is wider than the hall's walls (outer half side " + std::to_string(a) + " m)");
  // x + y is linear, so its least value over the part of the ring off the walls (x, y < b in
  // the first quadrant) is at a corner of the inner polygon or where one of its sides crosses
  // x = b or y = b; the outer polygon lies farther out along every ray.
  double least = std::numeric_limits<double>::infinity();
  auto corner = [&](int k) {
    const double t = 2 * std::numbers::pi * k / segments;
    return Vec2(drumInner * std::cos(t), drumInner * std::sin(t));
  };
  auto consider = [&](const Vec2& p) {
    if (p[0] <= b + 1e-12 && p[1] <= b + 1e-12) least = std::min(least, p[0] + p[1]);
  };
  for (int k = 0; k < segments / 4; ++k) {
    const Vec2 p = corner(k), q = corner(k + 1);
    consider(p);
    consider(q);
    for (int axis : {0, 1})
      if ((p[axis] - b) * (q[axis] - b) < 0) consider(p + (q - p) * ((b - p[axis]) / (q[axis] - p[axis])));
  }
  if (!std::isfinite(least)) throw Error("hall: the drum lies wholly on the walls; no corner slabs are needed");
  if (!(least > b))
    throw Error("hall: the drum's inner face (radius " + std::to_string(drumInner) +
                " m) reaches inside the walls' inner face (" + std::to_string(b) +
                " m from the centre); make the walls at least as thick as the drum");
  return least;
}

}  // namespace corbel::statics
