#include "extrude/walls.h"

#include <algorithm>
#include <cmath>
#include <regex>

namespace corbel::extrude {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

// Whether corner i of `l` can go: its two edges share a wall and a profile, and it lies on the
// line between its neighbours (within `colinear` m), between them.
bool joinable(const PlanLoop& l, int i, double colinear) {
  const int n = static_cast<int>(l.points.size());
  const int before = (i + n - 1) % n;
  if (wallOf(l, before) != wallOf(l, i) || l.profile[before] != l.profile[i]) return false;
  const Vec2 &a = l.points[before], &p = l.points[i], &b = l.points[(i + 1) % n];
  const Vec2 d = b - a;
  const double len = d.norm();
  if (!(len > 0)) return false;
  return std::abs(cross(d, p - a)) / len <= colinear && OpenMesh::dot(p - a, d) > 0 && OpenMesh::dot(b - p, d) > 0;
}

}  // namespace

std::optional<KernelWalls> kernelWalls(const ExtrusionSpec& spec, double colinear) {
  bool multi = false;  // some wall has more than one edge
  for (const PlanLoop& l : spec.loops) {
    const int n = static_cast<int>(l.points.size());
    for (int i = 0; i < n && !multi; ++i) multi = n > 1 && wallOf(l, i) == wallOf(l, (i + 1) % n);
  }
  if (!multi) return std::nullopt;

  KernelWalls out;
  out.spec = spec;
  // Per loop: the kernel edge each input edge lies in, and how far into it the input edge starts.
  std::vector<std::vector<int>> kernelEdge(spec.loops.size());
  std::vector<std::vector<double>> offset(spec.loops.size());
  std::vector<std::vector<double>> kernelLength(spec.loops.size());
  for (std::size_t li = 0; li < spec.loops.size(); ++li) {
    const PlanLoop& l = spec.loops[li];
    const int n = static_cast<int>(l.points.size());
    std::vector<int> kept;
    for (int i = 0; i < n; ++i)
      if (!joinable(l, i, colinear)) kept.push_back(i);
    if (kept.size() < 3) kept.clear();  // never join a loop away: keep it as it is
    if (kept.empty())
      for (int i = 0; i < n; ++i) kept.push_back(i);
    PlanLoop& k = out.spec.loops[li];
    k.points.clear();
    k.profile.clear();
    k.walls.clear();
    kernelEdge[li].assign(n, 0);
    offset[li].assign(n, 0.0);
    for (std::size_t c = 0; c < kept.size(); ++c) {
      const int from = kept[c], to = kept[(c + 1) % kept.size()];
      k.points.push_back(l.points[from]);
      k.profile.push_back(l.profile[from]);
      k.walls.push_back(wallOf(l, from));
      double along = 0;
      int e = from;
      do {
        kernelEdge[li][e] = static_cast<int>(c);
        offset[li][e] = along;
        along += (l.points[(e + 1) % n] - l.points[e]).norm();
        e = (e + 1) % n;
      } while (e != to);
      kernelLength[li].push_back((l.points[to] - l.points[from]).norm());
    }
    out.inputCorner.push_back(kept);
  }
  // Anchors: the point on the wall, then on the kernel edge that holds it.
  auto move = [&](Anchor& a) {
    const WallRun run = wallRun(spec, a.loop, a.edge);
    if (run.edges.empty()) return;
    const PlanLoop& l = spec.loops[a.loop];
    double s = a.absolute ? a.along : a.along * run.length;
    int at = run.edges.back();
    double into = 0;
    for (int e : run.edges) {
      const double len = (l.points[(e + 1) % l.points.size()] - l.points[e]).norm();
      if (s <= len || e == run.edges.back()) {
        at = e;
        into = std::clamp(s, 0.0, len);
        break;
      }
      s -= len;
    }
    const int k = kernelEdge[a.loop][at];
    // Kernel edges never span two walls, so a run within one kernel edge is that edge.
    const bool whole = kernelEdge[a.loop][run.edges.front()] == k && kernelEdge[a.loop][run.edges.back()] == k;
    a.edge = k;
    if (whole) return;  // the run is the kernel edge: `along` means the same on it
    const double there = offset[a.loop][at] + into, len = kernelLength[a.loop][k];
    a.along = a.absolute ? there : (len > 0 ? std::clamp(there / len, 0.0, 1.0) : 0.0);
  };
  for (PlanStep& st : out.spec.steps) move(st.anchor);
  for (MeshAnchor& m : out.spec.anchors) move(m.anchor);
  return out;
}

std::string KernelWalls::inputPath(const std::string& where) const {
  static const std::regex corner(R"(^loops\[(\d+)\]\.(points|profile)\[(\d+)\])");
  std::smatch m;
  if (!std::regex_search(where, m, corner)) return where;
  const std::size_t loop = std::stoul(m[1]), k = std::stoul(m[3]);
  if (loop >= inputCorner.size() || k >= inputCorner[loop].size()) return where;
  return "loops[" + m[1].str() + "]." + m[2].str() + "[" + std::to_string(inputCorner[loop][k]) + "]" + m.suffix().str();
}

}  // namespace corbel::extrude
