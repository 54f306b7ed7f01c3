// The shell where stages meet (Sec. 4.5.2): vertices welded by position at a seam, faces of
// one edge and profile segment joined across it, and every boundary piece split at the
// vertices that lie on it (no T-junctions).
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::extrude::staging {

int Stager::point(const Vec3& p) {
  points_.push_back(p);
  return static_cast<int>(points_.size()) - 1;
}

int Stager::weld(const Vec2& p, double seam) {
  auto& grid = seams_[seam];
  const double cell = tol_.cluster;
  const auto ix = static_cast<std::int64_t>(std::floor(p[0] / cell)), iy = static_cast<std::int64_t>(std::floor(p[1] / cell));
  auto key = [](std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^ static_cast<std::uint64_t>(y);
  };
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      auto it = grid.find(key(ix + dx, iy + dy));
      if (it == grid.end()) continue;
      for (int v : it->second)
        if (std::abs(points_[v][0] - p[0]) <= tol_.cluster && std::abs(points_[v][1] - p[1]) <= tol_.cluster) return v;
    }
  const int v = point(Vec3(p[0], p[1], seam));
  grid[key(ix, iy)].push_back(v);
  return v;
}

// Faces of one edge and profile segment in one plane are one face, whichever stage made them.
void Stager::addFace(RawFace f) {
  if (f.segments.empty()) return;
  const ShellFace& i = f.info;
  if (!i.base && (i.segment >= 0 || i.step >= 0)) {
    const auto key = std::make_tuple(i.sourceLoop, i.sourceEdge, i.step, i.profile, i.segment);
    const Vec3 p = points_[f.segments.front().first];
    auto range = byKey_.equal_range(key);
    for (auto it = range.first; it != range.second; ++it) {
      RawFace& g = faces_[it->second];
      const Vec3 q = points_[g.segments.front().first];
      if (OpenMesh::dot(g.info.normal, i.normal) > 1 - 1e-12 && std::abs(OpenMesh::dot(i.normal, p - q)) <= tol_.cluster) {
        g.segments.insert(g.segments.end(), f.segments.begin(), f.segments.end());
        return;
      }
    }
    byKey_.emplace(key, static_cast<int>(faces_.size()));
  }
  faces_.push_back(std::move(f));
}

void Stager::addFlatFace(std::vector<int> loop, bool up, const ShellFace& info) {
  double a = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 &p = points_[loop[k]], &q = points_[loop[(k + 1) % loop.size()]];
    a += p[0] * q[1] - p[1] * q[0];
  }
  if ((a > 0) != up) std::reverse(loop.begin(), loop.end());
  RawFace f;
  f.info = info;
  f.info.normal = Vec3(0, 0, up ? 1 : -1);
  for (std::size_t k = 0; k < loop.size(); ++k) f.segments.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  addFace(std::move(f));
}

// Every boundary piece is split at the shell's vertices that lie on it, so faces meet edge to
// edge: faces from different stages along a seam, and the pieces of one face where simultaneous
// events left a long top opposite several short ones (ambiguous events along one line,
// Fig. 22). A piece and its reverse then cancel when the face is traced.
void Stager::fixTJunctions() {
  // The vertices sorted by x and by y: a piece looks only among those within its bounding box
  // on the axis where the box is narrower (by x alone, the eaves of a ring of walls running
  // north-south scan a fifth of the shell each), and tests the box before the distance. Each
  // entry carries the vertex's coordinates, so the scan reads one array in order, and both
  // the search and the box test are free of branches that depend on the data (the scan runs
  // for every piece of every shell, and mispredicted branches were most of its time).
  struct Entry {
    double key;
    Vec3 p;
    int id;
  };
  std::array<std::vector<Entry>, 2> sorted;
  for (int axis = 0; axis < 2; ++axis) {
    sorted[axis].resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) sorted[axis][i] = {points_[i][axis], points_[i], static_cast<int>(i)};
    std::sort(sorted[axis].begin(), sorted[axis].end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  }
  // The first entry whose key is not below x (std::lower_bound, without the branches).
  auto firstFrom = [](const std::vector<Entry>& v, double x) {
    if (v.empty()) return v.data();
    const Entry* base = v.data();
    for (std::size_t n = v.size(); n > 1;) {
      const std::size_t half = n / 2;
      base = base[half].key < x ? base + half : base;
      n -= half;
    }
    return base + (base->key < x ? 1 : 0);
  };
  // A tenth of δ2: vertices of one event lie on their edges to rounding, seam vertices to
  // the weld; a wider net would split edges at vertices that merely pass close (measured on
  // the real footprints: at δ2 one roof's area identity degrades to 3e-9, at δ2/10 it stays
  // at 5e-11 and two footprints that failed before close).
  const double splitTol = 0.1 * tol_.cluster;

  // Pieces come in pairs, (u, v) in one face and (v, u) in its neighbour, and the box and so
  // the vertices that pass it are the same both ways: each undirected piece is scanned once
  // (pieces grouped by their lower vertex, a counting sort), and only where some vertex passes
  // the box is the distance measured, for each direction on its own as before.
  std::vector<int> first(points_.size() + 1, 0);
  std::size_t pieces = 0;
  for (const RawFace& f : faces_) {
    pieces += f.segments.size();
    for (auto [u, v] : f.segments) ++first[std::min(u, v) + 1];
  }
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  struct Piece {
    int u, v;  // as the face runs it
    int at;    // its place among all pieces, face by face
  };
  std::vector<Piece> byLow(pieces);
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    int at = 0;
    for (const RawFace& f : faces_)
      for (auto [u, v] : f.segments) byLow[fill[std::min(u, v)]++] = {u, v, at++};
  }
  // The vertices each piece is split at: (piece, t, vertex), sorted at the end.
  struct Split {
    int at;
    double t;
    int w;
    bool operator<(const Split& o) const { return std::tie(at, t, w) < std::tie(o.at, o.t, o.w); }
  };
  std::vector<Split> splits;
  std::vector<const Entry*> near;
  std::size_t visited = 0;
  for (std::size_t low = 0; low < points_.size(); ++low) {
    for (int i = first[low]; i < first[low + 1]; ++i) {
      const Piece& pc = byLow[i];
      const int high = std::max(pc.u, pc.v);
      // An earlier piece of this vertex with the same other end was scanned already.
      bool seen = false;
      for (int j = first[low]; j < i && !seen; ++j) seen = std::max(byLow[j].u, byLow[j].v) == high;
      if (seen) continue;
      // A runaway shell (a sweep that diverged far beyond its plan) can make this quadratic:
      // honour the time limit and cancellation here too.
      if ((++visited & 1023) == 0) {
        remaining();
        if (progress_ && progress_->cancelled()) throw Cancelled();
      }
      const Vec3 &pa = points_[pc.u], &pb = points_[pc.v];
      if (!((pb - pa).sqrnorm() > 0)) continue;
      // Every vertex within splitTol of the piece lies in its box widened by δ2 > splitTol.
      Vec3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(pa[k], pb[k]) - tol_.cluster;
        hi[k] = std::max(pa[k], pb[k]) + tol_.cluster;
      }
      const int axis = hi[1] - lo[1] < hi[0] - lo[0] ? 1 : 0;
      const std::vector<Entry>& order = sorted[axis];
      const Entry* const last = order.data() + order.size();
      near.clear();
      for (const Entry* e = firstFrom(order, lo[axis]); e != last && e->key <= hi[axis]; ++e) {
        const Vec3& p = e->p;
        const bool inBox = (p[0] >= lo[0]) & (p[0] <= hi[0]) & (p[1] >= lo[1]) & (p[1] <= hi[1]) & (p[2] >= lo[2]) &
                           (p[2] <= hi[2]) & (e->id != pc.u) & (e->id != pc.v);
        if (inBox) near.push_back(e);
      }
      if (near.empty()) continue;
      // Each piece on this line, each way, measured from its own start.
      for (int j = i; j < first[low + 1]; ++j) {
        const Piece& q = byLow[j];
        if (std::max(q.u, q.v) != high) continue;
        const Vec3 &a = points_[q.u], &b = points_[q.v];
        const Vec3 d = b - a;
        const double len2 = d.sqrnorm();
        for (const Entry* e : near) {
          const double t = OpenMesh::dot(e->p - a, d) / len2;
          if (t <= 0 || t >= 1) continue;
          if ((a + d * t - e->p).norm() <= splitTol) splits.push_back({q.at, t, e->id});
        }
      }
    }
  }
  if (splits.empty()) return;
  std::sort(splits.begin(), splits.end());
  std::vector<std::pair<int, int>> out;
  auto next = splits.begin();
  int at = 0;
  for (RawFace& f : faces_) {
    if (next == splits.end()) break;
    if (next->at >= at + static_cast<int>(f.segments.size())) {
      at += static_cast<int>(f.segments.size());
      continue;
    }
    out.clear();
    for (auto [u, v] : f.segments) {
      int prev = u;
      for (; next != splits.end() && next->at == at; ++next) {
        out.emplace_back(prev, next->w);
        prev = next->w;
      }
      out.emplace_back(prev, v);
      ++at;
    }
    f.segments = out;
  }
}

}  // namespace corbel::extrude::staging
