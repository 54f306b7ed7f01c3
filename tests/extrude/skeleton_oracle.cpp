#include "skeleton_oracle.h"
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <unistd.h>
#include <sys/wait.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_straight_skeleton_from_polygon_with_holes_2.h>

#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace corbel::extrude::test {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
// One skeleton at a time: the random run builds them on every core, and with CGAL 5.5.1 it
// crashed under load (SIGSEGV in Straight_skeleton_builder_2::MergeCoincidentNodes on a check
// thread, 2 of 5 full runs on 2 busy cores; the same plans pass one at a time).
std::mutex skeletonMutex;
}  // namespace

SkeletonRoof cgalRoof(const std::vector<std::vector<Vec2>>& loops, double pitch) {
  auto toPoly = [](const std::vector<Vec2>& l) {
    Polygon p;
    for (const Vec2& v : l) p.push_back(K::Point_2(v[0], v[1]));
    return p;
  };
  PolygonWithHoles pwh(toPoly(loops[0]));
  for (std::size_t i = 1; i < loops.size(); ++i) pwh.add_hole(toPoly(loops[i]));
  std::unique_lock<std::mutex> lock(skeletonMutex);
  auto ss = CGAL::create_interior_straight_skeleton_2(pwh, K());
  lock.unlock();
  if (!ss) throw std::runtime_error("CGAL could not build the straight skeleton");
  const double t = std::tan(pitch);
  SkeletonRoof r;
  for (auto v = ss->vertices_begin(); v != ss->vertices_end(); ++v) r.maxHeight = std::max(r.maxHeight, v->time() * t);
  for (auto f = ss->faces_begin(); f != ss->faces_end(); ++f) {
    ++r.faces;
    std::vector<Vec3> poly;
    auto h = f->halfedge();
    auto start = h;
    do {
      const auto& p = h->vertex()->point();
      poly.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), h->vertex()->time() * t);
      h = h->next();
    } while (h != start);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      r.volume += OpenMesh::dot(poly[0], OpenMesh::cross(poly[i], poly[i + 1])) / 6.0;
    r.roofArea += 0.5 * newellNormal(poly).norm();
  }
  return r;
}

namespace {

// Height of the profile at horizontal distance t (the first rise at t = 0 included; past the
// last point, the last segment goes on).
double profileHeight(const std::vector<Vec2>& pr, double t) {
  // The last sloped segment that starts at or before t (else the first one): vertical pieces
  // (a wall) only lift the segments after them.
  int seg = -1;
  for (std::size_t i = 0; i + 1 < pr.size(); ++i)
    if (pr[i + 1][0] > pr[i][0] && (seg < 0 || pr[i][0] <= t)) seg = static_cast<int>(i);
  const Vec2 a = pr[seg], b = pr[seg + 1];
  return a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0]);
}

struct Corner {
  double x, y, t;
};

// ∫ H(t) over a triangle whose t is linear, split at the profile's breakpoints so H is
// linear on each piece: each piece gives its area × H at its centroid.
double integrateTriangle(const std::array<Corner, 3>& tri, const std::vector<Vec2>& pr) {
  const double signedArea =
      0.5 * ((tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[2].x - tri[0].x) * (tri[1].y - tri[0].y));
  if (signedArea == 0) return 0;
  std::vector<double> cuts{-std::numeric_limits<double>::infinity()};
  for (std::size_t i = 1; i + 1 < pr.size(); ++i) cuts.push_back(pr[i][0]);
  cuts.push_back(std::numeric_limits<double>::infinity());
  double sum = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    std::vector<Corner> poly(tri.begin(), tri.end());
    for (int side = 0; side < 2; ++side) {  // keep t >= cuts[k], then t <= cuts[k + 1]
      const double level = side == 0 ? cuts[k] : cuts[k + 1];
      if (!std::isfinite(level)) continue;
      auto inside = [&](const Corner& c) { return side == 0 ? c.t >= level : c.t <= level; };
      std::vector<Corner> out;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Corner &a = poly[i], &b = poly[(i + 1) % poly.size()];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) {
          const double u = (level - a.t) / (b.t - a.t);
          out.push_back({a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), level});
        }
      }
      poly = std::move(out);
    }
    if (poly.size() < 3) continue;
    double area = 0, cx = 0, cy = 0, ct = 0;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const Corner &a = poly[0], &b = poly[i], &c = poly[i + 1];
      const double w = std::abs(0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
      area += w;
      cx += w * (a.x + b.x + c.x) / 3;
      cy += w * (a.y + b.y + c.y) / 3;
      ct += w * (a.t + b.t + c.t) / 3;
    }
    if (area == 0) continue;
    sum += area * profileHeight(pr, ct / area);
  }
  return signedArea > 0 ? sum : -sum;
}

auto skeleton(const std::vector<std::vector<Vec2>>& loops) {
  const std::lock_guard<std::mutex> lock(skeletonMutex);
  PolygonWithHoles pwh;
  {
    Polygon outer;
    for (const Vec2& v : loops[0]) outer.push_back(K::Point_2(v[0], v[1]));
    pwh = PolygonWithHoles(outer);
  }
  for (std::size_t i = 1; i < loops.size(); ++i) {
    Polygon h;
    for (const Vec2& v : loops[i]) h.push_back(K::Point_2(v[0], v[1]));
    pwh.add_hole(h);
  }
  auto ss = CGAL::create_interior_straight_skeleton_2(pwh, K());
  if (!ss) throw std::runtime_error("CGAL could not build the straight skeleton");
  return ss;
}

}  // namespace

double cgalHeightUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile) {
  const auto ss = skeleton(loops);
  double t = 0;
  for (auto v = ss->vertices_begin(); v != ss->vertices_end(); ++v) t = std::max(t, v->time());
  return profileHeight(profile, t);
}

double cgalVolumeUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile) {
  const auto ss = skeleton(loops);
  double volume = 0;
  for (auto f = ss->faces_begin(); f != ss->faces_end(); ++f) {
    std::vector<Corner> poly;
    auto h = f->halfedge();
    const auto start = h;
    do {
      const auto& p = h->vertex()->point();
      poly.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), h->vertex()->time()});
      h = h->next();
    } while (h != start);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      volume += integrateTriangle({poly[0], poly[i], poly[i + 1]}, profile);
  }
  return volume;
}

std::vector<std::optional<double>> cgalHeightsIsolated(const std::vector<HeightQuery>& queries) {
  std::vector<std::optional<double>> out(queries.size());
  std::size_t next = 0;  // the first query no child has answered or died on
  while (next < queries.size()) {
    int fd[2];
    if (pipe(fd) != 0) throw std::runtime_error("cgalHeightsIsolated: pipe failed");
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error("cgalHeightsIsolated: fork failed");
    if (child == 0) {
      close(fd[0]);
      for (std::size_t k = next; k < queries.size(); ++k) {
        struct {
          std::uint64_t index;
          double height;
          std::uint64_t ok;
        } record{k, 0.0, 1};
        if (queries[k].dieForTest) std::abort();
        try {
          record.height = cgalHeightUnderProfile(queries[k].loops, queries[k].profile);
        } catch (...) {
          record.ok = 0;
        }
        if (write(fd[1], &record, sizeof record) != ssize_t(sizeof record)) _exit(2);
      }
      _exit(0);
    }
    close(fd[1]);
    struct {
      std::uint64_t index;
      double height;
      std::uint64_t ok;
    } record{};
    std::size_t got = 0;
    for (;;) {
      std::size_t have = 0;
      while (have < sizeof record) {
        const ssize_t n = read(fd[0], reinterpret_cast<char*>(&record) + have, sizeof record - have);
        if (n <= 0) break;
        have += std::size_t(n);
      }
      if (have < sizeof record) break;
      if (record.ok) out[record.index] = record.height;
      got = record.index + 1;
    }
    close(fd[0]);
    int status = 0;
    waitpid(child, &status, 0);
    const std::size_t resume = std::max(got, next);
    if (resume >= queries.size()) break;
    // The child died on query `resume` (no answer for it): skip it and go on.
    next = resume + 1;
  }
  return out;
}

}  // namespace corbel::extrude::test
