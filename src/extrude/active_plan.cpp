// The active plan's geometry and topology (Sec. 4.1–4.2): each edge on its direction plane,
// each corner moving where its two edges' lines meet, the shell's vertices welded at one
// height, and corners made and ended at events. Where a corner arrives: intersection_event.cpp.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::extrude::sweeping {

void Sweeper::setEdgePlane(Edge& e, const Vec2& d, const Vec2& p, double z, double angle) {
  e.d = d;
  e.n = leftOf(d);
  e.k = std::tan(angle);
  e.c = OpenMesh::dot(e.n, p) - e.k * z;
}

void Sweeper::setCornerMotion(int ci, const Vec2& at, double z) {
  Corner& c = corners_[ci];
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double det = cross2(a.n, b.n);
  c.p0 = at;
  c.z0 = z;
  // Neighbours on almost one line in one direction with one angle: their lines may meet
  // metres from the corner (two walls 2e-8 rad apart whose offsets differ by 1e-7 m meet 5 m
  // away), and the corner, which sits where the event made it, would jump there. It moves
  // with the edges instead, as between parallel ones.
  const bool oneLine = OpenMesh::dot(a.d, b.d) > 0 && a.k == b.k;
  bool straight = oneLine && std::abs(det) <= tol_.mergeSine && (cornerAt(ci, z) - at).norm() > tol_.cluster;
  // Up to ridgeMaxSine the same holds where both lines pass within δ2 of the event point (so
  // their meeting point is known only to δ2 / sine along them) and they meet beyond the far
  // end of one of the two edges: there the corner would turn that edge inside out, and the
  // plan would overlap itself (random1023: two gable walls 1.4e-7 rad apart meeting 1.9 m
  // away, past a 1.5 m wall's end, ran that gable's top out and back; random34510 overlapped).
  // Not where an edge has taken over a colinear neighbour's extent (mergeColinear): its line
  // lies off that extent by up to sine × length, and the meeting point is where the perturbed
  // plan's roof agrees with the unperturbed plan's (random12886 moves 0.6 % off it when the
  // corner stays).
  if (!straight && oneLine && !a.merged && !b.merged && std::abs(det) <= tol_.ridgeMaxSine &&
      std::abs(OpenMesh::dot(a.n, at) - (a.c + a.k * z)) <= tol_.cluster &&
      std::abs(OpenMesh::dot(b.n, at) - (b.c + b.k * z)) <= tol_.cluster) {
    const double meet = (cornerAt(ci, z) - at).norm();
    double nearestEnd = INFINITY;
    for (const int cj : {a.start, b.end})
      if (cj >= 0 && cj != ci && corners_[cj].alive) nearestEnd = std::min(nearestEnd, (liveAt(cj, z) - at).norm());
    straight = meet > nearestEnd;
    if (straight)
      SWEEP_TRACE("  corner %d stays: its lines meet %g m away, past an end %g m away", ci, meet, nearestEnd);
  }
  if (std::abs(det) > tol_.parallelSine && !straight) {
    c.parallel = false;
    c.v = Vec2((a.k * b.n[1] - b.k * a.n[1]) / det, (a.n[0] * b.k - b.n[0] * a.k) / det);
    c.speed = c.v.norm();
    if (c.speed * tol_.height > tol_.cluster) {
      // A racing corner (see nearestOnPath): its lines meet so obliquely that the rounding of
      // the event's height (1e-9 relative) moves their meeting point by decimetres along the
      // ridge. It is made where its lines pass through the event point, which may be a little
      // above the event; below that it does not exist yet (liveAt), and cannot reach back
      // along its ridge into events below. "A little" is δ1, or more where both lines pass
      // within δ2 of the point (as every line of the event does): a split by a wall 6e-8 rad
      // off antiparallel puts their meeting point 0.4 m back along the ridge, 1.3 δ1 below,
      // and a corner made there crossed the event point again and undid the split.
      const double later = OpenMesh::dot(c.v, at - cornerAt(ci, z)) / (c.speed * c.speed);
      const double offA = std::abs(OpenMesh::dot(a.n, at) - (a.c + a.k * z));
      const double offB = std::abs(OpenMesh::dot(b.n, at) - (b.c + b.k * z));
      if (later > 0 && (later <= tol_.height || std::max(offA, offB) <= tol_.cluster)) c.z0 = z + later;
    }
    c.base = cornerAt(ci, c.z0);
    c.baseNorm = c.base.norm();
    return;
  }
  // Parallel neighbours: colinear edges of one plane move the corner with them; an
  // antiparallel spike is zipped before it moves (resolveCorner).
  c.parallel = true;
  c.v = OpenMesh::dot(a.d, b.d) > 0 ? a.n * a.k : Vec2(0.0, 0.0);
  c.speed = c.v.norm();
  c.base = at;
  c.baseNorm = at.norm();
}

// Points made at one event height that coincide are one vertex: several corners and zips of
// one event (or of events clustered at one height) meet there, and the shell must share it.
bool Sweeper::cellOf(const Vec2& p, std::int64_t& ix, std::int64_t& iy) const {
  const double x = std::floor(p[0] / tol_.cluster), y = std::floor(p[1] / tol_.cluster);
  if (!(std::abs(x) < 1e15 && std::abs(y) < 1e15)) return false;  // also NaN
  ix = static_cast<std::int64_t>(x);
  iy = static_cast<std::int64_t>(y);
  return true;
}

namespace {
std::uint64_t cellKey(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(iy);
}
}  // namespace

int Sweeper::addVertex(const Vec2& p, double z) {
  constexpr std::size_t kGridFrom = 64;  // below this many, a scan of the list is cheaper
  if (recentZ_ != z) {
    if (std::abs(recentZ_ - z) > tol_.height) {
      recent_.clear();
      if (!recentGrid_.empty()) recentGrid_.clear();
    }
    recentZ_ = z;
  }
  auto near = [&](int v) {
    return std::abs(points_[v][0] - p[0]) <= tol_.cluster && std::abs(points_[v][1] - p[1]) <= tol_.cluster;
  };
  std::int64_t ix = 0, iy = 0;
  const bool gridded = recent_.size() >= kGridFrom && cellOf(p, ix, iy);
  if (recent_.size() == kGridFrom) {
    // Switching to the grid: the list so far goes in (points no cell holds stay in the list).
    for (int v : recent_) {
      std::int64_t vx, vy;
      if (cellOf(Vec2(points_[v][0], points_[v][1]), vx, vy)) recentGrid_[cellKey(vx, vy)].push_back(v);
    }
  }
  if (gridded) {
    // The first vertex made within δ2 (the least index), as the scan of the list found it.
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = recentGrid_.find(cellKey(ix + dx, iy + dy));
        if (it == recentGrid_.end()) continue;
        for (int v : it->second)
          if ((found < 0 || v < found) && near(v)) found = v;
      }
    if (found >= 0) return found;
  } else {
    for (int v : recent_)
      if (near(v)) return v;
  }
  points_.emplace_back(p[0], p[1], z);
  const int v = static_cast<int>(points_.size()) - 1;
  recent_.push_back(v);
  if (recent_.size() > kGridFrom && cellOf(p, ix, iy)) recentGrid_[cellKey(ix, iy)].push_back(v);
  return v;
}

int Sweeper::addFace(int src, int segment, double angle, const Edge& e) {
  FaceBuild f;
  f.src = src;
  f.segment = segment;
  f.angle = angle;
  // Outward normal of the direction plane n·x − k z = c is −(n, −k), normalised.
  f.normal = Vec3(-e.n[0], -e.n[1], e.k);
  f.normal.normalize();
  f.segments.reserve(4);  // its bottom, two sides and a top, in the common case
  faces_.push_back(std::move(f));
  return static_cast<int>(faces_.size()) - 1;
}

int Sweeper::newCorner(int prev, int next, int vertex, const Vec2& at, double z) {
  SWEEP_TRACE("  new corner %zu: edges %d -> %d at v%d (%g, %g, %g)", corners_.size(), prev, next, vertex, at[0], at[1],
              z);
  Corner c;
  c.prev = prev;
  c.next = next;
  c.vertex = vertex;
  c.turned = turning_;
  corners_.push_back(c);
  pending_.emplace_back();
  const int ci = static_cast<int>(corners_.size()) - 1;
  edges_[prev].end = ci;
  edges_[next].start = ci;
  setCornerMotion(ci, at, z);
  stepToWhereItStarts(ci, at, z);
  SWEEP_TRACE("    v=(%g, %g), sine %g", corners_[ci].v[0], corners_[ci].v[1], cross2(edges_[prev].n, edges_[next].n));
  return ci;
}

// A corner lives where its two lines meet. Between edges of almost one line that point may lie
// metres from the event that made the corner, though both lines pass within δ2 of the event
// (a wall 1.2e-7 rad off its neighbour's line meets it 0.76 m along: random56778), and where
// setCornerMotion lets it go there, the corner starts there. Its path then begins with a level
// step at the event's height from the event's vertex to where it is, which both of its edges'
// faces must share: without it, the arc ran straight from the event up to where the corner ended,
// across the face's own top (a wall's top past its end and back, a roof face past its ridge:
// random39100, random56778, random84790, random89383), and a shell whose only gap was the
// step stayed open (random58375). Racing corners are not stepped: they begin where their lines pass
// through the event point (setCornerMotion), and corners moving with their edges begin at it.
// Steps within the collapse length are rounding, left to the clean-up (collapseShortEdges).
void Sweeper::stepToWhereItStarts(int ci, const Vec2& at, double z) {
  const Corner& c = corners_[ci];
  if (c.parallel || c.vertex < 0 || c.speed * tol_.height > tol_.cluster) return;
  const Vec2 start = cornerAt(ci, z);
  if (!((start - at).norm() > tol_.collapse)) return;
  const int v = addVertex(start, z);
  SWEEP_TRACE("    corner %d starts %g m from its event, at v%d", ci, (start - at).norm(), v);
  arc(ci, v);
  corners_[ci].vertex = v;
}

// The corner's path from where it was created to topVertex is an arc shared by the faces of
// its two edges: the edge ending here sees it going up, the edge starting here going down.
void Sweeper::arc(int ci, int top) {
  const Corner& c = corners_[ci];
  if (c.vertex == top) return;
  faces_[edges_[c.prev].face].segments.emplace_back(c.vertex, top);
  faces_[edges_[c.next].face].segments.emplace_back(top, c.vertex);
}

void Sweeper::killCorner(int ci, int top) {
  arc(ci, top);
  corners_[ci].alive = false;
}

}  // namespace corbel::extrude::sweeping
