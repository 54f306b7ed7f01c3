#pragma once
// The measure of infeasibility as a function of a model's free parameters, y(θ), and its
// gradient by the envelope theorem (Whiting et al. 2009, Sec. 4; statics notes, "Gradients
// without finite differences"): at the QP's optimum x* with equilibrium multipliers λ,
//   dy/dθ = ∂L/∂θ = −λᵀ (∂A/∂θ x* + ∂w/∂θ),
// since the friction and sign rows do not depend on θ. One QP per evaluation: ∂A/∂θ and
// ∂w/∂θ come from central differences of the *geometry* (the model rebuilt at θ ± h, its
// contacts and loads found again, no QP solved), x* and λ stay those of the one solve.
#include "statics/analysis.h"
#include "statics/parameters.h"

#include <string>
#include <vector>

namespace corbel::statics {

struct MeasureEvaluation {
  AnalysisResult analysis;        // the one QP at θ
  double measure = 0;             // y/W² (the search's objective; scale-free)
  std::vector<double> gradient;   // d(y/W²)/dθ_k for the free parameters, in their order
  std::vector<std::string> notes; // where a one-sided difference had to be used, and why
};

// Builds the model at `values`, solves the penalty QP and, when `withGradient`, differentiates
// the measure with respect to the free parameters. Throws corbel::Error when the model cannot
// be built or analysed there (naming the problem), or when the contact layout changes on both
// sides of a parameter within the difference step (the measure is not differentiable there).
MeasureEvaluation evaluateMeasure(const ParametricModel& model, const ParameterSet& values,
                                  const std::vector<FreeParameter>& free, const AnalysisOptions& options,
                                  bool withGradient);

// The gradient for an evaluation made at `values` without one (fills ev.gradient and
// ev.notes; the model is rebuilt at `values` for its layout, no QP is solved). Lets a search
// reuse the QP of its scaling evaluation when the optimizer asks for the same point again.
void addGradient(const ParametricModel& model, const ParameterSet& values, const std::vector<FreeParameter>& free,
                 const AnalysisOptions& options, MeasureEvaluation& ev);

}  // namespace corbel::statics
