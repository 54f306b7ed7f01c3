#pragma once
// A uniform grid of buckets over a plan: which boxes may lie near a plan rectangle, without
// looking at every box. The growth engine's queries (what lies in front of a face, what a part
// rests on, what an advance would hit) each touch a few metres of a site; on a site of a
// thousand units a scan of every part makes a step quadratic in the units, a grid lookup keeps
// it linear.
//
// Entries are integer keys with a plan rectangle. A query returns every key whose rectangle
// meets the query's (closed: touching counts), and possibly more, ascending and each once, so a
// caller that visits the keys in that order visits them in the order a full scan would.
// Rectangles outside the grid's bounds fall into its border cells, so nothing is ever missed.
#include "growth/box.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace corbel::growth {

class PlanGrid {
 public:
  PlanGrid() = default;
  // Square cells of about `cell` metres over `bounds` (at most 4096 a side).
  PlanGrid(const Rect& bounds, double cell);

  // Adds `key` over r (a key already present is moved).
  void insert(std::uint64_t key, const Rect& r);
  void erase(std::uint64_t key);
  bool empty() const { return spans_.empty(); }

  // Every key whose rectangle may meet r (closed), ascending and unique, into `out` (cleared).
  void query(const Rect& r, std::vector<std::uint64_t>& out) const;

 private:
  struct Span {
    int i0, j0, i1, j1;  // cells [i0, i1] × [j0, j1]
  };
  Span spanOf(const Rect& r) const;
  int column(double x) const;
  int row(double y) const;
  Rect bounds_;
  double cellU_ = 1, cellV_ = 1;
  int columns_ = 0, rows_ = 0;
  std::vector<std::vector<std::uint64_t>> cells_;
  std::unordered_map<std::uint64_t, Span> spans_;
};

}  // namespace corbel::growth
