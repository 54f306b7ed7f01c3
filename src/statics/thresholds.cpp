#include "statics/thresholds.h"

#include "core/error.h"

#include <cmath>

namespace corbel::statics {

double bisectThreshold(const std::function<bool(double)>& feasible, double feasibleEnd, double infeasibleEnd,
                       double tolerance, const std::string& parameter) {
  if (!(tolerance > 0) || !std::isfinite(feasibleEnd) || !std::isfinite(infeasibleEnd))
    throw Error("bisection: the ends and the tolerance must be finite, the tolerance positive");
  if (!feasible(feasibleEnd)) throw Error("the structure does not stand at " + parameter + " = " + std::to_string(feasibleEnd));
  if (feasible(infeasibleEnd)) throw Error("the structure still stands at " + parameter + " = " + std::to_string(infeasibleEnd));
  double ok = feasibleEnd, bad = infeasibleEnd;
  while (std::abs(ok - bad) > tolerance) {
    const double mid = 0.5 * (ok + bad);
    (feasible(mid) ? ok : bad) = mid;
  }
  return 0.5 * (ok + bad);
}

double minimumArchThickness(ArchSpec spec, const AnalysisOptions& options, double tolerance) {
  return bisectThreshold(
      [&](double t) {
        ArchSpec s = spec;
        s.thickness = t;
        return checkFeasibility(semicircularArch(s), options).feasible;
      },
      0.5 * spec.radius, 0.01 * spec.radius, tolerance, "thickness");
}

double criticalArchTilt(ArchSpec spec, const AnalysisOptions& options, double toleranceDeg) {
  return bisectThreshold(
      [&](double deg) {
        ArchSpec s = spec;
        s.tiltDeg = deg;
        return checkFeasibility(semicircularArch(s), options).feasible;
      },
      0.0, 60.0, toleranceDeg, "tilt (degrees)");
}

double largestKernMargin(const Assembly& assembly, AnalysisOptions options, double tolerance) {
  if (!(tolerance > 0)) throw Error("kern margin: the tolerance must be positive");
  auto stands = [&](double s) {
    options.kernShrink = s;
    return checkFeasibility(assembly, options).feasible;
  };
  if (!stands(0.0)) return -1.0;
  if (stands(kMaxKernMargin)) return kMaxKernMargin;
  double ok = 0.0, bad = kMaxKernMargin;
  while (bad - ok > tolerance) {
    const double mid = 0.5 * (ok + bad);
    (stands(mid) ? ok : bad) = mid;
  }
  return ok;
}

}  // namespace corbel::statics
