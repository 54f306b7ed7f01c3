// Floorplans of ShapeTrees with incidence links (Sec. 7.1). See floorplan.h.
#include "growth/floorplan.h"

#include <algorithm>

namespace corbel::growth {

bool touching(const ShapeEdge& a, const ShapeEdge& b, GridCoord& from, GridCoord& to) {
  if (oppositeFacing(a.facing) != b.facing || a.line() != b.line()) return false;
  // Facing each other: a north edge touches a south edge above... on the same line, the
  // interiors lie on opposite sides, which opposite labels already say.
  from = std::max(a.lo(), b.lo());
  to = std::min(a.hi(), b.hi());
  return to > from;
}

std::vector<Incidence> Floorplan::linksOf(LeafRef leaf) const {
  std::vector<Incidence> out;
  for (const Incidence& l : links_)
    if (l.a == leaf || l.b == leaf) out.push_back(l);
  return out;
}

bool Floorplan::overlapsOthers(int unit) const {
  for (const GridRect& a : units_[std::size_t(unit)].boxes())
    for (std::size_t j = 0; j < units_.size(); ++j) {
      if (int(j) == unit) continue;
      for (const GridRect& b : units_[j].boxes())
        if (interiorsMeet(a, b)) return true;
    }
  return false;
}

void Floorplan::relink(int unit) {
  std::erase_if(links_, [&](const Incidence& l) { return l.a.unit == unit || l.b.unit == unit; });
  const std::vector<ShapeEdge> mine = units_[std::size_t(unit)].edges();
  for (std::size_t j = 0; j < units_.size(); ++j) {
    if (int(j) == unit) continue;
    for (const ShapeEdge& theirs : units_[j].edges())
      for (const ShapeEdge& e : mine) {
        GridCoord from = 0, to = 0;
        if (!touching(e, theirs, from, to)) continue;
        LeafRef a{unit, e.node}, b{int(j), theirs.node};
        if (b < a) std::swap(a, b);
        links_.push_back({a, b, from, to});
      }
  }
  std::sort(links_.begin(), links_.end());
}

int Floorplan::addUnit(ShapeTree t, std::string* why) {
  units_.push_back(std::move(t));
  const int i = int(units_.size()) - 1;
  if (overlapsOthers(i)) {
    units_.pop_back();
    if (why) *why = "the new unit overlaps another unit";
    return -1;
  }
  relink(i);
  history_.push_back(-2);
  return i;
}

SplitNodes Floorplan::faceSplit(int unit, int leaf, GridCoord at, std::string* why) {
  if (unit < 0 || std::size_t(unit) >= units_.size()) {
    if (why) *why = "no such unit";
    return {};
  }
  const SplitNodes s = units_[std::size_t(unit)].faceSplit(leaf, at, why);
  if (s.first < 0) return s;
  history_.push_back(unit);
  relink(unit);
  return s;
}

bool Floorplan::faceAdvance(int unit, int leaf, GridCoord alpha, std::string* why) {
  if (unit < 0 || std::size_t(unit) >= units_.size()) {
    if (why) *why = "no such unit";
    return false;
  }
  ShapeTree& t = units_[std::size_t(unit)];
  if (!t.faceAdvance(leaf, alpha, why)) return false;
  if (overlapsOthers(unit)) {
    t.undo();
    if (why) *why = "the unit would overlap another unit";
    return false;
  }
  history_.push_back(unit);
  relink(unit);
  return true;
}

bool Floorplan::undo() {
  if (history_.empty()) return false;
  const int u = history_.back();
  history_.pop_back();
  if (u == -2) {
    const int last = int(units_.size()) - 1;
    units_.pop_back();
    std::erase_if(links_, [&](const Incidence& l) { return l.a.unit == last || l.b.unit == last; });
    return true;
  }
  units_[std::size_t(u)].undo();
  relink(u);
  return true;
}

GridRect Floorplan::bounds() const {
  if (units_.empty()) return {};
  GridRect r = units_[0].bounds();
  for (const ShapeTree& t : units_) {
    const GridRect b = t.bounds();
    r = {std::min(r.x0, b.x0), std::min(r.y0, b.y0), std::max(r.x1, b.x1), std::max(r.y1, b.y1)};
  }
  return r;
}

bool Floorplan::valid(std::string* why) const {
  for (std::size_t i = 0; i < units_.size(); ++i) {
    if (!units_[i].valid(why)) return false;
    if (overlapsOthers(int(i))) {
      if (why) *why = "unit " + std::to_string(i) + " overlaps another";
      return false;
    }
  }
  return true;
}

std::vector<Unit> extrude(const Floorplan& plan, const Extrusion& how) {
  std::vector<Unit> out;
  for (std::size_t i = 0; i < plan.units().size(); ++i) {
    const int storeys = i < how.storeys.size() ? std::max(1, how.storeys[i]) : 1;
    Unit u;
    u.id = int(i) + 1;
    for (const GridRect& r : plan.unit(int(i)).boxes())
      u.parts.push_back({{double(r.x0) * how.cell, double(r.y0) * how.cell, how.z0},
                         {double(r.x1) * how.cell, double(r.y1) * how.cell, how.z0 + storeys * how.storeyHeight}});
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace corbel::growth
