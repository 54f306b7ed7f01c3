#include "editor/plan_crossings.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace corbel::editor {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
double dot2(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

// Where segments pq and rs meet (a point of their overlap when collinear), or none. `eps`
// scales with the plan so a corner lying on an edge counts as touching it.
std::optional<Vec2> meet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s, double eps) {
  const Vec2 d1 = q - p, d2 = s - r;
  const double denom = cross(d1, d2);
  const double l1 = std::sqrt(dot2(d1, d1)), l2 = std::sqrt(dot2(d2, d2));
  if (l1 == 0 || l2 == 0) return std::nullopt;
  if (std::abs(denom) > eps * l1 * l2) {
    const double t = cross(r - p, d2) / denom, u = cross(r - p, d1) / denom;
    const double et = eps / l1, eu = eps / l2;
    if (t < -et || t > 1 + et || u < -eu || u > 1 + eu) return std::nullopt;
    return p + d1 * std::clamp(t, 0.0, 1.0);
  }
  // Parallel: they meet only when collinear and overlapping.
  if (std::abs(cross(r - p, d1)) > eps * l1) return std::nullopt;
  const double a = dot2(r - p, d1) / (l1 * l1), b = dot2(s - p, d1) / (l1 * l1);
  const double lo = std::max(0.0, std::min(a, b)), hi = std::min(1.0, std::max(a, b));
  if (lo > hi + eps / l1) return std::nullopt;
  return p + d1 * (0.5 * (lo + hi));
}

}  // namespace

std::vector<PlanCrossing> planCrossings(const std::vector<std::vector<Vec2>>& loops) {
  double extent = 0;
  for (const auto& l : loops)
    for (const Vec2& v : l) extent = std::max({extent, std::abs(v[0]), std::abs(v[1])});
  const double eps = 1e-9 * std::max(1.0, extent);
  std::vector<PlanCrossing> out;
  for (int la = 0; la < int(loops.size()); ++la) {
    const auto& A = loops[la];
    const int na = int(A.size());
    if (na < 2) continue;
    for (int ea = 0; ea < na; ++ea) {
      for (int lb = la; lb < int(loops.size()); ++lb) {
        const auto& B = loops[lb];
        const int nb = int(B.size());
        if (nb < 2) continue;
        for (int eb = lb == la ? ea + 1 : 0; eb < nb; ++eb) {
          const Vec2 &p = A[ea], &q = A[(ea + 1) % na], &r = B[eb], &s = B[(eb + 1) % nb];
          const bool next = lb == la && (eb == (ea + 1) % na), prev = lb == la && (ea == (eb + 1) % nb);
          if (next || prev) {
            // Neighbours share a corner; they cross only where one turns back along the other.
            const Vec2 shared = next ? q : p, u = (next ? p : q) - shared, v = (next ? s : r) - shared;
            const double lu = std::sqrt(dot2(u, u)), lv = std::sqrt(dot2(v, v));
            if (lu > 0 && lv > 0 && std::abs(cross(u, v)) <= eps * lu * lv && dot2(u, v) > 0)
              out.push_back({la, ea, lb, eb, shared + (lu < lv ? u : v) * 0.5});
            continue;
          }
          if (const auto at = meet(p, q, r, s, eps)) out.push_back({la, ea, lb, eb, *at});
        }
      }
    }
  }
  return out;
}

}  // namespace corbel::editor
