// The square hall under a drum (hall.h) against hand computations: block counts from the wall
// template, the slab course's area from the octagon it leaves open, the corner slabs' line
// from the drum's polygon, and the drum wholly on walls and slabs (contact areas).
#include "statics/hall.h"
#include "core/error.h"
#include "statics/builder.h"
#include "statics/dome.h"
#include "statics/equilibrium.h"
#include "statics/tolerances.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace corbel::statics {
namespace {

struct Measured {
  std::vector<BlockProperties> props;
  Contacts contacts;
};

Measured measured(const Assembly& as) {
  BBox box;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  Measured m;
  m.props = validateAssembly(as, lengthTolerance(box));
  m.contacts = prepareEquilibrium(as, {}).contacts;
  return m;
}

double volumeOf(const Assembly& as, const Measured& m) {
  double v = 0;
  for (std::size_t i = 0; i < as.blocks.size(); ++i)
    if (!as.blocks[i].fixed) v += m.props[i].volume;
  return v;
}

// The default hall (R = 3, 0.8 m walls, 4 courses of 1 m, 1 m windows) under a 16-sided drum
// 0.6 m thick: the drum's inner corners are at ri = 2.7, the walls' inner face at b = 2.6.
TEST(SquareHall, CornerLineIsWhereTheDrumLeavesTheWalls) {
  SquareHallSpec h;
  const double ri = 2.7, ro = 3.3, b = 2.6;
  // In the first quadrant the inner polygon's first side runs from (ri, 0) to ri(cos 22.5°,
  // sin 22.5°); it crosses x = b at y = ri sin 22.5° (ri − b) / (ri − ri cos 22.5°). Its next
  // corner is off the walls too but farther out in x + y.
  const double t = std::numbers::pi / 8;
  const double y = ri * std::sin(t) * (ri - b) / (ri - ri * std::cos(t));
  EXPECT_NEAR(squinchLine(h, ri, ro, 16), b + y, 1e-12);
  EXPECT_LT(b + y, ri * (std::cos(t) + std::sin(t)));
  // A drum that reaches inside the walls, or beyond them, or of 18 sides does not fit.
  EXPECT_THROW(squinchLine(h, 2.5, 3.1, 16), Error);
  EXPECT_THROW(squinchLine(h, 2.7, 3.5, 16), Error);
  EXPECT_THROW(squinchLine(h, 2.7, 3.3, 18), Error);
}

// Four walls of the wall template (pinwheel: each a + b long) and 8 slabs; the slab course is
// the outer square (2a)² less the octagon |x|, |y| ≤ b, |x| + |y| ≤ c, that is (2b)² less four
// corner triangles of legs 2b − c.
TEST(SquareHall, BlocksAndVolumeAreTheWallsAndTheSlabCourse) {
  SquareHallSpec h;
  const double a = h.radius + h.wallThickness / 2, b = h.radius - h.wallThickness / 2;
  for (double c : {3.2, 3.6}) {  // a = 3.4: corner slabs meeting on the axes, and side slabs between them
    h.cornerLine = c;
    WallSpec w{a + b, h.wallThickness, h.height, h.courses, h.height / h.courses, {{b - 0.5, 1.0, 1, 3}}, 2400.0};
    const std::size_t wall = wallBlocks(w).size();
    StructureBuilder sb;
    sb.add("hall", squareHallBlocks(h));
    sb.groundUnder(1.0);
    const Assembly as = sb.build();
    EXPECT_EQ(as.blocks.size(), 4 * wall + 8 + 1) << c;
    const double walls = 4 * ((a + b) * h.height - 1.0 * 2 * h.height / h.courses) * h.wallThickness;
    const double octagon = 4 * b * b - 2 * (2 * b - c) * (2 * b - c);
    const Measured m = measured(as);
    EXPECT_NEAR(volumeOf(as, m), walls + (4 * a * a - octagon) * h.slabThickness, 1e-9) << c;
    // The slabs' undersides lie on the walls' tops wherever they are over a wall: the contact
    // area under the slab course is the walls' top, the ring between the squares.
    double under = 0;
    for (const Interface& f : m.contacts.interfaces) {
      const bool slabA = as.blocks[std::size_t(f.a)].name.find("slab") != std::string::npos;
      const bool slabB = as.blocks[std::size_t(f.b)].name.find("slab") != std::string::npos;
      if (slabA != slabB && std::abs(f.normal[2]) > 0.5) under += f.area;
    }
    EXPECT_NEAR(under, 4 * a * a - 4 * b * b, 1e-9) << c;
    EXPECT_TRUE(checkFeasibility(as).feasible) << c;
  }
  h.cornerLine = 2.5;  // inside the walls' face: no octagon
  EXPECT_THROW(squareHallBlocks(h), Error);
  h.cornerLine = 3.6;
  h.windowWidth = 5.0;  // wider than a wall leaves
  EXPECT_THROW(squareHallBlocks(h), Error);
}

// A drum on the hall at the corner line squinchLine finds rests wholly on walls and slabs:
// the contacts under its first course add up to its footprint, the ring between two
// 16-gons, (n/2)(ro² − ri²) sin(2π/n). Moving the line out by 5 cm leaves part of it over
// the octagon's opening.
TEST(SquareHall, TheDrumRestsWhollyOnWallsAndSlabs) {
  SquareHallSpec h;
  DrumSpec d;
  d.segments = 16;
  d.courses = 2;
  d.radius = h.radius;
  d.thickness = 0.6;
  d.height = 2.0;
  d.bond = false;
  const double ri = d.radius - d.thickness / 2, ro = d.radius + d.thickness / 2;
  const double footprint = 8 * (ro * ro - ri * ri) * std::sin(2 * std::numbers::pi / 16);
  const double line = squinchLine(h, ri, ro, 16);
  for (double shift : {0.0, 0.05}) {
    h.cornerLine = line + shift;
    StructureBuilder sb;
    sb.add("hall", squareHallBlocks(h));
    sb.add("drum", drumBlocks(d), Vec3(0.0, 0.0, h.height + h.slabThickness));
    sb.groundUnder(1.0);
    const Assembly as = sb.build();
    const Measured m = measured(as);
    double under = 0;
    for (const Interface& f : m.contacts.interfaces) {
      const bool drumA = as.blocks[std::size_t(f.a)].name.rfind("drum/", 0) == 0;
      const bool drumB = as.blocks[std::size_t(f.b)].name.rfind("drum/", 0) == 0;
      if (drumA != drumB) under += f.area;
    }
    if (shift == 0)
      EXPECT_NEAR(under, footprint, 1e-9);
    else
      EXPECT_LT(under, footprint - 1e-3);
  }
}

}  // namespace
}  // namespace corbel::statics
