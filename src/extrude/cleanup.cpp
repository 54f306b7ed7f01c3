// The traced shell's clean-up, pass by pass, and the wider collapse where a loop stays twisted
// (docs/extrude.md, "Decisions").
#include "extrude/sweep.h"

#include <utility>

namespace corbel::extrude {

namespace {

// Whether a loop with an edge shorter than `length` is not simple in its plane (the cheap
// test first: most shells have no such edge).
bool twistedAtAShortEdge(const SweepOutput& shell, double length) {
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops) {
      bool shortEdge = false;
      for (std::size_t i = 0; i < loop.size() && !shortEdge; ++i)
        shortEdge = (shell.points[loop[(i + 1) % loop.size()]] - shell.points[loop[i]]).norm() < length;
      if (shortEdge && !simpleInItsPlane(shell, f, loop)) return true;
    }
  return false;
}

void passes(SweepOutput& shell, double collapse, const Tolerances& tol) {
  collapseShortEdges(shell, collapse, tol.tinyFace, tol.height);
  weldLoopCorners(shell, collapse, tol.height);
  mergeUntoldEdges(shell, tol.tinyFace, tol.cluster, tol.height);
  // A zip moves a corner into the face across, which can leave a fold there with a third face
  // that no zip of this round looked at: zip again until none is left (a few rounds at most).
  for (int round = 0; round < 8 && zipSpurs(shell, tol.tinyFace, tol.cluster) > 0; ++round) {
  }
  unfoldSharedRuns(shell);
  splitTouchingLoops(shell, collapse);
}

}  // namespace

void cleanUpShell(SweepOutput& shell, const Tolerances& tol) {
  passes(shell, tol.collapse, tol);
  if (!twistedAtAShortEdge(shell, tol.tinyFace)) return;
  SweepOutput wider = shell;
  passes(wider, tol.tinyFace, tol);
  if (loopsNotSimple(wider) < loopsNotSimple(shell)) shell = std::move(wider);
}

}  // namespace corbel::extrude
