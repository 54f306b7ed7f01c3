// Finding a generalized intersection event (Sec. 4.4): event clustering, filtering invalid
// events, the event point, and the guards against events that feed themselves.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace corbel::extrude::sweeping {

// A generalized intersection event (Sec. 4.4): the candidate's cluster of arriving corners,
// the edges through its point, and the point itself; then the chains change the plan
// (chains.cpp) and the result is checked (post_inter_chain.cpp).
bool Sweeper::handleIntersection(const Candidate& cand) {
  const double z = cand.z;
  Vec2 l;
  if (!clusterEvent(cand, l) || !filterEvent(l, z)) return false;
  placeEvent(l, z);
  refuseCascades(l, z);
  ++events_;
  const int vl = addVertex(l, z);
  SWEEP_TRACE("event %zu at (%g, %g, %g): %zu corners, %zu edges, %zu splits -> v%d", events_, l[0], l[1], z, arriving_.size(),
              involvedList_.size(), splitList_.size(), vl);
  for (int ci : arriving_) killCorner(ci, vl);  // the arriving corners end at l

  buildChains();
  intraChain();
  if (!interChain(vl, l, z)) return true;
  // The new corners: resolved where degenerate (ambiguities.cpp), then predicted.
  const std::vector<int>& newCorners = newCorners_;
  const std::size_t firstMade = corners_.size() - newCorners.size();
  for (int ci : newCorners) resolveCorner(ci, z);
  for (int ci : newCorners)
    if (corners_[ci].alive) predict(ci);
  postInterChain(firstMade, vl, l, z);
  return true;
}

// Events within δ1 of height are one event (Sec. 4.4), so a corner arrives at p if its path
// passes within δ2 of p somewhere within δ1 of z. For most corners this is where it is at z;
// a corner racing along a near-flat ridge (between almost antiparallel edges) moves thousands
// of metres per metre of rise, and the rounding of two predictions of one event in height
// alone would put it microns away.
constexpr double kRaceReach = 100;
// Walls this close to one line (a sine) make a near-straight corner (nearestOnPath).
constexpr double kNearStraight = 1e-4;
// ... and a racing corner may reach such a corner this many δ2 along its path (nearestOnPath).
constexpr double kFarEndReach = 1000;

Vec2 Sweeper::nearestOnPath(int ci, const Vec2& p, double z) const {
  // A corner does not exist below the height it was made at: events clustered within δ1 may
  // come a little below an event already handled, and a racing corner made there, taken back
  // along its path, would sweep the whole ridge it is about to zip in no height at all.
  const double z0 = corners_[ci].z0;
  z = std::max(z, z0);
  const Vec2 at = cornerAt(ci, z);
  const Vec2& v = corners_[ci].v;
  const double vv = OpenMesh::dot(v, v);
  // Slower corners move less than δ2 in δ1 of height: their place at z decides, so the
  // clustering of ordinary events stays exactly δ2.
  if (!(vv * tol_.height * tol_.height > tol_.cluster * tol_.cluster)) return at;
  // ... but never further along its path than kRaceReach δ2, so a corner racing at 1e8 m/m
  // cannot skip past the ends of its own edges into an unrelated event on its line. Its own
  // edge's far end, where that end is a near-straight corner (the edge and the next wall
  // within kNearStraight of one line), it reaches further: there the two small sines leave
  // the meeting point uncertain along the ridge by far more than kRaceReach δ2, while its
  // height is certain to 1e-9 m. Back along its path (it has passed that corner) anywhere
  // within δ1 of height; ahead, up to kFarEndReach δ2 (further ahead it may still meet
  // something else first); never when it was made within 2 δ1. osm:w387700951: a hip end's
  // ridge corner had passed the opposite wall's corner (1.1e-5 rad off straight) by 108 δ2;
  // missed, it split that wall and left a two-edge sliver 0.46 m above the ridge. In a dozen
  // random plans (walls 1e-9 to 1e-7 rad off one line) a corner had passed by 0.03 to 1 m,
  // within δ1, and left a face that ran past the corner and back.
  const double tp = OpenMesh::dot(v, p - at) / vv;
  if (tp >= -tol_.height && tp * std::sqrt(vv) <= kFarEndReach * tol_.cluster && tp >= z0 - z && z - z0 > 2 * tol_.height) {
    const Corner& c = corners_[ci];
    for (const int ei : {c.prev, c.next}) {
      const bool forward = ei == c.next;
      const int cj = forward ? edges_[ei].end : edges_[ei].start;
      if (cj < 0 || cj == ci || !corners_[cj].alive) continue;
      const int eo = forward ? corners_[cj].next : corners_[cj].prev;
      if (eo < 0 || !edges_[eo].alive) continue;
      const Edge& e = edges_[ei];
      const Edge& o = edges_[eo];
      if (!(OpenMesh::dot(e.d, o.d) > 0 && std::abs(cross2(e.d, o.d)) <= kNearStraight)) continue;
      if ((liveAt(cj, z) - p).norm() <= tol_.cluster) {
        SWEEP_TRACE("   racing corner %d reaches the far end of edge %d, corner %d, %.3g above (%.3g m along its path, %.3g δ2; sine %.3g)", ci, ei, cj,
                    tp, tp * std::sqrt(vv), tp * std::sqrt(vv) / tol_.cluster, cross2(e.d, o.d));
        return at + v * tp;
      }
    }
  }
  const double window = std::min(tol_.height, kRaceReach * tol_.cluster / std::sqrt(vv));
  const double t = std::clamp(tp, std::max(-window, z0 - z), window);
  return at + v * t;
}

// Event clustering (Sec. 4.4).
bool Sweeper::clusterEvent(const Candidate& cand, Vec2& l) {
  const double z = cand.z;
  if (!corners_[cand.corner].alive) return false;
  if ((nearestOnPath(cand.corner, cand.p, z) - cand.p).norm() > tol_.cluster) {
    SWEEP_TRACE("   its corner is no longer there");
    return false;
  }

  // Corners that arrive at the point.
  // (The lists are members, reused: most candidates are no event, and they cost more to
  // allocate than to fill.)
  std::vector<int>& K = arriving_;
  K.clear();
  l = Vec2(0.0, 0.0);
  syncLive();
  for (int ci : liveCorners_) {
    // Far corners are rejected from where their lines met at z0 and their speed alone; the
    // bound is loose by 2 δ2 plus a relative margin far above rounding, so no corner within δ2
    // of the point is ever skipped.
    const Corner& c = corners_[ci];
    const double travel = c.speed * (std::abs(z - c.z0) + tol_.height);
    const double reach = travel + 2 * tol_.cluster + 1e-12 * (c.baseNorm + travel);
    if ((c.base - cand.p).sqrnorm() > reach * reach) continue;
    const Vec2 p = nearestOnPath(ci, cand.p, z);
    if ((p - cand.p).norm() <= tol_.cluster) {
      K.push_back(ci);
      l += p;
    }
  }
  if (K.empty()) return false;
  l /= static_cast<double>(K.size());
  Marks& inK = inK_;
  inK.reset(corners_.size());
  for (int ci : K) inK.set(ci);
  return true;
}

// Filtering invalid events (Sec. 4.4).
bool Sweeper::filterEvent(const Vec2& l, double z) {
  const std::vector<int>& K = arriving_;
  const Marks& inK = inK_;
  // Edges through the point: those of arriving corners, and edges the point splits.
  std::vector<int>& involved = involvedList_;
  involved.clear();
  Marks& isInvolved = involved_;
  isInvolved.reset(edges_.size());
  auto involve = [&](int ei) {
    if (!isInvolved[ei]) {
      isInvolved.set(ei);
      involved.push_back(ei);
    }
  };
  for (int ci : K) {
    involve(corners_[ci].prev);
    involve(corners_[ci].next);
  }
  std::vector<int>& splits = splitList_;
  splits.clear();
  for (int ei : liveEdges_) {
    const Edge& e = edges_[ei];
    if (!e.alive || isInvolved[ei]) continue;
    if (std::abs(OpenMesh::dot(e.n, l) - (e.c + e.k * z)) > tol_.cluster) continue;
    const Vec2 s = liveAt(e.start, z), t = liveAt(e.end, z);
    const double along = OpenMesh::dot(e.d, l - s), length = OpenMesh::dot(e.d, t - s);
    if (along < -tol_.edgeMargin || along > length + tol_.edgeMargin) continue;
    involve(ei);
    splits.push_back(ei);
  }
  if (splits.empty()) {
    // Corners that an event made at this point a moment ago, meeting only one another again:
    // nothing has happened since; a prediction against a plane within rounding of one of
    // theirs (a wall 6e-9 rad off its colinear neighbour) brought the sweep back here, and
    // relinking them would undo what that event did. Two or more corners made at one vertex
    // qualify wherever the event point now lies: their paths are straight lines out of that
    // vertex, which meet again nowhere else, so a fast one that has moved more than δ2 off it
    // in the height by which the prediction is off has not met anything either (the sharp
    // corner a split made, at 3.4 m/m and 1.4e-7 m higher, relinked with its partner, undid
    // the split and left two corners on one path: random11959). A two-edge loop (fewer than
    // three planes) is left to the test below, which closes it.
    // (Corners an edge direction event has just made are exempt: it met nothing at their point.)
    bool madeHere = true, oneVertex = K.size() > 1 && involved.size() > 2;
    for (int ci : K) {
      if (corners_[ci].turned && z - points_[corners_[ci].vertex][2] <= tol_.height) madeHere = oneVertex = false;
      const Vec3& p = points_[corners_[ci].vertex];
      const bool recent = z - p[2] <= 1e3 * tol_.cluster;
      madeHere = madeHere && std::abs(p[0] - l[0]) <= tol_.cluster && std::abs(p[1] - l[1]) <= tol_.cluster && recent;
      oneVertex = oneVertex && corners_[ci].vertex == corners_[K[0]].vertex && recent;
    }
    if (madeHere || oneVertex) {
      SWEEP_TRACE("   only corners made here a moment ago meet there%s",
                  madeHere ? "" : " (at one vertex, moved off it)");
      return false;
    }
  }
  if (involved.size() < 3) {
    // Fewer than three planes meet only where a whole loop has shrunk to the point (a
    // two-edge sliver whose corners arrive together).
    bool closed = true;
    for (int ei : involved) closed = closed && inK[edges_[ei].start] && inK[edges_[ei].end];
    if (!closed) {
      SWEEP_TRACE("   only %zu planes meet there", involved.size());
      return false;
    }
  }
  return true;
}

void Sweeper::placeEvent(Vec2& l, double z) const {
  const std::vector<int>& involved = involvedList_;
  // The event point: the least-squares meeting point of all involved lines at this height
  // (closer to every plane than the mean of the arriving corners), unless they are too close
  // to parallel to pin it down.
  {
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (int ei : involved) {
      const Edge& e = edges_[ei];
      const double r = e.c + e.k * z;
      a11 += e.n[0] * e.n[0], a12 += e.n[0] * e.n[1], a22 += e.n[1] * e.n[1];
      b1 += e.n[0] * r, b2 += e.n[1] * r;
    }
    const double det = a11 * a22 - a12 * a12;
    if (det > 1e-6 * (a11 + a22) * (a11 + a22)) {
      const Vec2 ls((a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det);
      if ((ls - l).norm() <= tol_.cluster) l = ls;
    }
  }
}

void Sweeper::refuseCascades(const Vec2& l, double z) {
  const std::vector<int>& involved = involvedList_;
  // A cascade of events at one point within a sliver of height means the configuration
  // re-creates itself (coincident corner paths): stop with a reason instead of looping.
  if ((l - lastEventPoint_).norm() <= tol_.cluster && z - lastEventZ_ <= 1e3 * tol_.cluster) {
    if (++repeats_ > 32) {
      std::ostringstream m;
      m << "degenerate event cascade at (" << l[0] << ", " << l[1] << ", " << z
        << "): coincident corner paths the sweep cannot separate";
      throw Error(m.str());
    }
  } else {
    repeats_ = 0;
    lastEventPoint_ = l;
    lastEventZ_ = z;
  }
  {
    // However degenerate, a plan of n edges has no more than a few n events at one height
    // (each ends an edge or splits one, and splits are used up by the ends they cause). Far
    // more within a sliver of height means the events feed themselves: stop with a reason.
    if (z - burstZ_ > 1e3 * tol_.cluster) {
      burstZ_ = z;
      burst_ = 0;
    }
    if (++burst_ > 4 * inputs_.size() + 64) {
      std::ostringstream m;
      m << "degenerate event cascade at (" << l[0] << ", " << l[1] << ", " << z << "): " << burst_
        << " events without rising, from a plan of " << inputs_.size() << " edges (an earlier configuration was degenerate)";
      throw Error(m.str());
    }
  }
  {
    // Relinking the same edges again and again, each time a sliver higher, never ends the
    // sweep (it would crawl up at 1e-7 m per event): stop with a reason after 64 rounds.
    std::vector<int>& sig = signature_;
    sig.assign(involved.begin(), involved.end());
    std::sort(sig.begin(), sig.end());
    bool again = false;
    for (int k = 0; k < 2; ++k) again = again || (sig == lastInvolved_[k] && z - lastInvolvedZ_[k] <= 1e3 * tol_.cluster);
    swaps_ = again ? swaps_ + 1 : 0;
    if (swaps_ > 64) {
      std::ostringstream m;
      m << "degenerate event cycle at (" << l[0] << ", " << l[1] << ", " << z << "): the same " << sig.size()
        << " edges are relinked back and forth (the active plan overlaps itself along a line there)";
      throw Error(m.str());
    }
    // The three lists trade places, so none is allocated again.
    lastInvolved_[1].swap(lastInvolved_[0]);
    lastInvolvedZ_[1] = lastInvolvedZ_[0];
    lastInvolved_[0].swap(sig);
    lastInvolvedZ_[0] = z;
  }
}

}  // namespace corbel::extrude::sweeping
