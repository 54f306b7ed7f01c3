// The winding rule of Sec. 4.4 (extrude/winding.h) on hand-built plans that overlap
// themselves, each checked against an independent oracle: CGAL's exact Booleans of the same
// polygons, or the closed-form areas of a pentagram. The shell-level repair it drives is
// tested in post_check_test.cpp.
#include "extrude/winding.h"
#include "support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace corbel::extrude::test {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

CGAL::Polygon_2<EK> epolygon(const std::vector<Vec2>& p) {
  CGAL::Polygon_2<EK> q;
  for (const Vec2& v : p) q.push_back(EK::Point_2(v[0], v[1]));
  return q;
}

double setArea(const CGAL::Polygon_set_2<EK>& s) {
  std::vector<CGAL::Polygon_with_holes_2<EK>> regions;
  s.polygons_with_holes(std::back_inserter(regions));
  double a = 0;
  for (const auto& r : regions) {
    a += CGAL::to_double(r.outer_boundary().area());
    for (auto h = r.holes_begin(); h != r.holes_end(); ++h) a += CGAL::to_double(h->area());
  }
  return a;
}

double loopsArea(const WindingResult& r) {
  double a = 0;
  for (const auto& l : r.loops) {
    std::vector<Vec2> p;
    for (const WindingEdge& e : l) p.push_back(e.start);
    a += shoelace(p);
  }
  return a;
}

const WindingCap* capAt(const WindingResult& r, int level) {
  for (const WindingCap& c : r.caps)
    if (c.level == level) return &c;
  return nullptr;
}

// Every edge of the result lies on the old edge it names, from its start to the next start.
void expectOnSources(const WindingResult& r, const std::vector<std::vector<Vec2>>& loops) {
  std::vector<std::pair<Vec2, Vec2>> flat;
  for (const auto& l : loops)
    for (std::size_t i = 0; i < l.size(); ++i) flat.emplace_back(l[i], l[(i + 1) % l.size()]);
  for (const auto& l : r.loops)
    for (std::size_t i = 0; i < l.size(); ++i) {
      ASSERT_GE(l[i].source, 0);
      ASSERT_LT(l[i].source, static_cast<int>(flat.size()));
      const auto [a, b] = flat[l[i].source];
      Vec2 d = b - a;
      d.normalize();
      for (const Vec2& p : {l[i].start, l[(i + 1) % l.size()].start}) {
        const Vec2 q = p - a;
        EXPECT_NEAR(q[0] * d[1] - q[1] * d[0], 0.0, 1e-12) << "edge " << i << " is off its source " << l[i].source;
      }
      // Same way round: the region stays on the old edge's left.
      const Vec2 e = l[(i + 1) % l.size()].start - l[i].start;
      EXPECT_GT(OpenMesh::dot(e, d), 0) << "edge " << i << " runs against its source";
    }
}

TEST(WindingRule, ASimplePlanIsItsOwnRegionWithNoCaps) {
  const std::vector<std::vector<Vec2>> plan{rectangle(10, 6), reversed(rectangle(2, 2, 3, 2))};
  const WindingResult r = windingRule(plan);
  EXPECT_EQ(r.maxWinding, 1);
  EXPECT_EQ(r.minWinding, 0);
  EXPECT_TRUE(r.caps.empty());
  ASSERT_EQ(r.loops.size(), 2u);
  std::size_t edges = 0;
  for (const auto& l : r.loops) edges += l.size();
  EXPECT_EQ(edges, 8u);
  EXPECT_DOUBLE_EQ(loopsArea(r), 60.0 - 4.0);
  expectOnSources(r, plan);
}

// Two loops that cover one square twice: the region is their union (CGAL's join), with new
// corners where their edges cross; the doubly covered square gets one cap.
TEST(WindingRule, TwoOverlappingLoopsBecomeTheirUnionAndTheOverlapIsCapped) {
  const std::vector<std::vector<Vec2>> plan{rectangle(2, 2), rectangle(2, 2, 1, 1)};
  const WindingResult r = windingRule(plan);
  CGAL::Polygon_set_2<EK> u(epolygon(plan[0])), i(epolygon(plan[0]));
  u.join(epolygon(plan[1]));
  i.intersection(epolygon(plan[1]));
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].size(), 8u);
  EXPECT_DOUBLE_EQ(loopsArea(r), setArea(u));
  EXPECT_EQ(r.maxWinding, 2);
  const WindingCap* cap = capAt(r, 2);
  ASSERT_NE(cap, nullptr);
  EXPECT_DOUBLE_EQ(piecesArea(cap->pieces), setArea(i));
  EXPECT_EQ(r.caps.size(), 1u);
  expectOnSources(r, plan);
}

// A loop turned inside out (clockwise, as a collapsed loop whose edge runs against itself is):
// nothing of it is left in the plan; its region is closed by one cap facing down (clockwise
// seen from above). Where it crosses an outer loop, the part inside cancels (winding 0): a
// notch, as CGAL's difference gives.
TEST(WindingRule, AnInvertedLoopIsRemovedUnderADownwardCap) {
  const std::vector<Vec2> inverted = reversed(rectangle(2, 1, 3, 1));
  {
    const WindingResult r = windingRule({inverted});
    EXPECT_TRUE(r.loops.empty());
    EXPECT_EQ(r.minWinding, -1);
    const WindingCap* cap = capAt(r, -1);
    ASSERT_NE(cap, nullptr);
    EXPECT_DOUBLE_EQ(piecesArea(cap->pieces), -2.0);
  }
  const std::vector<std::vector<Vec2>> plan{rectangle(4, 4), inverted};
  const WindingResult r = windingRule(plan);
  CGAL::Polygon_set_2<EK> rest(epolygon(plan[0])), outside(epolygon(rectangle(2, 1, 3, 1)));
  rest.difference(epolygon(rectangle(2, 1, 3, 1)));
  outside.difference(epolygon(plan[0]));
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_DOUBLE_EQ(loopsArea(r), setArea(rest));
  const WindingCap* cap = capAt(r, -1);
  ASSERT_NE(cap, nullptr);
  EXPECT_DOUBLE_EQ(piecesArea(cap->pieces), -setArea(outside));
  expectOnSources(r, plan);
}

// One loop that winds twice round its middle: the pentagram {5/2}. Its region is the star
// (ten edges, each on one of the five old ones), its doubly wound pentagon is capped. Areas in
// closed form: with circumradius R, the inner pentagon's circumradius is r = R cos 72° / cos 36°,
// the star is ten triangles (centre, tip, inner corner) of area R r sin 36° / 2, and the
// pentagon 5 r² sin 72° / 2.
TEST(WindingRule, APentagramIsItsStarWithItsPentagonCapped) {
  const double R = 3.0, pi = std::numbers::pi;
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) star.emplace_back(R * std::cos(pi / 2 + 4 * pi * k / 5), R * std::sin(pi / 2 + 4 * pi * k / 5));
  const WindingResult r = windingRule({star});
  const double rin = R * std::cos(2 * pi / 5) / std::cos(pi / 5);
  EXPECT_EQ(r.maxWinding, 2);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].size(), 10u);
  EXPECT_NEAR(loopsArea(r), 10 * 0.5 * R * rin * std::sin(pi / 5), 1e-12);
  const WindingCap* cap = capAt(r, 2);
  ASSERT_NE(cap, nullptr);
  EXPECT_NEAR(piecesArea(cap->pieces), 2.5 * rin * rin * std::sin(2 * pi / 5), 1e-12);
  expectOnSources(r, {star});
}

// Two loops that share an edge in opposite directions (winding 1 on both sides of it): the
// shared edge is inside the region and drops out; nothing is capped.
TEST(WindingRule, AnEdgeSharedBothWaysIsInsideTheRegion) {
  const std::vector<std::vector<Vec2>> plan{rectangle(1, 1), rectangle(1, 1, 1, 0)};
  const WindingResult r = windingRule(plan);
  EXPECT_TRUE(r.caps.empty());
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].size(), 6u);  // the two bottoms and two tops stay separate edges
  EXPECT_DOUBLE_EQ(loopsArea(r), 2.0);
  expectOnSources(r, plan);
}

// Tiny overlaps, as the sweep's are (microns in a 50 m plan), are resolved exactly: the cap's
// area is the overlap's to rounding.
TEST(WindingRule, AMicronOverlapIsResolvedExactly) {
  const double e = 1e-6;
  const std::vector<std::vector<Vec2>> plan{rectangle(20, 10), rectangle(30, 10, 20 - e, 0)};
  const WindingResult r = windingRule(plan);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_NEAR(loopsArea(r), 500.0 - 10 * e, 1e-9);
  const WindingCap* cap = capAt(r, 2);
  ASSERT_NE(cap, nullptr);
  EXPECT_NEAR(piecesArea(cap->pieces), 10 * e, 1e-12);
  expectOnSources(r, plan);
}

}  // namespace
}  // namespace corbel::extrude::test
