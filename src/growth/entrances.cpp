#include "growth/entrances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::growth {

namespace {

constexpr double kEps = 1e-9;

struct Interval {
  double lo, hi;
};

// from − [lo, hi]
std::vector<Interval> cut(const std::vector<Interval>& from, double lo, double hi) {
  std::vector<Interval> out;
  for (const Interval& i : from) {
    if (hi <= i.lo + kEps || lo >= i.hi - kEps) {
      out.push_back(i);
      continue;
    }
    if (lo > i.lo + kEps) out.push_back({i.lo, lo});
    if (hi < i.hi - kEps) out.push_back({hi, i.hi});
  }
  return out;
}

bool spansStorey(const Box& b, double zMid) { return b.lo[2] < zMid && b.hi[2] > zMid; }

}  // namespace

std::vector<Entrance> entrancesInRegion(const std::vector<Unit>& units, const PlanRect& region,
                                        const EntranceOptions& options, const std::vector<Box>& obstacles) {
  const double zMid = options.base + (options.storey + 0.5) * options.storeyHeight;
  const double rlo[2] = {region.x0, region.y0}, rhi[2] = {region.x1, region.y1};
  // Everything that can stand right outside a face: every unit's parts and the obstacles on the storey.
  std::vector<Box> solids;
  for (const Unit& u : units)
    for (const Box& b : u.parts)
      if (spansStorey(b, zMid)) solids.push_back(b);
  for (const Box& b : obstacles)
    if (spansStorey(b, zMid)) solids.push_back(b);

  std::vector<Entrance> out;
  for (const Unit& u : units) {
    Entrance best;
    best.unit = u.id;
    for (int p = 0; p < int(u.parts.size()); ++p) {
      const Box& b = u.parts[std::size_t(p)];
      if (!spansStorey(b, zMid)) continue;
      for (Side s : kVerticalSides) {
        if (sideTouchesOwnPart(u, p, s)) continue;
        const int a = sideAxis(s), t = 1 - a;
        const double c = sideCoord(b, s), sign = sideSign(s);
        // On the region's closed extent, and facing into it.
        if (c < rlo[a] - kEps || c > rhi[a] + kEps) continue;
        if (sign > 0 ? c >= rhi[a] - kEps : c <= rlo[a] + kEps) continue;
        const double lo = std::max(b.lo[t], rlo[t]), hi = std::min(b.hi[t], rhi[t]);
        if (hi - lo <= kEps) continue;
        std::vector<Interval> free{{lo, hi}};
        for (const Box& o : solids) {
          // o stands right outside the face: it spans the line c toward the outward side.
          const bool outside = sign > 0 ? (o.lo[a] <= c + kEps && o.hi[a] > c + kEps)
                                        : (o.hi[a] >= c - kEps && o.lo[a] < c - kEps);
          if (outside) free = cut(free, o.lo[t], o.hi[t]);
        }
        for (const Interval& i : free) {
          const double w = i.hi - i.lo;
          if (w < options.minWidth || w <= best.width) continue;
          best.width = w;
          best.facing = s;
          best.at[a] = c;
          best.at[t] = 0.5 * (i.lo + i.hi);
        }
      }
    }
    if (best.width > 0) out.push_back(best);
  }
  if (int(out.size()) > options.maxCount) {
    std::stable_sort(out.begin(), out.end(), [](const Entrance& x, const Entrance& y) { return x.width > y.width; });
    out.resize(std::size_t(std::max(0, options.maxCount)));
    std::sort(out.begin(), out.end(), [](const Entrance& x, const Entrance& y) { return x.unit < y.unit; });
  }
  return out;
}

bool findGap(const std::vector<Unit>& units, const std::vector<Box>& obstacles, const PlanRect& bounds,
             const EntranceOptions& storey, double minSide, double maxSide, PlanRect& gap) {
  const double zMid = storey.base + (storey.storey + 0.5) * storey.storeyHeight;
  const int W = int(std::floor(bounds.x1 - bounds.x0)), H = int(std::floor(bounds.y1 - bounds.y0));
  if (W < 1 || H < 1 || W > 4096 || H > 4096) return false;
  // Occupied cells: a cell is taken when a solid covers any of it.
  std::vector<int> taken(std::size_t(W * H), 0);
  auto mark = [&](const Box& b) {
    if (!spansStorey(b, zMid)) return;
    const int i0 = std::max(0, int(std::floor(b.lo[0] - bounds.x0 + kEps)));
    const int i1 = std::min(W, int(std::ceil(b.hi[0] - bounds.x0 - kEps)));
    const int j0 = std::max(0, int(std::floor(b.lo[1] - bounds.y0 + kEps)));
    const int j1 = std::min(H, int(std::ceil(b.hi[1] - bounds.y0 - kEps)));
    for (int j = j0; j < j1; ++j)
      for (int i = i0; i < i1; ++i) taken[std::size_t(j * W + i)] = 1;
  };
  for (const Unit& u : units)
    for (const Box& b : u.parts) mark(b);
  for (const Box& b : obstacles) mark(b);
  // Prefix sums: S(i, j) = taken cells in [0, i) × [0, j).
  std::vector<int> S(std::size_t((W + 1) * (H + 1)), 0);
  auto at = [&](int i, int j) -> int& { return S[std::size_t(j * (W + 1) + i)]; };
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) at(i + 1, j + 1) = taken[std::size_t(j * W + i)] + at(i, j + 1) + at(i + 1, j) - at(i, j);
  auto count = [&](int i0, int j0, int i1, int j1) {  // clamped to the grid
    i0 = std::clamp(i0, 0, W), i1 = std::clamp(i1, 0, W), j0 = std::clamp(j0, 0, H), j1 = std::clamp(j1, 0, H);
    if (i1 <= i0 || j1 <= j0) return 0;
    return at(i1, j1) - at(i0, j1) - at(i1, j0) + at(i0, j0);
  };
  const int lo = std::max(1, int(std::ceil(minSide))), hi = std::max(lo, int(std::floor(maxSide)));
  long bestScore = -1;
  for (int j0 = 0; j0 < H; ++j0)
    for (int i0 = 0; i0 < W; ++i0)
      for (int w = lo; w <= hi && i0 + w <= W; ++w)
        for (int h = lo; h <= hi && j0 + h <= H; ++h) {
          const int i1 = i0 + w, j1 = j0 + h;
          if (count(i0, j0, i1, j1)) break;  // taller ones hold the same cells
          const long rim = count(i0, j0 - 1, i1, j0) + count(i0, j1, i1, j1 + 1) + count(i0 - 1, j0, i0, j1) +
                           count(i1, j0, i1 + 1, j1);
          const long score = rim * 1000000L + long(w) * h;
          if (score > bestScore) {
            bestScore = score;
            gap = {bounds.x0 + i0, bounds.y0 + j0, bounds.x0 + i1, bounds.y0 + j1};
          }
        }
  if (bestScore < 0) return false;
  // Grid cells are whole meters, faces are not: each side moves out onto the nearest face of a
  // solid in the rim cell beyond it, so the units around the gap face into it (entrancesInRegion).
  // The nearest such face bounds the move, so the gap stays free of solids.
  const double inf = std::numeric_limits<double>::infinity();
  double x0 = -inf, x1 = inf, y0 = -inf, y1 = inf;
  std::vector<Box> solids = obstacles;
  for (const Unit& u : units) solids.insert(solids.end(), u.parts.begin(), u.parts.end());
  for (const Box& b : solids) {
    if (!spansStorey(b, zMid)) continue;
    const bool spansY = b.lo[1] < gap.y1 - kEps && b.hi[1] > gap.y0 + kEps;
    const bool spansX = b.lo[0] < gap.x1 - kEps && b.hi[0] > gap.x0 + kEps;
    if (spansY && b.hi[0] <= gap.x0 + kEps && b.hi[0] > gap.x0 - 1) x0 = std::max(x0, b.hi[0]);
    if (spansY && b.lo[0] >= gap.x1 - kEps && b.lo[0] < gap.x1 + 1) x1 = std::min(x1, b.lo[0]);
    if (spansX && b.hi[1] <= gap.y0 + kEps && b.hi[1] > gap.y0 - 1) y0 = std::max(y0, b.hi[1]);
    if (spansX && b.lo[1] >= gap.y1 - kEps && b.lo[1] < gap.y1 + 1) y1 = std::min(y1, b.lo[1]);
  }
  PlanRect g = gap;
  if (x0 > -inf) g.x0 = x0;
  if (x1 < inf) g.x1 = x1;
  if (y0 > -inf) g.y0 = y0;
  if (y1 < inf) g.y1 = y1;
  gap = g;
  return true;
}

EntranceOptions storeyOptions(const Site& site, int storey) {
  EntranceOptions eo;
  eo.storey = storey;
  eo.base = site.base;
  eo.storeyHeight = site.storeyHeight;
  return eo;
}

std::vector<Box> entranceObstacles(const Site& site) {
  std::vector<Box> obstacles = site.circulation;
  for (std::size_t i = 0; i < site.cores.size(); ++i) obstacles.push_back(site.coreBox(i));
  return obstacles;
}

}  // namespace corbel::growth
