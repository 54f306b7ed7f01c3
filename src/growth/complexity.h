#pragma once
// Form complexity (Sec. 7.2): F_q(S) = (Σ_{i<j} C_ij) / Σ |s_i|, where |s_i| counts the faces
// (real ShapeTree leaves) of unit i and C_ij the incidence links between units i and j.
// Kept as an exact fraction so comparisons and the series of Sec. 7.2.1 are exact.
#include "growth/floorplan.h"

#include <cstdint>
#include <vector>

namespace corbel::growth {

// A non-negative fraction in lowest terms (den > 0).
struct Fraction {
  std::int64_t num = 0, den = 1;
  static Fraction of(std::int64_t n, std::int64_t d);
  double value() const { return double(num) / double(den); }
  bool operator==(const Fraction&) const = default;
  friend bool operator<(const Fraction& a, const Fraction& b) { return a.num * b.den < b.num * a.den; }
  friend bool operator<=(const Fraction& a, const Fraction& b) { return !(b < a); }
  friend Fraction operator-(const Fraction& a, const Fraction& b);  // may be negative
};

struct Complexity {
  std::int64_t incidences = 0;                   // Σ_{i<j} C_ij
  std::int64_t faces = 0;                        // Σ |s_i|
  std::vector<std::vector<std::int64_t>> pairs;  // C_ij (symmetric, zero diagonal)
  Fraction value() const { return faces ? Fraction::of(incidences, faces) : Fraction{}; }
};

Complexity formComplexity(const Floorplan& plan);

}  // namespace corbel::growth
