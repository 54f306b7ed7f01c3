// Zipping zero-width spurs out of the traced shell's faces (docs/extrude.md, "Decisions").
#include "extrude/shell_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace corbel::extrude {

namespace {

using Place = EdgePlace;

class Zipper {
 public:
  Zipper(SweepOutput& shell, double width, double straight) : shell_(shell), width_(width), straight_(straight) {}

  std::size_t run() {
    // Only loops with a corner where the boundary turns straight back are looked at (a cheap
    // test first), and of those the loops that are not simple in their plane (the exact test),
    // whose spur the face across runs too, backwards (a mirrored spur), or whose spur runs
    // straight past a corner (straightAt): a spur in a simple loop harms nothing where it
    // is wide enough for its triangles to stand apart, and every zip moves a corner into a
    // neighbouring face; but two faces that run one spur both cover its sliver, and a straight
    // spur's triangles lie along the edge of the face across its far side, and the shell
    // crosses itself.
    // (A fold's corner is one two loops alone pass, found by the loops through each vertex.)
    std::vector<std::size_t> first(shell_.points.size() + 1, 0);
    for (const ShellFace& f : shell_.faces)
      for (const auto& l : f.loops)
        for (int v : l) ++first[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
    std::vector<Place> through(first.back());
    {
      std::vector<std::size_t> next(first.begin(), first.end() - 1);
      for (std::size_t fi = 0; fi < shell_.faces.size(); ++fi)
        for (std::size_t li = 0; li < shell_.faces[fi].loops.size(); ++li)
          for (int v : shell_.faces[fi].loops[li])
            through[next[static_cast<std::size_t>(v)]++] = Place{static_cast<int>(fi), static_cast<int>(li)};
    }
    // Whether corner i of loop (fi, li) may be a fold (foldedAt, without the edge index).
    auto mayFold = [&](int fi, int li, const std::vector<int>& l, std::size_t i) {
      const std::size_t t = static_cast<std::size_t>(l[i]);
      if (first[t + 1] - first[t] != 2 || !thinAt(l, i)) return false;
      const Place g =
          through[first[t]].face == fi && through[first[t]].loop == li ? through[first[t] + 1] : through[first[t]];
      return g.face != fi && bothTurnIn(l, i, fi, g.face);
    };
    std::vector<Place> turning;
    for (std::size_t fi = 0; fi < shell_.faces.size(); ++fi)
      for (std::size_t li = 0; li < shell_.faces[fi].loops.size(); ++li) {
        const auto& l = shell_.faces[fi].loops[li];
        bool turns = false;
        for (std::size_t i = 0; i < l.size() && !turns; ++i)
          turns = turnsBack(l, i) || mayFold(static_cast<int>(fi), static_cast<int>(li), l, i);
        if (turns) turning.push_back(Place{static_cast<int>(fi), static_cast<int>(li)});
      }
    if (turning.empty() || !indexEdges(shell_, edges_)) return 0;
    // The loops to zip, each with whether it was simple when first looked at (there, only
    // mirrored spurs and folds go; in a loop that was not, a spur of several corners goes one
    // corner at a time, through loops that may be simple before the last).
    std::vector<std::pair<Place, bool>> spurred;
    for (const Place& p : turning) {
      bool mirrored = false, turns = false;
      for (std::size_t i = 0; i < loopOf(p).size() && !mirrored; ++i) {
        const bool back = turnsBack(loopOf(p), i);
        turns = turns || back;
        mirrored =
            (back && (mirroredAt(p.face, loopOf(p), i) || straightAt(loopOf(p), i))) || foldedAt(p.face, loopOf(p), i);
      }
      const bool simple = !turns || simpleInItsPlane(shell_, shell_.faces[p.face], loopOf(p));
      if (mirrored || !simple) spurred.push_back({p, simple});
    }
    std::size_t zipped = 0;
    // Each zip removes a corner from a face, so this ends; the bound is a guard.
    std::size_t corners = 0;
    for (const ShellFace& f : shell_.faces)
      for (const auto& l : f.loops) corners += l.size();
    for (bool changed = true; changed && zipped <= corners;) {
      changed = false;
      for (std::size_t s = 0; s < spurred.size(); ++s)
        for (std::size_t i = 0; i < loopOf(spurred[s].first).size();) {
          Place across;
          if (zipAt(spurred[s].first.face, spurred[s].first.loop, i, spurred[s].second, across)) {
            ++zipped;
            changed = true;
            i = 0;  // the loop changed: look at it again from its start
            // The face across took a corner into its edge: it may run a spur this one runs
            // backwards now.
            if (std::none_of(spurred.begin(), spurred.end(),
                             [&](const auto& q) { return q.first.face == across.face && q.first.loop == across.loop; }))
              spurred.push_back({across, simpleInItsPlane(shell_, shell_.faces[across.face], loopOf(across))});
          } else {
            ++i;
          }
        }
    }
    if (zipped == 0) return 0;
    // Loops that a zip closed (two corners left) are gone; so is a face whose outer loop went.
    std::vector<ShellFace> faces;
    for (ShellFace& f : shell_.faces) {
      if (f.loops.empty() || f.loops[0].size() < 3) continue;
      std::vector<std::vector<int>> loops;
      for (auto& l : f.loops)
        if (l.size() >= 3) loops.push_back(std::move(l));
      f.loops = std::move(loops);
      faces.push_back(std::move(f));
    }
    shell_.faces = std::move(faces);
    return zipped;
  }

 private:
  std::vector<int>& loopOf(const Place& p) { return shell_.faces[p.face].loops[p.loop]; }

  // Whether the boundary turns straight back at corner i: A → T → B with the nearer of A and
  // B within `width` (width_ unless given) of the line T–far, both sides longer than width_
  // (shorter ones are short edges, collapseShortEdges' matter).
  bool turnsBack(const std::vector<int>& loop, std::size_t i) const { return turnsBack(loop, i, width_); }
  bool turnsBack(const std::vector<int>& loop, std::size_t i, double width) const {
    const std::size_t n = loop.size();
    if (n < 3) return false;
    const Vec3 &A = shell_.points[loop[(i + n - 1) % n]], &T = shell_.points[loop[i]],
               &B = shell_.points[loop[(i + 1) % n]];
    const Vec3 ta = A - T, tb = B - T;
    const double la = ta.norm(), lb = tb.norm();
    if (!(la > width_ && lb > width_) || OpenMesh::dot(ta, tb) <= 0) return false;
    const Vec3 nearV = la <= lb ? ta : tb;
    const Vec3 farU = la <= lb ? tb / lb : ta / la;
    return (nearV - farU * OpenMesh::dot(nearV, farU)).norm() <= width;
  }

  // Whether the boundary runs straight out past a corner and back at corner i: it turns back
  // with its sides within straight_ of each other (turnsBack), and the far side is longer than
  // the near one by more than width_. (Where the two are as long, A and B lie within width_ of
  // each other: a sliver between two corners a short edge apart, a wall's foot a few µm above
  // the base, which is no spur past an end.)
  bool straightAt(const std::vector<int>& loop, std::size_t i) const {
    if (straight_ <= 0 || !turnsBack(loop, i, straight_)) return false;
    const std::size_t n = loop.size();
    const Vec3 &A = shell_.points[loop[(i + n - 1) % n]], &T = shell_.points[loop[i]],
               &B = shell_.points[loop[(i + 1) % n]];
    return std::abs((A - T).norm() - (B - T).norm()) > width_;
  }

  // Whether the triangle A → T → B at corner i of a loop has no width: its least height (twice
  // its area over its longest side) within width_.
  bool thinAt(const std::vector<int>& loop, std::size_t i) const {
    const std::size_t n = loop.size();
    if (n < 3) return false;
    const Vec3 &A = shell_.points[loop[(i + n - 1) % n]], &T = shell_.points[loop[i]],
               &B = shell_.points[loop[(i + 1) % n]];
    const double longest = std::max({(T - A).norm(), (B - T).norm(), (A - B).norm()});
    return longest > 0 && OpenMesh::cross(T - A, B - T).norm() <= width_ * longest;
  }

  // Whether corner i of a loop, A → T → B, is a fold of no width between two faces: the
  // triangle there has no width (thinAt), the face across runs B → T → A (mirroredAt), and
  // both turn towards their inside at T, so that both cover the triangle. Two faces of one
  // plane cannot (one turns in, the other out); two faces of different planes share only a
  // straight line, so a bend between them is rounding, and where both turn in, the shell
  // crosses itself.
  bool foldedAt(int fi, const std::vector<int>& loop, std::size_t i) const {
    if (!thinAt(loop, i) || !mirroredAt(fi, loop, i)) return false;
    return bothTurnIn(loop, i, fi, edges_.at(edgeKey(loop[(i + 1) % loop.size()], loop[i])).face);
  }

  // Whether face fi, whose loop runs A → T → B at corner i, turns towards its inside at T, and
  // face g, running the same corners backwards, does too.
  bool bothTurnIn(const std::vector<int>& loop, std::size_t i, int fi, int g) const {
    const std::size_t n = loop.size();
    const Vec3 &A = shell_.points[loop[(i + n - 1) % n]], &T = shell_.points[loop[i]],
               &B = shell_.points[loop[(i + 1) % n]];
    const Vec3 turn = OpenMesh::cross(T - A, B - T);
    return OpenMesh::dot(turn, shell_.faces[fi].normal) > 0 && OpenMesh::dot(turn, shell_.faces[g].normal) < 0;
  }

  // Whether the face across corner i of a loop, A → T → B, runs B → T → A (one face on both
  // sides of the spur, which it runs backwards).
  bool mirroredAt(int fi, const std::vector<int>& loop, std::size_t i) const {
    const std::size_t n = loop.size();
    const int a = loop[(i + n - 1) % n], t = loop[i], b = loop[(i + 1) % n];
    const auto acrossB = edges_.find(edgeKey(b, t)), acrossA = edges_.find(edgeKey(t, a));
    if (acrossB == edges_.end() || acrossA == edges_.end()) return false;
    const Place g = acrossB->second, h = acrossA->second;
    if (g.face == fi || g.face != h.face || g.loop != h.loop) return false;
    const std::vector<int>& G = shell_.faces[g.face].loops[g.loop];
    const auto at = std::find(G.begin(), G.end(), b);
    if (at == G.end()) return false;
    const std::size_t k = static_cast<std::size_t>(at - G.begin());
    return G[(k + 1) % G.size()] == t && G[(k + 2) % G.size()] == a;
  }

  // At corner i of a loop, the boundary A → T → B turns straight back (turnsBack) or folds
  // against the face across (foldedAt). Then T
  // leaves the loop, which runs A → B, and the face across the far side takes the nearer of A
  // and B into its edge there; where one face lies across both sides, running B → T → A, T
  // leaves it too. The shell stays closed (every directed edge keeps a partner). In a loop that
  // was simple in its plane (`simple`) only a mirrored spur, a straight one (straightAt) or a
  // fold is zipped, and only where both loops stay simple. `other`: the face
  // loop across that changed with it.
  bool zipAt(int fi, int li, std::size_t i, bool simple, Place& other) {
    std::vector<int>& loop = shell_.faces[fi].loops[li];
    const bool spur = turnsBack(loop, i);
    if (!spur && !foldedAt(fi, loop, i)) return false;
    const std::size_t n = loop.size();
    const int a = loop[(i + n - 1) % n], t = loop[i], b = loop[(i + 1) % n];
    if (a == b) return false;
    if (simple && !mirroredAt(fi, loop, i) && !straightAt(loop, i)) return false;
    const bool nearA = (shell_.points[a] - shell_.points[t]).norm() <= (shell_.points[b] - shell_.points[t]).norm();
    const auto acrossB = edges_.find(edgeKey(b, t)), acrossA = edges_.find(edgeKey(t, a));
    if (acrossB == edges_.end() || acrossA == edges_.end()) return false;
    const Place g = acrossB->second, h = acrossA->second;
    if (g.face == fi || h.face == fi) return false;

    // The loops as they would be, and the shell's directed edges that go and come.
    std::vector<int> newLoop = loop;
    newLoop.erase(newLoop.begin() + static_cast<std::ptrdiff_t>(i));
    std::vector<std::uint64_t> gone{edgeKey(a, t), edgeKey(t, b)};
    std::vector<std::pair<std::uint64_t, Place>> made;
    if (newLoop.size() == 2) {
      gone.push_back(edgeKey(b, a));  // a triangle goes altogether, its third edge with it
      newLoop.clear();
    } else {
      made.push_back({edgeKey(a, b), Place{fi, li}});
    }
    std::vector<int> newSide;
    const std::vector<int>& G = loopOf(g);
    const std::size_t gn = G.size();
    std::size_t at = 0;
    while (at < gn && G[at] != b) ++at;
    if (at == gn || G[(at + 1) % gn] != t) return false;
    if (g.face == h.face && g.loop == h.loop && G[(at + 2) % gn] == a) {
      // One face across both sides, b → t → a: t leaves it too.
      other = g;
      newSide = G;
      newSide.erase(newSide.begin() + static_cast<std::ptrdiff_t>((at + 1) % gn));
      gone.push_back(edgeKey(b, t));
      gone.push_back(edgeKey(t, a));
      if (newSide.size() == 2) {
        gone.push_back(edgeKey(a, b));
        newSide.clear();
      } else {
        made.push_back({edgeKey(b, a), g});
      }
    } else {
      // The face across the far side takes the near corner into that edge: b → t becomes
      // b → a → t (or t → a becomes t → b → a).
      other = nearA ? g : h;
      const int near = nearA ? a : b;
      const std::vector<int>& side = loopOf(other);
      if (std::find(side.begin(), side.end(), near) != side.end()) return false;  // it would pass a corner twice
      const int s0 = nearA ? b : t, s1 = nearA ? t : a;
      const std::size_t sn = side.size();
      std::size_t k = 0;
      while (k < sn && !(side[k] == s0 && side[(k + 1) % sn] == s1)) ++k;
      if (k == sn) return false;
      newSide = side;
      newSide.insert(newSide.begin() + static_cast<std::ptrdiff_t>(k + 1), near);
      gone.push_back(edgeKey(s0, s1));
      made.push_back({edgeKey(s0, near), other});
      made.push_back({edgeKey(near, s1), other});
    }
    if (newLoop.empty() && newSide.empty()) return false;  // two faces of no area, alone
    // An outer loop does not go while its face has holes (they would lose their face).
    if ((newLoop.empty() && li == 0 && shell_.faces[fi].loops.size() > 1) ||
        (newSide.empty() && other.loop == 0 && shell_.faces[other.face].loops.size() > 1))
      return false;
    for (const auto& [k, p] : made)
      if (edges_.count(k) && std::find(gone.begin(), gone.end(), k) == gone.end()) return false;
    // The face across must stay simple in its plane where it was: the near corner lies within
    // the width of the far side, but on either side of it, and may meet a corner of that face
    // in its plane (a wall's foot a few µm above the base, put into the base, crossed it).
    // (This face may not be simple yet: a spur of several corners goes one corner at a time.)
    const ShellFace& across = shell_.faces[other.face];
    if (!newSide.empty() && !simpleInItsPlane(shell_, across, newSide) &&
        simpleInItsPlane(shell_, across, loopOf(other)))
      return false;
    if (simple && !newLoop.empty() && !simpleInItsPlane(shell_, shell_.faces[fi], newLoop)) return false;
    for (const std::uint64_t k : gone) edges_.erase(k);
    for (const auto& [k, p] : made) edges_[k] = p;
    loop = std::move(newLoop);
    loopOf(other) = std::move(newSide);
    return true;
  }

  SweepOutput& shell_;
  double width_, straight_;
  EdgeIndex edges_;
};

}  // namespace

std::size_t zipSpurs(SweepOutput& shell, double width, double straight) { return Zipper(shell, width, straight).run(); }

}  // namespace corbel::extrude
