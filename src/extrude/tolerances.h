#pragma once
// Every tolerance of the procedural-extrusion kernel, in one place. They scale with the
// model: `scale` is the diagonal of the plan's bounding box (meters), so a 10 m house and a
// 1 km estate get the same relative behaviour. See docs/extrude.md for how they were chosen.
#include <algorithm>

namespace corbel::extrude {

struct Tolerances {
  // δ1 (Sec. 4.4): events whose heights differ by less than this are handled together.
  double height;
  // δ2: events whose positions on the sweep plane are closer than this are one event.
  double cluster;
  // δ3: an edge takes part in an event at l if l lies within this of its segment.
  double edgeMargin;
  // Below this sine of their angle two edge directions are parallel for computing a corner's
  // motion (their lines' intersection is ill-conditioned).
  double parallelSine;
  // Below this sine, colinear neighbours of different angles merge into one line (Sec. 4.8):
  // the higher priority takes over. 1e-7 moves a 50 m wall by 5 µm at most.
  double mergeSine;
  // Antiparallel neighbours (a spike) within ridgeSine meet along a ridge at once instead of
  // racing a corner along an almost flat ridge; up to ridgeMaxSine they do so only where the
  // sliver this ignores is small: sine · (shorter edge)² below ridgeArea (an area, m²).
  double ridgeSine;
  double ridgeMaxSine;
  double ridgeArea;
  // Input points closer than this are one point (zero-length edges are refused).
  double minEdge;
  // Output edges shorter than this are collapsed (collapseShortEdges): near-simultaneous events
  // kept apart by the clustering leave them, with faces of no area between. 5 δ2 clears the
  // Scene's degenerate-face bar in the cases seen and moves no vertex far enough to disturb the
  // projection identity (the random test's worst stays under 1e-7, docs/extrude.md).
  double collapse;
  // A face whose corners all lie within this of one another is collapsed to a point: what is
  // left of a loop that a change (a chimney's top stepping in) closed up to rounding.
  double tinyFace;

  // `factor` widens every tolerance of the sweep by that multiple (a rebuild of a shell that
  // failed with the defaults, extrude/batch.cpp); the sines stay below 1e-3 and ridgeArea
  // grows with the square of the factor, as a length squared. minEdge, the input check's
  // bar, does not change: a plan is valid or not whatever the sweep's tolerances.
  static Tolerances forScale(double scale, double factor = 1.0) {
    const double s = std::max(scale, 1e-3);
    const double f = std::max(factor, 1.0);
    auto sine = [&](double v) { return std::min(v * f, 1e-3); };
    return {1e-9 * s * f, 1e-8 * s * f,          1e-8 * s * f, sine(1e-8),   sine(1e-7),  sine(1e-8),
            sine(1e-5),   1e-11 * s * s * f * f, 1e-7 * s,     5e-8 * s * f, 1e-6 * s * f};
  }
};

}  // namespace corbel::extrude
