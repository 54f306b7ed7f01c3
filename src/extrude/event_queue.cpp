// The sweep's event queue (Sec. 4.2): where each corner's path meets the other edges'
// direction planes, kept per corner, and the earliest live prediction first.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::extrude::sweeping {

void Sweeper::checkClock() const {
  if (in_.timeLimitSeconds > 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > in_.timeLimitSeconds)
    throw Error("the extrusion took longer than its time limit of " + std::to_string(in_.timeLimitSeconds) + " s");
}

// Where the corner's path meets each other edge's direction plane above the sweep.
void Sweeper::predict(int ci) {
  const Corner& c = corners_[ci];
  if (!c.alive) return;
  // The corner's path: x(z) = q + v z.
  Vec2 v, q;
  if (c.parallel) {
    v = c.v;
    q = c.p0 - c.v * c.z0;
  } else {
    const Edge& a = edges_[c.prev];
    const Edge& b = edges_[c.next];
    const double det = cross2(a.n, b.n);
    v = Vec2((a.k * b.n[1] - b.k * a.n[1]) / det, (a.n[0] * b.k - b.n[0] * a.k) / det);
    q = Vec2((a.c * b.n[1] - b.c * a.n[1]) / det, (a.n[0] * b.c - b.n[0] * a.c) / det);
  }
  syncLive();
  const double after = c.z0 + settle(c), before = lastUseful(c);
  // All of them at once: the corner's heap is built in one go and only its head enters the
  // global queue (pushed one by one, every new minimum would).
  auto& h = pending_[ci];
  const std::size_t had = h.size();
  const bool wasEmpty = h.empty();
  const double oldHead = wasEmpty ? std::numeric_limits<double>::infinity() : h.front().z;
  h.reserve(had + liveEdges_.size());
  for (int ei : liveEdges_) {
    const Edge& e = edges_[ei];
    if (!e.alive || ei == c.prev || ei == c.next) continue;
    const double denom = OpenMesh::dot(e.n, v) - e.k;
    if (std::abs(denom) < 1e-14) continue;
    const double z = (e.c - OpenMesh::dot(e.n, q)) / denom;
    // A corner takes part in nothing more at the height it was made: everything at its
    // point and height was handled by the event that made it.
    if (!(z > after) || !std::isfinite(z) || z > before) continue;
    h.push_back({z, q + v * z, ci, ++nextId_});
  }
  // A racing corner (one that moves more than δ2 in δ1 of height) heading for the far corner of
  // one of its edges, where that edge meets a second edge of its own line (within the merge
  // sine), meets that corner where its path crosses the second edge's plane. The two planes lie
  // within rounding of one another there, so that crossing is ill-conditioned: it can land
  // metres short of the far corner and below the racing corner's own height, where predict
  // drops it, and the corner then races past the end of its edge (random20886: 1.8e7 m/m along
  // a ridge, the second wall 5e-8 rad off, the crossing 6 m short). Only then is the meeting
  // predicted along the shared edge instead: where the two corners reach one place along it, a
  // well-conditioned solve. Where the plane's crossing is kept, it stands (and a coincident
  // collapse along a ridge stays one event).
  if (c.speed * tol_.height > tol_.cluster) {
    for (const bool forward : {false, true}) {
      const int ei = forward ? c.next : c.prev;
      const int cj = forward ? edges_[ei].end : edges_[ei].start;
      if (cj < 0 || cj == ci || !corners_[cj].alive) continue;
      const int eo = forward ? corners_[cj].next : corners_[cj].prev;
      if (eo < 0 || eo == c.prev || eo == c.next || !edges_[eo].alive) continue;
      const Edge& e = edges_[ei];
      const Edge& o = edges_[eo];
      if (!(OpenMesh::dot(e.d, o.d) > 0 && std::abs(cross2(e.d, o.d)) <= tol_.mergeSine)) continue;
      // The crossing with the second edge's plane, as predict computes it: kept (or beyond
      // lastUseful), it stands.
      const double dn = OpenMesh::dot(o.n, v) - o.k;
      if (std::abs(dn) < 1e-14) continue;
      const double zPlane = (o.c - OpenMesh::dot(o.n, q)) / dn;
      if (!std::isfinite(zPlane) || zPlane > after) continue;
      // Along the edge: where the racing corner and the far corner reach one place on it.
      const Vec2 pj = cornerAt(cj, z_), vj = cornerAt(cj, z_ + 1.0) - pj;
      const double denom = OpenMesh::dot(e.d, v - vj);
      if (std::abs(denom) < 1e-14) continue;
      const double z = OpenMesh::dot(e.d, pj - vj * z_ - q) / denom;
      if (!(z > after) || !std::isfinite(z) || z > before) continue;
      SWEEP_TRACE("   racing corner %d meets corner %d along edge %d at %.12g (the crossing with plane %d: %.12g)", ci, cj, ei,
                  z, eo, zPlane);
      h.push_back({z, q + v * z, ci, ++nextId_});
    }
  }
  if (h.size() == had) return;
  if (wasEmpty) std::make_heap(h.begin(), h.end(), std::greater<Candidate>());
  else
    for (std::size_t i = had; i < h.size(); ++i) std::push_heap(h.begin(), h.begin() + i + 1, std::greater<Candidate>());
  if (h.front().z < oldHead) queue_.push(h.front());
}

// Predictions this little above the height a corner was made at are what that event handled.
// δ1 for most corners; a racing corner covers metres in δ1 (an initial corner between a
// shallow roof and a wall 2.5e-7 rad off it races at 1e7 m per m of rise and may sweep its
// whole edge in that height), so for it, the height in which it moves kRaceSettle δ2.
constexpr double kRaceSettle = 2;

double Sweeper::settle(const Corner& c) const {
  return c.speed > 0 ? std::min(tol_.height, kRaceSettle * tol_.cluster / c.speed) : tol_.height;
}

// Predictions above this height can never be handled: at the next angle step of either of
// the corner's edges, the direction event replaces that edge and kills the corner (its
// candidates are then dropped unseen). The step's height comes from the input edge, which an
// edge keeps through splits. Four δ1 of margin cover the clustering of direction heights
// (each edge changes at the first kept height within δ1 below its step) and a sweep stopped
// near that height (it handles events up to δ1 past its stop). Most candidates of a corner
// between two steep mansard planes lie far above the shallow step that ends them: in the
// 50-corner re-extrusion benchmark this drops about half of them.
double Sweeper::lastUseful(const Corner& c) const {
  double h = std::numeric_limits<double>::infinity();
  for (int ei : {c.prev, c.next}) {
    const Edge& e = edges_[ei];
    const auto& steps = inputs_[e.src]->steps;
    if (e.step + 1 < static_cast<int>(steps.size())) h = std::min(h, steps[e.step + 1].z + 4 * tol_.height);
  }
  return h;
}

void Sweeper::syncLive() {
  auto compact = [](std::vector<int>& live, auto alive) {
    live.erase(std::remove_if(live.begin(), live.end(), [&](int i) { return !alive(i); }), live.end());
  };
  compact(liveCorners_, [&](int i) { return corners_[i].alive; });
  compact(liveEdges_, [&](int i) { return edges_[i].alive; });
  for (; syncedCorners_ < corners_.size(); ++syncedCorners_)
    if (corners_[syncedCorners_].alive) liveCorners_.push_back(static_cast<int>(syncedCorners_));
  for (; syncedEdges_ < edges_.size(); ++syncedEdges_)
    if (edges_[syncedEdges_].alive) liveEdges_.push_back(static_cast<int>(syncedEdges_));
}

void Sweeper::push(Candidate c) {
  c.id = ++nextId_;
  auto& h = pending_[c.corner];
  const bool head = h.empty() || c.z < h.front().z;
  h.push_back(c);
  std::push_heap(h.begin(), h.end(), std::greater<Candidate>());
  if (head) queue_.push(c);
}

// The earliest prediction of a live corner, if any (stale global entries are dropped).
bool Sweeper::nextCandidate(Candidate& out) {
  while (!queue_.empty()) {
    const Candidate& t = queue_.top();
    auto& h = pending_[t.corner];
    if (!corners_[t.corner].alive) {
      h.clear();
      h.shrink_to_fit();
      queue_.pop();
      continue;
    }
    if (!h.empty() && h.front().id == t.id) {
      out = t;
      return true;
    }
    queue_.pop();
  }
  return false;
}

void Sweeper::predictAgainst(const std::vector<int>& planes) {
  // Every live corner against each new plane, plane by plane; each corner's path and the
  // heights its predictions must lie between are worked out once for all the planes.
  syncLive();
  std::vector<CornerPath>& paths = paths_;
  paths.resize(liveCorners_.size());
  for (std::size_t k = 0; k < liveCorners_.size(); ++k) {
    const int ci = liveCorners_[k];
    const Corner& c = corners_[ci];
    if (!c.alive) continue;
    const Vec2 p0 = cornerAt(ci, z_), p1 = cornerAt(ci, z_ + 1.0);
    const Vec2 v = p1 - p0;
    paths[k] = {v, p0 - v * z_, std::max(c.z0 + settle(c), z_ + tol_.height), lastUseful(c)};
  }
  for (int ei : planes) {
    checkClock();
    const Edge& e = edges_[ei];
    for (std::size_t k = 0; k < liveCorners_.size(); ++k) {
      const int ci = liveCorners_[k];
      const Corner& c = corners_[ci];
      if (!c.alive || c.prev == ei || c.next == ei) continue;
      const CornerPath& path = paths[k];
      const double denom = OpenMesh::dot(e.n, path.v) - e.k;
      if (std::abs(denom) < 1e-14) continue;
      const double z = (e.c - OpenMesh::dot(e.n, path.q)) / denom;
      if (!(z > path.lo) || !std::isfinite(z) || z > path.hi) continue;
      push({z, path.q + path.v * z, ci});
    }
  }
}

}  // namespace corbel::extrude::sweeping
