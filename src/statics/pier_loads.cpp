#include "statics/pier_loads.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace corbel::statics {

std::vector<PierShare> pierShares(const CoursingSpec& spec, int courses) {
  const std::size_t np = spec.plan.size(), ne = spec.closed ? np : np - 1;
  const double ch = spec.height / courses;
  std::vector<PierShare> out;
  for (std::size_t e = 0; e < ne; ++e) {
    std::vector<int> piers;
    for (std::size_t k = 0; k < spec.buttresses.size(); ++k) {
      const WallButtress& b = spec.buttresses[k];
      if (b.edge == int(e) && std::clamp(int(std::lround(b.top / ch)), 1, courses) == courses) piers.push_back(int(k));
    }
    if (piers.empty()) continue;
    auto centre = [&](int k) {
      const WallButtress& b = spec.buttresses[std::size_t(k)];
      return 0.5 * (b.from + b.to);
    };
    std::sort(piers.begin(), piers.end(), [&](int a, int b) { return centre(a) < centre(b); });
    const double length = (spec.plan[(e + 1) % np] - spec.plan[e]).norm();
    for (std::size_t i = 0; i < piers.size(); ++i) {
      PierShare s;
      s.edge = int(e);
      s.buttress = piers[i];
      s.from = i == 0 ? 0.0 : 0.5 * (centre(piers[i - 1]) + centre(piers[i]));
      s.to = i + 1 == piers.size() ? length : 0.5 * (centre(piers[i]) + centre(piers[i + 1]));
      out.push_back(s);
    }
  }
  return out;
}

void loadHeadsOnPiers(const CoursingSpec& spec, CoursedWalls& walls, const std::vector<HeadLoad>& perEdge) {
  const std::size_t np = spec.plan.size(), ne = spec.closed ? np : np - 1;
  if (perEdge.size() != ne)
    throw Error("coursing: " + std::to_string(perEdge.size()) + " head loads for " + std::to_string(ne) + " edges");
  for (const HeadLoad& load : perEdge)
    if (!std::isfinite(load.down) || !std::isfinite(load.out)) throw Error("coursing: a head load is not finite");
  const std::vector<PierShare> shares = pierShares(spec, walls.courses);
  // Edges without piers: along the head.
  std::vector<HeadLoad> along = perEdge;
  for (const PierShare& s : shares) along[std::size_t(s.edge)] = HeadLoad{};
  loadWallHeads(spec, walls, along);

  const double top = spec.base + walls.courses * walls.courseHeight;
  for (const PierShare& s : shares) {
    const HeadLoad& load = perEdge[std::size_t(s.edge)];
    if (load.down == 0 && load.out == 0) continue;
    const WallButtress& b = spec.buttresses[std::size_t(s.buttress)];
    const Vec2 p0 = spec.plan[std::size_t(s.edge)], p1 = spec.plan[(std::size_t(s.edge) + 1) % np];
    const Vec2 d = (p1 - p0) / (p1 - p0).norm(), n(-d[1], d[0]);  // n: into the wall
    // The head spans over the pier and how much of it each covers.
    struct Over {
      int block;
      double lo, hi;
    };
    std::vector<Over> over;
    for (const HeadSpan& h : walls.heads) {
      if (h.edge != s.edge) continue;
      const double lo = std::max(h.from, b.from), hi = std::min(h.to, b.to);
      if (hi > lo) over.push_back({h.block, lo, hi});
    }
    const double covered =
        std::accumulate(over.begin(), over.end(), 0.0, [](double a, const Over& o) { return a + (o.hi - o.lo); });
    if (!(covered > 0)) throw Error("coursing: no wall head over buttress \"" + b.name + "\"");
    const double carried = s.to - s.from;
    for (const Over& o : over) {
      const double part = carried * (o.hi - o.lo) / covered;
      const Vec2 at = p0 + d * (0.5 * (o.lo + o.hi)) + n * (spec.thickness / 2);
      PointLoad l;
      l.at = Vec3(at[0], at[1], top);
      l.force = Vec3(-n[0] * load.out * part, -n[1] * load.out * part, -load.down * part);
      walls.blocks[std::size_t(o.block)].pointLoads.push_back(l);
    }
  }
}

}  // namespace corbel::statics
