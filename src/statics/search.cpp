#include "statics/search.h"

#include "core/error.h"

#include <nlopt.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <memory>

namespace corbel::statics {

std::string toString(SearchStatus s) {
  switch (s) {
    case SearchStatus::Feasible: return "feasible";
    case SearchStatus::LocalMinimum: return "local minimum";
    case SearchStatus::IterationLimit: return "iteration limit";
    case SearchStatus::TimeLimit: return "time limit";
    case SearchStatus::Cancelled: return "cancelled";
    case SearchStatus::Failed: return "failed";
  }
  return "unknown";
}

namespace {

// Equilibrium residual ‖A f + w‖/‖w‖ up to which a best iterate is used (see objective).
constexpr double kUsableResidual = 1e-5;

nlopt_algorithm algorithmByName(const std::string& name) {
  if (name == "slsqp") return NLOPT_LD_SLSQP;
  if (name == "mma") return NLOPT_LD_MMA;
  if (name == "lbfgs") return NLOPT_LD_LBFGS;
  throw Error("parameter search: unknown algorithm '" + name + "' (slsqp, mma, lbfgs)");
}

struct Search {
  const ParametricModel* model = nullptr;
  const std::vector<FreeParameter>* free = nullptr;
  const SearchOptions* options = nullptr;
  ParameterSet values;
  double scale = 1;  // the objective handed to NLopt is y/W² × scale (O(1) at the start)
  int evaluations = 0;
  std::vector<double> history;
  double bestMeasure = std::numeric_limits<double>::infinity();
  double bestY = 0;  // y in N² at the best iterate
  std::vector<double> best;
  std::string failure;
  bool cancelled = false;
  nlopt_opt opt = nullptr;
  // The scaling evaluation at the start: the optimizer's first call is usually at the same
  // point, and then reuses its QP (only the gradient's geometry is added).
  std::vector<double> start;
  const MeasureEvaluation* first = nullptr;

  ParameterSet at(const double* x) const {
    ParameterSet s = values;
    for (std::size_t k = 0; k < free->size(); ++k) s.set((*free)[k].name, x[k]);
    return s;
  }
};

double objective(unsigned n, const double* x, double* grad, void* data) {
  Search& s = *static_cast<Search*>(data);
  try {
    MeasureEvaluation ev;
    if (s.first && std::equal(x, x + n, s.start.begin())) {
      ev = *s.first;
      if (grad) addGradient(*s.model, s.at(x), *s.free, s.options->analysis, ev);
      s.first = nullptr;  // once: a later call at the start again solves afresh (NLopt rarely does)
    } else {
      ev = evaluateMeasure(*s.model, s.at(x), *s.free, s.options->analysis, grad != nullptr);
    }
    // The solver's best iterate serves when it is in equilibrium (its y is then an upper
    // bound within the iterate's gap); anything worse stops the search.
    if (ev.analysis.status != SolveStatus::Optimal && !(ev.analysis.equilibriumResidual <= kUsableResidual))
      throw Error("the QP solver stopped (" + toString(ev.analysis.status) + ") away from equilibrium");
    ++s.evaluations;
    s.history.push_back(ev.measure);
    if (ev.measure < s.bestMeasure) {
      s.bestMeasure = ev.measure;
      s.bestY = ev.analysis.y;
      s.best.assign(x, x + n);
    }
    if (grad)
      for (unsigned k = 0; k < n; ++k) grad[k] = ev.gradient[k] * s.scale;
    if (s.options->progress) {
      SearchProgress p;
      p.evaluation = s.evaluations;
      p.measure = ev.measure;
      p.values.assign(x, x + n);
      if (!s.options->progress(p)) {
        s.cancelled = true;
        nlopt_force_stop(s.opt);
      }
    }
    return ev.measure * s.scale;
  } catch (const std::exception& e) {
    std::string where;
    for (std::size_t k = 0; k < n; ++k)
      where += (k ? ", " : "") + (*s.free)[k].name + " = " + std::to_string(x[k]);
    s.failure = "at " + where + ": " + e.what();
    nlopt_force_stop(s.opt);
    if (grad)
      for (unsigned k = 0; k < n; ++k) grad[k] = 0;
    return std::numeric_limits<double>::max();
  }
}

double projected(const std::vector<double>& g, const std::vector<double>& x, const std::vector<FreeParameter>& free) {
  double worst = 0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const double span = std::max(free[k].hi - free[k].lo, 1e-300);
    const bool atLo = x[k] <= free[k].lo + 1e-9 * span, atHi = x[k] >= free[k].hi - 1e-9 * span;
    if ((atLo && g[k] > 0) || (atHi && g[k] < 0)) continue;  // pushing against a bound
    worst = std::max(worst, std::abs(g[k]));
  }
  return worst;
}

}  // namespace

// Sec. 4: argmin y(θ) within the bounds.
SearchResult searchParameters(const ParametricModel& model, const std::vector<FreeParameter>& free,
                              const SearchOptions& options, const ParameterSet* start) {
  const auto t0 = std::chrono::steady_clock::now();
  const ParameterSet& initial = start ? *start : model.parameters;
  validateFreeParameters(initial, free);
  const nlopt_algorithm algorithm = algorithmByName(options.algorithm);
  if (options.maxEvaluations < 1) throw Error("parameter search: the evaluation cap must be at least 1");
  if (!(options.maxSeconds >= 0) || !std::isfinite(options.maxSeconds))
    throw Error("parameter search: the time cap must be a number ≥ 0");
  if (!(options.stopMeasure >= 0) || !std::isfinite(options.stopMeasure))
    throw Error("parameter search: the stop measure must be a number ≥ 0");

  Search s;
  s.model = &model;
  s.free = &free;
  s.options = &options;
  s.values = initial;
  const unsigned n = unsigned(free.size());
  std::vector<double> x(n), lo(n), hi(n);
  for (unsigned k = 0; k < n; ++k) {
    lo[k] = free[k].lo;
    hi[k] = free[k].hi;
    x[k] = std::clamp(initial[free[k].name], lo[k], hi[k]);
  }

  SearchResult r;
  r.free = free;
  // The start, once, to scale the objective (y/W² may be 1e-8 or 1e-2; NLopt's tolerances
  // behave best when the objective is O(1)).
  MeasureEvaluation first;
  try {
    first = evaluateMeasure(model, s.at(x.data()), free, options.analysis, false);
  } catch (const std::exception& e) {
    r.status = SearchStatus::Failed;
    r.message = std::string("at the start: ") + e.what();
    r.values = s.at(x.data());
    return r;
  }
  r.initialMeasure = first.measure;
  s.scale = first.measure > 0 ? 1.0 / first.measure : 1.0;

  nlopt_result code = NLOPT_STOPVAL_REACHED;
  if (first.measure > options.stopMeasure) {
    std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(nlopt_create(algorithm, n), &nlopt_destroy);
    if (!opt) throw Error("parameter search: NLopt could not create the optimizer");
    s.opt = opt.get();
    s.start = x;
    s.first = &first;
    nlopt_set_lower_bounds(s.opt, lo.data());
    nlopt_set_upper_bounds(s.opt, hi.data());
    nlopt_set_min_objective(s.opt, objective, &s);
    nlopt_set_stopval(s.opt, options.stopMeasure * s.scale);
    nlopt_set_ftol_rel(s.opt, options.fTolerance);
    nlopt_set_xtol_rel(s.opt, options.xTolerance);
    nlopt_set_maxeval(s.opt, options.maxEvaluations);
    if (options.maxSeconds > 0) nlopt_set_maxtime(s.opt, options.maxSeconds);
    double f = 0;
    code = nlopt_optimize(s.opt, x.data(), &f);
    if (!s.best.empty()) x = s.best;  // the best iterate, whatever the optimizer returned
  } else {
    s.evaluations = 1;
    s.history.push_back(first.measure);
    if (options.progress) {  // the one evaluation, reported like the optimizer's
      SearchProgress p;
      p.evaluation = 1;
      p.measure = first.measure;
      p.values = x;
      options.progress(p);
    }
    s.bestMeasure = first.measure;
    s.bestY = first.analysis.y;
  }

  r.evaluations = s.evaluations;
  r.history = s.history;
  r.values = s.at(x.data());
  // The result. A standing one has y ≡ 0 around it, so its gradient is 0 and the best
  // evaluation says all; otherwise one more QP gives the gradient for the report.
  try {
    if (s.bestMeasure <= options.stopMeasure) {
      r.measure = s.bestMeasure;
      r.y = s.bestY;
      r.gradient.assign(n, 0.0);
      r.projectedGradient = 0;
    } else {
      const MeasureEvaluation last = evaluateMeasure(model, r.values, free, options.analysis, true);
      r.measure = last.measure;
      r.y = last.analysis.y;
      r.gradient = last.gradient;
      r.projectedGradient = projected(last.gradient, x, free);
    }
    if (options.strictCheck) r.standsStrictly = checkFeasibility(model.build(r.values), options.analysis).feasible;
  } catch (const std::exception& e) {
    r.measure = s.bestMeasure;
    if (s.failure.empty()) s.failure = std::string("at the result: ") + e.what();
  }

  const std::string why = nlopt_result_to_string(code);
  if (r.measure <= options.stopMeasure) {
    r.status = SearchStatus::Feasible;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", options.stopMeasure);
    r.message = std::string("the structure stands (y/W² ≤ ") + buf + ")";
  } else if (!s.failure.empty()) {
    r.status = SearchStatus::Failed;
    r.message = s.failure;
  } else if (s.cancelled) {
    r.status = SearchStatus::Cancelled;
    r.message = "cancelled";
  } else if (code == NLOPT_MAXEVAL_REACHED) {
    r.status = SearchStatus::IterationLimit;
    r.message = "the evaluation cap was reached";
  } else if (code == NLOPT_MAXTIME_REACHED) {
    r.status = SearchStatus::TimeLimit;
    r.message = "the time cap was reached";
  } else if (code > 0 || code == NLOPT_ROUNDOFF_LIMITED) {
    r.status = SearchStatus::LocalMinimum;
    r.message = "local minimum with y > 0 (optimizer: " + why + ", projected gradient " +
                std::to_string(r.projectedGradient) + "): no feasible structure near here within the bounds";
  } else {
    r.status = SearchStatus::Failed;
    r.message = "the optimizer failed (" + why + ")";
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

SearchResult updateAfterEdit(const ParametricModel& model, const std::vector<FreeParameter>& free,
                             const ParameterSet& previous, const std::string& name, double value,
                             const SearchOptions& options) {
  for (const FreeParameter& f : free)
    if (f.name == name) throw Error("interactive edit: '" + name + "' is a free parameter; the search sets it");
  ParameterSet start = previous;
  start.set(name, value);
  return searchParameters(model, free, options, &start);
}

}  // namespace corbel::statics
