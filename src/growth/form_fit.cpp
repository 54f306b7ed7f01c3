#include "growth/form_fit.h"

#include "core/error.h"
#include "growth/constraints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

namespace corbel::growth {

namespace {

// Distance from a point to a plan rectangle (0 inside).
double distanceTo(const PlanRect& r, const Vec2& p) {
  const double dx = std::max({0.0, r.x0 - p[0], p[0] - r.x1});
  const double dy = std::max({0.0, r.y0 - p[1], p[1] - r.y1});
  return std::hypot(dx, dy);
}

// The region's side nearest to p: 0 south (y0), 1 east (x1), 2 north (y1), 3 west (x0).
int nearestSide(const PlanRect& region, const Vec2& p) {
  const double cx = std::clamp(p[0], region.x0, region.x1), cy = std::clamp(p[1], region.y0, region.y1);
  const std::array<double, 4> d{std::hypot(cx - p[0], region.y0 - p[1]), std::hypot(region.x1 - p[0], cy - p[1]),
                                std::hypot(cx - p[0], region.y1 - p[1]), std::hypot(region.x0 - p[0], cy - p[1])};
  return int(std::min_element(d.begin(), d.end()) - d.begin());
}

// Along a side: axis 0 (x) for south and north, 1 (y) for east and west.
int alongAxis(int side) { return side == 0 || side == 2 ? 0 : 1; }

// Whether a rectangle lies on the side, and its span along it.
bool onSide(const PlanRect& r, const PlanRect& region, int side, double& a, double& b) {
  const bool on = side == 0   ? r.y0 == region.y0
                  : side == 1 ? r.x1 == region.x1
                  : side == 2 ? r.y1 == region.y1
                              : r.x0 == region.x0;
  a = alongAxis(side) == 0 ? r.x0 : r.y0;
  b = alongAxis(side) == 0 ? r.x1 : r.y1;
  return on;
}

// The corners of a rectangle on a side, at the low and the high end along it (0 SW, 1 SE, 2 NE, 3 NW).
std::pair<int, int> sideCorners(int side) {
  switch (side) {
    case 0:
      return {0, 1};
    case 1:
      return {1, 2};
    case 2:
      return {3, 2};
    default:
      return {0, 3};
  }
}

// What it costs unit u to take an entrance at p: the distance along the region's side from the
// door to the unit's nearest stretch of that side (0 when it covers the door), or, for a unit
// that does not reach that side (its entrance could not be realized), the region's perimeter
// plus its distance to p.
double entranceCost(const Layout& l, const PlanRect& region, int u, const Vec2& p, double doorWidth) {
  const int side = nearestSide(region, p);
  const int axis = alongAxis(side);
  const double lo = axis == 0 ? region.x0 : region.y0, hi = axis == 0 ? region.x1 : region.y1;
  const double d = std::min(doorWidth, hi - lo);
  const double t = std::clamp(p[std::size_t(axis)], lo + d / 2, hi - d / 2);
  double along = std::numeric_limits<double>::infinity(), away = along;
  for (std::size_t i = 0; i < l.rects.size(); ++i) {
    if (l.unit[i] != u) continue;
    double a, b;
    if (onSide(l.rects[i], region, side, a, b))
      along = std::min(along, std::max({0.0, a - (t - d / 2), (t + d / 2) - b}));
    away = std::min(away, distanceTo(l.rects[i], p));
  }
  if (std::isfinite(along)) return along;
  return 2 * ((region.x1 - region.x0) + (region.y1 - region.y0)) + away;
}

// Each entrance to a different unit at the least total cost (returned, with Σ distance): exact by
// dynamic programming over the sets of units taken (forms have at most 12 units, and entrances
// are at most 12), an entrance left over costing more than any unit could; greedy, cheapest
// pairs first, beyond 16 of either.
double assign(const Layout& l, const PlanRect& region, int units, const std::vector<Vec2>& entrances, double doorWidth,
              std::vector<int>& entranceOf, double* distance = nullptr) {
  entranceOf.assign(std::size_t(units), -1);
  const std::size_t E = entrances.size(), U = std::size_t(units);
  std::vector<std::vector<double>> c(E, std::vector<double>(U));
  for (std::size_t e = 0; e < E; ++e)
    for (std::size_t u = 0; u < U; ++u) c[e][u] = entranceCost(l, region, int(u), entrances[e], doorWidth);
  const double leftOver = 4 * (2 * ((region.x1 - region.x0) + (region.y1 - region.y0))) + 1;
  std::vector<int> unitOf(E, -1);
  if (E <= 16 && U <= 16) {
    const std::size_t masks = std::size_t(1) << U;
    const double inf = std::numeric_limits<double>::infinity();
    // best[e][mask]: entrances e.. assigned given the units in mask are taken; choice to rebuild.
    std::vector<std::vector<double>> best(E + 1, std::vector<double>(masks, inf));
    std::vector<std::vector<int>> choice(E + 1, std::vector<int>(masks, -1));
    for (std::size_t m = 0; m < masks; ++m) best[E][m] = 0;
    for (std::size_t e = E; e-- > 0;)
      for (std::size_t m = 0; m < masks; ++m) {
        double b = leftOver + best[e + 1][m];
        int ch = -1;
        for (std::size_t u = 0; u < U; ++u)
          if (!(m >> u & 1) && c[e][u] + best[e + 1][m | (std::size_t(1) << u)] < b - 1e-12)
            b = c[e][u] + best[e + 1][m | (std::size_t(1) << u)], ch = int(u);
        best[e][m] = b;
        choice[e][m] = ch;
      }
    std::size_t m = 0;
    for (std::size_t e = 0; e < E; ++e)
      if ((unitOf[e] = choice[e][m]) >= 0) m |= std::size_t(1) << unitOf[e];
  } else {
    std::vector<bool> taken(E, false), used(U, false);
    for (std::size_t round = 0; round < std::min(E, U); ++round) {
      double b = std::numeric_limits<double>::infinity();
      std::size_t be = 0, bu = 0;
      for (std::size_t e = 0; e < E; ++e)
        if (!taken[e])
          for (std::size_t u = 0; u < U; ++u)
            if (!used[u] && c[e][u] < b) b = c[e][u], be = e, bu = u;
      taken[be] = used[bu] = true;
      unitOf[be] = int(bu);
    }
  }
  double total = 0;
  if (distance) *distance = 0;
  for (std::size_t e = 0; e < E; ++e) {
    if (unitOf[e] < 0) {
      total += leftOver;
      continue;
    }
    entranceOf[std::size_t(unitOf[e])] = int(e);
    total += c[e][std::size_t(unitOf[e])];
    if (distance) {
      double away = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < l.rects.size(); ++i)
        if (l.unit[i] == unitOf[e]) away = std::min(away, distanceTo(l.rects[i], entrances[e]));
      *distance += away;
    }
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

Correspondence cornerTo(const std::vector<PlanRect>& rects, int rect, int corner, int axis, double along) {
  const auto at = cornerAt(rects, {rect, corner});
  Correspondence c{{rect, corner}, at[0], at[1]};
  (axis == 0 ? c.x : c.y) = along;
  return c;
}

// Realizes each taken entrance in turn (Sec. 7.3.3): the unit's rectangle on the entrance's side
// nearest to it is widened along the side until it covers the door, by realizeBySegments; the
// corners of doors already realized are held where they are, so a later move cannot undo them.
std::vector<EntranceFit> realizeEntrances(Layout& l, const PlanRect& region, const std::vector<Vec2>& entrances,
                                          const std::vector<int>& entranceOf, double doorWidth, double minWidth) {
  std::vector<EntranceFit> fits;
  for (std::size_t u = 0; u < entranceOf.size(); ++u) {
    if (entranceOf[u] < 0) continue;
    EntranceFit f;
    f.unit = int(u);
    f.entrance = entranceOf[u];
    const Vec2 p = entrances[std::size_t(f.entrance)];
    f.side = nearestSide(region, p);
    const int axis = alongAxis(f.side);
    const double lo = axis == 0 ? region.x0 : region.y0, hi = axis == 0 ? region.x1 : region.y1;
    const double d = std::min(doorWidth, hi - lo);
    const double t = std::clamp(p[std::size_t(axis)], lo + d / 2, hi - d / 2);
    f.from = t - d / 2;
    f.to = t + d / 2;
    fits.push_back(f);
  }
  // Doors their units already cover first: they are held from the start.
  auto covering = [&](const EntranceFit& f, double& a, double& b) {
    int best = -1;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < l.rects.size(); ++i) {
      double ra, rb;
      if (l.unit[i] != f.unit || !onSide(l.rects[i], region, f.side, ra, rb)) continue;
      const double g = std::max({0.0, ra - f.from, f.to - rb});
      if (g < gap) gap = g, best = int(i), a = ra, b = rb;
    }
    return std::make_pair(best, gap);
  };
  std::stable_sort(fits.begin(), fits.end(), [&](const EntranceFit& x, const EntranceFit& y) {
    double a, b;
    return covering(x, a, b).second < covering(y, a, b).second;
  });
  const double tol = 1e-9 * std::max(region.x1 - region.x0, region.y1 - region.y0);
  std::vector<Correspondence> held;
  for (EntranceFit& f : fits) {
    double a = 0, b = 0;
    const auto [rect, gap] = covering(f, a, b);
    const auto [cLo, cHi] = sideCorners(f.side);
    const int axis = alongAxis(f.side);
    if (rect < 0) {
      f.why = "unit " + std::to_string(f.unit + 1) + " does not reach the region's side where its entrance is";
      continue;
    }
    if (gap > tol) {
      std::vector<Correspondence> targets = held;
      if (a > f.from) targets.push_back(cornerTo(l.rects, rect, cLo, axis, f.from));
      if (b < f.to) targets.push_back(cornerTo(l.rects, rect, cHi, axis, f.to));
      std::string why;
      if (!realizeBySegments(l, targets, minWidth, &why)) {
        f.why = "unit " + std::to_string(f.unit + 1) + " cannot be widened to its entrance: " + why;
        continue;
      }
      f.moved = true;
    }
    f.realized = true;
    for (int c : {cLo, cHi}) {
      const auto at = cornerAt(l.rects, {rect, c});
      held.push_back({{rect, c}, at[0], at[1]});
    }
  }
  return fits;
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
  if (!(options.doorWidth > 0) || !std::isfinite(options.doorWidth))
    throw InputError("doorWidth", "expected a positive width in metres");
  for (const Vec2& e : entrances)
    if (!std::isfinite(e[0]) || !std::isfinite(e[1])) throw InputError("entrances", "expected finite points");
  const Layout grid = Layout::of(Cartogram::of(plan));

  FittedForm out;
  const double minWidth = std::min(0.5, 0.05 * std::min(region.x1 - region.x0, region.y1 - region.y0));
  SizingOptions so;
  so.minWidth = minWidth;
  so.roomWidth = options.roomWidth;
  // With a room width every orientation is sized and the one whose rooms fall least short of
  // it wins (a form laid across a shallow region has rooms a metre wide); then the entrances.
  const bool byRooms = options.size && options.roomWidth > 0;
  double bestShort = std::numeric_limits<double>::infinity(), bestCost = bestShort;
  const int first = options.orientation >= 0 ? options.orientation : 0;
  const int last = options.orientation >= 0 ? options.orientation : (entrances.empty() && !byRooms ? 0 : 7);
  for (int g = first; g <= last; ++g) {
    Layout l = laidOut(grid, g, region);
    SizingResult sized;
    if (byRooms) sized = sizeGeometry(l, so);
    const double shortfall = byRooms ? roomShortfall(l, options.roomWidth) : 0.0;
    std::vector<int> taken;
    const double cost = assign(l, region, n, entrances, options.doorWidth, taken);
    if (shortfall < bestShort - 1e-9 || (shortfall < bestShort + 1e-9 && cost < bestCost - 1e-9)) {
      bestShort = shortfall;
      bestCost = cost;
      out.layout = std::move(l);
      out.orientation = g;
      out.sizing = sized;
    }
  }
  if (options.size && !byRooms) out.sizing = sizeGeometry(out.layout, so);
  out.entranceCost = assign(out.layout, region, n, entrances, options.doorWidth, out.entranceOf, &out.entranceDistance);
  if (options.realizeEntrances && !entrances.empty())
    out.entranceFits = realizeEntrances(out.layout, region, entrances, out.entranceOf, options.doorWidth, minWidth);
  out.areaError = maxAreaError(out.layout);
  out.units = sizedUnits(out.layout, n, options.z0, options.storeyHeight);
  return out;
}

std::vector<std::string> formViolations(const Site& site, const std::vector<Unit>& units, const FittedForm& form) {
  const ConstraintEnforcer rules(site);
  int maxId = 0;
  for (const Unit& u : units) maxId = std::max(maxId, u.id);
  // The form's units first, so a clash between one and a model's unit is reported as the form's.
  std::vector<Unit> all;
  for (const Unit& u : form.units) {
    all.push_back(u);
    all.back().id = maxId + u.id;
  }
  all.insert(all.end(), units.begin(), units.end());
  std::set<std::string> before;  // what the model breaks on its own is not the form's
  for (std::string& v : rules.violations(units)) before.insert(std::move(v));
  std::vector<std::string> out;
  for (std::string& v : rules.violations(all)) {
    if (before.count(v)) continue;
    // "unit N ..." of a form unit → "form unit K ..."
    if (v.rfind("unit ", 0) == 0) {
      const std::size_t end = v.find_first_not_of("0123456789", 5);
      const int id = std::stoi(v.substr(5, end - 5));
      if (id > maxId) v = "form unit " + std::to_string(id - maxId) + v.substr(end);
    }
    out.push_back(std::move(v));
  }
  return out;
}

int bestFit(const std::vector<FittedForm>& forms, const std::vector<bool>& fits) {
  auto met = [](const FittedForm& f) {
    return std::count_if(f.entranceFits.begin(), f.entranceFits.end(), [](const EntranceFit& e) { return e.realized; });
  };
  int best = -1;
  for (std::size_t k = 0; k < forms.size() && k < fits.size(); ++k) {
    if (!fits[k]) continue;
    if (best < 0) {
      best = int(k);
      continue;
    }
    const FittedForm& a = forms[k];
    const FittedForm& b = forms[std::size_t(best)];
    if (met(a) > met(b) || (met(a) == met(b) && a.areaError < b.areaError)) best = int(k);
  }
  return best;
}

}  // namespace corbel::growth
