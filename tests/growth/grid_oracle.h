#pragma once
// Independent oracles for the ShapeTree tests: cells of the integer grid inside a polygon
// (crossing count at the cell centre) and the unit-length boundary segments of an edge.
// Written from the definitions, not from shapetree.cpp.
#include "growth/completion.h"
#include "growth/floorplan.h"
#include "growth/shapetree.h"

#include <algorithm>
#include <map>

#include <ostream>
#include <set>
#include <tuple>
#include <vector>

namespace corbel::growth {
inline std::ostream& operator<<(std::ostream& o, GridPoint p) { return o << "(" << p.x << "," << p.y << ")"; }
}  // namespace corbel::growth

namespace corbel::growth::test {

using Cell = std::pair<GridCoord, GridCoord>;

inline bool centreInside(const std::vector<GridPoint>& poly, GridCoord cx, GridCoord cy) {
  // The centre of cell (cx, cy) is (cx + ½, cy + ½); count vertical edges to its right.
  int crossings = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const GridPoint a = poly[i], b = poly[(i + 1) % poly.size()];
    if (a.x != b.x || a.x <= cx) continue;
    if (std::min(a.y, b.y) <= cy && cy < std::max(a.y, b.y)) ++crossings;
  }
  return crossings % 2 == 1;
}

inline std::set<Cell> cellsOf(const std::vector<GridPoint>& poly) {
  GridCoord x0 = poly[0].x, x1 = x0, y0 = poly[0].y, y1 = y0;
  for (auto p : poly) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  std::set<Cell> out;
  for (GridCoord x = x0; x < x1; ++x)
    for (GridCoord y = y0; y < y1; ++y)
      if (centreInside(poly, x, y)) out.insert({x, y});
  return out;
}

inline std::set<Cell> cellsOf(const std::vector<GridRect>& rects) {
  std::set<Cell> out;
  for (const GridRect& r : rects)
    for (GridCoord x = r.x0; x < r.x1; ++x)
      for (GridCoord y = r.y0; y < r.y1; ++y) out.insert({x, y});
  return out;
}

// The unit-length pieces of a real edge, each named by its lower-left grid point and whether
// it is horizontal; two edges touch along a piece when both list it with opposite facings.
using Piece = std::tuple<GridCoord, GridCoord, bool>;
inline std::vector<Piece> piecesOf(const ShapeEdge& e) {
  std::vector<Piece> out;
  const GridPoint t = travelOf(e.facing);
  for (GridPoint p = e.from; p != e.to; p = {p.x + t.x, p.y + t.y})
    out.push_back({std::min(p.x, p.x + t.x), std::min(p.y, p.y + t.y), t.y == 0});
  return out;
}

// The links an independent count of shared unit pieces implies, as (a, b, length).
inline std::set<std::tuple<LeafRef, LeafRef, GridCoord>> sharedPieces(const Floorplan& plan) {
  std::map<Piece, std::vector<std::pair<LeafRef, Facing>>> at;
  for (std::size_t u = 0; u < plan.units().size(); ++u)
    for (const ShapeEdge& e : plan.unit(int(u)).edges())
      for (const Piece& p : piecesOf(e)) at[p].push_back({{int(u), e.node}, e.facing});
  std::map<std::pair<LeafRef, LeafRef>, GridCoord> len;
  for (const auto& [piece, users] : at)
    for (std::size_t i = 0; i < users.size(); ++i)
      for (std::size_t j = i + 1; j < users.size(); ++j) {
        if (users[i].first.unit == users[j].first.unit) continue;
        if (oppositeFacing(users[i].second) != users[j].second) continue;
        auto key = std::minmax(users[i].first, users[j].first);
        ++len[{key.first, key.second}];
      }
  std::set<std::tuple<LeafRef, LeafRef, GridCoord>> out;
  for (const auto& [k, n] : len) out.insert({k.first, k.second, n});
  return out;
}

inline std::set<std::tuple<LeafRef, LeafRef, GridCoord>> recorded(const Floorplan& plan) {
  std::set<std::tuple<LeafRef, LeafRef, GridCoord>> out;
  for (const Incidence& l : plan.incidences()) out.insert({l.a, l.b, l.to - l.from});
  return out;
}

// The clockwise outline of a cell set, or empty when it has a pinch (two cells meeting only
// at a corner) or, unless outerOnly, a hole: then it is not one simple polygon. The loop
// through the least corner is the outer one.
inline std::vector<GridPoint> outlineOfCells(const std::set<Cell>& cells, bool outerOnly = false) {
  for (const Cell& c : cells)
    for (int dx : {-1, 1})
      for (int dy : {-1, 1}) {
        const bool diag = cells.count({c.first + dx, c.second + dy});
        const bool side1 = cells.count({c.first + dx, c.second}), side2 = cells.count({c.first, c.second + dy});
        if (diag && !side1 && !side2) return {};
      }
  std::map<GridPoint, GridPoint> next;  // unit boundary edges, clockwise (y up)
  for (const auto& [x, y] : cells) {
    if (!cells.count({x, y + 1})) next[{x, y + 1}] = {x + 1, y + 1};
    if (!cells.count({x + 1, y})) next[{x + 1, y + 1}] = {x + 1, y};
    if (!cells.count({x, y - 1})) next[{x + 1, y}] = {x, y};
    if (!cells.count({x - 1, y})) next[{x, y}] = {x, y + 1};
  }
  std::vector<GridPoint> loop;
  GridPoint p = next.begin()->first;
  do {
    loop.push_back(p);
    p = next.at(p);
  } while (p != loop.front() && loop.size() <= next.size());
  if (loop.size() != next.size() && !outerOnly) return {};  // a second loop: a hole
  return cleanOutline(loop);
}

// A form request in one line (the tests' common case).
inline FormRequest formRequest(int seeds, Fraction lo, Fraction hi, int count, std::uint64_t seed = 1) {
  FormRequest rq;
  rq.seeds = seeds;
  rq.lo = lo;
  rq.hi = hi;
  rq.count = count;
  rq.seed = seed;
  return rq;
}

}  // namespace corbel::growth::test
