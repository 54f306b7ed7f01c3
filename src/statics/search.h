#pragma once
// The parameter search of Whiting et al. 2009, Sec. 4: argmin_θ y(θ) s.t. lb ≤ θ ≤ ub, by a
// gradient-based bound-constrained optimizer from NLopt, gradients by the envelope theorem
// (sensitivity.h), one QP per evaluation. Stops at a feasible structure (y = 0 up to
// kFeasibleMeasure) or at a local minimum, and says which.
#include "statics/sensitivity.h"
#include "statics/tolerances.h"

#include <functional>
#include <string>
#include <vector>

namespace corbel::statics {

enum class SearchStatus {
  Feasible,        // y/W² ≤ the stop measure: the structure stands
  LocalMinimum,    // converged with y > 0: no feasible structure near here within the bounds
  IterationLimit,  // the evaluation cap was reached first
  TimeLimit,       // the time cap was reached first
  Cancelled,       // the progress callback asked to stop
  Failed           // the model could not be built or analysed at some θ (see `message`)
};

std::string toString(SearchStatus s);

struct SearchProgress {
  int evaluation = 0;
  double measure = 0;
  std::vector<double> values;  // the free parameters at this evaluation
};

struct SearchOptions {
  AnalysisOptions analysis;
  // "mma" (method of moving asymptotes: conservative steps, so the result stays near the
  // start), "slsqp" (sequential quadratic programming, as the paper; its first steps often
  // jump to a bound), "lbfgs".
  std::string algorithm = "mma";
  int maxEvaluations = 200;         // QPs
  double maxSeconds = 0;            // 0: no time cap
  double stopMeasure = kFeasibleMeasure;  // y/W² at or below which the structure counts as standing
  double xTolerance = 1e-9;         // relative step below which the search has converged
  double fTolerance = 1e-12;        // relative change of y below which it has converged
  // Check the result with the strict LP phase-1 test too (SearchResult::standsStrictly);
  // interactive updates may leave it off to save one LP.
  bool strictCheck = true;
  // Called after every evaluation; return false to cancel.
  std::function<bool(const SearchProgress&)> progress;
};

struct SearchResult {
  SearchStatus status = SearchStatus::Failed;
  std::string message;           // why it stopped, in words (the optimizer's reason too)
  int evaluations = 0;           // QPs solved, each with its gradient when the optimizer asked
  double initialMeasure = 0;     // y/W² at the start
  double measure = 0;            // y/W² at the result
  double y = 0;                  // y in N² at the result
  std::vector<double> gradient;  // d(y/W²)/dθ at the result
  double projectedGradient = 0;  // ‖gradient projected on the bounds‖∞, 0 at a bound-constrained stationary point
  bool standsStrictly = false;   // the LP phase-1 test at the result (exact, no tolerance on y); false unless strictCheck
  ParameterSet values;           // every parameter at the result
  std::vector<FreeParameter> free;
  std::vector<double> history;   // y/W² per evaluation
  double seconds = 0;
};

// Starts from `start` (the model's current values when empty) clamped into the free bounds.
// Throws corbel::Error for bad free parameters (unknown names, lo > hi, bounds outside the
// valid range) and an unknown algorithm; failures during the search are a status instead.
SearchResult searchParameters(const ParametricModel& model, const std::vector<FreeParameter>& free,
                              const SearchOptions& options = {}, const ParameterSet* start = nullptr);

// Interactive editing (Sec. 5 "Editing Parameters", Fig. 13): the user has set the fixed
// parameter `name` to `value`; the free parameters are searched again starting from
// `previous` (the last result's values), which is usually close. Throws corbel::Error when
// `name` is one of the free parameters or unknown.
SearchResult updateAfterEdit(const ParametricModel& model, const std::vector<FreeParameter>& free,
                             const ParameterSet& previous, const std::string& name, double value,
                             const SearchOptions& options = {});

}  // namespace corbel::statics
