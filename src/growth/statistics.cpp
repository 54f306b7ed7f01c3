#include "growth/statistics.h"

#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>

namespace corbel::growth {

char housingType(double a) {
  if (a > 85) return 'A';
  if (a >= 50) return 'B';
  if (a >= 30) return 'C';
  return '-';
}

int occupantsOf(char type) { return type == 'A' ? 5 : type == 'B' ? 3 : type == 'C' ? 1 : 0; }

namespace {

// The longest unbroken stretch along which the garden (disjoint rectangles) lies against the
// sides of plan rectangle p: pieces of the garden side by side along one side of p add up, as
// a door may straddle the line between them.
double longestContact(const std::vector<Rect>& garden, const Rect& p) {
  double best = 0;
  for (int side = 0; side < 4; ++side) {
    std::vector<std::pair<double, double>> along;
    for (const Rect& g : garden) {
      const bool touches = side == 0   ? std::abs(g.u1 - p.u0) <= kEps
                           : side == 1 ? std::abs(g.u0 - p.u1) <= kEps
                           : side == 2 ? std::abs(g.v1 - p.v0) <= kEps
                                       : std::abs(g.v0 - p.v1) <= kEps;
      if (!touches) continue;
      const double lo = side < 2 ? std::max(g.v0, p.v0) : std::max(g.u0, p.u0);
      const double hi = side < 2 ? std::min(g.v1, p.v1) : std::min(g.u1, p.u1);
      if (hi > lo) along.push_back({lo, hi});
    }
    std::sort(along.begin(), along.end());
    double lo = 0, hi = -1;
    for (const auto& [a, b] : along) {
      if (a > hi + kEps) lo = a;
      hi = std::max(hi, b);
      best = std::max(best, hi - lo);
    }
  }
  return best;
}

}  // namespace

bool hasOutdoorSpace(const Site& site, const std::vector<Unit>& units, std::size_t unit) {
  // Everything that can stand on a roof: every part, core and circulation box.
  std::vector<Box> solids;
  for (const Unit& u : units) solids.insert(solids.end(), u.parts.begin(), u.parts.end());
  for (std::size_t i = 0; i < site.cores.size(); ++i) solids.push_back(site.coreBox(i));
  solids.insert(solids.end(), site.circulation.begin(), site.circulation.end());
  for (std::size_t v = 0; v < units.size(); ++v) {
    if (v == unit) continue;
    for (const Box& roof : units[v].parts) {
      const double z = roof.hi[2];
      bool atFloor = false;
      for (const Box& p : units[unit].parts) atFloor = atFloor || std::abs(p.lo[2] - z) <= kEps;
      if (!atFloor) continue;
      // A garden lies on the roof, so a roof that meets none of the unit's parts at z cannot
      // give one; and only solids over the roof can take from it.
      const Rect top = footprint(roof);
      Rect x;
      bool near = false;
      for (const Box& p : units[unit].parts)
        near = near || (std::abs(p.lo[2] - z) <= kEps && intersect(grown(top, 2 * kEps), footprint(p), true, x));
      if (!near) continue;
      std::vector<Rect> garden{top};
      for (const Box& s : solids)
        if (s.lo[2] <= z + kEps && s.hi[2] > z + kEps && intersect(top, footprint(s), false, x))
          garden = subtract(garden, footprint(s));
      if (totalArea(garden) < kMinGardenArea) continue;
      for (const Box& p : units[unit].parts)
        if (std::abs(p.lo[2] - z) <= kEps && longestContact(garden, footprint(p)) >= kMinDoorWidth - kEps) return true;
    }
  }
  return false;
}

Statistics computeStatistics(const Site& site, const std::vector<Unit>& units, const ViewMaps& views) {
  Statistics st;
  st.siteArea = site.area();
  st.storeys = site.storeys;
  st.units = int(units.size());
  double viewSum = 0, areaSum = 0;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const Unit& u = units[i];
    UnitStatistics us;
    us.id = u.id;
    us.floorArea = u.floorArea();
    us.volume = u.volume();
    for (ViewDirection d : kViewDirections) {
      const double a = views.view(std::uint32_t(u.id), d);
      us.viewByDirection[int(d)] = a;
      us.view += a;
      if (a >= kMinViewArea) ++us.views;
    }
    us.type = housingType(us.floorArea);
    for (const Box& p : u.parts) us.doubleVolume = us.doubleVolume || p.size(2) > 1.5 * site.storeyHeight;
    us.outdoorSpace = hasOutdoorSpace(site, units, i);
    st.occupants += occupantsOf(us.type);
    (us.type == 'A' ? st.typeA : us.type == 'B' ? st.typeB : us.type == 'C' ? st.typeC : st.unclassified)++;
    if (us.views == 2) ++st.twoViews;
    if (us.views == 3) ++st.threeViews;
    if (us.views == 4) ++st.fourViews;
    if (us.doubleVolume) ++st.doubleVolume;
    if (us.outdoorSpace) ++st.outdoorSpace;
    viewSum += us.view;
    areaSum += us.floorArea;
    st.perUnit.push_back(us);
  }
  if (!units.empty()) {
    st.averageView = viewSum / units.size();
    st.averageFloorArea = areaSum / units.size();
  }
  st.occupancyRatio = st.occupants / (st.siteArea * site.storeys);
  return st;
}

}  // namespace corbel::growth
