#pragma once
// Helpers of the growth tests, and an independent check of the constraints: written from
// the definitions in docs/growth.md without the enforcer's code (pairwise box tests, and
// the cantilever rule by sampling the plan on a fine grid).
#include "growth/site.h"
#include "growth/unit.h"

#include <cmath>
#include <string>
#include <vector>

namespace corbel::growth::test {

inline Site openSite(double w, double d, int storeys) {
  Site s;
  s.plan = rectanglePlan(0, 0, w, d);
  s.storeys = storeys;
  s.storeyHeight = 3.0;
  return s;
}

inline Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {{x0, y0, z0}, {x1, y1, z1}};
}

inline Unit unitOf(int id, std::vector<Box> parts) {
  Unit u;
  u.id = id;
  u.parts = std::move(parts);
  return u;
}

inline Seed seedAt(double x, double y, int storey, double target, double w = 3, double d = 3) {
  Seed s;
  s.at = Vec2(x, y);
  s.size = Vec2(w, d);
  s.storey = storey;
  s.targetArea = target;
  return s;
}

inline bool overlaps(const Box& a, const Box& b, double tol = 1e-6) {
  for (int k = 0; k < 3; ++k)
    if (std::min(a.hi[k], b.hi[k]) - std::max(a.lo[k], b.lo[k]) <= tol) return false;
  return true;
}

// Plan gap (L∞) between two boxes whose vertical extents overlap; +inf otherwise.
inline double gapInPlan(const Box& a, const Box& b) {
  if (std::min(a.hi[2], b.hi[2]) - std::max(a.lo[2], b.lo[2]) <= 1e-6) return INFINITY;
  const double gx = std::max({0.0, a.lo[0] - b.hi[0], b.lo[0] - a.hi[0]});
  const double gy = std::max({0.0, a.lo[1] - b.hi[1], b.lo[1] - a.hi[1]});
  return std::max(gx, gy);
}

// Whether plan point (x, y) is within `reach` (L∞) of a support of unit u.
inline bool supportedPoint(const Site& site, const std::vector<Unit>& units, std::size_t ui, double x, double y) {
  const double reach = site.cantilever + 1e-6;
  auto near = [&](double x0, double y0, double x1, double y1) {
    return x >= x0 - reach && x <= x1 + reach && y >= y0 - reach && y <= y1 + reach;
  };
  for (const Box& p : units[ui].parts) {
    const double fx0 = p.lo[0], fy0 = p.lo[1], fx1 = p.hi[0], fy1 = p.hi[1];
    if (std::abs(p.lo[2] - site.base) < 1e-6 && near(fx0, fy0, fx1, fy1)) return true;
    auto under = [&](const Box& o) {
      if (std::abs(o.hi[2] - p.lo[2]) > 1e-6) return false;
      const double x0 = std::max(fx0, o.lo[0]), x1 = std::min(fx1, o.hi[0]);
      const double y0 = std::max(fy0, o.lo[1]), y1 = std::min(fy1, o.hi[1]);
      return x1 > x0 && y1 > y0 && near(x0, y0, x1, y1);
    };
    for (std::size_t j = 0; j < units.size(); ++j)
      if (j != ui)
        for (const Box& o : units[j].parts)
          if (under(o)) return true;
    for (const Box& c : site.circulation)
      if (under(c)) return true;
    auto beside = [&](const Box& o, double clearance) {
      if (!(gapInPlan(p, o) <= clearance + 1e-6)) return false;
      const double g = clearance + 1e-6;
      const double x0 = std::max(fx0, o.lo[0] - g), x1 = std::min(fx1, o.hi[0] + g);
      const double y0 = std::max(fy0, o.lo[1] - g), y1 = std::min(fy1, o.hi[1] + g);
      return x1 >= x0 && y1 >= y0 && near(x0, y0, x1, y1);
    };
    for (std::size_t c = 0; c < site.cores.size(); ++c)
      if (beside(site.coreBox(c), site.coreClearance)) return true;
    for (const Box& c : site.circulation)
      if (beside(c, site.circulationClearance)) return true;
  }
  return false;
}

// Every violated constraint, one line each (empty when all hold).
inline std::vector<std::string> independentViolations(const Site& site, const std::vector<Unit>& units) {
  std::vector<std::string> out;
  const Box env = site.bounds();
  for (std::size_t i = 0; i < units.size(); ++i) {
    const Unit& u = units[i];
    const std::string name = "unit " + std::to_string(u.id);
    double zmin = INFINITY, zmax = -INFINITY;
    for (std::size_t j = 0; j < u.parts.size(); ++j) {
      const Box& p = u.parts[j];
      zmin = std::min(zmin, p.lo[2]);
      zmax = std::max(zmax, p.hi[2]);
      const std::string part = name + "." + std::to_string(j);
      if (!site.planContains(footprint(p)) || p.lo[2] < env.lo[2] - 1e-6 || p.hi[2] > env.hi[2] + 1e-6)
        out.push_back(part + " outside the envelope");
      if (p.size(0) < 3 - 1e-6 || p.size(1) < 3 - 1e-6) out.push_back(part + " narrower than 3 m");
      const double h = p.size(2) / site.storeyHeight, z = (p.lo[2] - site.base) / site.storeyHeight;
      if (std::abs(h - std::round(h)) > 1e-6 || std::abs(z - std::round(z)) > 1e-6 || std::round(h) < 1 ||
          std::round(h) > 2)
        out.push_back(part + " not one or two storeys on a storey level");
      for (std::size_t c = 0; c < site.cores.size(); ++c)
        if (gapInPlan(p, site.coreBox(c)) < site.coreClearance - 1e-6) out.push_back(part + " too near a core");
      for (const Box& c : site.circulation)
        if (gapInPlan(p, c) < site.circulationClearance - 1e-6 || overlaps(p, c))
          out.push_back(part + " too near circulation");
      for (std::size_t k = i; k < units.size(); ++k)
        for (std::size_t l = (k == i ? j + 1 : 0); l < units[k].parts.size(); ++l)
          if (overlaps(p, units[k].parts[l])) out.push_back(part + " overlaps unit " + std::to_string(units[k].id));
      // Cantilever: sample the footprint every 0.25 m, edges included.
      const int nx = int(std::ceil(p.size(0) / 0.25)), ny = int(std::ceil(p.size(1) / 0.25));
      bool held = true;
      for (int a = 0; a <= nx && held; ++a)
        for (int b = 0; b <= ny && held; ++b)
          held = supportedPoint(site, units, i, p.lo[0] + p.size(0) * a / nx, p.lo[1] + p.size(1) * b / ny);
      if (!held) out.push_back(part + " reaches beyond its supports");
    }
    if (zmax - zmin > 2 * site.storeyHeight + 1e-6) out.push_back(name + " spans more than two storeys");
  }
  return out;
}

}  // namespace corbel::growth::test
