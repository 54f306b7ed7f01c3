// Anchors on the active plan (Sec. 3.4): where a step's or mesh anchor's edge is at its
// height, and the frame of the face there.
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::extrude::staging {

std::optional<Located> Stager::locate(const Plan& plan, const Anchor& a) const {
  std::optional<Located> best;
  for (int li = 0; li < static_cast<int>(plan.size()); ++li) {
    const auto& loop = plan[li];
    for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
      const Active& e = loop[i];
      if (e.step != -1 || e.sourceLoop != a.loop || e.sourceEdge != a.edge) continue;
      Located l;
      l.loop = li;
      l.index = i;
      Vec2 d = loop[(i + 1) % loop.size()].start - e.start;
      l.length = d.norm();
      if (l.length <= tol_.minEdge) continue;
      l.d = d / l.length;
      if (a.absolute) {
        const auto& in = spec_.loops[a.loop].points;
        const Vec2 s = in[a.edge];
        Vec2 din = in[(a.edge + 1) % in.size()] - s;
        din.normalize();
        l.t = a.along - OpenMesh::dot(din, e.start - s);
        if (l.t < 0 || l.t > l.length) continue;
        l.at = e.start + l.d * l.t;
        return l;
      }
      l.t = a.along * l.length;
      l.at = e.start + l.d * l.t;
      if (!best || l.length > best->length) best = l;
    }
  }
  return best;
}

void Stager::frame(const Plan& plan, double h) {
  for (std::size_t k = 0; k < spec_.anchors.size(); ++k) {
    const MeshAnchor& m = spec_.anchors[k];
    if (std::abs(spec_.baseZ + m.anchor.height - h) > tol_.height) continue;
    AnchorFrame& f = frames_[k];
    const auto at = locate(plan, m.anchor);
    if (!at) continue;
    const Active& e = plan[at->loop][at->index];
    double angle = 0;
    for (const Seg& g : segs(e))
      if (!g.horizontal && g.hi > h + tol_.height) {
        angle = g.angle;
        break;
      }
    const Vec2 n = leftOf(at->d);
    f.instanced = true;
    f.position = Vec3(at->at[0], at->at[1], h);
    f.along = Vec3(at->d[0], at->d[1], 0);
    f.normal = Vec3(-n[0], -n[1], std::tan(angle));
    f.normal.normalize();
    f.up = OpenMesh::cross(f.normal, f.along);
  }
}

}  // namespace corbel::extrude::staging
