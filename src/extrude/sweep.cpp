// The sweep-plane algorithm of Kelly & Wonka (Sec. 4.2): the driver. It builds the initial
// active plan, takes events from the queue in height order (edge direction events before
// intersection events at one height), and closes or hands back what is left. The steps it
// calls live in files of their own (sweeper.h lists them).
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace corbel::extrude::sweeping {

// A loop left at the base when no event is left, every edge of which is vertical for good: it
// never rises, and capping it would make a shell of no volume. That is the spec's doing, not
// rounding's: each straight run of the plan mixes sloped edges with gables (vertical last
// segments), and the priority (Sec. 4.8) gives the run to a gable at the base, as volume
// maximising does (random33502, random35776). Said as bad input, naming the edges.
void Sweeper::refuseStandingLoop(const std::vector<int>& loop) const {
  std::vector<int> sources;
  const SweepEdge* first = nullptr;
  for (int ci : loop) {
    const Edge& e = edges_[corners_[ci].next];
    const SweepEdge& in = *inputs_[e.src];
    if (e.k != 0 || e.step + 1 < static_cast<int>(in.steps.size())) return;  // it rises, or will
    if (!first) first = &in;
    else if (in.step != first->step || in.sourceLoop != first->sourceLoop) return;  // not one loop of the spec's
    sources.push_back(in.sourceEdge);
  }
  if (!first) return;
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  std::ostringstream where, why;
  if (first->step >= 0) where << "steps[" << first->step << "]";
  else where << "loops[" << first->sourceLoop << "]";
  why << "the roof cannot close: every edge left of this loop at its base is vertical for good (edge";
  if (sources.size() > 1) why << "s";
  for (std::size_t i = 0; i < sources.size() && i < 12; ++i) why << (i ? ", " : " ") << sources[i];
  if (sources.size() > 12) why << ", ...";
  why << "), the sloped edges in line with them having given way by priority (Sec. 4.8), so nothing "
         "rises; give each straight run a sloped last segment, or let the sloped edges win "
         "(priority minimise_volume, or manual with their segments tagged high)";
  throw InputError(where.str(), why.str());
}

// Loops still open when no event is left (a missed event in a degenerate configuration):
// close each with a flat cap so the shell stays closed, and say so.
void Sweeper::capRemaining(double z, std::vector<std::vector<PlanCorner>>* plan) {
  std::vector<char> seen(corners_.size(), 0);
  int capped = 0;
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    if (!corners_[ci].alive || seen[ci]) continue;
    std::vector<int> loop;
    int cur = ci;
    while (!seen[cur]) {
      seen[cur] = 1;
      loop.push_back(cur);
      cur = edges_[corners_[cur].next].end;
      if (cur < 0) break;
    }
    if (!plan && in_.emitBase && z <= in_.baseZ + tol_.height) refuseStandingLoop(loop);
    FaceBuild cap;
    cap.normal = Vec3(0, 0, 1);
    cap.segment = -2;
    std::vector<int> verts;
    std::vector<PlanCorner> out;
    for (int c : loop) {
      const Vec2 p = cornerAt(c, z);
      verts.push_back(addVertex(p, z));
      out.push_back({p, verts.back(), edges_[corners_[c].next].src});
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int c = loop[i];
      killCorner(c, verts[i]);
      const int e = corners_[c].next;
      const int vs = verts[i], vt = verts[(i + 1) % loop.size()];
      faces_[edges_[e].face].segments.emplace_back(vt, vs);
      cap.segments.emplace_back(vs, vt);
      edges_[e].alive = false;
    }
    if (plan) {
      plan->push_back(std::move(out));
      continue;
    }
    faces_.push_back(std::move(cap));
    ++capped;
  }
  if (capped) {
    std::ostringstream s;
    s << "the roof did not close: " << capped << " loop(s) were capped flat at height " << z
      << " (a degenerate configuration, Sec. 4.4 Fig. 15)";
    warnings_.push_back(s.str());
  }
}

SweepOutput Sweeper::run() {
  started_ = std::chrono::steady_clock::now();
  z_ = in_.baseZ;
  // Room for what a plan of n edges usually makes (an event ends or splits an edge and makes
  // a corner or two; a face has a few pieces), so a small shell grows no list piece by piece.
  std::size_t n = 0, faces = 1;
  for (const auto& loop : in_.loops) {
    n += loop.size();
    for (const SweepEdge& e : loop) faces += e.steps.size();
  }
  const std::size_t room = 2 * n + 8;
  inputs_.reserve(n);
  edges_.reserve(room);
  corners_.reserve(room);
  pending_.reserve(room);
  points_.reserve(room);
  faces_.reserve(faces);
  liveCorners_.reserve(room);
  liveEdges_.reserve(room);
  recent_.reserve(n);
  for (Marks* m : {&inK_, &involved_, &used_}) m->reserve(room);
  {
    std::vector<Candidate> heads;
    heads.reserve(room);
    queue_ = decltype(queue_)(std::greater<Candidate>(), std::move(heads));
  }
  // Input edges, their first faces, and the base.
  FaceBuild base;
  base.base = true;
  base.normal = Vec3(0, 0, -1);
  base.segments.reserve(n);
  std::vector<int> verts;
  for (const auto& loop : in_.loops) {
    const int first = static_cast<int>(edges_.size());
    const int n = static_cast<int>(loop.size());
    verts.clear();
    verts.reserve(n);
    // (The clock is read every 1,024 corners here too: a plan of 100,000 takes a while to set up.)
    for (int i = 0; i < n; ++i) {
      if ((i & 1023) == 1023) checkClock();
      verts.push_back(addVertex(loop[i].start, z_));
    }
    for (int i = 0; i < n; ++i) {
      if ((i & 1023) == 1023) checkClock();
      inputs_.push_back(&loop[i]);
      Edge e;
      e.src = static_cast<int>(inputs_.size()) - 1;
      Vec2 d = loop[(i + 1) % n].start - loop[i].start;
      d.normalize();
      setEdgePlane(e, d, loop[i].start, z_, loop[i].steps[0].angle);
      e.face = addFace(e.src, loop[i].steps[0].segment, loop[i].steps[0].angle, e);
      edges_.push_back(e);
      faces_[e.face].segments.emplace_back(verts[i], verts[(i + 1) % n]);
      base.segments.emplace_back(verts[(i + 1) % n], verts[i]);
      for (std::size_t s = 1; s < loop[i].steps.size(); ++s) directionHeights_.push_back(loop[i].steps[s].z);
    }
    for (int i = 0; i < n; ++i) {
      const int prev = first + (i + n - 1) % n, next = first + i;
      newCorner(prev, next, verts[i], loop[i].start, z_);
    }
  }
  if (in_.emitBase) faces_.push_back(base);
  std::sort(directionHeights_.begin(), directionHeights_.end());
  directionHeights_.erase(std::unique(directionHeights_.begin(), directionHeights_.end(),
                                      [&](double a, double b) { return std::abs(a - b) <= tol_.height; }),
                          directionHeights_.end());
  const int initialCorners = static_cast<int>(corners_.size());
  for (int ci = 0; ci < initialCorners; ++ci) {
    if ((ci & 1023) == 1023) checkClock();
    resolveCorner(ci, z_);
  }
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    checkClock();
    if (corners_[ci].alive) predict(ci);
  }

  // No real event lies far above the plan: the roof over a plan of size s whose edges climb
  // at most k per metre inward tops out within s·k of the last profile change. Events far
  // beyond that mean the sweep has diverged in a degenerate configuration: fail at once
  // instead of chasing them up to the event limit, and cap what is left.
  double maxK = 1.0, lastChange = in_.baseZ;
  for (const SweepEdge* e : inputs_)
    for (const auto& st : e->steps) {
      maxK = std::max(maxK, std::abs(std::tan(st.angle)));
      lastChange = std::max(lastChange, st.z);
    }
  const double scale = tol_.minEdge / 1e-7;
  const double divergedZ = lastChange + 1e3 * scale * maxK;
  std::size_t nextDirection = 0;
  const std::size_t cap = 200000 + 400 * edges_.size() * edges_.size();
  std::size_t popped = 0;
  Candidate cand{};
  std::vector<std::vector<std::vector<PlanCorner>>> probed;
  while (true) {
    const bool any = nextCandidate(cand);
    const double nextEventZ = any ? cand.z : std::numeric_limits<double>::infinity();
    {
      // Probes below everything still to come see the plan as it is between events.
      double upcoming = nextEventZ;
      if (nextDirection < directionHeights_.size()) upcoming = std::min(upcoming, directionHeights_[nextDirection]);
      while (probed.size() < in_.probes.size() && in_.probes[probed.size()] + tol_.height < upcoming &&
             in_.probes[probed.size()] < stopZ_)
        probed.push_back(snapshot(in_.probes[probed.size()]));
    }
    if (nextDirection < directionHeights_.size() && directionHeights_[nextDirection] <= nextEventZ + tol_.height &&
        directionHeights_[nextDirection] < stopZ_ - tol_.height) {
      z_ = std::max(z_, directionHeights_[nextDirection]);
      handleDirectionChanges(directionHeights_[nextDirection++]);
      continue;
    }
    if (!any || nextEventZ > stopZ_ + tol_.height) break;
    if (++popped > cap) {
      warnings_.push_back("event limit reached; the result is incomplete");
      break;
    }
    if ((popped & 255) == 0) {
      if (progress_ && progress_->cancelled()) throw Cancelled();
      checkClock();
    }
    if (cand.z > divergedZ && std::isinf(stopZ_)) {
      // What is left is capped where the last real event was (capRemaining says so).
      std::ostringstream m;
      m << "the sweep diverged: the next event was at height " << cand.z << ", far above the plan";
      warnings_.push_back(m.str());
      diverged_ = true;
      break;
    }
    queue_.pop();
    auto& h = pending_[cand.corner];
    std::pop_heap(h.begin(), h.end(), std::greater<Candidate>());
    h.pop_back();
    if (!h.empty()) queue_.push(h.front());
    if (cand.z < z_ - tol_.height) continue;  // predicted before an earlier change
    SWEEP_TRACE(" candidate of corner %d at (%.12g, %.12g, %.12g)", cand.corner, cand.p[0], cand.p[1], cand.z);
    if (handleIntersection(cand)) {
      z_ = std::max(z_, cand.z);
      // An event can cost far more than a pop (hundreds of edges through one point in a
      // degenerate plan), so the time limit is also checked after every one.
      checkClock();
    }
  }
  if (overlaps_) {
    std::ostringstream m;
    m << "the active plan overlapped itself after " << overlaps_ << " event(s), first at (" << firstOverlap_[0] << ", "
      << firstOverlap_[1] << ", " << firstOverlap_[2] << "): a degenerate configuration (Sec. 4.4); the output may be undesirable";
    warnings_.push_back(m.str());
  }
  SweepOutput out;
  // Probes above the last event: the plan is empty if the roof closed, else as it stands.
  // (A sweep stopped for the winding rule leaves the probes above its stop to the next one.)
  while (probed.size() < in_.probes.size() && !(stoppedAtOverlap_ && in_.probes[probed.size()] >= stopZ_))
    probed.push_back(snapshot(in_.probes[probed.size()]));
  out.probed = std::move(probed);
  if (stoppedAtOverlap_) out.stoppedAt = stopZ_;
  if (std::isfinite(stopZ_)) capRemaining(stopZ_, &out.plan);
  else capRemaining(z_);
  buildFaces(out);
  out.warnings = std::move(warnings_);
  out.events = events_;
  out.diverged = diverged_;
  return out;
}

std::vector<std::vector<PlanCorner>> Sweeper::snapshot(double z) const {
  std::vector<std::vector<PlanCorner>> plan;
  std::vector<char> seen(corners_.size(), 0);
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    if (!corners_[ci].alive || seen[ci]) continue;
    std::vector<PlanCorner> loop;
    for (int cur = ci; cur >= 0 && !seen[cur]; cur = edges_[corners_[cur].next].end) {
      seen[cur] = 1;
      loop.push_back({cornerAt(cur, z), -1, edges_[corners_[cur].next].src});
    }
    if (loop.size() >= 3) plan.push_back(std::move(loop));
  }
  return plan;
}

}  // namespace corbel::extrude::sweeping

namespace corbel::extrude {

SweepOutput sweep(const SweepInput& input, const Tolerances& tol, Progress* progress) {
  sweeping::Sweeper s(input, tol, progress);
  return s.run();
}

}  // namespace corbel::extrude