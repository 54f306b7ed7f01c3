#include "statics/sensitivity.h"

#include "core/error.h"
#include "statics/equilibrium.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace corbel::statics {
namespace {

// Relative step of the geometric differences: the equilibrium matrix is a smooth (mostly
// polynomial) function of the geometry, so the central difference's truncation error is
// O(h²) ≈ 1e-12 and its rounding error about 1e-16/h ≈ 1e-10 of the entries.
constexpr double kRelativeStep = 1e-6;

// λᵀ(A x + w) for the system built at `values`, with x laid out as in `base`.
std::optional<double> lagrangianTerm(const ParametricModel& model, const ParameterSet& values,
                                     const EquilibriumSystem& base, const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& lambda, const AnalysisOptions& options) {
  const EquilibriumSystem sys = prepareEquilibrium(model.build(values), options);
  if (!sameLayout(sys, base)) return std::nullopt;
  return penaltyLagrangianTerm(sys, x, lambda);
}

}  // namespace

// The envelope gradient at `values` whose system `base` ev.analysis solved.
void gradientAt(const ParametricModel& model, const ParameterSet& values, const std::vector<FreeParameter>& free,
                const AnalysisOptions& options, const EquilibriumSystem& base, MeasureEvaluation& ev);

MeasureEvaluation evaluateMeasure(const ParametricModel& model, const ParameterSet& values,
                                  const std::vector<FreeParameter>& free, const AnalysisOptions& options,
                                  bool withGradient) {
  if (!model.build) throw Error("statics: the model '" + model.name + "' has no builder");
  MeasureEvaluation ev;
  const Assembly assembly = model.build(values);
  const EquilibriumSystem base = prepareEquilibrium(assembly, options);
  ev.analysis = analyseSystem(base, options);
  ev.measure = ev.analysis.yNormalised;
  if (withGradient) gradientAt(model, values, free, options, base, ev);
  return ev;
}

void addGradient(const ParametricModel& model, const ParameterSet& values, const std::vector<FreeParameter>& free,
                 const AnalysisOptions& options, MeasureEvaluation& ev) {
  if (!model.build) throw Error("statics: the model '" + model.name + "' has no builder");
  gradientAt(model, values, free, options, prepareEquilibrium(model.build(values), options), ev);
}

void gradientAt(const ParametricModel& model, const ParameterSet& values, const std::vector<FreeParameter>& free,
                const AnalysisOptions& options, const EquilibriumSystem& base, MeasureEvaluation& ev) {
  ev.notes.clear();
  const Eigen::VectorXd& x = ev.analysis.solution;
  const Eigen::VectorXd& lambda = ev.analysis.multipliers;
  if (x.size() == 0 || lambda.size() != base.rows)
    throw Error("statics: the solver returned no solution to differentiate (" + toString(ev.analysis.status) + ")");
  // The term at θ itself, from the system already built (used by one-sided differences).
  const std::optional<double> at = penaltyLagrangianTerm(base, x, lambda);
  ev.gradient.assign(free.size(), 0.0);
  for (std::size_t k = 0; k < free.size(); ++k) {
    const Parameter& p = values.find(free[k].name);
    const double h = kRelativeStep * std::max({std::abs(p.value), free[k].hi - free[k].lo, 1e-3});
    // Stay where the template makes valid geometry; one-sided at its limits.
    auto shifted = [&](double delta) -> std::optional<double> {
      const double v = p.value + delta;
      if (v < p.lo || v > p.hi) return std::nullopt;
      ParameterSet s = values;
      s.set(p.name, v);
      return lagrangianTerm(model, s, base, x, lambda, options);
    };
    const std::optional<double> plus = shifted(h), minus = shifted(-h);
    double slope = 0;
    if (plus && minus) {
      slope = (*plus - *minus) / (2 * h);
    } else if (plus && at) {
      slope = (*plus - *at) / h;
      ev.notes.push_back(p.name + ": one-sided (forward) difference");
    } else if (minus && at) {
      slope = (*at - *minus) / h;
      ev.notes.push_back(p.name + ": one-sided (backward) difference");
    } else {
      throw Error("statics: the contacts change on both sides of " + p.name + " = " + std::to_string(p.value) +
                  "; the measure is not differentiable there");
    }
    // L = ½xᵀQx − λᵀ(A x − b) with b = −w: ∂L/∂θ = −λᵀ(∂A x + ∂w).
    ev.gradient[k] = -slope;
  }
}

}  // namespace corbel::statics
