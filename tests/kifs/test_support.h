#pragma once
// Shared by the KIFS tests: seeded random points and the presets under test.
#include "kifs/distance.h"
#include "kifs/mass_field.h"

#include <glm/glm.hpp>

#include <random>
#include <string>
#include <vector>

namespace corbel::kifs::test {

inline glm::dvec3 uniformIn(std::mt19937_64& rng, const glm::dvec3& lo, const glm::dvec3& hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return lo + glm::dvec3(u(rng), u(rng), u(rng)) * (hi - lo);
}

// A uniformly distributed unit vector.
inline glm::dvec3 unitVector(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  glm::dvec3 v;
  do v = glm::dvec3(n(rng), n(rng), n(rng));
  while (glm::length(v) < 1e-9);
  return glm::normalize(v);
}

// The building presets under test: every footprint and coordinate system, R1 and R2 ≠ I.
inline std::vector<std::string> buildingPresets() { return {"box", "t", "h", "polar", "curved", "crumbling", "star"}; }

// The azimuth (degrees) the tests look at a preset from: the curved one faces +x.
inline double viewAzimuth(const std::string& preset) { return preset == "curved" ? -20.0 : preset == "polar" ? -35.0 : -60.0; }

// A straight prism over a convex plan (counter-clockwise, metres) from z = 0 to `height`.
inline TriangleSoup prism(const std::vector<glm::dvec2>& plan, double height) {
  TriangleSoup s;
  const int n = int(plan.size());
  for (double z : {0.0, height})
    for (const glm::dvec2& p : plan) s.points.emplace_back(p.x, p.y, z);
  for (int i = 1; i + 1 < n; ++i) {
    s.triangles.push_back({0, i + 1, i});
    s.triangles.push_back({n, n + i, n + i + 1});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    s.triangles.push_back({i, j, n + j});
    s.triangles.push_back({i, n + j, n + i});
  }
  return s;
}

}  // namespace corbel::kifs::test
