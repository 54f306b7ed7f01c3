#pragma once
// Floorplans (Sec. 7.1): a set of ShapeTrees with incidence links between touching edges of
// different units. Every operation goes through the floorplan, which refuses one that would
// make two units overlap and then relinks the changed unit's leaves (Fig. 7.3).
#include "core/mesh_data.h"
#include "growth/shapetree.h"
#include "growth/unit.h"

#include <compare>
#include <string>
#include <vector>

namespace corbel::growth {

struct LeafRef {
  int unit = -1, node = -1;
  bool operator==(const LeafRef&) const = default;
  auto operator<=>(const LeafRef&) const = default;
};

// Leaf a of one unit and leaf b of a later unit face each other on one grid line and share
// the interval [from, to] of positive length.
struct Incidence {
  LeafRef a, b;  // a.unit < b.unit
  GridCoord from = 0, to = 0;
  bool operator==(const Incidence&) const = default;
  auto operator<=>(const Incidence&) const = default;
};

// The incidences between two edges of different units, if they touch (exposed for tests
// and the completion code; the floorplan keeps its own list up to date).
bool touching(const ShapeEdge& a, const ShapeEdge& b, GridCoord& from, GridCoord& to);

class Floorplan {
 public:
  int addUnit(ShapeTree t, std::string* why = nullptr);  // -1 when it overlaps a unit
  const std::vector<ShapeTree>& units() const { return units_; }
  const ShapeTree& unit(int i) const { return units_[std::size_t(i)]; }
  const std::vector<Incidence>& incidences() const { return links_; }
  // The links of one leaf.
  std::vector<Incidence> linksOf(LeafRef leaf) const;

  SplitNodes faceSplit(int unit, int leaf, GridCoord at, std::string* why = nullptr);
  bool faceAdvance(int unit, int leaf, GridCoord alpha, std::string* why = nullptr);
  bool undo();  // the last faceSplit or faceAdvance (or addUnit)
  std::size_t historySize() const { return history_.size(); }

  GridRect bounds() const;  // of all units (empty when there are none)
  // Every unit valid and no two overlap.
  bool valid(std::string* why = nullptr) const;

 private:
  std::vector<ShapeTree> units_;
  std::vector<Incidence> links_;
  std::vector<int> history_;  // the unit of each op; -2 for addUnit
  bool overlapsOthers(int unit) const;
  void relink(int unit);
};

// Extrusion to 3D (Sec. 6.1): unit i becomes a growth::Unit of id i + 1 whose parts are its
// boxes, `cell` meters to a grid step, from z0 up `storeys` storeys (2: a double volume).
struct Extrusion {
  double cell = 1.0;
  double z0 = 0.0;
  double storeyHeight = 3.0;
  std::vector<int> storeys;  // per unit; missing entries are 1
};
std::vector<Unit> extrude(const Floorplan& plan, const Extrusion& how);

}  // namespace corbel::growth
