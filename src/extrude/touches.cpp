// Loops that touch themselves: a corner of a face's boundary within a rounding of one of the
// same loop's edges (splitTouchingLoops). docs/extrude.md, "Decisions".
#include "extrude/extrude.h"
#include "extrude/sweep.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace corbel::extrude {

namespace {

// The distance from p to the segment a–b.
double toSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len2 = OpenMesh::dot(d, d);
  const double t = len2 > 0 ? std::clamp(OpenMesh::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + d * t)).norm();
}

// The loop's area seen along `normal` (positive where it runs counter-clockwise seen from
// the side the normal points to).
double areaAlong(const SweepOutput& shell, const std::vector<int>& loop, const Vec3& normal) {
  std::vector<Vec3> poly;
  poly.reserve(loop.size());
  for (int v : loop) poly.push_back(shell.points[v]);
  return OpenMesh::dot(newellNormal(poly), normal) * 0.5;
}

// Where a face's loop and its neighbour across one edge would be after the split.
struct Split {
  std::vector<int> first, second;  // the two loops the face's loop becomes
  std::size_t neighbour;           // the face across the touched edge
  std::vector<int> neighbourLoop;  // its outer loop with the corner put into that edge
};

// The first split of face fi's loop that leaves two simple loops, both running the face's way,
// at a corner within `length` of a non-adjacent edge of the same loop (and not within `length`
// of that edge's ends: two corners that close are welded, weldLoopCorners).
std::optional<Split> findSplit(const SweepOutput& shell, std::size_t fi, double length) {
  const ShellFace& f = shell.faces[fi];
  const std::vector<int>& loop = f.loops[0];
  const std::size_t n = loop.size();
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t e = 0; e < n; ++e) {
      const std::size_t e1 = (e + 1) % n;
      if (e == c || e1 == c) continue;
      const Vec3 &p = shell.points[loop[c]], &a = shell.points[loop[e]], &b = shell.points[loop[e1]];
      if (toSegment(p, a, b) >= length || (p - a).norm() < length || (p - b).norm() < length) continue;
      // The loop, from c, is c … e, e1 … (back to c); with c in the edge e → e1 it parts into
      // c … e (closed by e → c) and c, e1 … (closed by the corner before c → c).
      Split s;
      for (std::size_t i = c; i != e1; i = (i + 1) % n) s.first.push_back(loop[i]);
      s.second.push_back(loop[c]);
      for (std::size_t i = e1; i != c; i = (i + 1) % n) s.second.push_back(loop[i]);
      if (s.first.size() < 3 || s.second.size() < 3) continue;
      if (areaAlong(shell, s.first, f.normal) <= 0 || areaAlong(shell, s.second, f.normal) <= 0) continue;
      if (!simpleInItsPlane(shell, f, s.first) || !simpleInItsPlane(shell, f, s.second)) continue;
      // The face that runs the edge the other way, b → a, takes the corner too.
      const int va = loop[e], vb = loop[e1], vc = loop[c];
      bool found = false;
      for (std::size_t g = 0; g < shell.faces.size() && !found; ++g) {
        if (g == fi || shell.faces[g].loops.size() != 1) continue;
        const std::vector<int>& l = shell.faces[g].loops[0];
        for (std::size_t i = 0; i < l.size() && !found; ++i)
          if (l[i] == vb && l[(i + 1) % l.size()] == va) {
            if (std::find(l.begin(), l.end(), vc) != l.end()) break;
            s.neighbour = g;
            s.neighbourLoop = l;
            s.neighbourLoop.insert(s.neighbourLoop.begin() + static_cast<std::ptrdiff_t>(i + 1), vc);
            found =
                simpleInItsPlane(shell, shell.faces[g], s.neighbourLoop) || !simpleInItsPlane(shell, shell.faces[g], l);
          }
      }
      if (found) return s;
    }
  return std::nullopt;
}

}  // namespace

std::size_t splitTouchingLoops(SweepOutput& shell, double length) {
  std::size_t splits = 0;
  bool closed = false;  // checked at the first loop to split (most shells have none)
  // Faces the split adds are looked at in turn: a loop may touch itself more than once.
  for (std::size_t fi = 0; fi < shell.faces.size(); ++fi) {
    if (shell.faces[fi].loops.size() != 1 || shell.faces[fi].loops[0].size() < 5 ||
        simpleInItsPlane(shell, shell.faces[fi], shell.faces[fi].loops[0]))
      continue;
    if (!closed && unpairedEdges(shell) != 0) return 0;
    closed = true;
    std::optional<Split> s = findSplit(shell, fi, length);
    if (!s) continue;
    shell.faces[s->neighbour].loops[0] = std::move(s->neighbourLoop);
    ShellFace part = shell.faces[fi];
    part.loops[0] = std::move(s->second);
    shell.faces[fi].loops[0] = std::move(s->first);
    shell.faces.push_back(std::move(part));
    ++splits;
  }
  return splits;
}

}  // namespace corbel::extrude
