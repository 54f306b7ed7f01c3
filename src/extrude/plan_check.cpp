#include "extrude/plan_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <sstream>

namespace corbel::extrude {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using S2 = K::Segment_2;

std::vector<P2> toCgal(const std::vector<Vec2>& loop) {
  std::vector<P2> out;
  out.reserve(loop.size());
  for (const Vec2& p : loop) out.emplace_back(p[0], p[1]);
  return out;
}
}  // namespace

std::vector<int> nestingDepths(const std::vector<std::vector<Vec2>>& loops) {
  std::vector<std::vector<P2>> polys;
  for (const auto& l : loops) polys.push_back(toCgal(l));
  std::vector<int> depth(loops.size(), 0);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    for (std::size_t j = 0; j < loops.size(); ++j) {
      if (i == j || polys[j].size() < 3 || polys[i].empty()) continue;
      // Loops do not cross, so any vertex of i tells whether i lies inside j.
      if (CGAL::bounded_side_2(polys[j].begin(), polys[j].end(), polys[i][0], K()) == CGAL::ON_BOUNDED_SIDE) ++depth[i];
    }
  }
  return depth;
}

std::optional<std::string> checkPlanTopology(const std::vector<std::vector<Vec2>>& loops) {
  struct Seg {
    S2 s;
    int loop, edge, n;
  };
  std::vector<Seg> segs;
  std::size_t total = 0;
  for (const auto& l : loops) total += l.size();
  segs.reserve(total);
  for (int li = 0; li < static_cast<int>(loops.size()); ++li) {
    const int n = static_cast<int>(loops[li].size());
    for (int i = 0; i < n; ++i) {
      const Vec2 &a = loops[li][i], &b = loops[li][(i + 1) % n];
      segs.push_back({S2(P2(a[0], a[1]), P2(b[0], b[1])), li, i, n});
    }
  }
  // Only segments whose boxes overlap can meet (CGAL's box intersection: n log n, where a sweep
  // over x alone met thousands of near-vertical segments at once on a 100,000-corner circle).
  // Of the pairs that fail, the one reported is the first in the order of the segments' least
  // x (then their index), whatever order the boxes come in.
  std::vector<int> order(segs.size()), rank(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  auto xmin = [&](int i) { return std::min(segs[i].s.source().x(), segs[i].s.target().x()); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return xmin(a) < xmin(b) || (xmin(a) == xmin(b) && a < b); });
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<int>(k);
  // What is wrong where segments i and j (i before j in that order) meet, if anything.
  auto problem = [&](int i, int j) -> std::optional<std::string> {
    const Seg &a = segs[i], &b = segs[j];
    const bool sameLoop = a.loop == b.loop;
    const bool adjacent = sameLoop && ((a.edge + 1) % a.n == b.edge || (b.edge + 1) % b.n == a.edge);
    if (!CGAL::do_intersect(a.s, b.s)) return std::nullopt;
    if (adjacent) {
      // Neighbours share one corner; they must not fold back onto each other.
      const bool aFirst = (a.edge + 1) % a.n == b.edge;
      const S2& first = aFirst ? a.s : b.s;
      const S2& second = aFirst ? b.s : a.s;
      if (a.n > 2 && CGAL::collinear(first.source(), first.target(), second.target()) &&
          !CGAL::collinear_are_ordered_along_line(first.source(), first.target(), second.target())) {
        std::ostringstream m;
        const Seg& s2 = aFirst ? b : a;
        m << "loops[" << s2.loop << "].points[" << s2.edge << "]: the plan folds back on itself (a zero-width spike)";
        return m.str();
      }
      return std::nullopt;
    }
    std::ostringstream m;
    m << "loops[" << a.loop << "] edge " << a.edge << " and loops[" << b.loop << "] edge " << b.edge
      << (sameLoop ? " cross or touch: the loop intersects itself" : " cross or touch: loops must be disjoint");
    return m.str();
  };
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;
  std::vector<Box> boxes;
  boxes.reserve(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) boxes.emplace_back(segs[i].s.bbox(), static_cast<int>(i));
  std::pair<int, int> first{std::numeric_limits<int>::max(), 0};
  std::optional<std::string> found;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    int i = x.info(), j = y.info();
    if (rank[i] > rank[j]) std::swap(i, j);
    const std::pair<int, int> at{rank[i], rank[j]};
    if (at >= first) return;
    if (auto p = problem(i, j)) {
      first = at;
      found = std::move(p);
    }
  });
  if (found) return found;
  // One loop is outer; with more, each one's depth decides its orientation.
  const std::vector<int> depth = loops.size() > 1 ? nestingDepths(loops) : std::vector<int>(1, 0);
  std::vector<P2> poly;
  poly.reserve(total);
  for (int li = 0; li < static_cast<int>(loops.size()); ++li) {
    poly.clear();
    for (const Vec2& p : loops[li]) poly.emplace_back(p[0], p[1]);
    const auto o = CGAL::orientation_2(poly.begin(), poly.end(), K());
    const bool hole = depth[li] % 2 == 1;
    if (o == CGAL::COLLINEAR) return "loops[" + std::to_string(li) + "]: the loop encloses no area";
    if (hole && o != CGAL::CLOCKWISE)
      return "loops[" + std::to_string(li) + "]: a hole must run clockwise (it runs counter-clockwise)";
    if (!hole && o != CGAL::COUNTERCLOCKWISE)
      return "loops[" + std::to_string(li) + "]: an outer loop must run counter-clockwise (it runs clockwise)";
  }
  return std::nullopt;
}

}  // namespace corbel::extrude
