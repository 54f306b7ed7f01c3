#pragma once
// Units as rectilinear polyhedra (Sec. 5.1) and the two shape operators.
//
// Representation: a unit is a list of parts, axis-aligned boxes with pairwise disjoint
// interiors whose union is the unit. Every part spans one or two whole storeys and is at
// least 3 m × 3 m in plan; parts touch along faces. A part's side that touches no other
// part of its unit is a face of the polyhedron, and only such a face can advance:
//
// - Face Advance(F, α): side F of a part moves out along its normal by α (vertical sides),
//   or by one storey (floor and ceiling: a one-storey part becomes a double volume).
// - Face Split(F): an orthogonal cut through the part at a chosen position splits F (and the
//   part) in two; each new face then advances on its own. The union does not change, so a
//   split is always valid geometry; it only needs both pieces to stay 3 m wide.
//
// Parts of one unit never stack (every part contains the unit's home storey and a unit
// spans at most two storeys), so a unit's floor area is the sum of its parts' footprints
// and a double-volume part counts its floor once.
#include "core/mesh_data.h"
#include "growth/box.h"

#include <array>
#include <vector>

namespace corbel::growth {

struct Unit {
  int id = 0;  // ≥ 1, stable over a run (the seed's index + 1)
  std::vector<Box> parts;
  std::array<bool, 6> locked{};  // by Side

  double floorArea() const;
  double volume() const;
  Box bounds() const;
};

struct Move {
  // StairBase (Fig. 5.4): side `side` of part `part` has reached staircase `staircase` (an index
  // into the site's circulation) and the unit takes the whole of its top as a new part, `box`
  // (set by the constraint enforcer, see growth/collide.h's stairBasePart).
  enum class Type { Advance, Split, StairBase };
  Type type = Type::Advance;
  int part = 0;
  Side side = Side::PosX;  // Advance: the face that moves
  double distance = 0;     // Advance: how far (α, or one storey for floor and ceiling)
  int axis = 0;            // Split: the cut is the plane x (0) or y (1) = at
  double at = 0;
  int staircase = -1;  // StairBase
  Box box;             // StairBase: the part added

  static Move advance(int part, Side side, double distance) {
    return {Type::Advance, part, side, distance, 0, 0, -1, {}};
  }
  static Move split(int part, int axis, double at) { return {Type::Split, part, Side::PosX, 0, axis, at, -1, {}}; }
  static Move stairBase(int part, Side side, int staircase) {
    return {Type::StairBase, part, side, 0, 0, 0, staircase, {}};
  }
  bool operator==(const Move&) const = default;
};

// Whether side s of part `part` touches another part of the unit over a positive area
// (then it is not a face of the polyhedron on its own and cannot advance).
bool sideTouchesOwnPart(const Unit& u, int part, Side s);

// Applies a move without checking it (the constraint enforcer decides what is valid).
// Split keeps the low piece at `part` and appends the high piece as the last part; StairBase
// appends `box`.
void applyMove(Unit& u, const Move& m);

// The closed surface of the union of the parts: one quad per exposed cell face of the grid
// spanned by the parts' coordinates (shared corners, outward, counter-clockwise), tagged
// "wall", "roof" or "floor".
MeshData unitMesh(const Unit& u);

}  // namespace corbel::growth
