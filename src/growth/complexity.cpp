// Form complexity F_q (Sec. 7.2). See complexity.h.
#include "growth/complexity.h"

#include <cstdlib>
#include <numeric>

namespace corbel::growth {

Fraction Fraction::of(std::int64_t n, std::int64_t d) {
  if (d < 0) n = -n, d = -d;
  const std::int64_t g = std::gcd(std::llabs(n), d);
  return g ? Fraction{n / g, d / g} : Fraction{0, 1};
}

Fraction operator-(const Fraction& a, const Fraction& b) {
  return Fraction::of(a.num * b.den - b.num * a.den, a.den * b.den);
}

Complexity formComplexity(const Floorplan& plan) {
  Complexity c;
  const std::size_t n = plan.units().size();
  c.pairs.assign(n, std::vector<std::int64_t>(n, 0));
  for (const ShapeTree& t : plan.units()) c.faces += t.faceCount();
  for (const Incidence& l : plan.incidences()) {
    ++c.pairs[std::size_t(l.a.unit)][std::size_t(l.b.unit)];
    ++c.pairs[std::size_t(l.b.unit)][std::size_t(l.a.unit)];
    ++c.incidences;
  }
  return c;
}

}  // namespace corbel::growth
