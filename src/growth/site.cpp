#include "growth/site.h"

#include "core/error.h"
#include "growth/tolerances.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>

namespace corbel::growth {

std::vector<Vec2> rectanglePlan(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

Box Site::seedBox(std::size_t i) const {
  const Seed& s = seeds[i];
  const double z = base + s.storey * storeyHeight;
  return {{s.at[0], s.at[1], z}, {s.at[0] + s.size[0], s.at[1] + s.size[1], z + storeyHeight}};
}

Box Site::bounds() const {
  Box b{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), base},
        {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), top()}};
  for (const Vec2& p : plan)
    for (int k = 0; k < 2; ++k) {
      b.lo[k] = std::min(b.lo[k], p[k]);
      b.hi[k] = std::max(b.hi[k], p[k]);
    }
  return b;
}

double Site::area() const {
  double a = 0;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Vec2& p = plan[i];
    const Vec2& q = plan[(i + 1) % plan.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return std::abs(a) / 2;
}

namespace {

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.sqrnorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + ab * t)).norm();
}

// Inside or on the boundary (within kEps).
bool polygonContains(const std::vector<Vec2>& poly, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if (pointSegmentDistance(p, poly[j], poly[i]) <= kEps) return true;
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) inside = !inside;
  }
  return inside;
}

// Whether segment ab passes through the open rectangle r (Liang–Barsky clipping).
bool segmentCrossesInterior(const Vec2& a, const Vec2& b, const Rect& r) {
  double t0 = 0, t1 = 1;
  const double d[2] = {b[0] - a[0], b[1] - a[1]};
  const double lo[2] = {r.u0, r.v0}, hi[2] = {r.u1, r.v1};
  for (int k = 0; k < 2; ++k) {
    const double pLo = -d[k], qLo = a[k] - lo[k];
    const double pHi = d[k], qHi = hi[k] - a[k];
    for (auto [p, q] : {std::pair{pLo, qLo}, std::pair{pHi, qHi}}) {
      if (p == 0) {
        if (q <= 0) return false;  // parallel and outside (or on) this slab's boundary
      } else {
        const double t = q / p;
        if (p < 0)
          t0 = std::max(t0, t);
        else
          t1 = std::min(t1, t);
      }
    }
  }
  return t1 - t0 > 1e-12;
}

[[noreturn]] void bad(const std::string& where, const std::string& reason) { throw InputError(where, reason); }

void finite(const std::string& where, double v) {
  if (!std::isfinite(v)) bad(where, "is not a finite number");
}

}  // namespace

bool Site::planContains(const Rect& r) const {
  const Rect inner{r.u0 + kEps, r.v0 + kEps, r.u1 - kEps, r.v1 - kEps};
  for (const Vec2& c : {Vec2(r.u0, r.v0), Vec2(r.u1, r.v0), Vec2(r.u1, r.v1), Vec2(r.u0, r.v1)})
    if (!polygonContains(plan, c)) return false;
  if (inner.u0 >= inner.u1 || inner.v0 >= inner.v1) return true;
  for (std::size_t i = 0; i < plan.size(); ++i)
    if (segmentCrossesInterior(plan[i], plan[(i + 1) % plan.size()], inner)) return false;
  return true;
}

bool Site::contains(const Box& b) const {
  return b.lo[2] >= base - kEps && b.hi[2] <= top() + kEps && planContains(footprint(b));
}

void validateSite(const Site& site) {
  finite("base", site.base);
  finite("storey_height", site.storeyHeight);
  if (!(site.storeyHeight > 0)) bad("storey_height", "must be positive");
  if (site.storeys < 1) bad("storeys", "must be at least 1");
  finite("alpha", site.alpha);
  if (site.alpha < kMinAlpha || site.alpha > kMaxAlpha)
    bad("alpha", "Face Advance distance must lie in [0.2, 0.5] m (Sec. 5.1)");
  for (auto [name, v] :
       {std::pair{"clearance.core", site.coreClearance}, std::pair{"clearance.circulation", site.circulationClearance},
        std::pair{"cantilever", site.cantilever}}) {
    finite(name, v);
    if (v < 0) bad(name, "must not be negative");
  }
  if (site.plan.size() < 3) bad("envelope", "needs a plan of at least 3 corners");
  for (std::size_t i = 0; i < site.plan.size(); ++i)
    for (int k = 0; k < 2; ++k) finite("envelope.polygon[" + std::to_string(i) + "]", site.plan[i][k]);
  if (!(site.area() > 0)) bad("envelope", "has no area");
  if (site.plan.size() > 3) {
    // Exact predicates: whether two edges cross is an orientation question.
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> pts;
    for (const Vec2& p : site.plan) pts.emplace_back(p[0], p[1]);
    if (!CGAL::is_simple_2(pts.begin(), pts.end(), K()))
      bad("envelope.polygon", "is not a simple polygon (two edges cross or touch, or a corner repeats)");
  }

  for (std::size_t i = 0; i < site.cores.size(); ++i) {
    const std::string where = "cores[" + std::to_string(i) + "]";
    const Rect& c = site.cores[i];
    for (double v : {c.u0, c.v0, c.u1, c.v1}) finite(where, v);
    if (!(c.u1 > c.u0 && c.v1 > c.v0)) bad(where + ".size", "must be positive");
    if (!site.planContains(c)) bad(where, "lies outside the site envelope");
    for (std::size_t j = 0; j < i; ++j) {
      Rect x;
      if (intersect(c, site.cores[j], false, x) && x.u1 - x.u0 > kEps && x.v1 - x.v0 > kEps)
        bad(where, "overlaps cores[" + std::to_string(j) + "]");
    }
  }
  for (std::size_t i = 0; i < site.circulation.size(); ++i) {
    const std::string where = "circulation[" + std::to_string(i) + "]";
    const Box& b = site.circulation[i];
    for (int k = 0; k < 3; ++k) {
      finite(where, b.lo[k]);
      finite(where, b.hi[k]);
    }
    if (!(b.size(0) > 0 && b.size(1) > 0 && b.size(2) > 0)) bad(where + ".size", "must be positive");
    if (!site.contains(b)) bad(where, "lies outside the site envelope");
    // A landing may touch a core (its lift door opens onto it), so the core's clearance, which
    // keeps units off a core, does not apply here: only a shared interior is refused.
    for (std::size_t j = 0; j < site.cores.size(); ++j)
      if (interiorsOverlap(b, site.coreBox(j), kEps)) bad(where, "overlaps cores[" + std::to_string(j) + "]");
  }
  for (std::size_t i = 0; i < site.seeds.size(); ++i) {
    const std::string where = "seeds[" + std::to_string(i) + "]";
    const Seed& s = site.seeds[i];
    for (int k = 0; k < 2; ++k) {
      finite(where + ".at", s.at[k]);
      finite(where + ".size", s.size[k]);
    }
    finite(where + ".target_area", s.targetArea);
    finite(where + ".target_volume", s.targetVolume);
    if (s.size[0] < kMinPartWidth - kEps || s.size[1] < kMinPartWidth - kEps)
      bad(where + ".size", "a seed is at least 3 m x 3 m (Sec. 5.3)");
    if (s.storey < 0 || s.storey >= site.storeys)
      bad(where + ".storey", "must lie in 0.." + std::to_string(site.storeys - 1));
    if (s.targetArea < 0 || s.targetVolume < 0) bad(where, "targets must not be negative");
    if ((s.targetArea > 0) == (s.targetVolume > 0)) bad(where, "needs exactly one of target_area and target_volume");
    const Box b = site.seedBox(i);
    if (!site.contains(b)) bad(where + ".at", "the seed lies outside the site envelope");
    for (std::size_t j = 0; j < site.cores.size(); ++j)
      if (interiorsOverlap(b, grownInPlan(site.coreBox(j), site.coreClearance), kEps))
        bad(where, "lies within the clearance of cores[" + std::to_string(j) + "]");
    for (std::size_t j = 0; j < site.circulation.size(); ++j)
      if (interiorsOverlap(b, grownInPlan(site.circulation[j], site.circulationClearance), kEps))
        bad(where, "overlaps (or lies within the clearance of) circulation[" + std::to_string(j) + "]");
    for (std::size_t j = 0; j < i; ++j)
      if (interiorsOverlap(b, site.seedBox(j), kEps)) bad(where, "overlaps seeds[" + std::to_string(j) + "]");
    for (const Site::FixedUnit& f : site.fixed)
      for (const Box& p : f.parts)
        if (interiorsOverlap(b, p, kEps)) bad(where, "overlaps the unit \"" + f.name + "\" already there");
  }
  for (const Site::FixedUnit& f : site.fixed) {
    if (f.parts.empty()) bad("unit \"" + f.name + "\"", "has no parts");
    for (const Box& p : f.parts) {
      for (int k = 0; k < 3; ++k) {
        finite("unit \"" + f.name + "\"", p.lo[k]);
        finite("unit \"" + f.name + "\"", p.hi[k]);
      }
      if (!(p.size(0) > 0 && p.size(1) > 0 && p.size(2) > 0)) bad("unit \"" + f.name + "\"", "a part has no volume");
    }
  }
}

}  // namespace corbel::growth
