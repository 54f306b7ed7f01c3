#pragma once
// Named parameters of a procedural masonry model and the ones the user frees for the
// parameter search (Whiting et al. 2009, Sec. 2 "Free Parameters", Sec. 4).
#include "statics/model.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace corbel::statics {

struct Parameter {
  std::string name;
  double value = 0;  // the current value (a template's default until set)
  // Where the template makes valid geometry; free bounds must lie inside.
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool continuous = true;  // counts (blocks, courses) are not: they cannot be freed
  std::string description;
};

// An ordered set of named parameters. Lookups of a name that does not exist throw
// corbel::Error listing the names that do.
class ParameterSet {
 public:
  // Adds a parameter; throws for a duplicate name, an empty name, a value outside [lo, hi].
  void add(Parameter p);
  double operator[](const std::string& name) const { return find(name).value; }
  // Sets a value; throws for an unknown name, a non-finite value, one outside [lo, hi] or a
  // fractional value of a count.
  void set(const std::string& name, double value);
  const Parameter& find(const std::string& name) const;
  bool has(const std::string& name) const;
  const std::vector<Parameter>& all() const { return params_; }
  std::string names() const;  // "a, b, c" for messages

 private:
  std::vector<Parameter> params_;
};

// A parameter the search may change, within [lo, hi] (the user's bounds, Sec. 2).
struct FreeParameter {
  std::string name;
  double lo = 0, hi = 0;
};

// A parametric model: named parameters and the procedure that builds the blocks from them.
struct ParametricModel {
  std::string name;
  std::string description;
  ParameterSet parameters;
  std::function<Assembly(const ParameterSet&)> build;
  std::vector<FreeParameter> suggestedFree;  // what a search frees when the user names none
};

// A parameter of a model: its name, default value, valid range and what it is in words; counts
// (blocks, courses) are not continuous.
Parameter makeParameter(std::string name, double value, double lo, double hi, std::string description,
                        bool continuous = true);
// The value of a count parameter, rounded to the nearest integer.
int countOf(const ParameterSet& p, const std::string& name);

// Parses "NAME=LO:HI". Throws corbel::Error naming the problem (no '=', no ':', a bound that
// is not a finite number, lo > hi).
FreeParameter parseFreeParameter(const std::string& text);

// Checks free parameters against a model's parameters: known, continuous, not repeated,
// finite bounds with lo ≤ hi inside the parameter's valid range. Throws corbel::Error.
void validateFreeParameters(const ParameterSet& parameters, const std::vector<FreeParameter>& free);

}  // namespace corbel::statics
