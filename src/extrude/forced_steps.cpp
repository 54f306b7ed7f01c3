// Forced steps (Sec. 3.5, 4.7): arbitrary polygons, placed in the frame of their anchor,
// unioned with the active plan (exactly, so the plan never self-intersects); the part outside
// the old plan gets a soffit, the new edges the step's front profile.
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::extrude::staging {

Plan Stager::forcedSteps(Plan plan, double h, bool atBase) {
  struct Placed {
    std::size_t si;
    std::vector<Vec2> pts;
  };
  std::vector<Placed> placed;
  for (std::size_t si = 0; si < spec_.steps.size(); ++si) {
    const PlanStep& st = spec_.steps[si];
    if (st.shape != StepShape::Forced || stepDone_[si] || std::abs(spec_.baseZ + st.anchor.height - h) > tol_.height)
      continue;
    stepDone_[si] = 1;
    const auto at = locate(plan, st.anchor);
    if (!at) {
      warnings_.push_back("steps[" + std::to_string(si) + "]" + (st.name.empty() ? "" : " (" + st.name + ")") +
                          ": not placed: its edge is not in the active plan at height " + std::to_string(h));
      continue;
    }
    const Vec2 o = -leftOf(at->d);
    Placed p{si, {}};
    for (const Vec2& q : st.points) p.pts.push_back(at->at + at->d * q[0] + o * q[1]);
    placed.push_back(std::move(p));
  }
  if (placed.empty()) return plan;
  const EPolygonSet active = planSet(plan);
  EPolygonSet added;
  for (const Placed& p : placed) added.join(toPolygon(p.pts));
  EPolygonSet next = active, flats = added;
  next.join(added);
  flats.difference(active);
  std::vector<EPolygonH> regions;
  flats.polygons_with_holes(std::back_inserter(regions));
  for (const EPolygonH& r : regions) {
    if (atBase) break;  // the base face covers it
    ShellFace info;
    info.angle = -std::numbers::pi / 2;
    addFlatRegion(r, h, false, info);
  }
  return rebuild(plan, next, h, [&](const Vec2& mid) {
    Active n;
    n.z0 = h;
    n.profile = spec_.steps[placed.front().si].frontProfile;
    n.step = static_cast<int>(placed.front().si);
    double best = std::numeric_limits<double>::infinity();
    for (const Placed& p : placed)
      for (std::size_t k = 0; k < p.pts.size(); ++k) {
        const double dist = distanceToSegment(mid, p.pts[k], p.pts[(k + 1) % p.pts.size()]);
        if (dist >= best) continue;
        best = dist;
        n.profile = spec_.steps[p.si].frontProfile;
        n.step = static_cast<int>(p.si);
        n.sourceEdge = static_cast<int>(k);
      }
    return n;
  }, atBase);
}

}  // namespace corbel::extrude::staging
