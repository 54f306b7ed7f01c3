#pragma once
// Exact stability thresholds by bisection on the strict LP feasibility test.
#include "statics/analysis.h"
#include "statics/arch.h"

#include <functional>
#include <string>

namespace corbel::statics {

// Bisection between a parameter value where `feasible` holds and one where it fails, until
// they are within `tolerance`. Returns the midpoint of the last bracket. Throws corbel::Error
// naming `parameter` if the two ends do not bracket a change.
double bisectThreshold(const std::function<bool(double)>& feasible, double feasibleEnd, double infeasibleEnd,
                       double tolerance, const std::string& parameter = "the parameter");

// The least thickness at which the arch stands (spec.thickness is ignored), to `tolerance`.
double minimumArchThickness(ArchSpec spec, const AnalysisOptions& options = {}, double tolerance = 1e-6);

// The ground tilt in degrees at which the arch stops standing (spec.tiltDeg is ignored).
double criticalArchTilt(ArchSpec spec, const AnalysisOptions& options = {}, double toleranceDeg = 1e-5);

// The largest kern shrink s (Sec. 3.4: every contact polygon scaled by 1 − s about its
// centroid) at which the assembly still stands by the strict LP test, with `options`' friction,
// to `tolerance` (bisection over [0, kMaxKernMargin]; the value returned is the bracket's
// standing end, so the assembly stands at it). −1 when it does not stand even at s = 0;
// kMaxKernMargin when it stands there too.
inline constexpr double kMaxKernMargin = 0.95;
double largestKernMargin(const Assembly& assembly, AnalysisOptions options = {}, double tolerance = 0.01);

}  // namespace corbel::statics
