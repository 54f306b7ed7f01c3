#pragma once
// The sweep-plane algorithm of Kelly & Wonka (Sec. 4): an active plan rises with the sweep
// plane; each edge moves along its direction plane; generalized intersection events
// (Sec. 4.4) and edge direction events (Sec. 4.5) change the plan's topology. The output is
// the set of faces the edges trace, one per input edge and profile segment, plus the base.
#include "core/geometry.h"
#include "core/progress.h"
#include "extrude/tolerances.h"

#include <string>
#include <vector>

namespace corbel::extrude {

// One plan edge of the sweep's input: where it starts (it ends where the next edge of its
// loop starts) and the angle it takes from each height on.
struct SweepEdge {
  Vec2 start;
  struct Step {
    double z;      // from this height on
    double angle;  // direction-plane angle θ, radians, in (−π/2, π/2)
    int segment;   // provenance: profile segment index
  };
  std::vector<Step> steps;  // sorted by z; steps[0].z = base height
  int sourceLoop = 0;
  int sourceEdge = 0;
  // Higher wins when colinear neighbours of different angles must merge (Sec. 4.8).
  double priority = 0.0;
};

struct SweepInput {
  std::vector<std::vector<SweepEdge>> loops;
  double baseZ = 0.0;
  bool emitBase = true;  // the floor face(s)
  double timeLimitSeconds = 0.0;  // > 0: give up with an Error after this long
};

// A face of the output shell: a planar polygon with holes, in one direction plane.
struct ShellFace {
  std::vector<std::vector<int>> loops;  // [0] outer, counter-clockwise seen from outside; others holes
  Vec3 normal;                          // outward unit normal
  int sourceLoop = -1;                  // -1 for base faces
  int sourceEdge = -1;
  int segment = -1;                     // profile segment; -1 for base faces
  double angle = 0.0;                   // θ of the direction plane (base: NaN-free 0)
  bool base = false;
};

struct SweepOutput {
  std::vector<Vec3> points;
  std::vector<ShellFace> faces;
  std::vector<std::string> warnings;
  double maxHeight = 0.0;
  std::size_t events = 0;  // generalized intersection events handled
};

// Runs the sweep. The input must already be valid (see checkSpec): simple, consistently
// oriented loops and angles within (−π/2, π/2) with the last one > 0.
SweepOutput sweep(const SweepInput& input, const Tolerances& tol, Progress* progress = nullptr);

}  // namespace corbel::extrude
