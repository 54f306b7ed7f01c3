// Geometry sizing (Sec. 7.3.4). See sizing.h.
#include "growth/sizing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace corbel::growth {

namespace {

struct Score {
  double worst = 0, squares = 0;
  bool operator<(const Score& o) const {
    if (worst < o.worst - 1e-12) return true;
    if (worst > o.worst + 1e-12) return false;
    return squares < o.squares - 1e-12;
  }
};

double target(const Cartogram& c) {
  const double box = (c.xs.back() - c.xs.front()) * (c.ys.back() - c.ys.front());
  return box / std::max(1, c.subUnits());
}

double rectError(const Cartogram& c, int i, double M, double m) {
  const double a = c.geometry(i).area();
  return c.rects[std::size_t(i)].unit >= 0 ? std::abs(a - M) / M : std::max(0.0, a - m) / M;
}

Score score(const Cartogram& c, double M, double m) {
  Score s;
  for (int i = 0; i < int(c.rects.size()); ++i) {
    const double e = rectError(c, i, M, m);
    if (c.rects[std::size_t(i)].unit >= 0) s.worst = std::max(s.worst, e);
    s.squares += e * e;
  }
  return s;
}

}  // namespace

double maxAreaError(const Cartogram& c) {
  const double M = target(c);
  double worst = 0;
  for (int i = 0; i < int(c.rects.size()); ++i)
    if (c.rects[std::size_t(i)].unit >= 0) worst = std::max(worst, std::abs(c.geometry(i).area() - M) / M);
  return worst;
}

SizingResult sizeGeometry(Cartogram& c, const SizingOptions& o) {
  SizingResult out;
  const double M = target(c), m = o.seaShare * M;
  out.before = maxAreaError(c);
  Score now = score(c, M, m);
  double delta = 0.25 * std::min((c.xs.back() - c.xs.front()) / double(c.xs.size()), (c.ys.back() - c.ys.front()) / double(c.ys.size()));
  const double stop = 1e-4 * std::max(c.xs.back() - c.xs.front(), c.ys.back() - c.ys.front());
  while (out.passes < o.maxPasses && delta > stop) {
    ++out.passes;
    // Lines touching the worst rectangles first.
    std::vector<int> order(c.rects.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> err(c.rects.size());
    for (int i = 0; i < int(c.rects.size()); ++i) err[std::size_t(i)] = rectError(c, i, M, m);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return err[std::size_t(a)] > err[std::size_t(b)]; });
    std::vector<std::pair<int, int>> lines;  // (axis, index)
    for (int i : order) {
      const Cartogram::Rect& r = c.rects[std::size_t(i)];
      for (auto line : {std::pair{0, r.x0}, std::pair{0, r.x1}, std::pair{1, r.y0}, std::pair{1, r.y1}})
        if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
    }
    bool moved = false;
    for (const auto& [axis, idx] : lines) {
      std::vector<double>& v = axis == 0 ? c.xs : c.ys;
      if (idx == 0 || idx + 1 == int(v.size())) continue;
      const double lo = v[std::size_t(idx - 1)] + o.minWidth, hi = v[std::size_t(idx + 1)] - o.minWidth;
      const double was = v[std::size_t(idx)];
      double bestAt = was;
      Score best = now;
      for (double step : {delta, -delta}) {
        const double at = std::clamp(was + step, lo, hi);
        if (at == was || !(lo <= hi)) continue;
        v[std::size_t(idx)] = at;
        const Score s = score(c, M, m);
        if (s < best) best = s, bestAt = at;
      }
      v[std::size_t(idx)] = bestAt;
      if (bestAt != was) now = best, moved = true, ++out.moves;
    }
    if (!moved) delta *= 0.5;
  }
  out.after = maxAreaError(c);
  return out;
}

void fitToRegion(Cartogram& c, const PlanRect& region) {
  auto stretch = [](std::vector<double>& v, double a, double b) {
    const double v0 = v.front(), v1 = v.back();
    for (double& x : v) x = a + (b - a) * (x - v0) / (v1 - v0);
    v.front() = a;
    v.back() = b;
  };
  stretch(c.xs, region.x0, region.x1);
  stretch(c.ys, region.y0, region.y1);
}

std::vector<Unit> sizedUnits(const Cartogram& c, int units, double z0, double storeyHeight) {
  std::vector<Unit> out(std::size_t(std::max(0, units)));
  for (int u = 0; u < units; ++u) out[std::size_t(u)].id = u + 1;
  for (int i = 0; i < int(c.rects.size()); ++i) {
    const int u = c.rects[std::size_t(i)].unit;
    if (u < 0 || u >= units) continue;
    const PlanRect r = c.geometry(i);
    out[std::size_t(u)].parts.push_back({{r.x0, r.y0, z0}, {r.x1, r.y1, z0 + storeyHeight}});
  }
  return out;
}

}  // namespace corbel::growth
