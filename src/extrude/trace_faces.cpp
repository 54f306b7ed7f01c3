// The shell's faces (Sec. 4.2): the boundary pieces each edge traced, traced into planar
// polygons with holes.
#include "extrude/sweeper.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace corbel::extrude::sweeping {

void Sweeper::buildFaces(SweepOutput& out) {
  out.points = std::move(points_);
  for (const Vec3& p : out.points) out.maxHeight = std::max(out.maxHeight, p[2]);
  std::vector<RawFace> raw;
  raw.reserve(faces_.size());
  for (FaceBuild& f : faces_) {
    RawFace r;
    r.segments = std::move(f.segments);
    r.info.normal = f.normal;
    r.info.base = f.base;
    r.info.segment = f.segment;
    r.info.angle = f.angle;
    if (f.src >= 0) {
      r.info.sourceLoop = inputs_[f.src]->sourceLoop;
      r.info.sourceEdge = inputs_[f.src]->sourceEdge;
      r.info.profile = inputs_[f.src]->profile;
      r.info.step = inputs_[f.src]->step;
    }
    raw.push_back(std::move(r));
  }
  if (in_.keepRaw) out.raw = std::move(raw);
  else traceFaces(out.points, raw, tol_, out.faces, warnings_);
}


}  // namespace corbel::extrude::sweeping

namespace corbel::extrude {

using sweeping::cross2;

void traceFaces(const std::vector<Vec3>& points_, const std::vector<RawFace>& raw, const Tolerances& tol_,
                std::vector<ShellFace>& faces, std::vector<std::string>& warnings) {
  // Working lists shared by the faces (cleared for each): a shell has a few dozen faces of a
  // few pieces each, and allocating them anew for every face cost more than the tracing.
  std::vector<std::pair<int, int>> all, segs;
  std::vector<char> usedSeg;
  std::vector<int> outers, holes, loop, verts;
  std::vector<std::size_t> starts;
  std::vector<Vec2> flat2D;
  faces.reserve(faces.size() + raw.size());
  for (const RawFace& rf : raw) {
    const ShellFace& f = rf.info;
    // Drop zero-length pieces and pieces cancelled by their reverse (a face folded onto itself):
    // each piece keeps its count less its reverse's. Sorted vectors, not maps: faces are small
    // and this runs for every face of every shell.
    all.clear();
    all.reserve(rf.segments.size());
    for (auto [u, v] : rf.segments)
      if (u != v && (points_[u] - points_[v]).norm() > tol_.cluster * 1e-3) all.emplace_back(u, v);
    std::sort(all.begin(), all.end());
    segs.clear();
    for (std::size_t i = 0; i < all.size();) {
      std::size_t j = i;
      while (j < all.size() && all[j] == all[i]) ++j;
      const auto rev = std::equal_range(all.begin(), all.end(), std::make_pair(all[i].second, all[i].first));
      const long net = static_cast<long>(j - i) - static_cast<long>(rev.second - rev.first);
      for (long k = 0; k < net; ++k) segs.push_back(all[i]);
      i = j;
    }
    if (segs.size() < 3) continue;
    auto leaving = [&](int at) {
      return std::equal_range(segs.begin(), segs.end(), at, [](const auto& a, const auto& b) {
        if constexpr (std::is_same_v<std::decay_t<decltype(a)>, int>) return a < b.first;
        else return a.first < b;
      });
    };

    // 2D frame of the face plane, counter-clockwise seen from outside.
    Vec3 u = std::abs(f.normal[2]) < 0.9 ? OpenMesh::cross(Vec3(0, 0, 1), f.normal) : Vec3(1, 0, 0);
    u.normalize();
    const Vec3 w = OpenMesh::cross(f.normal, u);
    auto flat = [&](int v) { return Vec2(OpenMesh::dot(points_[v], u), OpenMesh::dot(points_[v], w)); };

    usedSeg.assign(segs.size(), 0);
    // The face's loops, end to end in `verts` (loop k is [starts[k], starts[k + 1])).
    verts.clear();
    starts.assign(1, 0);
    auto keep = [&](auto first, auto last) {
      if (last - first < 3) return;
      verts.insert(verts.end(), first, last);
      starts.push_back(verts.size());
    };
    for (int s0 = 0; s0 < static_cast<int>(segs.size()); ++s0) {
      if (usedSeg[s0]) continue;
      loop.clear();
      int s = s0;
      while (s >= 0 && !usedSeg[s]) {
        usedSeg[s] = 1;
        loop.push_back(segs[s].first);
        const int at = segs[s].second;
        // Among the pieces leaving `at`, the first one clockwise from the way back.
        int best = -1, candidates = 0;
        const auto range = leaving(at);
        for (auto it = range.first; it != range.second; ++it)
          if (!usedSeg[it - segs.begin()]) {
            ++candidates;
            best = static_cast<int>(it - segs.begin());
          }
        if (candidates > 1) {
          const Vec2 back = flat(segs[s].first) - flat(at);
          double bestTurn = 1e9;
          for (auto it = range.first; it != range.second; ++it) {
            const int k = static_cast<int>(it - segs.begin());
            if (usedSeg[k]) continue;
            const Vec2 out = flat(segs[k].second) - flat(at);
            double turn = std::atan2(cross2(out, back), OpenMesh::dot(out, back));  // clockwise angle back → out
            if (turn <= 0) turn += 2 * std::numbers::pi;
            if (turn < bestTurn) {
              bestTurn = turn;
              best = k;
            }
          }
        }
        s = best;
      }
      // A loop that passes one vertex twice (a dormer's ridge reaching the top of the wall it
      // stands on) is two loops touching there: a polygon mesh takes each as its own face.
      // Split at the first repeat, the part after it first, until none is left (rare: the
      // common loop goes straight to `verts`).
      auto repeatIn = [](const std::vector<int>& l) {
        for (std::size_t i = 0; i < l.size(); ++i)
          for (std::size_t j = i + 1; j < l.size(); ++j)
            if (l[i] == l[j]) return std::make_pair(i, j);
        return std::make_pair(l.size(), l.size());
      };
      if (repeatIn(loop).first == loop.size()) {
        keep(loop.begin(), loop.end());
        continue;
      }
      std::vector<std::vector<int>> pending{loop};
      while (!pending.empty()) {
        std::vector<int> l = std::move(pending.back());
        pending.pop_back();
        const auto [i, j] = repeatIn(l);
        if (i == l.size()) {
          keep(l.begin(), l.end());
          continue;
        }
        pending.emplace_back(l.begin() + i, l.begin() + j);
        std::vector<int> rest(l.begin(), l.begin() + i);
        rest.insert(rest.end(), l.begin() + j, l.end());
        pending.push_back(std::move(rest));
      }
    }
    const int loopCount = static_cast<int>(starts.size()) - 1;
    auto begin = [&](int k) { return verts.begin() + static_cast<std::ptrdiff_t>(starts[k]); };
    auto end = [&](int k) { return verts.begin() + static_cast<std::ptrdiff_t>(starts[k + 1]); };
    // Outer loops are counter-clockwise in the face frame; holes go to the outer loop that
    // contains them. Each vertex of a loop in the face's frame is worked out once (flat2D[i]
    // for verts[i]).
    flat2D.resize(verts.size());
    for (std::size_t i = 0; i < verts.size(); ++i) flat2D[i] = flat(verts[i]);
    auto signedArea = [&](int k) {
      const std::size_t first = starts[k], last = starts[k + 1];
      double a = 0;
      for (std::size_t i = first; i < last; ++i) a += cross2(flat2D[i], flat2D[i + 1 == last ? first : i + 1]);
      return 0.5 * a;
    };
    outers.clear();
    holes.clear();
    for (int i = 0; i < loopCount; ++i) {
      const double a = signedArea(i);
      if (std::abs(a) <= tol_.cluster * tol_.cluster) continue;
      (a > 0 ? outers : holes).push_back(i);
    }
    // The faces made here go straight to the output, from `made` on.
    const std::size_t made = faces.size();
    for (int o : outers) {
      faces.push_back(f);
      faces.back().loops.emplace_back(begin(o), end(o));
    }
    auto inside = [&](const Vec2& p, const std::vector<int>& loop) {
      bool in = false;
      for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec2 a = flat(loop[i]), b = flat(loop[j]);
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
      }
      return in;
    };
    for (int h : holes) {
      // A hole's test point: the midpoint of its first edge nudged to its inside is robust
      // against holes touching their outer loop at a vertex.
      const auto hl = begin(h);
      Vec2 probe = (flat(hl[0]) + flat(hl[1])) * 0.5;
      int owner = -1;
      double ownerArea = 1e300;
      for (std::size_t k = made; k < faces.size(); ++k) {
        const std::vector<int>& outer = faces[k].loops[0];
        if (!inside(probe, outer)) continue;
        const double a = signedArea(outers[k - made]);
        if (a < ownerArea) {
          ownerArea = a;
          owner = static_cast<int>(k);
        }
      }
      if (owner >= 0) faces[owner].loops.emplace_back(begin(h), end(h));
      else if (faces.size() > made) {
        warnings.push_back("a face boundary piece could not be placed (hole outside its face)");
      }
    }
  }
}

}  // namespace corbel::extrude
