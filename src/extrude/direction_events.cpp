// Edge direction events (Sec. 4.5.1): at a profile's turn every edge it drives goes on along
// a new direction plane and starts a new face; the corners this makes may lie on other edges.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace corbel::extrude::sweeping {

void Sweeper::meetAtTurn(const std::vector<int>& made, double h) {
  syncLive();
  for (int ci : made) {
    checkClock();
    const Corner& c = corners_[ci];
    if (!c.alive) continue;
    const Vec2 p = cornerAt(ci, h);
    for (int ei : liveEdges_) {
      const Edge& e = edges_[ei];
      if (!e.alive || ei == c.prev || ei == c.next) continue;
      if (std::abs(OpenMesh::dot(e.n, p) - (e.c + e.k * h)) > tol_.cluster) continue;
      const Vec2 s = liveAt(e.start, h), t = liveAt(e.end, h);
      const double along = OpenMesh::dot(e.d, p - s), length = OpenMesh::dot(e.d, t - s);
      if (along < -tol_.edgeMargin || along > length + tol_.edgeMargin) continue;
      SWEEP_TRACE("  turned corner %d lies on edge %d at (%g, %g, %g)", ci, ei, p[0], p[1], h);
      push({h, p, ci});
      break;
    }
  }
}

// Edge direction events (Sec. 4.5.1): every edge whose profile turns at height h continues
// on a new direction plane and starts a new face.
void Sweeper::handleDirectionChanges(double h) {
  std::vector<int> changing;
  for (int ei = 0; ei < static_cast<int>(edges_.size()); ++ei) {
    const Edge& e = edges_[ei];
    if (!e.alive) continue;
    const auto& steps = inputs_[e.src]->steps;
    if (e.step + 1 < static_cast<int>(steps.size()) && std::abs(steps[e.step + 1].z - h) <= tol_.height)
      changing.push_back(ei);
  }
  if (changing.empty()) return;
  std::map<int, int> replaced;  // old edge → new edge
  std::map<int, int> cornerVertex;
  std::map<int, Vec2> cornerPos;
  for (int ei : changing) {
    for (int ci : {edges_[ei].start, edges_[ei].end}) {
      if (cornerVertex.count(ci)) continue;
      const Vec2 p = cornerAt(ci, h);
      cornerPos[ci] = p;
      cornerVertex[ci] = addVertex(p, h);
    }
  }
  for (int ei : changing) {
    Edge next = edges_[ei];
    const auto& st = inputs_[next.src]->steps[next.step + 1];
    // The new plane holds the old one's line at h exactly (n·x = c + k h), rather than passing
    // through a corner computed on it: between almost colinear neighbours that corner is a
    // badly conditioned intersection whose residual off the line, ~1e-8 m, would move the
    // new corner metres along it (the lines' offsets divided by their sine).
    const Vec2 on = cornerPos[edges_[ei].start];
    setEdgePlane(next, edges_[ei].d, on, h, st.angle);
    next.c = edges_[ei].c + edges_[ei].k * h - next.k * h;
    next.step = edges_[ei].step + 1;
    next.face = addFace(next.src, st.segment, st.angle, next);
    edges_.push_back(next);
    const int nj = static_cast<int>(edges_.size()) - 1;
    replaced[ei] = nj;
  }
  // Old faces end along their top, new faces start along their bottom.
  for (int ei : changing) {
    const int vs = cornerVertex[edges_[ei].start], vt = cornerVertex[edges_[ei].end];
    faces_[edges_[ei].face].segments.emplace_back(vt, vs);
    faces_[edges_[replaced[ei]].face].segments.emplace_back(vs, vt);
  }
  // Corners of changing edges move along new paths from here.
  std::vector<int> fresh;
  turning_ = true;
  for (const auto& [ci, v] : cornerVertex) {
    const Corner old = corners_[ci];
    killCorner(ci, v);
    const int prev = replaced.count(old.prev) ? replaced[old.prev] : old.prev;
    const int next = replaced.count(old.next) ? replaced[old.next] : old.next;
    fresh.push_back(newCorner(prev, next, v, cornerPos[ci], h));
  }
  for (int ei : changing) edges_[ei].alive = false;
  const std::size_t firstMade = corners_.size() - fresh.size();
  for (int ci : fresh) resolveCorner(ci, h);
  turning_ = false;
  for (int ci : fresh) {
    checkClock();
    if (corners_[ci].alive) predict(ci);
  }
  // What the old corners would have met at h (an edge that shrinks to nothing just as it
  // turns, loops that touch as their flare ends) is the new corners' to meet, at h itself:
  // their predictions start above it, and corners on vertical walls predict nothing at all.
  std::vector<int> made;
  for (std::size_t ci = firstMade; ci < corners_.size(); ++ci)
    if (corners_[ci].alive) made.push_back(static_cast<int>(ci));
  meetAtTurn(made, h);
  std::vector<int> planes;
  for (const auto& [old, nj] : replaced)
    if (edges_[nj].alive) planes.push_back(nj);
  predictAgainst(planes);
}

}  // namespace corbel::extrude::sweeping
