#pragma once
// Walls laid in courses of stone: a plan polyline of wall faces becomes rigid blocks in running
// bond, bonded at the corners, with openings under lintels or flat arches (the wall template of
// Whiting et al. 2009, Sec. 2, generalised from one straight wall to a plan). The blocks feed
// the statics kernel (model.h); loads on the wall heads act where the roof bears.
#include "core/stone_walls.h"
#include "statics/model.h"

#include <string>
#include <vector>

namespace corbel::statics {

// An opening through the wall of one plan edge.
struct WallOpening {
  std::string name;              // for messages
  int edge = 0;                  // the plan edge whose wall it pierces
  double from = 0.0, to = 1.0;   // m along the edge's outer face, from its first corner
  double bottom = 0.0, top = 1.0;  // m above the wall's foot; snapped to the nearest course joints
  OpeningHead head = OpeningHead::Lintel;
  double archDepth = 0.0;        // m, a semicircular arch's ring depth; 0: one course height
  // Open up to the wall head, with no head of its own here: the wall above is laid as another
  // band (a second courseWalls on top) whose opening goes on from its foot.
  bool throughHead = false;
};

// A buttress (a pier of solid stone) against the outer face of one plan edge's wall, from its
// foot up: [from, to] along the face, `depth` out of it. On even courses (the first included)
// the wall's stretch behind it and the buttress are one through-stone, so the pier is bonded
// into the wall; on odd courses the buttress is a block of its own against the wall, except the
// wall's head course, which is a through-stone over a pier reaching it (the stone a roof truss
// bears on, so the wall stones under the truss cannot be pushed off the pier).
struct WallButtress {
  std::string name;              // for messages
  int edge = 0;
  double from = 0.0, to = 1.0;   // m along the edge's outer face, from its first corner
  double depth = 0.5;            // m out of the face
  double top = 3.0;              // m above the wall's foot; snapped to a course joint (≥ 1 course)
};

struct CoursingSpec {
  // The walls' outer faces: corners counter-clockwise seen from above, each wall lying on the
  // left of its edge (inside the plan). A corner may turn left (convex) or right (reflex, by at
  // most a right angle, as where a bay's cheek leaves the main wall).
  std::vector<Vec2> plan;
  bool closed = true;          // false: an open polyline whose two ends are free wall ends
  double base = 0.0;           // z of the wall's foot
  double height = 3.0;         // m
  double courseHeight = 0.4;   // the height is cut into round(height / courseHeight) courses
  double blockLength = 0.8;    // odd courses are shifted by half a block (running bond)
  double thickness = 0.5;
  double density = 2400.0;
  // The number of the first course: its parity sets the bond (even courses give a corner's
  // square to the incoming wall), so a band laid on another carries its bond on.
  int firstCourse = 0;
  std::vector<WallOpening> openings;
  std::vector<WallButtress> buttresses;
};

// A top-course block's share of one edge's wall head: the stretch [from, to] (m along the edge's
// outer face) it carries.
struct HeadSpan {
  int block = -1;
  int edge = -1;
  double from = 0.0, to = 0.0;
};

struct CoursedWalls {
  std::vector<Block> blocks;   // course by course, edge by edge; no ground
  std::vector<HeadSpan> heads; // together they cover every edge's head once
  int courses = 0;
  double courseHeight = 0.0;   // the height actually used, height / courses
};

// An opening whose top is at or below the wall's foot (top ≤ 0) has only its head, in the first
// course: the wall of a band spanning an opening below it (a lower bay's mouth).
// Each course of each edge's wall is cut at bond joints (k·b on even courses, (k + ½)·b on odd
// ones, measured from the edge's first corner), at the sides of openings it crosses and at the
// ends of the lintel or arch it holds; joints closer than a quarter block to another cut or to
// the inner corner line are dropped (no slivers). At a corner the wall square (the
// quadrilateral between the outer corner, the inner corner and their feet on both faces; at a
// reflex corner, between the outer corner, the inner corner and the outer corner's feet on both
// inner faces) belongs to the incoming wall's last block on even courses and to the outgoing
// wall's first block on odd ones, so the corner is bonded. Every block stays convex. A lintel spans its opening and half a block of
// bearing each side in the course over the opening as one stone; a flat arch fills the opening's
// width in that course with an odd number of voussoirs whose joints meet below the opening (at
// the apex of the equilateral triangle under it), the two outer joints being its skewbacks.
// A semicircular arch springs from the opening's top corners: the voussoirs of the arch
// template (arch.h, radial joints at kπ/N, chords at the intrados radius r = half the width and
// the extrados radius r + depth), N odd; its spandrels, from the arch out to half a block
// beyond the extrados on each side and up to a course joint at least a quarter course above
// it, are cut in their courses along the voussoirs' joints carried on outwards, neighbouring
// pieces joined wherever the join is convex.
// Buttresses (WallButtress) are cut out of the bond: on their through-stone courses (even ones
// and the head course over a pier reaching the head) the wall is
// cut at the buttress's sides and bond joints between and within a quarter block of them are
// dropped.
// Throws corbel::Error for bad numbers, a reflex corner turning by more than a right angle,
// openings that leave their wall, reach a corner's square (come within a quarter block of a
// reflex corner) or the wall head, or overlap; buttresses that leave their wall's stretch
// between the corner squares, overlap each other or an opening with its head.
CoursedWalls courseWalls(const CoursingSpec& spec);

// Loads along an edge's wall head, in N per metre of the edge: `down` acts downwards and
// `out` horizontally, outwards across the wall (a roof's weight and its thrust).
struct HeadLoad {
  double down = 0.0, out = 0.0;
};

// Adds each edge's head load to the top-course blocks as point loads on the wall's centre
// line at the head, each block taking its span's share. `perEdge` has one entry per edge.
void loadWallHeads(const CoursingSpec& spec, CoursedWalls& walls, const std::vector<HeadLoad>& perEdge);

// Wind: a horizontal pressure (N/m²) blowing along the plan direction `towards` onto the walls'
// outer faces. Each block face on an edge's outer face that the wind meets (outward normal o
// with o·ŵ < 0) takes pressure × its area × (−o·ŵ), pushing along −o, at the face's area
// centroid. Suction on the lee side, wind on the roof and through openings are left out.
void loadWind(const CoursingSpec& spec, CoursedWalls& walls, double pressure, const Vec2& towards);

}  // namespace corbel::statics
