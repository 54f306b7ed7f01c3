// Corners the sweep left a rounding apart, merged into one vertex: the ends of short edges
// (collapseShortEdges, and mergeUntoldEdges where no face's plane tells them apart) and two
// corners of one loop that are not neighbours (weldLoopCorners).
// docs/extrude.md, "Decisions".
#include "extrude/extrude.h"
#include "extrude/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace corbel::extrude {

namespace {

// Whether the faces around every vertex of a closed shell form one fan (one cycle of corners),
// as a polygon mesh library requires: two cones touching at a vertex fail.
bool vertexFansClosed(const SweepOutput& shell) {
  // Per vertex, its corners as (previous, next) vertex pairs.
  std::vector<std::vector<std::pair<int, int>>> corners(shell.points.size());
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        corners[loop[i]].emplace_back(loop[(i + loop.size() - 1) % loop.size()], loop[(i + 1) % loop.size()]);
  for (auto& c : corners) {
    if (c.empty()) continue;
    // Round the vertex: the corner after (p, n) is the one whose previous is n.
    std::sort(c.begin(), c.end());
    std::size_t steps = 0;
    int at = c.front().first;
    do {
      const auto it = std::lower_bound(c.begin(), c.end(), std::make_pair(at, std::numeric_limits<int>::min()));
      if (it == c.end() || it->first != at) return false;
      at = it->second;
    } while (++steps <= c.size() && at != c.front().first);
    if (steps != c.size()) return false;
  }
  return true;
}

// The groups of vertices to merge (a union-find), each into its lowest-numbered member, the
// first the sweep made. A group never joins a corner of the base to a vertex more than
// `baseHeight` above it: an event a little above the base next to a plan corner (a corner
// between two edges a few 1e-7 rad apart, of different angles, racing along one of them and
// ending it 6e-7 m up) would take the plan corner's place, and the face beside it, whose
// bottom then runs along the base round the other edge's corner, would lie flat on the base
// there. Kept apart, that edge's face stays the sliver the sweep made.
class Groups {
 public:
  Groups(const SweepOutput& shell, double baseHeight)
      : parent_(shell.points.size()),
        onBase_(parent_.size(), 0),
        low_(parent_.size()),
        high_(parent_.size()),
        baseHeight_(baseHeight) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (const ShellFace& f : shell.faces)
      if (f.base)
        for (const auto& loop : f.loops)
          for (int v : loop) onBase_[v] = 1;
    for (std::size_t v = 0; v < parent_.size(); ++v) low_[v] = high_[v] = shell.points[v][2];
  }

  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }

  // Joins the groups of a and b unless that joins the base to a vertex too high above it.
  // Returns whether they were joined now.
  bool join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    const double lo = std::min(low_[a], low_[b]), hi = std::max(high_[a], high_[b]);
    if ((onBase_[a] || onBase_[b]) && hi - lo > baseHeight_) return false;
    const int r = std::min(a, b);
    parent_[std::max(a, b)] = r;
    onBase_[r] = onBase_[a] || onBase_[b];
    low_[r] = lo;
    high_[r] = hi;
    return true;
  }

  // Joins them whatever their heights.
  bool force(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }

  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<int> parent_;
  std::vector<char> onBase_;
  std::vector<double> low_, high_;
  double baseHeight_;
};

// A loop's corners with each group's vertex in place of its members, without the repeats a
// merge leaves, and with `dropSpurs` without the spurs of no width it leaves (a run x → t → x:
// t and one x go, and the faces either side of the spur, which ran t → x and x → t, meet
// along it).
std::vector<int> mergedLoop(const std::vector<int>& loop, Groups& groups, bool dropSpurs) {
  std::vector<int> l;
  for (int v : loop) {
    const int r = groups.find(v);
    if (!l.empty() && l.back() == r) continue;
    if (dropSpurs && l.size() >= 2 && l[l.size() - 2] == r) {
      l.pop_back();
      continue;
    }
    l.push_back(r);
  }
  // The same round the loop's join.
  for (bool again = true; again && l.size() >= 2;) {
    const std::size_t n = l.size();
    again = true;
    if (l[n - 1] == l[0])
      l.pop_back();
    else if (dropSpurs && n >= 3 && l[n - 2] == l[0])
      l.resize(n - 2);
    else if (dropSpurs && n >= 3 && l[n - 1] == l[1])
      l.erase(l.begin(), l.begin() + 2);
    else
      again = false;
  }
  return l;
}

// Applies the groups to the shell (with `dropSpurs`, taking out the spurs of no width they
// leave) and returns `merges`, or leaves the shell as it was and returns 0 where that would open
// it, leave a vertex with two fans of faces, or run a loop through one vertex twice.
std::size_t mergeGroups(SweepOutput& shell, Groups& groups, std::size_t merges, bool dropSpurs) {
  if (merges == 0) return 0;
  std::vector<ShellFace> faces;
  for (const ShellFace& f : shell.faces) {
    ShellFace g = f;
    g.loops.clear();
    for (std::size_t k = 0; k < f.loops.size(); ++k) {
      std::vector<int> l = mergedLoop(f.loops[k], groups, dropSpurs);
      if (l.size() >= 3)
        g.loops.push_back(std::move(l));
      else if (k == 0)
        break;  // the outer loop vanished: so does the face
    }
    // A loop through one vertex twice: leave the shell. (A hole may come to touch its outer
    // loop: triangulated, the face then meets itself at a point, and toMeshData gives that
    // point one vertex per fan.)
    for (const auto& l : g.loops) {
      std::vector<int> used = l;
      std::sort(used.begin(), used.end());
      if (std::adjacent_find(used.begin(), used.end()) != used.end()) return 0;
    }
    if (!g.loops.empty()) faces.push_back(std::move(g));
  }
  // A merged group takes the place of its first vertex made. Where that leaves a face through
  // it not simple in its plane, the groups on that face take the place of their highest member
  // instead: events a few δ1 apart at an apex or along a ridge merge into one vertex, and the
  // place of the first (the lowest) can put a face's top under the corners that later events
  // made a little higher, so its sides cross. The sweep makes each face from the bottom up, so
  // the highest member, from the group's last event, is above the face's other corners. (Only
  // there: elsewhere the first made stays, as rebuilds with wider tolerances, whose groups are
  // wider, agree best with the oracles that way.)
  std::vector<int> highest(groups.size(), -1), size(groups.size(), 0);
  for (std::size_t v = 0; v < groups.size(); ++v) {
    const int r = groups.find(static_cast<int>(v));
    ++size[r];
    if (highest[r] < 0 || shell.points[v][2] > shell.points[highest[r]][2]) highest[r] = static_cast<int>(v);
  }
  // (A group moves once; a move can spoil another face through the group, which is then
  // looked at again.)
  std::vector<std::pair<int, Vec3>> moved;  // (group, its place before): undone if the collapse is
  for (bool again = true; again;) {
    again = false;
    for (const ShellFace& g : faces) {
      bool merged = false;
      for (const auto& l : g.loops)
        for (int r : l) merged = merged || (size[r] > 1 && highest[r] != r);
      bool simple = true;
      for (const auto& l : g.loops) simple = simple && (!merged || simpleInItsPlane(shell, g, l));
      if (simple) continue;
      for (const auto& l : g.loops)
        for (int r : l)
          if (size[r] > 1 && highest[r] != r) {
            moved.emplace_back(r, shell.points[r]);
            shell.points[r] = shell.points[highest[r]];
            highest[r] = r;
            again = true;
          }
    }
  }
  const std::size_t before = unpairedEdges(shell);
  std::swap(shell.faces, faces);
  if (unpairedEdges(shell) > before || (before == 0 && !vertexFansClosed(shell))) {
    std::swap(shell.faces, faces);
    for (auto it = moved.rbegin(); it != moved.rend(); ++it) shell.points[it->first] = it->second;
    return 0;
  }
  return merges;
}

// Joins the ends of every face edge shorter than `length` that `accept(a, b)` lets merge, and
// returns the number of joins.
template <class Accept>
std::size_t joinShortEdges(const SweepOutput& shell, Groups& groups, double length, Accept accept) {
  std::size_t joined = 0;
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        if ((shell.points[a] - shell.points[b]).norm() < length && accept(a, b) && groups.join(a, b)) ++joined;
      }
  return joined;
}

}  // namespace

std::size_t collapseShortEdges(SweepOutput& shell, double length, double tinyFace, double baseHeight) {
  Groups groups(shell, baseHeight);
  std::size_t collapsed = joinShortEdges(shell, groups, length, [](int, int) { return true; });
  // A face all within tinyFace of its first corner (the last speck of a loop a change closed)
  // becomes a point.
  for (const ShellFace& f : shell.faces) {
    if (f.loops.size() != 1) continue;
    const Vec3& o = shell.points[f.loops[0][0]];
    bool tiny = true;
    for (int v : f.loops[0]) tiny = tiny && (shell.points[v] - o).norm() < tinyFace;
    if (!tiny) continue;
    for (int v : f.loops[0]) collapsed += groups.force(f.loops[0][0], v) ? 1 : 0;
  }
  return mergeGroups(shell, groups, collapsed, false);
}

std::size_t weldLoopCorners(SweepOutput& shell, double length, double baseHeight) {
  Groups groups(shell, baseHeight);
  std::size_t welded = 0;
  std::vector<std::size_t> order;
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops) {
      const std::size_t n = loop.size();
      if (n < 4) continue;
      // Corners in order of x, so each is compared only with those within `length` in x.
      order.resize(n);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
                [&](std::size_t i, std::size_t j) { return shell.points[loop[i]][0] < shell.points[loop[j]][0]; });
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b) {
          const std::size_t i = order[a], j = order[b];
          const Vec3 &p = shell.points[loop[i]], &q = shell.points[loop[j]];
          if (q[0] - p[0] >= length) break;
          const std::size_t gap = i < j ? j - i : i - j;
          if (gap == 1 || gap == n - 1 || (p - q).norm() >= length) continue;
          welded += groups.join(loop[i], loop[j]) ? 1 : 0;
        }
    }
  return mergeGroups(shell, groups, welded, true);
}

std::size_t mergeUntoldEdges(SweepOutput& shell, double length, double offPlane, double baseHeight) {
  // Most shells have no edge that short: nothing to look at, and no closure to check.
  bool anyShort = false;
  for (const ShellFace& f : shell.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size() && !anyShort; ++i)
        anyShort = (shell.points[loop[i]] - shell.points[loop[(i + 1) % loop.size()]]).norm() < length;
  if (!anyShort || unpairedEdges(shell) != 0) return 0;
  // Per vertex, the faces through it.
  std::vector<std::vector<std::size_t>> facesAt(shell.points.size());
  for (std::size_t f = 0; f < shell.faces.size(); ++f)
    for (const auto& loop : shell.faces[f].loops)
      for (int v : loop)
        if (facesAt[v].empty() || facesAt[v].back() != f) facesAt[v].push_back(f);
  // Whether moving a to b, or b to a, takes no face through either off its plane by offPlane.
  auto untold = [&](int a, int b) {
    const Vec3 d = shell.points[b] - shell.points[a];
    for (int v : {a, b})
      for (std::size_t f : facesAt[v])
        if (std::abs(OpenMesh::dot(shell.faces[f].normal, d)) >= offPlane) return false;
    return true;
  };
  Groups groups(shell, baseHeight);
  const std::size_t merged = joinShortEdges(shell, groups, length, untold);
  if (merged == 0) return 0;
  // Kept only where no loop that was simple in its plane is then not.
  const std::size_t before = loopsNotSimple(shell);
  SweepOutput kept = shell;
  if (mergeGroups(shell, groups, merged, false) == 0) return 0;
  if (loopsNotSimple(shell) > before) {
    shell = std::move(kept);
    return 0;
  }
  return merged;
}

}  // namespace corbel::extrude
