// Topology generation (Sec. 7.3.1). See completion.h.
#include "growth/completion.h"

#include "core/error.h"
#include "core/progress.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>

namespace corbel::growth {

namespace {

struct FormMove {
  int unit = 0, leaf = 0;
  GridCoord at = 0;
  bool second = false;
  GridCoord alpha = 0;
  Fraction value;
};

// Applies split + advance; false (and nothing changed) when either is refused.
bool apply(Floorplan& plan, const FormMove& m) {
  const SplitNodes s = plan.faceSplit(m.unit, m.leaf, m.at);
  if (s.first < 0) return false;
  if (plan.faceAdvance(m.unit, m.second ? s.second : s.first, m.alpha)) return true;
  plan.undo();
  return false;
}

void undoMove(Floorplan& plan) {
  plan.undo();
  plan.undo();
}

// The red points of Fig. 7.9: ends of contacts strictly inside an edge, as distances from
// the edge's start, leaving both pieces at least `minPiece` long.
std::vector<GridCoord> splitPoints(const Floorplan& plan, int unit, const ShapeEdge& e, GridCoord minPiece) {
  std::set<GridCoord> out;
  const GridCoord len = plan.unit(unit).node(e.node).weight;
  const bool horizontal = e.facing == Facing::North || e.facing == Facing::South;
  const GridCoord start = horizontal ? e.from.x : e.from.y;
  const GridCoord dir = horizontal ? travelOf(e.facing).x : travelOf(e.facing).y;
  for (const Incidence& l : plan.linksOf({unit, e.node}))
    for (GridCoord end : {l.from, l.to}) {
      const GridCoord d = (end - start) * dir;
      if (d >= minPiece && len - d >= minPiece) out.insert(d);
    }
  return {out.begin(), out.end()};
}

std::vector<FormMove> candidates(Floorplan& plan, const FormRequest& rq, Fraction now) {
  std::vector<FormMove> out;
  for (int u = 0; u < int(plan.units().size()); ++u) {
    const std::vector<ShapeEdge> edges = plan.unit(u).edges();
    for (const ShapeEdge& e : edges)
      for (GridCoord at : splitPoints(plan, u, e, rq.minPiece))
        for (bool second : {false, true})
          for (GridCoord alpha : {rq.minPiece, std::max(rq.minPiece, rq.unitSize / 2)}) {
            FormMove m{u, e.node, at, second, alpha, {}};
            if (!apply(plan, m)) continue;
            m.value = formComplexity(plan).value();
            undoMove(plan);
            if (now < m.value && m.value <= rq.hi) out.push_back(m);
          }
  }
  return out;
}

std::string facingCycle(const ShapeTree& t) {
  const std::vector<GridPoint> c = t.outline();
  std::string s;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const GridPoint a = c[i], b = c[(i + 1) % c.size()];
    s += b.x > a.x ? 'a' : b.y < a.y ? 'b' : b.x < a.x ? 'c' : 'd';
  }
  std::string best = s;
  for (std::size_t k = 1; k < s.size(); ++k) best = std::min(best, s.substr(k) + s.substr(0, k));
  return best;
}

}  // namespace

Floorplan canonicalRow(int n, GridCoord size) {
  Floorplan plan;
  for (int i = 0; i < n; ++i) plan.addUnit(ShapeTree::canonical({GridCoord(i) * size, 0}, size, size));
  return plan;
}

std::string topologySignature(const Floorplan& plan) {
  std::string s;
  for (const ShapeTree& t : plan.units()) s += facingCycle(t) + "|";
  std::map<std::tuple<int, int, char, char>, int> links;
  for (const Incidence& l : plan.incidences())
    ++links[{l.a.unit, l.b.unit, facingLetter(plan.unit(l.a.unit).node(l.a.node).facing),
             facingLetter(plan.unit(l.b.unit).node(l.b.node).facing)}];
  for (const auto& [k, n] : links)
    s += std::to_string(std::get<0>(k)) + std::get<2>(k) + std::to_string(std::get<1>(k)) + std::get<3>(k) + "x" +
         std::to_string(n) + ";";
  return s;
}

FormSet generateForms(const FormRequest& rq, Progress* progress) {
  if (rq.seeds < 1 || rq.seeds > 12) throw InputError("seeds", "expected 1 to 12 units");
  if (rq.count < 1 || rq.count > 64) throw InputError("count", "expected 1 to 64 forms");
  if (rq.hi < rq.lo) throw InputError("complexity", "the range is empty (low > high)");
  if (!(rq.hi < Fraction::of(1, 2)))
    throw InputError("complexity", "Type I moves stay below 1/2 (Sec. 7.2.1); ask for less");
  if (rq.unitSize < 2 * rq.minPiece || rq.minPiece < 1) throw InputError("unit size", "too small for its pieces");
  FormSet out;
  std::set<std::string> seen;
  std::mt19937_64 rng(rq.seed);
  for (out.attempts = 0; out.attempts < rq.attempts && int(out.forms.size()) < rq.count; ++out.attempts) {
    if (progress) {
      if (progress->cancelled()) throw Cancelled();
      progress->report(std::max(double(out.forms.size()) / rq.count, double(out.attempts) / rq.attempts),
                       "attempt " + std::to_string(out.attempts + 1) + ", " + std::to_string(out.forms.size()) +
                           " forms");
    }
    // A different initial arrangement each attempt: the row, each unit shifted up or down
    // against the one before by a third or a half, so contacts end inside faces.
    Floorplan plan;
    GridCoord y = 0;
    const GridCoord shifts[4] = {-rq.unitSize / 2, -rq.unitSize / 3, rq.unitSize / 3, rq.unitSize / 2};
    for (int i = 0; i < rq.seeds; ++i) {
      if (i) y += shifts[rng() % 4];
      plan.addUnit(ShapeTree::canonical({GridCoord(i) * rq.unitSize, y}, rq.unitSize, rq.unitSize));
    }
    int moves = 0;
    Fraction now = formComplexity(plan).value();
    while (now < rq.lo && moves < 8 * rq.seeds + 16) {
      const std::vector<FormMove> c = candidates(plan, rq, now);
      if (c.empty()) break;
      // Balance: moves on the units with the fewest faces first.
      int fewest = 1 << 30;
      for (const FormMove& m : c) fewest = std::min(fewest, plan.unit(m.unit).faceCount());
      std::vector<const FormMove*> pool;
      for (const FormMove& m : c)
        if (plan.unit(m.unit).faceCount() == fewest) pool.push_back(&m);
      const FormMove& pick = *pool[rng() % pool.size()];
      apply(plan, pick);
      now = pick.value;
      ++moves;
    }
    if (now < rq.lo || rq.hi < now) continue;
    std::string sig = topologySignature(plan);
    if (!seen.insert(sig).second) continue;
    out.forms.push_back({std::move(plan), {}, moves, std::move(sig)});
    out.forms.back().complexity = formComplexity(out.forms.back().plan);
  }
  if (int(out.forms.size()) < rq.count)
    out.note = "found " + std::to_string(out.forms.size()) + " distinct forms in " + std::to_string(out.attempts) +
               " attempts";
  return out;
}

}  // namespace corbel::growth
