#include "extrude/plan_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
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
  // Sort by x-extent so only overlapping candidates are tested exactly.
  std::vector<int> order(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  auto xmin = [&](int i) { return std::min(segs[i].s.source().x(), segs[i].s.target().x()); };
  auto xmax = [&](int i) { return std::max(segs[i].s.source().x(), segs[i].s.target().x()); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return xmin(a) < xmin(b); });
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const int i = order[oi];
    for (std::size_t oj = oi + 1; oj < order.size() && xmin(order[oj]) <= xmax(i); ++oj) {
      const int j = order[oj];
      const Seg &a = segs[i], &b = segs[j];
      const bool sameLoop = a.loop == b.loop;
      // Apart in y (compared exactly), they cannot meet: most pairs end here, cheaper than
      // the exact test.
      if (std::max(a.s.source().y(), a.s.target().y()) < std::min(b.s.source().y(), b.s.target().y()) ||
          std::max(b.s.source().y(), b.s.target().y()) < std::min(a.s.source().y(), a.s.target().y()))
        continue;
      const bool adjacent = sameLoop && ((a.edge + 1) % a.n == b.edge || (b.edge + 1) % b.n == a.edge);
      if (!CGAL::do_intersect(a.s, b.s)) continue;
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
        continue;
      }
      std::ostringstream m;
      m << "loops[" << a.loop << "] edge " << a.edge << " and loops[" << b.loop << "] edge " << b.edge
        << (sameLoop ? " cross or touch: the loop intersects itself" : " cross or touch: loops must be disjoint");
      return m.str();
    }
  }
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
