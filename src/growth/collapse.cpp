// Collapsing staircases (Sec. 7.3.1). See collapse.h.
#include "growth/collapse.h"

#include <algorithm>
#include <cstdlib>
#include <random>

namespace corbel::growth {

namespace {

GridPoint sub(GridPoint a, GridPoint b) { return {a.x - b.x, a.y - b.y}; }
GridPoint plus(GridPoint a, GridPoint b) { return {a.x + b.x, a.y + b.y}; }
GridCoord manhattan(GridPoint a, GridPoint b) { return std::llabs(a.x - b.x) + std::llabs(a.y - b.y); }

// The facing of a clockwise edge running from a to b.
Facing facingOf(GridPoint a, GridPoint b) {
  const GridPoint d{(b.x > a.x) - (b.x < a.x), (b.y > a.y) - (b.y < a.y)};
  for (Facing f : {Facing::North, Facing::East, Facing::South, Facing::West})
    if (travelOf(f) == d) return f;
  return Facing::None;
}

// p lies on the closed segment a–b (axis-aligned).
bool onSegment(GridPoint p, GridPoint a, GridPoint b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y) && (a.x == b.x ? p.x == a.x : p.y == a.y);
}

GridRect spanOf(std::initializer_list<GridPoint> ps) {
  GridRect r{ps.begin()->x, ps.begin()->y, ps.begin()->x, ps.begin()->y};
  for (GridPoint p : ps) r = {std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x), std::max(r.y1, p.y)};
  return r;
}

struct Candidate {
  std::vector<GridPoint> outline;
  CollapseStep step;
};

// Moves edge `m` (corners m, m+1) of c by `shift`, cleans, and checks the result.
std::optional<Candidate> tryMove(const std::vector<GridPoint>& c, std::size_t m, GridPoint shift, bool removeOnly) {
  const std::size_t n = c.size();
  const GridPoint p = c[m], q = c[(m + 1) % n];
  const Facing f = facingOf(p, q);
  const GridPoint nrm = normalOf(f);
  const GridCoord along = shift.x * nrm.x + shift.y * nrm.y;  // > 0: outward (fills)
  if (removeOnly && along > 0) return std::nullopt;
  // The neighbours may shrink to nothing but not turn round (a ShapeTree never inverts an edge).
  const GridPoint before = sub(p, c[(m + n - 1) % n]), after = sub(c[(m + 2) % n], q);
  const GridPoint before2 = plus(before, shift), after2 = sub(after, shift);
  if (before.x * before2.x + before.y * before2.y < 0 || after.x * after2.x + after.y * after2.y < 0)
    return std::nullopt;
  std::vector<GridPoint> moved = c;
  moved[m] = plus(p, shift);
  moved[(m + 1) % n] = plus(q, shift);
  moved = cleanOutline(moved);
  if (moved.size() >= 4 && !simpleRectilinear(moved)) return std::nullopt;
  if (moved.size() < 4) return std::nullopt;
  const GridCoord len = manhattan(p, q);
  if (-signedArea2(moved) != -signedArea2(c) + 2 * along * len) return std::nullopt;
  // The merged edge: the new edge that holds the moved edge.
  const GridPoint p2 = plus(p, shift), q2 = plus(q, shift);
  for (std::size_t i = 0; i < moved.size(); ++i) {
    const GridPoint a = moved[i], b = moved[(i + 1) % moved.size()];
    if (!onSegment(p2, a, b) || !onSegment(q2, a, b) || facingOf(a, b) != f) continue;
    Candidate out;
    out.outline = std::move(moved);
    CollapseStep& s = out.step;
    s.from = a;
    s.to = b;
    s.facing = f;
    const GridCoord dp = manhattan(a, p2), dq = manhattan(a, q2), total = manhattan(a, b);
    if (dp > 0) s.cuts.push_back(dp);
    if (dq < total) s.cuts.push_back(dq);
    if (s.cuts.empty()) return std::nullopt;  // the whole edge moved: not a staircase
    s.piece = dp > 0 ? 1 : 0;
    s.alpha = -along;  // the forward step moves the piece back
    s.swept = spanOf({p, q, p2, q2});
    return out;
  }
  return std::nullopt;
}

}  // namespace

std::vector<GridPoint> canonicalCycle(std::vector<GridPoint> c) {
  if (c.empty()) return c;
  std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

std::optional<CollapseTrace> collapseStaircases(const std::vector<GridPoint>& outline, const CollapseOptions& options) {
  std::vector<GridPoint> c = cleanOutline(outline);
  if (!simpleRectilinear(c)) return std::nullopt;
  std::mt19937_64 rng(options.seed);
  CollapseTrace trace;
  while (c.size() > 4) {
    const std::size_t n = c.size();
    std::vector<Candidate> found;
    for (std::size_t i = 0; i < n; ++i) {
      // A = c[i]→c[i+1], B = c[i+1]→c[i+2], C = c[i+2]→c[i+3].
      const GridPoint a0 = c[i], a1 = c[(i + 1) % n], b1 = c[(i + 2) % n], c1 = c[(i + 3) % n];
      if (facingOf(a0, a1) != facingOf(b1, c1)) continue;
      const GridPoint B = sub(b1, a1);
      if (auto m = tryMove(c, (i + 2) % n, {-B.x, -B.y}, options.removeOnly)) found.push_back(std::move(*m));
      if (auto m = tryMove(c, i, B, options.removeOnly)) found.push_back(std::move(*m));
    }
    if (found.empty()) return std::nullopt;
    Candidate& pick = found[rng() % found.size()];
    trace.steps.push_back(pick.step);
    c = std::move(pick.outline);
  }
  GridRect r{c[0].x, c[0].y, c[0].x, c[0].y};
  for (GridPoint p : c) r = {std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x), std::max(r.y1, p.y)};
  trace.rectangle = r;
  return trace;
}

ShapeTree rebuildFromCanonical(const CollapseTrace& trace, std::string* why) {
  const GridRect& r = trace.rectangle;
  ShapeTree t = ShapeTree::canonical({r.x0, r.y0}, 1, 1);
  constexpr int kNorth = 0, kEast = 1;
  if (r.x1 - r.x0 > 1) t.faceAdvance(kEast, r.x1 - r.x0 - 1, why);
  if (r.y1 - r.y0 > 1) t.faceAdvance(kNorth, r.y1 - r.y0 - 1, why);
  for (auto it = trace.steps.rbegin(); it != trace.steps.rend(); ++it) {
    int leaf = -1;
    for (const ShapeEdge& e : t.edges())
      if (e.from == it->from && e.to == it->to && e.facing == it->facing) leaf = e.node;
    if (leaf < 0) {
      if (why) *why = "no leaf for a recorded step";
      return t;
    }
    std::vector<int> pieces;
    GridCoord done = 0;
    int rest = leaf;
    for (GridCoord cut : it->cuts) {
      const SplitNodes s = t.faceSplit(rest, cut - done, why);
      if (s.first < 0) return t;
      pieces.push_back(s.first);
      rest = s.second;
      done = cut;
    }
    pieces.push_back(rest);
    if (!t.faceAdvance(pieces[std::size_t(it->piece)], it->alpha, why)) return t;
  }
  return t;
}

}  // namespace corbel::growth
