#include "growth/form_fit.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::growth {

namespace {

// Distance from a point to a plan rectangle (0 inside).
double distanceTo(const PlanRect& r, const Vec2& p) {
  const double dx = std::max({0.0, r.x0 - p[0], p[0] - r.x1});
  const double dy = std::max({0.0, r.y0 - p[1], p[1] - r.y1});
  return std::hypot(dx, dy);
}

// Each entrance to a different unit, nearest pairs first; returns Σ distance.
double assign(const Layout& l, int units, const std::vector<Vec2>& entrances, std::vector<int>& entranceOf) {
  entranceOf.assign(std::size_t(units), -1);
  std::vector<std::vector<double>> d(entrances.size(), std::vector<double>(std::size_t(units),
                                                                           std::numeric_limits<double>::infinity()));
  for (std::size_t i = 0; i < l.rects.size(); ++i)
    if (l.unit[i] >= 0 && l.unit[i] < units)
      for (std::size_t e = 0; e < entrances.size(); ++e)
        d[e][std::size_t(l.unit[i])] = std::min(d[e][std::size_t(l.unit[i])], distanceTo(l.rects[i], entrances[e]));
  std::vector<bool> taken(entrances.size(), false);
  double total = 0;
  for (std::size_t round = 0; round < std::min(entrances.size(), std::size_t(units)); ++round) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t be = 0, bu = 0;
    for (std::size_t e = 0; e < entrances.size(); ++e)
      if (!taken[e])
        for (std::size_t u = 0; u < std::size_t(units); ++u)
          if (entranceOf[u] < 0 && d[e][u] < best) best = d[e][u], be = e, bu = u;
    if (!std::isfinite(best)) break;
    taken[be] = true;
    entranceOf[bu] = int(be);
    total += best;
  }
  return total;
}

// The cartogram's rectangles in `orientation`, their bounding box mapped exactly onto the region.
Layout laidOut(const Layout& grid, int orientation, const PlanRect& region) {
  Layout l = grid;
  double bx0 = std::numeric_limits<double>::infinity(), by0 = bx0, bx1 = -bx0, by1 = -bx0;
  for (PlanRect& r : l.rects) {
    const Vec2 a = orient(orientation, Vec2(r.x0, r.y0)), b = orient(orientation, Vec2(r.x1, r.y1));
    r = {std::min(a[0], b[0]), std::min(a[1], b[1]), std::max(a[0], b[0]), std::max(a[1], b[1])};
    bx0 = std::min(bx0, r.x0), by0 = std::min(by0, r.y0), bx1 = std::max(bx1, r.x1), by1 = std::max(by1, r.y1);
  }
  auto map = [](double v, double v0, double v1, double a, double b) {
    if (v == v0) return a;
    if (v == v1) return b;
    return a + (b - a) * (v - v0) / (v1 - v0);
  };
  for (PlanRect& r : l.rects) {
    r.x0 = map(r.x0, bx0, bx1, region.x0, region.x1);
    r.x1 = map(r.x1, bx0, bx1, region.x0, region.x1);
    r.y0 = map(r.y0, by0, by1, region.y0, region.y1);
    r.y1 = map(r.y1, by0, by1, region.y0, region.y1);
  }
  return l;
}

}  // namespace

Vec2 orient(int orientation, const Vec2& p) {
  Vec2 q = p;
  if (orientation & 4) q[0] = -q[0];
  for (int k = 0; k < (orientation & 3); ++k) q = Vec2(-q[1], q[0]);
  return q;
}

FittedForm fitForm(const Floorplan& plan, const PlanRect& region, const std::vector<Vec2>& entrances,
                   const FitOptions& options) {
  const int n = int(plan.units().size());
  if (n == 0) throw InputError("form", "the form has no units");
  if (!(region.x1 - region.x0 > 0) || !(region.y1 - region.y0 > 0) || !std::isfinite(region.area()))
    throw InputError("region", "expected x0 < x1 and y0 < y1");
  if (options.orientation > 7) throw InputError("orientation", "expected 0 to 7, or -1 to choose");
  const Layout grid = Layout::of(Cartogram::of(plan));

  FittedForm out;
  double bestCost = std::numeric_limits<double>::infinity();
  const int first = options.orientation >= 0 ? options.orientation : 0;
  const int last = options.orientation >= 0 ? options.orientation : (entrances.empty() ? 0 : 7);
  for (int g = first; g <= last; ++g) {
    Layout l = laidOut(grid, g, region);
    std::vector<int> taken;
    const double cost = assign(l, n, entrances, taken);
    if (cost < bestCost - 1e-9) {
      bestCost = cost;
      out.layout = std::move(l);
      out.orientation = g;
    }
  }
  if (options.size) {
    SizingOptions so;
    so.minWidth = std::min(0.5, 0.05 * std::min(region.x1 - region.x0, region.y1 - region.y0));
    out.sizing = sizeGeometry(out.layout, so);
  }
  out.entranceDistance = assign(out.layout, n, entrances, out.entranceOf);
  out.units = sizedUnits(out.layout, n, options.z0, options.storeyHeight);
  return out;
}

}  // namespace corbel::growth
