// Taking folds out of the boundary two faces share (docs/extrude.md, "Decisions").
#include "extrude/shell_edges.h"

#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace corbel::extrude {

namespace {

using Place = EdgePlace;

class Unfolder {
 public:
  explicit Unfolder(SweepOutput& shell) : shell_(shell) {}

  std::size_t run() {
    // Only loops through a corner that two faces alone pass, and that are not simple in their
    // plane, are looked at (the cheap test first: most shells have no such corner).
    passes_.assign(shell_.points.size(), 0);
    for (const ShellFace& f : shell_.faces)
      for (const auto& l : f.loops)
        for (int v : l) ++passes_[v];
    std::vector<Place> broken;
    for (std::size_t fi = 0; fi < shell_.faces.size(); ++fi)
      for (std::size_t li = 0; li < shell_.faces[fi].loops.size(); ++li) {
        const auto& l = shell_.faces[fi].loops[li];
        if (std::any_of(l.begin(), l.end(), [&](int v) { return passes_[v] == 2; }) &&
            !simpleInItsPlane(shell_, shell_.faces[fi], l))
          broken.push_back(Place{static_cast<int>(fi), static_cast<int>(li)});
      }
    if (broken.empty() || !indexEdges(shell_, edges_)) return 0;
    std::size_t removed = 0;
    for (const Place& p : broken)
      for (std::size_t i = 0; i < loopOf(p).size(); ++i) {
        const std::size_t n = unfoldAt(p, i);
        if (n == 0) continue;
        removed += n;
        i = static_cast<std::size_t>(-1);  // the loop changed: look at it again from its start
        if (simpleInItsPlane(shell_, shell_.faces[p.face], loopOf(p))) break;
      }
    return removed;
  }

 private:
  std::vector<int>& loopOf(const Place& p) { return shell_.faces[p.face].loops[p.loop]; }

  // Around corner i of a loop that is not simple: the longest run of corners c1 … ck that only
  // this face F and one other face G pass, F running p → c1 … ck → q and G q → ck … c1 → p. The
  // run is a boundary between F and G that is no edge of the shell; where F and G have area
  // there they lie in one plane, so p → q may divide them instead, and the fold the run made
  // goes. Kept only where no edge p → q exists yet, both faces keep three corners, and no loop
  // of the two that was simple stops being simple while one that was not becomes simple.
  // Returns the corners removed.
  std::size_t unfoldAt(const Place& at, std::size_t i) {
    const std::vector<int>& F = loopOf(at);
    const std::size_t n = F.size();
    auto count = [&](int v) { return passes_[v]; };
    if (count(F[i]) != 2) return 0;
    const auto across = edges_.find(edgeKey(F[(i + 1) % n], F[i]));
    if (across == edges_.end()) return 0;
    const Place g = across->second;
    if (g.face == at.face) return 0;
    // The run's ends: walk out from corner i while the corners lie on F and G only.
    auto onlyFAndG = [&](std::size_t j) {
      const int v = F[j];
      if (count(v) != 2) return false;
      const auto a = edges_.find(edgeKey(F[(j + 1) % n], v)), b = edges_.find(edgeKey(v, F[(j + n - 1) % n]));
      return a != edges_.end() && b != edges_.end() && a->second.face == g.face && b->second.face == g.face &&
             a->second.loop == g.loop && b->second.loop == g.loop;
    };
    if (!onlyFAndG(i)) return 0;
    std::size_t first = i, last = i, run = 1;
    while (run < n && onlyFAndG((first + n - 1) % n)) first = (first + n - 1) % n, ++run;
    while (run < n && onlyFAndG((last + 1) % n)) last = (last + 1) % n, ++run;
    if (run + 2 > n) return 0;
    const int p = F[(first + n - 1) % n], q = F[(last + 1) % n];
    if (p == q || edges_.count(edgeKey(p, q)) || edges_.count(edgeKey(q, p))) return 0;
    std::unordered_set<int> gone;
    for (std::size_t k = 0, j = first; k < run; ++k, j = (j + 1) % n) gone.insert(F[j]);
    std::vector<int> newF, newG;
    for (int v : F)
      if (!gone.count(v)) newF.push_back(v);
    const std::vector<int>& G = loopOf(g);
    for (int v : G)
      if (!gone.count(v)) newG.push_back(v);
    if (newF.size() < 3 || newG.size() < 3 || G.size() - newG.size() != run) return 0;
    const ShellFace &fF = shell_.faces[at.face], &fG = shell_.faces[g.face];
    const bool wasF = simpleInItsPlane(shell_, fF, F), wasG = simpleInItsPlane(shell_, fG, G);
    const bool isF = simpleInItsPlane(shell_, fF, newF), isG = simpleInItsPlane(shell_, fG, newG);
    if ((wasF && !isF) || (wasG && !isG) || (int(isF) + int(isG) <= int(wasF) + int(wasG))) return 0;
    // The shell's directed edges: the run's go, p → q and q → p come.
    for (std::size_t k = 0, j = (first + n - 1) % n; k <= run; ++k, j = (j + 1) % n) {
      edges_.erase(edgeKey(F[j], F[(j + 1) % n]));
      edges_.erase(edgeKey(F[(j + 1) % n], F[j]));
    }
    edges_[edgeKey(p, q)] = at;
    edges_[edgeKey(q, p)] = g;
    for (int v : gone) passes_[v] = 0;
    loopOf(at) = std::move(newF);
    loopOf(g) = std::move(newG);
    return run;
  }

  SweepOutput& shell_;
  EdgeIndex edges_;
  std::vector<int> passes_;  // per vertex, how many face loops pass it
};

}  // namespace

std::size_t unfoldSharedRuns(SweepOutput& shell) { return Unfolder(shell).run(); }

}  // namespace corbel::extrude
