#pragma once
// How a KIFS facade lies on the walls of the mass it follows (footprint "object", docs/kifs.md).
// McGraw folds facades along the box's x and z, so its walls face along those axes. On another
// object the walls may face any way: each wall in plan turns the fold's axes until it faces
// along one of them. Walls whose outward normals differ by a multiple of 90° (within
// kFacingToleranceDeg) share one turn, a *facing*. A house whose walls meet at right angles has
// one facing, which turns the whole frame. A house with a wing at 30° has two, and each point
// takes the facing of the nearest wall in plan; the bound is capped at the seams between facings
// (Building::evaluate). No GL.
#include "kifs/mass_field.h"

#include <glm/glm.hpp>

#include <vector>

namespace corbel::kifs {

inline constexpr int kMaxWalls = 32;    // walls kept for choosing a facing (the shader's arrays)
inline constexpr int kMaxFacings = 8;
inline constexpr double kFacingToleranceDeg = 2.0;
inline constexpr double kWallEndTrim = 0.01;   // metres taken off each end of a wall (facings.cpp)

struct Facings {
  // The turn of the longest walls' facing from the frame's x axis (radians, counter-clockwise
  // about z, in [−45°, 45°]): the frame is turned by it.
  double main = 0;
  // With more than one facing: each facing's turn from the turned frame, and the walls (in the
  // turned frame's plan, longest first, at most kMaxWalls) that choose among them. Both are
  // empty with one facing.
  std::vector<double> turns;
  std::vector<PlanWall> walls;
};

// The facings of a shell's walls: the triangles (world space) whose normal is within 45° of
// horizontal, seen in the frame that `origin` and `axis` (cos, sin of its turn) define, merged
// where they lie on one line in plan. Walls shorter than `shortest` (in plan) are left out: the
// follower passes its facade period w, so a wall too short to hold one bay (a bay window's
// cheek, a dormer, a window's reveal) takes the facing of the walls around it.
Facings facingsOf(const TriangleSoup& soup, const glm::dvec3& origin, const glm::dvec2& axis, double shortest);

// Sets the field's frame (origin and turn, the turn followed by facings.main), its walls and
// its facings' turns.
void setFrame(MassField& field, const glm::dvec3& origin, const glm::dvec2& axis, const Facings& facings);

}  // namespace corbel::kifs
