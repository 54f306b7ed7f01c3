// Table 8.1 of the shipped Alpha-like and Beta-like sites, seeds 1–5 (the figures
// docs/growth.md prints): computeStatistics against a recount from the grown boxes alone, by
// other means than the library's. Floor areas are areas of unions of footprints (the library
// sums footprints); views are each part face's area not hidden by any nearer box, face by face
// (the library reads the exact view maps); outdoor space is recounted on cells with the door
// as one unbroken run of at least 1 m (the library subtracts rectangles). The definitions are
// Ch. 8's as docs/growth.md states them; the thresholds are written out here again.
#include "growth/engine.h"
#include "growth/statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace corbel::growth {
namespace {

constexpr double kTol = 1e-6;

std::vector<double> edgesOf(const std::vector<Rect>& rects, bool u, const Rect& clip) {
  std::vector<double> e{u ? clip.u0 : clip.v0, u ? clip.u1 : clip.v1};
  for (const Rect& r : rects)
    for (double x : {u ? r.u0 : r.v0, u ? r.u1 : r.v1})
      if (x > e[0] && x < e[1]) e.push_back(x);
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

bool holds(const Rect& r, double u, double v) { return u > r.u0 && u < r.u1 && v > r.v0 && v < r.v1; }

// The area of `within` that none of `cover` covers (cells between every coordinate).
double uncovered(const Rect& within, const std::vector<Rect>& cover) {
  const auto us = edgesOf(cover, true, within), vs = edgesOf(cover, false, within);
  double a = 0;
  for (std::size_t i = 0; i + 1 < us.size(); ++i)
    for (std::size_t j = 0; j + 1 < vs.size(); ++j) {
      const double cu = (us[i] + us[i + 1]) / 2, cv = (vs[j] + vs[j + 1]) / 2;
      if (std::none_of(cover.begin(), cover.end(), [&](const Rect& r) { return holds(r, cu, cv); }))
        a += (us[i + 1] - us[i]) * (vs[j + 1] - vs[j]);
    }
  return a;
}

double unionArea(const std::vector<Rect>& rects) {
  Rect box{1e300, 1e300, -1e300, -1e300};
  for (const Rect& r : rects) box = {std::min(box.u0, r.u0), std::min(box.v0, r.v0), std::max(box.u1, r.u1), std::max(box.v1, r.v1)};
  return box.area() - uncovered(box, rects);
}

// The view of unit `u` toward direction +x (0), −x (1), +y (2) or −y (3): every part's face
// on that side, less what any box nearer the viewer hides of it.
double viewOf(const std::vector<Box>& all, const Unit& u, int dir) {
  const int k = dir < 2 ? 0 : 1, a = 1 - k;
  const bool pos = dir % 2 == 0;
  double sum = 0;
  for (const Box& p : u.parts) {
    const double front = pos ? p.hi[k] : p.lo[k];
    const Rect face{p.lo[a], p.lo[2], p.hi[a], p.hi[2]};
    std::vector<Rect> hiding;
    for (const Box& o : all)
      if ((pos ? o.hi[k] > front + kTol : o.lo[k] < front - kTol) && overlapLength(o.lo[a], o.hi[a], p.lo[a], p.hi[a]) > 0 &&
          overlapLength(o.lo[2], o.hi[2], p.lo[2], p.hi[2]) > 0)
        hiding.push_back({o.lo[a], o.lo[2], o.hi[a], o.hi[2]});
    sum += uncovered(face, hiding);
  }
  return sum;
}

// Another unit's roof at one of the unit's floor levels, open above over at least 4 m², along
// which one of the unit's parts at that level runs for at least 1 m without a break.
bool outdoorSpace(const std::vector<Box>& solids, const std::vector<Unit>& units, std::size_t i) {
  const Unit& me = units[i];
  for (std::size_t v = 0; v < units.size(); ++v) {
    if (v == i) continue;
    for (const Box& roof : units[v].parts) {
      const double z = roof.hi[2];
      const Rect top = footprint(roof);
      // Only what stands over the roof matters, and only the unit's parts touching it.
      auto meets = [&](const Rect& r) {
        return r.u0 <= top.u1 + kTol && top.u0 <= r.u1 + kTol && r.v0 <= top.v1 + kTol && top.v0 <= r.v1 + kTol;
      };
      std::vector<Rect> standing, mine;
      for (const Box& p : me.parts)
        if (std::abs(p.lo[2] - z) < kTol && meets(footprint(p))) mine.push_back(footprint(p));
      if (mine.empty()) continue;
      for (const Box& s : solids)
        if (s.lo[2] <= z + kTol && s.hi[2] > z + kTol && meets(footprint(s))) standing.push_back(footprint(s));
      std::vector<Rect> grid = standing;
      grid.insert(grid.end(), mine.begin(), mine.end());
      const auto us = edgesOf(grid, true, top), vs = edgesOf(grid, false, top);
      const std::size_t nu = us.size() - 1, nv = vs.size() - 1;
      std::vector<char> open(nu * nv);
      double area = 0;
      for (std::size_t a = 0; a < nu; ++a)
        for (std::size_t b = 0; b < nv; ++b) {
          const double cu = (us[a] + us[a + 1]) / 2, cv = (vs[b] + vs[b + 1]) / 2;
          open[a * nv + b] = std::none_of(standing.begin(), standing.end(), [&](const Rect& r) { return holds(r, cu, cv); });
          if (open[a * nv + b]) area += (us[a + 1] - us[a]) * (vs[b + 1] - vs[b]);
        }
      if (area < 4.0 - kTol) continue;
      // Runs of open cells along each side of each of the unit's parts.
      for (const Rect& p : mine) {
        auto run = [&](bool alongV, double line, bool cellBefore) {
          double best = 0, cur = 0;
          const auto& across = alongV ? us : vs;
          const auto& along = alongV ? vs : us;
          for (std::size_t c = 0; c + 1 < across.size(); ++c) {
            if (std::abs((cellBefore ? across[c + 1] : across[c]) - line) > kTol) continue;
            for (std::size_t t = 0; t + 1 < along.size(); ++t) {
              const double lo = along[t], hi = along[t + 1];
              const bool inside = alongV ? (lo >= p.v0 - kTol && hi <= p.v1 + kTol) : (lo >= p.u0 - kTol && hi <= p.u1 + kTol);
              const bool o = inside && open[alongV ? c * nv + t : t * nv + c];
              cur = o ? cur + (hi - lo) : 0;
              best = std::max(best, cur);
            }
          }
          return best;
        };
        if (std::max({run(true, p.u0, true), run(true, p.u1, false), run(false, p.v0, true), run(false, p.v1, false)}) >=
            1.0 - kTol)
          return true;
      }
    }
  }
  return false;
}

TEST(ShippedStatistics, Table81OfAlphaAndBetaSeeds1To5MatchesARecountFromTheBoxes) {
  for (const char* file : {"growth-alpha.json", "growth-beta.json"}) {
    const Site site = loadSite(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + file);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(std::string(file) + " seed " + std::to_string(seed));
      GrowthEngine engine(site, optionsFor(site, seed));
      engine.run(100000);
      const std::vector<Unit>& units = engine.units();
      const Statistics st = computeStatistics(site, units, engine.views());
      std::vector<Box> solids;
      for (const Unit& u : units) solids.insert(solids.end(), u.parts.begin(), u.parts.end());
      for (std::size_t c = 0; c < site.cores.size(); ++c) solids.push_back(site.coreBox(c));
      solids.insert(solids.end(), site.circulation.begin(), site.circulation.end());

      int occupants = 0, a = 0, b = 0, c = 0, unclassified = 0, two = 0, three = 0, doubles = 0, outdoor = 0;
      double areaSum = 0, viewSum = 0;
      for (std::size_t i = 0; i < units.size(); ++i) {
        const Unit& u = units[i];
        std::vector<Rect> plan;
        double volume = 0;
        for (const Box& p : u.parts) {
          plan.push_back(footprint(p));
          volume += p.volume();
        }
        const double area = unionArea(plan);
        EXPECT_NEAR(st.perUnit[i].floorArea, area, kTol);
        // Swedish standard (Ch. 8): A over 85 m² houses five, B 50–85 three, C 30–50 one.
        const int type = area > 85 ? 0 : area >= 50 ? 1 : area >= 30 ? 2 : 3;
        occupants += std::array{5, 3, 1, 0}[type];
        (type == 0 ? a : type == 1 ? b : type == 2 ? c : unclassified)++;
        // A double volume: more volume than one storey over the unit's plan.
        if (volume > area * site.storeyHeight + 1.0) ++doubles;
        int directions = 0;
        for (int d = 0; d < 4; ++d) {
          const double view = viewOf(solids, u, d);
          EXPECT_NEAR(st.perUnit[i].viewByDirection[d], view, kTol) << "unit " << u.id << " direction " << d;
          viewSum += view;
          directions += view >= 2.0;  // a view that way: at least 2 m² seen
        }
        two += directions == 2;
        three += directions == 3;
        const bool garden = outdoorSpace(solids, units, i);
        EXPECT_EQ(st.perUnit[i].outdoorSpace, garden) << "unit " << u.id;
        outdoor += garden;
        areaSum += area;
      }
      EXPECT_EQ(st.units, int(site.seeds.size()));
      EXPECT_EQ(st.typeA, a);
      EXPECT_EQ(st.typeB, b);
      EXPECT_EQ(st.typeC, c);
      EXPECT_EQ(st.unclassified, unclassified);
      EXPECT_EQ(st.occupants, occupants);
      EXPECT_NEAR(st.occupancyRatio, occupants / (site.area() * site.storeys), 1e-12);
      EXPECT_NEAR(st.averageFloorArea, areaSum / units.size(), kTol);
      EXPECT_NEAR(st.averageView, viewSum / units.size(), kTol);
      EXPECT_EQ(st.twoViews, two);
      EXPECT_EQ(st.threeViews, three);
      EXPECT_EQ(st.doubleVolume, doubles);
      EXPECT_EQ(st.outdoorSpace, outdoor);
    }
  }
}

}  // namespace
}  // namespace corbel::growth
