#pragma once
// The sweep-plane algorithm of Kelly & Wonka (Sec. 4): an active plan rises with the sweep
// plane; each edge moves along its direction plane; generalized intersection events
// (Sec. 4.4) and edge direction events (Sec. 4.5) change the plan's topology. The output is
// the set of faces the edges trace, one per input edge and profile segment, plus the base.
#include "core/geometry.h"
#include "core/progress.h"
#include "extrude/tolerances.h"

#include <limits>
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
    // Higher wins when colinear neighbours of different angles must merge (Sec. 4.8): the
    // priority of the segment the edge is on at the event, not at the stage's base.
    double priority;
  };
  std::vector<Step> steps;  // sorted by z; steps[0].z = base height
  int sourceLoop = 0;
  int sourceEdge = 0;
  int profile = -1;  // provenance: index into the spec's profile library (-1: none)
  int step = -1;     // provenance: the plan step (spec.steps) that made the edge, else -1
};

struct SweepInput {
  std::vector<std::vector<SweepEdge>> loops;
  double baseZ = 0.0;
  bool emitBase = true;  // the floor face(s)
  double timeLimitSeconds = 0.0;  // > 0: give up with an Error after this long
  // Finite: stop the sweep at this height and hand back the active plan there (SweepOutput::
  // plan) with the faces left open along it, for a recursive or staged extrusion (Sec. 4.5.2,
  // 4.6, 4.7). Events at the stop height itself are handled first.
  double stopZ = std::numeric_limits<double>::infinity();
  // Where the post inter-chain check (Sec. 4.4) finds the plan overlapping itself above an
  // event, stop there instead (halfway to whatever comes next) and hand back the plan, for the
  // winding rule (extrude/winding.h) to rebuild; SweepOutput::stoppedAt says where. Otherwise
  // the sweep carries on and warns.
  bool stopAtOverlap = false;
  // Keep the faces as untraced boundary pieces (SweepOutput::raw) instead of tracing them.
  bool keepRaw = false;
  // Heights (ascending, above baseZ) at which to read the active plan without stopping the
  // sweep or cutting its faces (SweepOutput::probed): where mesh anchors find their frame.
  std::vector<double> probes;
};

// A face of the output shell: a planar polygon with holes, in one direction plane.
struct ShellFace {
  std::vector<std::vector<int>> loops;  // [0] outer, counter-clockwise seen from outside; others holes
  Vec3 normal;                          // outward unit normal
  int sourceLoop = -1;                  // -1 for base faces
  int sourceEdge = -1;
  int segment = -1;                     // profile segment; -1 for base faces
  double angle = 0.0;                   // θ of the direction plane (base: NaN-free 0)
  int profile = -1;                     // profile library index (-1: base, caps)
  int step = -1;                        // the plan step whose edge traced it (sourceEdge: its
                                        // edge in the step's shape), else -1
  bool base = false;
};

// A face before tracing: its directed boundary pieces (vertex pairs) and what it comes from.
// Pieces of one face may come from several sweeps (staged extrusions); a piece and its reverse
// cancel when the face is traced.
struct RawFace {
  std::vector<std::pair<int, int>> segments;
  ShellFace info;  // everything but loops
};

// A corner of the active plan where a stopped sweep ended: its place, its shell vertex and
// the input edge (flat index over SweepInput::loops) that leaves it.
struct PlanCorner {
  Vec2 p;
  int vertex = -1;
  int input = -1;
};

struct SweepOutput {
  std::vector<Vec3> points;
  std::vector<ShellFace> faces;
  std::vector<std::string> warnings;
  double maxHeight = 0.0;
  std::size_t events = 0;  // generalized intersection events handled
  bool diverged = false;   // events ran away far above the plan; the rest was capped
  std::vector<RawFace> raw;                     // with SweepInput::keepRaw
  std::vector<std::vector<PlanCorner>> plan;    // with a finite SweepInput::stopZ, or stoppedAt
  // With SweepInput::stopAtOverlap: the height below stopZ where the sweep stopped because
  // the plan overlapped itself (NaN: it did not).
  double stoppedAt = std::numeric_limits<double>::quiet_NaN();
  // One active plan per SweepInput::probes entry (no loops once the roof has closed below
  // it); corners carry no vertex (-1).
  std::vector<std::vector<std::vector<PlanCorner>>> probed;
};

// Traces raw faces into planar polygons with holes (outer loops counter-clockwise seen from
// outside). Pieces cancelled by their reverse, and zero-length ones, are dropped.
void traceFaces(const std::vector<Vec3>& points, const std::vector<RawFace>& raw, const Tolerances& tol,
                std::vector<ShellFace>& faces, std::vector<std::string>& warnings);

// Merges the ends of every face edge shorter than `length` (near-simultaneous events the
// clustering kept apart leave such edges, and faces of no area between them) and every corner
// of a face that lies within `tinyFace` of its first corner, drops loops and faces that vanish,
// and keeps the result only if it is as closed as before, every vertex has one fan of faces and
// no face passes a vertex twice. No merge joins a corner of a base face to a vertex more than
// `baseHeight` above it (the sweep's δ1). Returns the number of merges (0: the shell is
// unchanged).
std::size_t collapseShortEdges(SweepOutput& shell, double length, double tinyFace = 0,
                               double baseHeight = std::numeric_limits<double>::infinity());

// Merges the ends of every face edge shorter than `length` where no face through either end
// tells them apart: moving one onto the other takes no such face off its plane by `offPlane`
// or more (collapse.cpp). Where nearly parallel planes meet, the sweep places their meeting
// along the line they share only to a rounding over the sine of their angle (a node of a
// ridge made twice, µm apart); such corners are one place as far as every face there can say.
// Only closed shells, with the same bar on base corners as collapseShortEdges; kept only if
// the shell stays closed, every vertex has one fan of faces, and no loop that was simple in
// its plane is then not. Returns the number of merges (0: the shell is unchanged).
std::size_t mergeUntoldEdges(SweepOutput& shell, double length, double offPlane,
                             double baseHeight = std::numeric_limits<double>::infinity());

// Welds two corners of one loop that are not neighbours but lie within `length` of each other
// (collapse.cpp): a face whose boundary runs out to a corner and back to a second vertex the
// sweep made a rounding away from the first. The spur between them, then of no width,
// leaves the face, and the faces either side of it meet along it. The same bar on base corners,
// and the same test of what is kept, as collapseShortEdges. Returns the number of welds.
std::size_t weldLoopCorners(SweepOutput& shell, double length,
                            double baseHeight = std::numeric_limits<double>::infinity());

// Whether a loop of the face is a simple polygon seen along the axis its normal is most
// across (exact predicates): two of its corners in one place, or sides that cross, are not.
bool simpleInItsPlane(const SweepOutput& shell, const ShellFace& f, const std::vector<int>& loop);

// How many loops of the shell are not simple in their plane (simpleInItsPlane).
std::size_t loopsNotSimple(const SweepOutput& shell);

// Zips every zero-width spur out of the faces (spurs.cpp): where a face's boundary runs out
// to a corner and straight back with the two sides within `width` of each other, the corner
// leaves that face and the faces either side of the spur meet along it instead. In a loop
// simple in its plane only a spur the face across runs too, a fold, or a spur whose sides lie
// within `straight` and whose far side is the longer by more than `width` is zipped. The shell stays closed; nothing is done to a shell that is not a
// closed 2-manifold. Returns the number of corners zipped.
std::size_t zipSpurs(SweepOutput& shell, double width, double straight = 0.0);

// Takes folds out of the boundaries between faces (folds.cpp): where a face that is not simple
// in its plane shares a run of corners with one other face, and no third face meets those
// corners, the two faces lie in one plane there and are divided by a straight edge between
// the run's ends instead. Kept only where that makes a loop simple and leaves no loop that was
// simple crossing itself; nothing is done to a shell that is not a closed 2-manifold. Returns
// the number of corners removed.
std::size_t unfoldSharedRuns(SweepOutput& shell);

// Splits a face whose loop touches itself (touches.cpp): where a corner lies within `length`
// of an edge of the same loop that does not end at it (and not within `length` of that edge's
// ends), the loop runs round a lobe and back to that edge. The corner goes into the edge, in
// the face across it too, and the loop parts there into two faces, each simple and running the
// face's way. Only closed 2-manifold shells, and only loops not simple in their plane, are
// looked at. Returns the number of splits.
std::size_t splitTouchingLoops(SweepOutput& shell, double length);

// The traced shell's clean-up (cleanup.cpp): collapseShortEdges and weldLoopCorners at
// tol.collapse, mergeUntoldEdges up to tol.tinyFace within tol.cluster of the planes, then
// zipSpurs, unfoldSharedRuns and splitTouchingLoops. Where a loop with an
// edge shorter than tol.tinyFace is then still not simple in its plane (corners a few δ2
// apart at an apex, or either side of a ridge's end), the passes run once more with edges up
// to tol.tinyFace collapsed, and that is kept only if fewer loops are then not simple.
void cleanUpShell(SweepOutput& shell, const Tolerances& tol);

// Runs the sweep. The input must already be valid (see checkSpec): simple, consistently
// oriented loops and angles within (−π/2, π/2) with the last one > 0.
SweepOutput sweep(const SweepInput& input, const Tolerances& tol, Progress* progress = nullptr);

}  // namespace corbel::extrude
