#include "volume_oracle.h"

#include "extrude/batch.h"
#include "skeleton_oracle.h"

#include <cmath>

namespace corbel::extrude::test {

VolumeOracle independentVolume(const ExtrusionSpec& spec) {
  VolumeOracle o;
  const Profile& p = spec.profiles[spec.loops[0].profile[0]];
  bool uniform = spec.steps.empty() && spec.offsets.empty() && p.points.front() == Vec2(0, 0);
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i)
    uniform = uniform && p.points[i + 1][0] >= p.points[i][0] && p.points[i + 1][1] > p.points[i][1];
  for (const auto& l : spec.loops)
    for (int k : l.profile) uniform = uniform && spec.profiles[k].points == p.points;
  if (uniform) {
    std::vector<std::vector<Vec2>> loops;
    for (const auto& l : spec.loops) loops.push_back(l.points);
    o.kind = VolumeOracle::Cgal;
    o.volume = cgalVolumeUnderProfile(loops, p.points);
    return o;
  }
  // An orthogonal plan perturbed by less than 1e-5 m: rounded to 1e-5 m, every edge is exactly
  // axis-parallel again (corners added along an edge stay on its line), so the rounding is
  // the plan before the perturbation, whose shell the normal tolerances build.
  BatchItem item{"unperturbed", spec, ""};
  bool orthogonal = true;
  for (auto& l : item.spec.loops) {
    for (Vec2& q : l.points) q = Vec2(std::round(q[0] * 1e5) / 1e5, std::round(q[1] * 1e5) / 1e5);
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const Vec2 &a = l.points[i], &b = l.points[(i + 1) % l.points.size()];
      orthogonal = orthogonal && (a[0] == b[0] || a[1] == b[1]);
    }
  }
  if (!orthogonal) return o;
  // The unperturbed plan must be unambiguous itself: it, its quarter turn and a copy moved
  // by (3, −1.5) m (all exact in floating point) must close without warnings and agree.
  std::vector<BatchItem> copies{item, item, item};
  for (auto& l : copies[1].spec.loops)
    for (Vec2& q : l.points) q = Vec2(-q[1], q[0]);
  for (auto& l : copies[2].spec.loops)
    for (Vec2& q : l.points) q += Vec2(3, -1.5);
  BatchOptions options;
  options.jobs = 1;
  options.retryFactors.clear();  // the normal tolerances only
  options.timeLimitSeconds = 1.0;
  const std::vector<BatchResult> r = extrudeBatch(copies, options);
  for (const BatchResult& c : r)
    if (!c.ok || !c.warnings.empty() ||
        std::abs(c.measures.volume - r[0].measures.volume) > 1e-9 * r[0].measures.volume ||
        std::abs(c.measures.roofArea - r[0].measures.roofArea) > 1e-9 * r[0].measures.roofArea)
      return o;
  o.kind = VolumeOracle::Unperturbed;
  o.volume = r[0].measures.volume;
  o.roofArea = r[0].measures.roofArea;
  return o;
}

}  // namespace corbel::extrude::test
