#include "growth/constraints.h"

#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>

namespace corbel::growth {

std::vector<Box> clearanceZones(const Site& site) {
  std::vector<Box> zones;
  for (std::size_t i = 0; i < site.cores.size(); ++i) zones.push_back(grownInPlan(site.coreBox(i), site.coreClearance));
  for (const Box& c : site.circulation) zones.push_back(grownInPlan(c, site.circulationClearance));
  return zones;
}

namespace {

// Plan grids' cells: a few parts' widths, so a face's neighbourhood is a handful of cells.
constexpr double kGridCell = 8.0;

std::uint64_t partKey(std::size_t unit, std::size_t part) { return (std::uint64_t(unit) << 8) | part; }
std::size_t keyUnit(std::uint64_t key) { return std::size_t(key >> 8); }
std::size_t keyPart(std::uint64_t key) { return std::size_t(key & 0xFF); }

}  // namespace

ConstraintEnforcer::ConstraintEnforcer(const Site& site)
    : site_(site), zones_(clearanceZones(site)), zoneGrid_(footprint(site.bounds()), kGridCell) {
  for (std::size_t z = 0; z < zones_.size(); ++z) zoneGrid_.insert(z, footprint(zones_[z]));
}

void ConstraintEnforcer::circulationNear(const Rect& r, std::vector<std::size_t>& out) const {
  out.clear();
  std::vector<std::uint64_t> keys;
  nearZones(r, keys);
  for (std::uint64_t z : keys)
    if (z >= site_.cores.size()) out.push_back(std::size_t(z - site_.cores.size()));
}

void ConstraintEnforcer::index(const std::vector<Unit>& units) {
  indexed_.units = &units;
  parts_ = PlanGrid(footprint(site_.bounds()), kGridCell);
  indexedParts_.assign(units.size(), 0);
  for (std::size_t i = 0; i < units.size(); ++i) reindex(i);
}

void ConstraintEnforcer::reindex(std::size_t unit) {
  if (!indexed_.units || unit >= indexed_.units->size()) return;
  for (int j = 0; j < indexedParts_[unit]; ++j) parts_.erase(partKey(unit, std::size_t(j)));
  const std::vector<Box>& parts = (*indexed_.units)[unit].parts;
  for (std::size_t j = 0; j < parts.size(); ++j) parts_.insert(partKey(unit, j), footprint(parts[j]));
  indexedParts_[unit] = int(parts.size());
}

namespace {

int storeyOf(const Site& site, double z) { return int(std::lround((z - site.base) / site.storeyHeight)); }

// The storeys a unit spans, as [first, last + 1).
std::pair<int, int> storeySpan(const Site& site, const Unit& u) {
  const Box b = u.bounds();
  return {storeyOf(site, b.lo[2]), storeyOf(site, b.hi[2])};
}

// Whether box o lies in front of side s of b and faces it across a positive area.
bool facesAcross(const Box& b, Side s, const Box& o) {
  const int k = sideAxis(s);
  for (int j = 0; j < 3; ++j)
    if (j != k && overlapLength(b.lo[j], b.hi[j], o.lo[j], o.hi[j]) <= kEps) return false;
  return sideSign(s) > 0 ? o.lo[k] >= b.hi[k] - kEps : o.hi[k] <= b.lo[k] + kEps;
}

}  // namespace

double ConstraintEnforcer::freeDistance(const std::vector<Unit>& units, std::size_t unit, int part, Side s,
                                        double limit) const {
  return distanceAhead(units, unit, units[unit].parts[part], part, s, limit, 0.0, nullptr);
}

double ConstraintEnforcer::lookAhead(const std::vector<Unit>& units, std::size_t unit, int part, Side s, double limit,
                                     double reach, const std::vector<bool>& growing) const {
  return distanceAhead(units, unit, units[unit].parts[part], part, s, limit, reach, &growing);
}

double ConstraintEnforcer::lookAheadFrom(const std::vector<Unit>& units, std::size_t unit, const Box& from, Side s,
                                         double limit, double reach, const std::vector<bool>& growing) const {
  return distanceAhead(units, unit, from, -1, s, limit, reach, &growing);
}

double ConstraintEnforcer::distanceAhead(const std::vector<Unit>& units, std::size_t unit, const Box& b, int part,
                                         Side s, double limit, double reach, const std::vector<bool>* growing) const {
  const int k = sideAxis(s);
  double d = limit;
  auto against = [&](const Box& o) {
    if (!facesAcross(b, s, o)) return;
    const double gap = sideSign(s) > 0 ? o.lo[k] - b.hi[k] : b.lo[k] - o.hi[k];
    d = std::min(d, std::max(gap, 0.0));
  };
  auto growOf = [&](std::size_t i) {
    return (i != unit && growing && i < growing->size() && (*growing)[i]) ? reach : 0.0;
  };
  if (!indexed(units)) {
    for (const Box& z : zones_) against(z);
    for (std::size_t i = 0; i < units.size(); ++i)
      for (std::size_t j = 0; j < units[i].parts.size(); ++j)
        if (i != unit || int(j) != part) against(grownInPlan(units[i].parts[j], growOf(i)));
  } else {
    // Strips in front of the face, twice as deep each round, until the nearest obstacle lies
    // within the strip (nothing beyond it can be nearer) or the strip covers the site. The
    // minimum does not depend on the order of the obstacles, nor on seeing one twice.
    const Rect site = footprint(site_.bounds());
    const double margin = (growing ? reach : 0.0) + 1e-6;
    std::vector<std::uint64_t> keys;
    for (double depth = kGridCell;; depth *= 2) {
      Box strip = sweptRegion(b, s, std::min(depth, d));
      if (k != 2) {
        // the face itself and (for the obstacles' reach) a margin all round
        (sideSign(s) > 0 ? strip.lo[k] : strip.hi[k]) = sideCoord(b, s);
      }
      Rect r = grown(footprint(strip), margin);
      nearZones(r, keys);
      for (std::uint64_t z : keys) against(zones_[z]);
      nearParts(r, keys);
      for (std::uint64_t key : keys) {
        const std::size_t i = keyUnit(key), j = keyPart(key);
        if (i != unit || int(j) != part) against(grownInPlan(units[i].parts[j], growOf(i)));
      }
      const bool coversSite = r.u0 <= site.u0 && r.v0 <= site.v0 && r.u1 >= site.u1 && r.v1 >= site.v1;
      if (d <= depth || depth >= limit || coversSite || k == 2) break;
      if (k != 2 && (sideSign(s) > 0 ? sideCoord(b, s) + depth >= (k == 0 ? site.u1 : site.v1)
                                     : sideCoord(b, s) - depth <= (k == 0 ? site.u0 : site.v0)))
        break;
    }
  }
  if (k == 2) {
    d = std::min(d, sideSign(s) > 0 ? site_.top() - b.hi[2] : b.lo[2] - site_.base);
    return std::max(d, 0.0);
  }
  if (d > 0 && !site_.contains(sweptRegion(b, s, d))) {
    // The envelope's plan may be any polygon: bisect for the farthest advance inside it.
    double lo = 0, hi = d;
    for (int it = 0; it < 40 && hi - lo > 1e-9; ++it) {
      const double mid = (lo + hi) / 2;
      (site_.contains(sweptRegion(b, s, mid)) ? lo : hi) = mid;
    }
    d = lo;
  }
  return d;
}

FaceObstacles ConstraintEnforcer::obstaclesAhead(const std::vector<Unit>& units, std::size_t unit, int part, Side s,
                                                 double distance) const {
  const Box& b = units[unit].parts[part];
  const int k = sideAxis(s), along = 1 - k;
  FaceObstacles out;
  out.face = {b.lo[along], b.lo[2], b.hi[along], b.hi[2]};
  auto against = [&](const Box& o) {
    if (!facesAcross(b, s, o)) return;
    const double gap = sideSign(s) > 0 ? o.lo[k] - b.hi[k] : b.lo[k] - o.hi[k];
    if (gap < distance)
      out.obstacles.push_back({std::max(o.lo[along], b.lo[along]), std::max(o.lo[2], b.lo[2]),
                               std::min(o.hi[along], b.hi[along]), std::min(o.hi[2], b.hi[2])});
  };
  if (!indexed(units)) {
    for (const Box& z : zones_) against(z);
    for (std::size_t i = 0; i < units.size(); ++i)
      for (std::size_t j = 0; j < units[i].parts.size(); ++j)
        if (i != unit || int(j) != part) against(units[i].parts[j]);
    return out;
  }
  // The same obstacles in the same order, from the grid: zones, then parts by unit and part.
  Box strip = sweptRegion(b, s, std::max(distance, 0.0));
  (sideSign(s) > 0 ? strip.lo[k] : strip.hi[k]) = sideCoord(b, s);
  const Rect r = grown(footprint(strip), 1e-6);
  std::vector<std::uint64_t> keys;
  nearZones(r, keys);
  for (std::uint64_t z : keys) against(zones_[z]);
  nearParts(r, keys);
  for (std::uint64_t key : keys)
    if (keyUnit(key) != unit || int(keyPart(key)) != part) against(units[keyUnit(key)].parts[keyPart(key)]);
  return out;
}

bool ConstraintEnforcer::plausible(const std::vector<Unit>& units, std::size_t unit) const {
  return plausibleAs(units, unit, units[unit]);
}

bool ConstraintEnforcer::plausibleAs(const std::vector<Unit>& units, std::size_t unit, const Unit& u) const {
  std::vector<Rect> anchors;
  std::vector<std::uint64_t> keys, zoneKeys;
  for (const Box& p : u.parts) {
    const Rect fp = footprint(p);
    if (std::abs(p.lo[2] - site_.base) <= kEps) {
      anchors.push_back(fp);
      continue;
    }
    Rect x;
    auto restsOn = [&](const Box& o) {
      if (std::abs(o.hi[2] - p.lo[2]) <= kEps && intersect(fp, footprint(o), false, x)) anchors.push_back(x);
    };
    auto fixedTo = [&](const Box& o, double clearance) {
      if (overlapLength(p.lo[2], p.hi[2], o.lo[2], o.hi[2]) <= kEps) return;
      const double reach = clearance + 10 * kEps;
      if (planGap(fp, footprint(o)) <= reach && intersect(fp, grown(footprint(o), reach), true, x))
        anchors.push_back(x);
    };
    const std::size_t cores = site_.cores.size();
    if (!indexed(units)) {
      for (std::size_t i = 0; i < units.size(); ++i)
        if (i != unit)
          for (const Box& o : units[i].parts) restsOn(o);
      for (const Box& c : site_.circulation) restsOn(c);
      for (std::size_t i = 0; i < cores; ++i) fixedTo(site_.coreBox(i), site_.coreClearance);
      for (const Box& c : site_.circulation) fixedTo(c, site_.circulationClearance);
      continue;
    }
    // The same anchors in the same order, from the grids. A zone holds its core or
    // circulation box grown by the clearance, so it meets whatever that box is fixed to.
    const Rect near = grown(fp, 1e-5);
    nearParts(near, keys);
    for (std::uint64_t key : keys)
      if (keyUnit(key) != unit) restsOn(units[keyUnit(key)].parts[keyPart(key)]);
    nearZones(near, zoneKeys);
    for (std::uint64_t z : zoneKeys)
      if (z >= cores) restsOn(site_.circulation[z - cores]);
    for (std::uint64_t z : zoneKeys)
      if (z < cores) fixedTo(site_.coreBox(z), site_.coreClearance);
    for (std::uint64_t z : zoneKeys)
      if (z >= cores) fixedTo(site_.circulation[z - cores], site_.circulationClearance);
  }
  if (anchors.empty()) return false;
  for (const Box& p : u.parts) {
    std::vector<Rect> left{footprint(p)};
    for (const Rect& a : anchors) {
      left = subtract(left, grown(a, site_.cantilever + kEps));
      if (left.empty()) break;
    }
    if (totalArea(left) > kEps) return false;
  }
  return true;
}

Verdict ConstraintEnforcer::check(const std::vector<Unit>& units, std::size_t unit, const Move& m) const {
  const Unit& u = units[unit];
  auto no = [&](std::string why) { return Verdict{false, m, std::move(why)}; };
  if (m.part < 0 || m.part >= int(u.parts.size())) return no("no such part");
  if (m.type == Move::Type::StairBase) return checkStairBase(units, unit, m);
  const Box& b = u.parts[m.part];
  if (m.type == Move::Type::Split) {
    if (m.axis != 0 && m.axis != 1) return no("a split cuts along x or y");
    if (int(u.parts.size()) >= kMaxParts) return no("the unit has its most parts");
    if (m.at - b.lo[m.axis] < kMinPartWidth - kEps || b.hi[m.axis] - m.at < kMinPartWidth - kEps)
      return no("both pieces of a split are at least 3 m wide");
    return {true, m, ""};
  }
  if (u.locked[static_cast<int>(m.side)]) return no("the face is locked");
  if (!(m.distance > 0)) return no("an advance moves forward");
  if (sideTouchesOwnPart(u, m.part, m.side)) return no("the face touches another part of the unit");
  Verdict v{true, m, ""};
  if (sideAxis(m.side) == 2) {
    if (std::abs(m.distance - site_.storeyHeight) > kEps) return no("floors and ceilings advance by one storey");
    if (std::abs(b.size(2) - site_.storeyHeight) > kEps) return no("the part is already a double volume");
    if (freeDistance(units, unit, m.part, m.side, m.distance) < m.distance - kEps) return no("blocked");
    auto [first, last] = storeySpan(site_, u);
    const int lo = std::min(first, storeyOf(site_, b.lo[2]) - (m.side == Side::Bottom ? 1 : 0));
    const int hi = std::max(last, storeyOf(site_, b.hi[2]) + (m.side == Side::Top ? 1 : 0));
    if (hi - lo > 2) return no("a unit spans at most two storeys");
  } else {
    const double d = freeDistance(units, unit, m.part, m.side, m.distance);
    if (d < kMinAdvance) return no("blocked");
    v.move.distance = std::min(d, m.distance);
  }
  Unit moved = u;
  applyMove(moved, v.move);
  if (!plausibleAs(units, unit, moved)) return no("the unit would reach beyond its supports (cantilever limit)");
  return v;
}

// Fig. 5.4: the whole top of a staircase, or nothing.
Verdict ConstraintEnforcer::checkStairBase(const std::vector<Unit>& units, std::size_t unit, const Move& m) const {
  const Unit& u = units[unit];
  auto no = [&](std::string why) { return Verdict{false, m, std::move(why)}; };
  if (m.staircase < 0 || m.staircase >= int(site_.circulation.size())) return no("no such staircase");
  if (sideAxis(m.side) == 2) return no("a stair base is reached through a vertical face");
  if (u.locked[static_cast<int>(m.side)]) return no("the face is locked");
  if (sideTouchesOwnPart(u, m.part, m.side)) return no("the face touches another part of the unit");
  if (int(u.parts.size()) >= kMaxParts) return no("the unit has its most parts");
  std::string why;
  const std::optional<Box> part =
      stairBasePart(u.parts[m.part], m.side, site_.circulation[m.staircase], site_.storeyHeight, site_.alpha, &why);
  if (!part) return no(why);
  if (part->size(0) < kMinPartWidth - kEps || part->size(1) < kMinPartWidth - kEps)
    return no("the staircase's top is under 3 m x 3 m");
  if (!site_.contains(*part)) return no("the staircase's top is not inside the envelope");
  // Never a partial occupancy: anything on any of the top refuses the whole.
  for (const Box& z : zones_)
    if (interiorsOverlap(*part, z, kEps)) return no("the staircase's top is not wholly free (a clearance zone)");
  for (const Unit& o : units)
    for (const Box& p : o.parts)
      if (interiorsOverlap(*part, p, kEps))
        return no("the staircase's top is not wholly free (unit " + std::to_string(o.id) + ")");
  Verdict v{true, m, ""};
  v.move.box = *part;
  Unit moved = u;
  applyMove(moved, v.move);
  auto [first, last] = storeySpan(site_, moved);
  if (last - first > 2) return no("a unit spans at most two storeys");
  if (!plausibleAs(units, unit, moved)) return no("the unit would reach beyond its supports (cantilever limit)");
  return v;
}

std::vector<std::string> ConstraintEnforcer::violations(const std::vector<Unit>& units) const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const Unit& u = units[i];
    const std::string name = "unit " + std::to_string(u.id);
    if (u.parts.empty() || int(u.parts.size()) > kMaxParts) out.push_back(name + ": has no parts or too many");
    for (std::size_t j = 0; j < u.parts.size(); ++j) {
      const Box& p = u.parts[j];
      const std::string part = name + " part " + std::to_string(j);
      if (!site_.contains(p)) out.push_back(part + ": outside the envelope");
      if (p.size(0) < kMinPartWidth - kEps || p.size(1) < kMinPartWidth - kEps)
        out.push_back(part + ": under 3 m x 3 m");
      const double storeys = p.size(2) / site_.storeyHeight;
      const double lo = (p.lo[2] - site_.base) / site_.storeyHeight;
      if (std::abs(lo - std::round(lo)) > 1e-6 || std::abs(storeys - std::round(storeys)) > 1e-6 || storeys < 0.5 ||
          storeys > 2.5)
        out.push_back(part + ": not one or two whole storeys");
      for (std::size_t z = 0; z < zones_.size(); ++z)
        if (interiorsOverlap(p, zones_[z], kEps))
          out.push_back(part + ": within the clearance of a core or circulation");
      for (std::size_t k = 0; k < units.size(); ++k)
        for (std::size_t l = 0; l < units[k].parts.size(); ++l)
          if ((k > i || (k == i && l > j)) && interiorsOverlap(p, units[k].parts[l], kEps))
            out.push_back(part + ": overlaps unit " + std::to_string(units[k].id) + " part " + std::to_string(l));
    }
    if (!u.parts.empty()) {
      auto [first, last] = storeySpan(site_, u);
      if (last - first > 2) out.push_back(name + ": spans more than two storeys");
      if (!plausible(units, i)) out.push_back(name + ": reaches beyond its supports");
    }
  }
  return out;
}

}  // namespace corbel::growth
