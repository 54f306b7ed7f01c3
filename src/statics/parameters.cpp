#include "statics/parameters.h"

#include "core/error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace corbel::statics {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double parseBound(const std::string& text, const std::string& whole) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw Error("free parameter '" + whole + "': '" + text + "' is not a finite number");
  return v;
}

}  // namespace

Parameter makeParameter(std::string name, double value, double lo, double hi, std::string description,
                        bool continuous) {
  Parameter p;
  p.name = std::move(name);
  p.value = value;
  p.lo = lo;
  p.hi = hi;
  p.continuous = continuous;
  p.description = std::move(description);
  return p;
}

int countOf(const ParameterSet& p, const std::string& name) { return int(std::lround(p[name])); }

void ParameterSet::add(Parameter p) {
  if (p.name.empty()) throw Error("parameters: a parameter needs a name");
  if (has(p.name)) throw Error("parameters: '" + p.name + "' is defined twice");
  if (!(p.lo <= p.hi)) throw Error("parameters: '" + p.name + "' has lo > hi");
  if (!std::isfinite(p.value) || p.value < p.lo || p.value > p.hi)
    throw Error("parameters: the default of '" + p.name + "' is outside [" + number(p.lo) + ", " + number(p.hi) + "]");
  params_.push_back(std::move(p));
}

bool ParameterSet::has(const std::string& name) const {
  for (const Parameter& p : params_)
    if (p.name == name) return true;
  return false;
}

const Parameter& ParameterSet::find(const std::string& name) const {
  for (const Parameter& p : params_)
    if (p.name == name) return p;
  throw Error("unknown parameter '" + name + "' (parameters: " + names() + ")");
}

void ParameterSet::set(const std::string& name, double value) {
  Parameter& p = params_[std::size_t(&find(name) - params_.data())];
  if (!std::isfinite(value)) throw Error("parameter '" + name + "': the value must be a finite number");
  if (value < p.lo || value > p.hi)
    throw Error("parameter '" + name + "' = " + number(value) + " is outside its valid range [" + number(p.lo) + ", " +
                number(p.hi) + "]");
  if (!p.continuous && value != std::floor(value)) throw Error("parameter '" + name + "' is a count: it must be whole");
  p.value = value;
}

std::string ParameterSet::names() const {
  std::string out;
  for (const Parameter& p : params_) out += (out.empty() ? "" : ", ") + p.name;
  return out.empty() ? "none" : out;
}

FreeParameter parseFreeParameter(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw Error("free parameter '" + text + "': expected NAME=LO:HI");
  const auto colon = text.find(':', eq);
  if (colon == std::string::npos) throw Error("free parameter '" + text + "': expected NAME=LO:HI (no ':')");
  FreeParameter f;
  f.name = text.substr(0, eq);
  f.lo = parseBound(text.substr(eq + 1, colon - eq - 1), text);
  f.hi = parseBound(text.substr(colon + 1), text);
  if (f.lo > f.hi) throw Error("free parameter '" + text + "': the lower bound is above the upper bound");
  return f;
}

void validateFreeParameters(const ParameterSet& parameters, const std::vector<FreeParameter>& free) {
  if (free.empty()) throw Error("parameter search: no free parameters");
  std::set<std::string> seen;
  for (const FreeParameter& f : free) {
    const Parameter& p = parameters.find(f.name);
    if (!seen.insert(f.name).second) throw Error("free parameter '" + f.name + "' is given twice");
    if (!p.continuous) throw Error("free parameter '" + f.name + "' is a count and cannot be searched");
    if (!std::isfinite(f.lo) || !std::isfinite(f.hi)) throw Error("free parameter '" + f.name + "': bounds must be finite");
    if (f.lo > f.hi) throw Error("free parameter '" + f.name + "': lo > hi");
    if (f.lo < p.lo || f.hi > p.hi)
      throw Error("free parameter '" + f.name + "': bounds [" + number(f.lo) + ", " + number(f.hi) +
                  "] leave its valid range [" + number(p.lo) + ", " + number(p.hi) + "]");
  }
}

}  // namespace corbel::statics
