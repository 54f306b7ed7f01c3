// Resolving a corner an event made (Sec. 4.4's degenerate chains, Sec. 4.8's ambiguities):
// antiparallel neighbours zip into a ridge, colinear neighbours of different angles merge by
// priority, and pieces of one input edge that lie in one line again become one edge.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::extrude::sweeping {

void Sweeper::resolveCorner(int ci, double z, int depth) {
  if (!corners_[ci].alive) return;
  if (depth > 64) {
    warnings_.push_back("unresolved degenerate corner cascade at height " + std::to_string(z));
    return;
  }
  const Corner& c = corners_[ci];
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double sine = std::abs(cross2(a.d, b.d));
  if (sine > std::max(tol_.mergeSine, tol_.ridgeMaxSine)) return;  // an ordinary corner
  if (OpenMesh::dot(a.d, b.d) < 0) {
    // Almost antiparallel: one line (a ridge) when they are within ridgeSine, or, up to
    // ridgeMaxSine, when the sliver between them is too small to matter (sine · L² of the
    // shorter edge under ridgeArea). Otherwise the corner races along the ridge exactly.
    // A loop of these two edges alone has no area to keep (both corners are where the lines
    // meet): it always closes along the ridge.
    if (sine > tol_.ridgeSine && a.start != b.end) {
      const Vec2 l = liveAt(ci, z);
      const double shorter = std::min((l - liveAt(a.start, z)).norm(), (liveAt(b.end, z) - l).norm());
      if (sine * shorter * shorter > tol_.ridgeArea) return;
    }
    zipSpike(ci, z, depth);
  } else if (sine <= tol_.mergeSine && (std::abs(a.k - b.k) > 1e-12 * (1.0 + std::abs(a.k) + std::abs(b.k)) ||
                                        samePiece(c.prev, c.next))) {
    mergeColinear(ci, z, depth);
  }
}

// Two pieces of one input edge (a step split it) whose profiles go on alike from here: once
// the step between them has closed and they lie in one line, they are one edge again (Sec.
// 4.8 merges all consecutive colinear edges of an ambiguous event into one). Merging them
// moves no plane; it keeps the edge whole for what comes later, such as an anchor placed by
// a fraction of its length (the terrace's dormers).
// (Two edges of one input, as a split event leaves them, stay apart: where the corner between
// them runs decides later events, and merging them moved random80914's roof by 3 %.)
bool Sweeper::samePiece(int A, int B) const {
  if (edges_[A].src == edges_[B].src) return false;
  const SweepEdge &a = *inputs_[edges_[A].src], &b = *inputs_[edges_[B].src];
  if (a.sourceLoop != b.sourceLoop || a.sourceEdge != b.sourceEdge || a.profile != b.profile || a.step != b.step)
    return false;
  const int sa = edges_[A].step, sb = edges_[B].step;
  if (a.steps.size() - sa != b.steps.size() - sb) return false;
  for (std::size_t k = 1; sa + k < a.steps.size(); ++k) {
    const SweepEdge::Step &x = a.steps[sa + k], &y = b.steps[sb + k];
    if (x.z != y.z || x.angle != y.angle || x.segment != y.segment || x.priority != y.priority) return false;
  }
  const SweepEdge::Step &x = a.steps[sa], &y = b.steps[sb];
  return x.angle == y.angle && x.segment == y.segment && x.priority == y.priority;
}

void Sweeper::shareTop(int A, int B, int vl, int v) {
  faces_[edges_[A].face].segments.emplace_back(vl, v);
  faces_[edges_[B].face].segments.emplace_back(v, vl);
}

void Sweeper::relink(int prev, int next, int vertex, const Vec2& at, double z, int depth) {
  const int n = newCorner(prev, next, vertex, at, z);
  resolveCorner(n, z, depth + 1);
  if (corners_[n].alive) predict(n);
}

// Two antiparallel edges meeting at a corner lie on one line: above this height they would
// cross. They meet along their overlap (a ridge); the longer one goes on (Sec. 4.4, the
// degenerate chains of two parallel edges). Corners are taken where they live (liveAt): a
// racing corner made a little above z would, taken back to z along its path, sit decimetres
// to metres along the ridge from its event (taking them at z: 265 random failures, not 131).
void Sweeper::zipSpike(int ci, double z, int depth) {
  Corner& c = corners_[ci];
  const int A = c.prev, B = c.next;
  const int a0 = edges_[A].start, b1 = edges_[B].end;
  const Vec2 l = liveAt(ci, z);
  const int vl = c.vertex;
  c.alive = false;
  SWEEP_TRACE("zip corner %d (edges %d, %d) at (%g, %g, %g)", ci, A, B, l[0], l[1], z);
  if (a0 == b1) {
    // A loop of two edges: it closes along the ridge.
    const Vec2 pa = liveAt(a0, z);
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    edges_[A].alive = edges_[B].alive = false;
    return;
  }
  const Vec2 pa = liveAt(a0, z), pb = liveAt(b1, z);
  const double la = OpenMesh::dot(edges_[A].d, l - pa);
  const double lb = OpenMesh::dot(edges_[B].d, pb - l);
  const int aPrev = corners_[a0].prev, bNext = corners_[b1].next;
  if (std::abs(la - lb) <= tol_.cluster) {
    const int v = addVertex((pa + pb) * 0.5, z);
    killCorner(a0, v);
    killCorner(b1, v);
    shareTop(A, B, vl, v);
    edges_[A].alive = edges_[B].alive = false;
    if (aPrev == bNext) {
      // A loop of three edges closing at once: the third edge's face ends at v too.
      edges_[aPrev].alive = false;
      return;
    }
    relink(aPrev, bNext, v, (pa + pb) * 0.5, z, depth);
  } else if (la < lb) {
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    edges_[A].alive = false;
    relink(aPrev, B, va, pa, z, depth);
  } else {
    const int vb = addVertex(pb, z);
    killCorner(b1, vb);
    shareTop(A, B, vl, vb);
    edges_[B].alive = false;
    relink(A, bNext, vb, pb, z, depth);
  }
}

// Colinear neighbours with different angles: the ambiguous case of Sec. 4.8. The edge of
// higher priority takes over the other's extent; the other's face ends here.
void Sweeper::mergeColinear(int ci, double z, int depth) {
  Corner& c = corners_[ci];
  const int A = c.prev, B = c.next;
  const int vl = c.vertex;
  // Each edge's priority is its segment's at this height (edges_[].step follows the direction
  // events), so an angle step inside a stage counts as it would at a stage's base.
  const double pa = inputs_[edges_[A].src]->steps[edges_[A].step].priority;
  const double pb = inputs_[edges_[B].src]->steps[edges_[B].step].priority;
  const bool keepA = pa >= pb;
  c.alive = false;
  SWEEP_TRACE("merge colinear corner %d (edges %d, %d) keeping %d", ci, A, B, keepA ? A : B);
  if (keepA) {
    const int b1 = edges_[B].end;
    const Vec2 pb = liveAt(b1, z);
    const int vb = addVertex(pb, z);
    killCorner(b1, vb);
    shareTop(A, B, vl, vb);  // B's face ends along its top; A's face goes on above it
    const int bNext = corners_[b1].next;
    edges_[B].alive = false;
    edges_[A].merged = true;
    relink(A, bNext, vb, pb, z, depth);
  } else {
    const int a0 = edges_[A].start;
    const Vec2 pa = liveAt(a0, z);
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    const int aPrev = corners_[a0].prev;
    edges_[A].alive = false;
    edges_[B].merged = true;
    relink(aPrev, B, va, pa, z, depth);
  }
}

}  // namespace corbel::extrude::sweeping
