// The winding rule over a self-overlapping active plan (Sec. 4.4). CGAL's arrangement of the
// plan's edges, over an exact kernel, splits the plane into faces; each arrangement edge knows
// which old edges it lies on (consolidated curve data), so a face's winding number follows from
// its neighbour's by the signed count of old edges between them, walking out from the
// unbounded face (winding 0).
#include "extrude/winding.h"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <deque>
#include <unordered_map>
#include <unordered_set>

namespace corbel::extrude {

namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Base = CGAL::Arr_segment_traits_2<EK>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<Base, int>;
using Arr = CGAL::Arrangement_2<Traits>;
using Halfedge = Arr::Halfedge_const_handle;
using Face = Arr::Face_const_handle;

Vec2 toVec(const EK::Point_2& p) { return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

}  // namespace

double piecesArea(const std::vector<std::pair<Vec2, Vec2>>& pieces) {
  double a = 0;
  for (const auto& [p, q] : pieces) a += p[0] * q[1] - p[1] * q[0];
  return 0.5 * a;
}

WindingResult windingRule(const std::vector<std::vector<Vec2>>& loops) {
  std::vector<Traits::Curve_2> curves;
  std::vector<char> leftToRight;  // per source: does the old edge run in CGAL's xy order?
  for (const auto& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int source = static_cast<int>(leftToRight.size());
      const EK::Point_2 a(loop[i][0], loop[i][1]), b(loop[(i + 1) % loop.size()][0], loop[(i + 1) % loop.size()][1]);
      const CGAL::Comparison_result order = CGAL::compare_xy(a, b);
      leftToRight.push_back(order == CGAL::SMALLER);
      if (order != CGAL::EQUAL) curves.emplace_back(Base::Curve_2(a, b), source);
    }
  Arr arr;
  CGAL::insert(arr, curves.begin(), curves.end());

  // Signed count of old edges along a halfedge: +1 for each running its way (the halfedge's
  // face, on its left, is inside that edge), −1 for each running against it.
  auto along = [&](Halfedge e) {
    const bool ltr = e->direction() == CGAL::ARR_LEFT_TO_RIGHT;
    int m = 0;
    for (auto it = e->curve().data().begin(); it != e->curve().data().end(); ++it) m += leftToRight[*it] == ltr ? 1 : -1;
    return m;
  };
  std::unordered_map<const void*, int> winding;
  auto w = [&](Face f) { return winding.at(&*f); };
  auto forEachHalfedge = [](Face f, auto&& fn) {
    if (f->has_outer_ccb()) {
      auto c = f->outer_ccb();
      auto start = c;
      do fn(Halfedge(c)); while (++c != start);
    }
    for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole) {
      auto c = *hole;
      auto start = c;
      do fn(Halfedge(c)); while (++c != start);
    }
  };
  std::deque<Face> todo{arr.unbounded_face()};
  winding[&*arr.unbounded_face()] = 0;
  while (!todo.empty()) {
    const Face f = todo.front();
    todo.pop_front();
    const int wf = w(f);
    forEachHalfedge(f, [&](Halfedge e) {
      const Face g = e->twin()->face();
      if (winding.emplace(&*g, wf - along(e)).second) todo.push_back(g);
    });
  }

  WindingResult result;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    result.minWinding = std::min(result.minWinding, w(f));
    result.maxWinding = std::max(result.maxWinding, w(f));
  }

  // The new plan: halfedges with winding ≥ 1 on their left and ≤ 0 on their right, chained
  // around each vertex so that the region stays on the left (a vertex where the region touches
  // itself starts two loops).
  auto boundary = [&](Halfedge e) { return w(e->face()) >= 1 && w(e->twin()->face()) <= 0; };
  auto sourceOf = [&](Halfedge e, int prefer) {
    const bool ltr = e->direction() == CGAL::ARR_LEFT_TO_RIGHT;
    int pick = -1;
    for (auto it = e->curve().data().begin(); it != e->curve().data().end(); ++it)
      if (leftToRight[*it] == ltr && (pick < 0 || *it == prefer)) pick = *it;
    return pick;
  };
  std::unordered_set<const void*> used;
  for (auto h = arr.halfedges_begin(); h != arr.halfedges_end(); ++h) {
    const Halfedge first = h;
    if (!boundary(first) || used.count(&*first)) continue;
    std::vector<WindingEdge> loop;
    Halfedge e = first;
    int prev = -1;
    do {
      used.insert(&*e);
      prev = sourceOf(e, prev);
      loop.push_back({toVec(e->source()->point()), prev});
      Halfedge n = e->next();
      while (!boundary(n)) n = n->twin()->next();
      e = n;
    } while (e != first && !used.count(&*e));
    // Consecutive pieces of one old edge are one edge.
    std::size_t k = 0;
    while (k < loop.size() && loop[k].source == loop[(k + loop.size() - 1) % loop.size()].source) ++k;
    if (k == loop.size()) continue;  // one old edge all round: no area
    std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(k), loop.end());
    std::vector<WindingEdge> merged;
    for (const WindingEdge& x : loop)
      if (merged.empty() || merged.back().source != x.source) merged.push_back(x);
    if (merged.size() >= 3) result.loops.push_back(std::move(merged));
  }

  // Caps: one per level, over every face at that level or beyond.
  for (int level = 2; level <= result.maxWinding; ++level) {
    WindingCap cap;
    cap.level = level;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
      if (!f->is_unbounded() && w(f) >= level)
        forEachHalfedge(f, [&](Halfedge e) { cap.pieces.emplace_back(toVec(e->source()->point()), toVec(e->target()->point())); });
    result.caps.push_back(std::move(cap));
  }
  for (int level = -1; level >= result.minWinding; --level) {
    WindingCap cap;
    cap.level = level;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
      if (!f->is_unbounded() && w(f) <= level)
        forEachHalfedge(f, [&](Halfedge e) { cap.pieces.emplace_back(toVec(e->target()->point()), toVec(e->source()->point())); });
    result.caps.push_back(std::move(cap));
  }
  return result;
}

}  // namespace corbel::extrude
