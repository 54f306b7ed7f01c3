#include "statics/examples.h"

#include "core/error.h"
#include "statics/arch.h"
#include "statics/builder.h"
#include "statics/buttress.h"
#include "statics/column.h"
#include "statics/dome.h"
#include "statics/groin.h"
#include "statics/hall.h"
#include "statics/shapes.h"
#include "statics/template_models.h"
#include "statics/vault.h"
#include "statics/wall.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

constexpr int kTowerLevels = 16;

// The parameters both vault examples share: the vault, its walls, the rings and courses.
void addVaultParameters(ParametricModel& m, double wallHeight, double wallThickness) {
  m.parameters.add(makeParameter("radius", 2.0, 0.3, 30.0, "centreline radius of the vault (half its span), m"));
  m.parameters.add(makeParameter("thickness", 0.25, 0.02, 3.0, "thickness of the vault, m"));
  m.parameters.add(makeParameter("length", 5.0, 0.1, 200.0, "length of the vault along its axis, m"));
  m.parameters.add(makeParameter("wallHeight", wallHeight, 0.1, 50.0, "height of the walls, m"));
  m.parameters.add(makeParameter("wallThickness", wallThickness, 0.02, 10.0, "thickness of the walls, m"));
  m.parameters.add(makeParameter("voussoirs", 12, 2, 400, "voussoirs per ring", false));
  m.parameters.add(makeParameter("rings", 5, 1, 400, "rings of the vault (and wall segments) along its axis", false));
  m.parameters.add(makeParameter("courses", 4, 1, 100, "courses of the walls (and buttresses)", false));
}

// A barrel vault on two walls of courses, one wall segment per ring; `prop(ring, y, depth,
// x)` adds what stands behind the +x wall's outer face x in that ring (mirrored for −x).
Assembly vaultOnWalls(const ParameterSet& p,
                      const std::function<std::vector<Block>(int, double, double, double)>& prop) {
  BarrelVaultSpec vault;
  vault.blocks = countOf(p, "voussoirs");
  vault.rings = countOf(p, "rings");
  vault.radius = p["radius"];
  vault.thickness = p["thickness"];
  vault.length = p["length"];
  const double h = p["wallHeight"], wt = p["wallThickness"];
  const double ring = vault.length / vault.rings;
  const double inner = vault.radius - vault.thickness / 2;  // the walls' inner faces, |x|
  std::vector<Block> side;  // the +x side, ring by ring
  for (int r = 0; r < vault.rings; ++r) {
    const double y = vault.length * r / vault.rings;
    ButtressSpec wall{h, wt, wt, ring, countOf(p, "courses"), 2400.0};
    for (Block& blk : placed(buttressBlocks(wall), Vec3(inner, y, 0.0), "wall " + std::to_string(r))) side.push_back(blk);
    for (Block& blk : prop(r, y, ring, inner + wt)) side.push_back(blk);
  }
  StructureBuilder b;
  b.add("vault", barrelVaultBlocks(vault), Vec3(0.0, 0.0, h));
  b.add("right", side);
  b.add("left", mirroredX(side));
  b.groundUnder(1.0);
  return b.build();
}

}  // namespace

ParametricModel towerExample() {
  ParametricModel m;
  m.name = "tower";
  m.description = "Fig. 11: 16 levels of four posts under a two-block slab (96 blocks); level k moved by (xk, yk)";
  for (int k = 1; k <= kTowerLevels; ++k)
    m.parameters.add(makeParameter("x" + std::to_string(k), 0.12, -0.5, 0.5, "x offset of level " + std::to_string(k) + " on the one below, m"));
  for (int k = 1; k <= kTowerLevels; ++k)
    m.parameters.add(makeParameter("y" + std::to_string(k), 0.0, -0.5, 0.5, "y offset of level " + std::to_string(k) + " on the one below, m"));
  for (int k = 1; k <= kTowerLevels; ++k) {
    m.suggestedFree.push_back({"x" + std::to_string(k), -0.2, 0.2});
  }
  for (int k = 1; k <= kTowerLevels; ++k) m.suggestedFree.push_back({"y" + std::to_string(k), -0.2, 0.2});
  m.build = [](const ParameterSet& p) {
    constexpr double post = 0.3, postHeight = 1.0, slab = 0.3;
    StructureBuilder b;
    Vec3 at(0.0);
    for (int k = 1; k <= kTowerLevels; ++k) {
      at += Vec3(p["x" + std::to_string(k)], p["y" + std::to_string(k)], 0.0);
      const double z = (k - 1) * (postHeight + slab);
      std::vector<Block> level;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.6, 0.6})
          level.push_back(boxBlock("post", Vec3(sx - post / 2, sy - post / 2, z), Vec3(sx + post / 2, sy + post / 2, z + postHeight)));
      level.push_back(boxBlock("slab -x", Vec3(-1, -1, z + postHeight), Vec3(0, 1, z + postHeight + slab)));
      level.push_back(boxBlock("slab +x", Vec3(0, -1, z + postHeight), Vec3(1, 1, z + postHeight + slab)));
      b.add("level " + std::to_string(k), std::move(level), at);
    }
    b.ground(Vec2(-5, -5), Vec2(5, 5));
    return b.build();
  };
  return m;
}

ParametricModel archOnColumnsExample() {
  ParametricModel m;
  m.name = "arch-on-columns";
  m.description = "Fig. 8: a semicircular arch on two square columns";
  m.parameters.add(makeParameter("thickness", 0.09, 0.01, 0.9, "radial thickness of the arch (centreline radius 1), m"));
  m.parameters.add(makeParameter("columnWidth", 0.15, 0.02, 3.0, "side of the square columns, m"));
  m.parameters.add(makeParameter("columnHeight", 1.5, 0.05, 20.0, "height of the columns, m"));
  m.parameters.add(makeParameter("voussoirs", 8, 2, 400, "blocks of the arch", false));
  m.parameters.add(makeParameter("drums", 1, 1, 100, "blocks of each column", false));
  m.suggestedFree = {{"thickness", 0.05, 0.5}, {"columnWidth", 0.05, 1.5}};
  m.build = [](const ParameterSet& p) {
    ArchSpec arch;
    arch.blocks = countOf(p, "voussoirs");
    arch.radius = 1.0;
    arch.thickness = p["thickness"];
    ColumnSpec column;
    column.drums = countOf(p, "drums");
    column.sides = 4;
    column.radius = p["columnWidth"] / std::sqrt(2.0);
    column.height = p["columnHeight"];
    StructureBuilder b;
    b.add("left column", columnBlocks(column), Vec3(-arch.radius, 0.0, 0.0));
    b.add("right column", columnBlocks(column), Vec3(arch.radius, 0.0, 0.0));
    b.add("arch", semicircularArchBlocks(arch), Vec3(0.0, 0.0, column.height));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel barrelVaultExample() {
  ParametricModel m;
  m.name = "barrel-vault";
  m.description = "Fig. 13: a barrel vault on two walls backed by buttresses (140 blocks)";
  addVaultParameters(m, 2.0, 0.35);
  m.parameters.add(makeParameter("buttressWidth", 0.1, 0.01, 10.0, "width of the buttresses behind the walls, m"));
  m.suggestedFree = {{"buttressWidth", 0.05, 3.0}};
  m.build = [](const ParameterSet& p) {
    return vaultOnWalls(p, [&](int r, double y, double depth, double x) {
      const double bw = p["buttressWidth"];
      ButtressSpec buttress{p["wallHeight"], bw, bw, depth, countOf(p, "courses"), 2400.0};
      return placed(buttressBlocks(buttress), Vec3(x, y, 0.0), "buttress " + std::to_string(r));
    });
  };
  return m;
}

ParametricModel bezierArchExample() {
  ParametricModel m;
  m.name = "bezier-arch";
  m.description = "Fig. 12: a thin arch whose centreline is a cubic Bezier; its inner control points move";
  m.parameters.add(makeParameter("x1", -1.0, -2.0, 2.0, "x of the first inner control point (span ±1), m"));
  m.parameters.add(makeParameter("x2", 1.0, -2.0, 2.0, "x of the second inner control point, m"));
  m.parameters.add(makeParameter("height", 1.2, 0.2, 5.0, "height of the centreline's crown, m"));
  m.parameters.add(makeParameter("thickness", 0.05, 0.01, 0.5, "thickness across the centreline, m"));
  m.parameters.add(makeParameter("voussoirs", 16, 4, 400, "blocks of the arch", false));
  m.suggestedFree = {{"x1", -1.5, 0.5}, {"x2", -0.5, 1.5}};
  m.build = [](const ParameterSet& p) {
    BezierArchSpec s;
    s.blocks = countOf(p, "voussoirs");
    s.x1 = p["x1"];
    s.x2 = p["x2"];
    s.height = p["height"];
    s.thickness = p["thickness"];
    return bezierArch(s);
  };
  return m;
}

ParametricModel flyingButtressVaultExample() {
  ParametricModel m;
  m.name = "flying-buttresses";
  m.description = "Fig. 13 with flying buttresses: a barrel vault on two walls propped by quarter-arc flyers on piers";
  addVaultParameters(m, 3.0, 0.3);
  m.parameters.add(makeParameter("reach", 0.6, 0.1, 40.0, "radius of the flyers' quarter arcs: their reach from the wall and their rise, m"));
  m.parameters.add(makeParameter("flyerThickness", 0.25, 0.02, 3.0, "thickness of the flyers, m"));
  m.parameters.add(makeParameter("pierWidth", 0.5, 0.05, 10.0, "width of the flyers' piers, m"));
  m.suggestedFree = {{"reach", 0.3, 2.5}};
  m.build = [](const ParameterSet& p) {
    FlyingButtressSpec flyer;
    flyer.radius = p["reach"];
    flyer.thickness = p["flyerThickness"];
    flyer.pierWidth = p["pierWidth"];
    flyer.pierHeight = p["wallHeight"] - flyer.thickness / 2 - flyer.radius;  // the head's top is the wall's top
    if (!(flyer.pierHeight > 0))
      throw Error("flying-buttresses: the flyers' reach leaves no pier (reach ≥ wall height − flyer thickness / 2)");
    return vaultOnWalls(p, [&](int r, double y, double depth, double x) {
      FlyingButtressSpec f = flyer;
      f.depth = depth;
      return placed(flyingButtressBlocks(f), Vec3(x, y, 0.0), "flyer " + std::to_string(r));
    });
  };
  return m;
}

// The wall template runs along x with its thickness along y; a side wall of a nave runs
// along y. Swapping x and y is a mirror, so faces are reversed to keep them outward.
std::vector<Block> alongY(std::vector<Block> blocks) {
  for (Block& b : blocks) {
    for (Vec3& v : b.vertices) std::swap(v[0], v[1]);
    for (auto& f : b.faces) std::reverse(f.begin(), f.end());
    std::swap(b.liveLoad[0], b.liveLoad[1]);
  }
  return blocks;
}

ParametricModel chapelExample() {
  ParametricModel m;
  m.name = "chapel";
  m.description =
      "Fig. 9 (after the Sainte Chapelle): a barrel-vaulted hall of bays, each side wall pierced by a tall window, "
      "buttress piers between the bays";
  m.parameters.add(makeParameter("radius", 3.0, 0.5, 30.0, "centreline radius of the vault (half the span), m"));
  m.parameters.add(makeParameter("thickness", 0.45, 0.05, 3.0, "thickness of the vault (a semicircle needs t/R > 0.1075), m"));
  m.parameters.add(makeParameter("bays", 6, 1, 60, "bays along the hall", false));
  m.parameters.add(makeParameter("bayLength", 3.0, 1.0, 20.0, "length of a bay along the hall, m"));
  m.parameters.add(makeParameter("wallHeight", 6.0, 1.0, 60.0, "height of the side walls (the vault springs from their top), m"));
  m.parameters.add(makeParameter("wallThickness", 0.6, 0.1, 5.0, "thickness of the side walls, m"));
  m.parameters.add(makeParameter("courses", 6, 3, 100, "courses of the walls and piers", false));
  m.parameters.add(makeParameter("windowWidth", 1.5, 0.2, 19.0, "width of each bay's window (centred in the bay), m"));
  m.parameters.add(makeParameter("buttressWidth", 0.4, 0.05, 10.0, "how far the piers between the bays stand out from the walls, m"));
  m.parameters.add(makeParameter("buttressDepth", 0.75, 0.1, 10.0, "depth of the piers along the hall, m"));
  m.parameters.add(makeParameter("voussoirs", 14, 2, 400, "voussoirs per ring of the vault", false));
  m.suggestedFree = {{"buttressWidth", 0.1, 3.0}, {"buttressDepth", 0.3, 1.5}, {"wallThickness", 0.3, 1.5}, {"wallHeight", 3.0, 6.0}};
  m.build = [](const ParameterSet& p) {
    const int bays = countOf(p, "bays"), courses = countOf(p, "courses");
    const double bay = p["bayLength"], h = p["wallHeight"], wt = p["wallThickness"];
    BarrelVaultSpec vault;
    vault.blocks = countOf(p, "voussoirs");
    vault.rings = 2 * bays;
    vault.radius = p["radius"];
    vault.thickness = p["thickness"];
    vault.length = bays * bay;
    const double inner = vault.radius - vault.thickness / 2;
    if (wt < vault.thickness) throw Error("chapel: the walls (" + std::to_string(wt) + " m) are thinner than the vault they carry");
    // One wall segment a bay, in courses of about square blocks, its window from the second
    // course to the one under the top (the top course holds the lintel).
    WallSpec wall;
    wall.length = bay;
    wall.thickness = wt;
    wall.height = h;
    wall.courses = courses;
    const double ww = p["windowWidth"], pierWall = (bay - ww) / 2;  // wall each side of a window
    if (!(pierWall >= 0.1))
      throw Error("chapel: a window of " + std::to_string(ww) + " m leaves less than 0.1 m of wall each side in a bay of " +
                  std::to_string(bay) + " m");
    // The wall each side of the window is a whole number of blocks about a course high.
    wall.blockLength = pierWall / std::max(1.0, std::round(pierWall / (h / courses)));
    wall.windows.push_back({(bay - ww) / 2, ww, 1, courses - 1});
    const double bw = p["buttressWidth"], bd = p["buttressDepth"];
    std::vector<Block> side;  // the +x side
    for (int k = 0; k < bays; ++k)
      for (Block& blk : placed(alongY(wallBlocks(wall)), Vec3(inner, k * bay, 0.0), "wall " + std::to_string(k))) side.push_back(blk);
    for (int k = 0; k <= bays; ++k) {
      // A pier centred on the joint between two bays, cut back to the hall at its ends.
      const double y0 = std::max(0.0, k * bay - bd / 2), y1 = std::min(bays * bay, k * bay + bd / 2);
      ButtressSpec pier{h, bw, bw, y1 - y0, courses, 2400.0};
      for (Block& blk : placed(buttressBlocks(pier), Vec3(inner + wt, y0, 0.0), "pier " + std::to_string(k))) side.push_back(blk);
    }
    StructureBuilder b;
    b.add("vault", barrelVaultBlocks(vault), Vec3(0.0, 0.0, h));
    b.add("right", side);
    b.add("left", mirroredX(side));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel abbeyExample() {
  // Fig. 1 (after Cluny): a long nave of the flying-buttress vault, with its four free
  // parameters (Table 1's first row): wall thickness, pier width, flyer thickness, reach.
  ParametricModel m = flyingButtressVaultExample();
  m.name = "abbey";
  m.description = "Fig. 1 (after Cluny Abbey): a nave of 26 bays, its barrel vault on walls propped by flying buttresses on piers";
  for (const auto& [name, value] : std::initializer_list<std::pair<const char*, double>>{
           {"radius", 4.0}, {"thickness", 0.6}, {"length", 26.0}, {"rings", 26}, {"wallHeight", 8.0},
           {"wallThickness", 0.8}, {"courses", 5}, {"reach", 2.0}, {"flyerThickness", 0.4}, {"pierWidth", 0.6}})
    m.parameters.set(name, value);
  m.suggestedFree = {{"wallThickness", 0.6, 2.0}, {"pierWidth", 0.3, 1.5}, {"flyerThickness", 0.2, 1.0}, {"reach", 1.5, 4.0}};
  return m;
}

ParametricModel mosqueExample() {
  ParametricModel m;
  m.name = "mosque";
  m.description =
      "Fig. 10 (c): a dome with an oculus on a round drum pierced by windows, propped by radial flying buttresses on "
      "piers";
  m.parameters.add(makeParameter("radius", 3.0, 0.5, 30.0, "middle-surface radius of the dome and the drum, m"));
  m.parameters.add(makeParameter("domeThickness", 0.25, 0.02, 3.0, "thickness of the dome, m"));
  m.parameters.add(makeParameter("drumHeight", 5.0, 0.5, 60.0, "height of the drum, m"));
  m.parameters.add(makeParameter("drumThickness", 0.3, 0.05, 5.0, "thickness of the drum's wall, m"));
  m.parameters.add(makeParameter("courses", 5, 1, 100, "courses of the drum", false));
  m.parameters.add(makeParameter("segments", 16, 6, 400, "blocks round the drum and the dome", false));
  m.parameters.add(makeParameter("rings", 8, 1, 100, "rings of the dome up to its oculus", false));
  m.parameters.add(
      makeParameter("windowWidth", 0.5, 0.0, 20.0, "width of the windows in every other segment of the drum (0: none), m"));
  m.parameters.add(makeParameter("windowSill", 1, 0, 99, "first course of the drum the windows open", false));
  m.parameters.add(
      makeParameter("windowHead", 4, 1, 99, "course of the drum over the windows, whose blocks are their lintels", false));
  m.parameters.add(makeParameter("flyers", 8, 0, 200, "radial flying buttresses, on every (segments / flyers)-th face of the drum", false));
  m.parameters.add(makeParameter("reach", 1.0, 0.2, 40.0, "radius of the flyers' quarter arcs: their reach from the drum and their rise, m"));
  m.parameters.add(makeParameter("flyerThickness", 0.4, 0.05, 3.0, "thickness of the flyers, m"));
  m.parameters.add(makeParameter("pierWidth", 0.6, 0.05, 10.0, "width of the flyers' piers, m"));
  m.parameters.add(makeParameter("hall", 0, 0, 1, "a square hall under the drum (1) or the drum on the ground (0)", false));
  m.parameters.add(makeParameter("hallHeight", 4.0, 0.5, 60.0, "height of the hall's walls, m"));
  m.parameters.add(
      makeParameter("hallWallThickness", 0.8, 0.05, 10.0, "thickness of the hall's walls (at least the drum's), m"));
  m.parameters.add(makeParameter("hallCourses", 4, 3, 100, "courses of the hall's walls", false));
  m.parameters.add(
      makeParameter("hallWindowWidth", 1.0, 0.0, 50.0, "width of the window in each of the hall's walls (0: none), m"));
  m.parameters.add(
      makeParameter("slabThickness", 0.4, 0.05, 5.0, "thickness of the corner slabs (squinches) the drum sits on, m"));
  m.suggestedFree = {{"drumThickness", 0.3, 1.5}, {"reach", 0.5, 3.0}};
  m.build = [](const ParameterSet& p) {
    const int segments = countOf(p, "segments"), flyers = countOf(p, "flyers");
    DrumSpec drum;
    drum.courses = countOf(p, "courses");
    drum.segments = segments;
    drum.radius = p["radius"];
    drum.thickness = p["drumThickness"];
    drum.height = p["drumHeight"];
    // Stack bond: every course has its faces in the same vertical planes, so a flyer's head
    // lies flat against the drum whatever courses it spans, and a window's jambs stand in
    // their segment.
    drum.bond = false;
    // Windows in the segments between the flyers' faces (those start at segment 0).
    drum.windowWidth = p["windowWidth"];
    drum.windowEvery = 2;
    drum.windowSill = countOf(p, "windowSill");
    drum.windowHead = countOf(p, "windowHead");
    DomeSpec dome;
    dome.rings = countOf(p, "rings");
    dome.segments = segments;
    dome.radius = p["radius"];
    dome.thickness = p["domeThickness"];
    if (dome.thickness > drum.thickness)
      throw Error("mosque: the dome (" + std::to_string(dome.thickness) + " m) is thicker than the drum that carries it (" +
                  std::to_string(drum.thickness) + " m)");
    StructureBuilder b;
    double base = 0;        // where the drum stands
    double hallCorner = 0;  // the hall's outer corner's distance from the axis
    if (countOf(p, "hall")) {
      SquareHallSpec hall;
      hall.radius = drum.radius;
      hall.wallThickness = p["hallWallThickness"];
      hall.height = p["hallHeight"];
      hall.courses = countOf(p, "hallCourses");
      hall.windowWidth = p["hallWindowWidth"];
      hall.slabThickness = p["slabThickness"];
      hall.cornerLine = squinchLine(hall, drum.radius - drum.thickness / 2, drum.radius + drum.thickness / 2, segments);
      b.add("hall", squareHallBlocks(hall));
      base = hall.height + hall.slabThickness;
      hallCorner = (hall.radius + hall.wallThickness / 2) * std::numbers::sqrt2;
    }
    b.add("drum", drumBlocks(drum), Vec3(0.0, 0.0, base));
    b.add("dome", domeBlocks(dome), Vec3(0.0, 0.0, base + drum.height));
    if (flyers > 0) {
      if (segments % flyers) throw Error("mosque: " + std::to_string(flyers) + " flyers do not divide " + std::to_string(segments) + " segments");
      FlyingButtressSpec f;
      f.radius = p["reach"];
      f.thickness = p["flyerThickness"];
      f.pierWidth = p["pierWidth"];
      f.pierHeight = base + drum.height - f.thickness / 2 - f.radius;
      if (!(f.pierHeight > 0)) throw Error("mosque: the flyers' reach leaves no pier (reach ≥ drum height − flyer thickness / 2)");
      const double face = 2 * (drum.radius + drum.thickness / 2) * std::sin(std::numbers::pi / segments);
      f.depth = std::min(0.6, 0.5 * face);
      // The drum's outer faces lie at the apothem of its outer polygon.
      const double apothem = (drum.radius + drum.thickness / 2) * std::cos(std::numbers::pi / segments);
      // The piers stand on the ground outside the hall: clear of its corners' circle.
      if (hallCorner > 0 && apothem + f.radius < hallCorner)
        throw Error("mosque: the flyers' piers (from " + std::to_string(apothem + f.radius) +
                    " m out) would stand in the hall (its corners " + std::to_string(hallCorner) +
                    " m out); reach further");
      for (int k = 0; k < flyers; ++k) {
        const double angle = 2 * std::numbers::pi * (k * (segments / flyers) + 0.5) / segments;
        b.add("flyer " + std::to_string(k), rotatedZ(placed(flyingButtressBlocks(f), Vec3(apothem, -f.depth / 2, 0.0)), angle));
      }
    }
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

ParametricModel mosqueHallExample() {
  // Fig. 10 (a, d): the mosque's dome and windowed drum on a square hall, without flyers.
  ParametricModel m = mosqueExample();
  m.name = "mosque-hall";
  m.description =
      "Fig. 10 (a, d): a dome on a windowed drum over a square hall (corner slabs turn its walls' square into an "
      "octagon), "
      "no flyers";
  for (const auto& [name, value] : std::initializer_list<std::pair<const char*, double>>{
           {"hall", 1}, {"flyers", 0}, {"drumThickness", 0.5}, {"windowWidth", 0.9}})
    m.parameters.set(name, value);
  m.suggestedFree = {{"windowWidth", 0.1, 0.9}};
  return m;
}

ParametricModel groinVaultExample() {
  ParametricModel m;
  m.name = "groin-vault";
  m.description = "A groin vault: two barrels of the same rise crossing over a bay, on four corner piers";
  m.parameters.add(makeParameter("radius", 2.0, 0.3, 30.0, "centreline radius of both barrels (their rise; half the span along y), m"));
  m.parameters.add(makeParameter("thickness", 0.3, 0.02, 3.0, "thickness of the webs, m"));
  m.parameters.add(makeParameter("stretch", 1.0, 0.5, 2.0, "the bay's length along x over its length along y (1: square)"));
  m.parameters.add(makeParameter("voussoirs", 12, 2, 400, "voussoirs per arch of each web", false));
  m.parameters.add(makeParameter("courses", 3, 1, 400, "transverse courses of each web from the centre to the bay's face", false));
  m.parameters.add(makeParameter("pierHeight", 2.0, 0.0, 50.0, "height of the corner piers (0: the vault springs from the ground), m"));
  m.parameters.add(makeParameter("pierWidth", 1.0, 0.05, 10.0, "side of the square corner piers (at least the thickness), m"));
  m.parameters.add(makeParameter("drums", 2, 1, 100, "courses of each pier", false));
  m.parameters.add(makeParameter("ribs", 0, 0, 1, "diagonal ribs under the groins (1) or none (0); they need an even number of voussoirs", false));
  m.parameters.add(makeParameter("ribWidth", 0.2, 0.01, 3.0, "width of the ribs across the diagonal (at most thickness·√2/2), m"));
  m.parameters.add(makeParameter("ribDepth", 0.2, 0.01, 5.0, "depth of the ribs below the intrados, m"));
  m.suggestedFree = {{"thickness", 0.1, 0.6}, {"pierWidth", 0.3, 2.0}};
  m.build = [](const ParameterSet& p) {
    GroinVaultSpec s;
    s.radius = p["radius"];
    s.thickness = p["thickness"];
    s.stretch = p["stretch"];
    s.voussoirs = countOf(p, "voussoirs");
    s.courses = countOf(p, "courses");
    s.pierHeight = p["pierHeight"];
    s.pierWidth = p["pierWidth"];
    s.pierDrums = countOf(p, "drums");
    s.ribs = countOf(p, "ribs") != 0;
    s.ribWidth = p["ribWidth"];
    s.ribDepth = p["ribDepth"];
    StructureBuilder b;
    b.add("vault", groinVaultBlocks(s), Vec3(0.0, 0.0, s.pierHeight));
    if (s.pierHeight > 0) b.add("piers", groinVaultPiers(s));
    b.groundUnder(1.0);
    return b.build();
  };
  return m;
}

std::vector<std::string> exampleNames() {
  return {"tower",  "arch-on-columns", "barrel-vault", "flying-buttresses", "bezier-arch",
          "chapel", "abbey",           "mosque",       "mosque-hall",       "groin-vault"};
}

ParametricModel exampleByName(const std::string& name) {
  if (name == "tower") return towerExample();
  if (name == "arch-on-columns") return archOnColumnsExample();
  if (name == "barrel-vault") return barrelVaultExample();
  if (name == "bezier-arch") return bezierArchExample();
  if (name == "flying-buttresses") return flyingButtressVaultExample();
  if (name == "chapel") return chapelExample();
  if (name == "abbey") return abbeyExample();
  if (name == "mosque") return mosqueExample();
  if (name == "mosque-hall") return mosqueHallExample();
  if (name == "groin-vault") return groinVaultExample();
  if (auto t = templateModelByName(name)) return std::move(*t);
  std::string known, templates;
  for (const std::string& n : exampleNames()) known += (known.empty() ? "" : ", ") + n;
  for (const std::string& n : templateModelNames()) templates += (templates.empty() ? "" : ", ") + n;
  throw Error("unknown example '" + name + "' (examples: " + known + "; templates: " + templates + ")");
}

}  // namespace corbel::statics
