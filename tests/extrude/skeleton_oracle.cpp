#include "skeleton_oracle.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_straight_skeleton_from_polygon_with_holes_2.h>

#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace corbel::extrude::test {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

// The interior skeleton of the loops turned `turn` quarter turns about the origin, each loop
// started `turn` corners on: the same polygon up to a rotation, exact in floating point, whose
// heights, areas and volumes are the plan's; another try where CGAL fails on one (its ties
// depend on the order it allocates its nodes in). Called in a child process only.
auto skeleton(const std::vector<std::vector<Vec2>>& loops, int turn) {
  auto toPoly = [turn](const std::vector<Vec2>& l) {
    Polygon p;
    for (std::size_t i = 0; i < l.size(); ++i) {
      Vec2 v = l[(i + std::size_t(turn)) % l.size()];
      for (int k = 0; k < turn; ++k) v = Vec2(-v[1], v[0]);
      p.push_back(K::Point_2(v[0], v[1]));
    }
    return p;
  };
  PolygonWithHoles pwh(toPoly(loops.at(0)));
  for (std::size_t i = 1; i < loops.size(); ++i) pwh.add_hole(toPoly(loops[i]));
  auto ss = CGAL::create_interior_straight_skeleton_2(pwh, K());
  if (!ss) throw std::runtime_error("CGAL could not build the straight skeleton");
  return ss;
}

SkeletonRoof roofInProcess(const std::vector<std::vector<Vec2>>& loops, double pitch, int turn) {
  const auto ss = skeleton(loops, turn);
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

// The height and volume under the profile (skeleton_oracle.h) from one skeleton.
std::array<double, 4> underProfileInProcess(const std::vector<std::vector<Vec2>>& loops,
                                            const std::vector<Vec2>& profile, int turn) {
  const auto ss = skeleton(loops, turn);
  double t = 0;
  for (auto v = ss->vertices_begin(); v != ss->vertices_end(); ++v) t = std::max(t, v->time());
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
  return {profileHeight(profile, t), volume, 0, 0};
}

// What one child sends back per query.
struct Record {
  std::uint64_t index;
  std::uint64_t ok;
  std::array<double, 4> values;
};

// Answers queries 0..n−1 by answer(k, turn) in forked children, one child at a time and each
// going through the queries from where the last one stopped. A query whose child dies on it, that
// throws, or that takes longer than secondsPerQuery gets another try turned a quarter and then a
// half turn (skeleton); after three it has no answer (nullopt).
std::vector<std::optional<std::array<double, 4>>> isolated(
    std::size_t n, const std::function<std::array<double, 4>(std::size_t, int)>& answer, double secondsPerQuery) {
  static std::mutex oneChildAtATime;
  const std::lock_guard<std::mutex> lock(oneChildAtATime);
  std::vector<std::optional<std::array<double, 4>>> out(n);
  std::vector<std::size_t> todo(n);
  for (std::size_t k = 0; k < n; ++k) todo[k] = k;
  for (int turn = 0; turn < 3 && !todo.empty(); ++turn) {
    std::vector<std::size_t> failed;
    std::size_t next = 0;  // the first of todo no child has answered or died on
    while (next < todo.size()) {
      int fd[2];
      if (pipe(fd) != 0) throw std::runtime_error("skeleton oracle: pipe failed");
      const pid_t child = fork();
      if (child < 0) throw std::runtime_error("skeleton oracle: fork failed");
      if (child == 0) {
        close(fd[0]);
        for (std::size_t j = next; j < todo.size(); ++j) {
          Record record{j, 1, {}};
          try {
            record.values = answer(todo[j], turn);
          } catch (...) {
            record.ok = 0;
          }
          if (write(fd[1], &record, sizeof record) != ssize_t(sizeof record)) _exit(2);
        }
        _exit(0);
      }
      close(fd[1]);
      std::size_t got = next;  // todo[got] is the next the child owes
      bool hung = false;
      for (;;) {
        Record record{};
        std::size_t have = 0;
        while (have < sizeof record) {
          pollfd p{fd[0], POLLIN, 0};
          if (poll(&p, 1, int(secondsPerQuery * 1000)) == 0) {
            hung = true;
            break;
          }
          const ssize_t r = read(fd[0], reinterpret_cast<char*>(&record) + have, sizeof record - have);
          if (r <= 0) break;
          have += std::size_t(r);
        }
        if (have < sizeof record) break;
        if (record.ok)
          out[todo[record.index]] = record.values;
        else
          failed.push_back(todo[record.index]);
        got = record.index + 1;
      }
      if (hung) kill(child, SIGKILL);
      close(fd[0]);
      int status = 0;
      waitpid(child, &status, 0);
      if (got >= todo.size()) break;
      failed.push_back(todo[got]);  // the child died or hung on it
      next = got + 1;
    }
    todo = std::move(failed);
    std::sort(todo.begin(), todo.end());
  }
  return out;
}

std::string describe(const std::vector<std::vector<Vec2>>& loops) {
  std::size_t corners = 0;
  for (const auto& l : loops) corners += l.size();
  return std::to_string(loops.size()) + " loop(s), " + std::to_string(corners) + " corners";
}

}  // namespace

SkeletonRoof cgalRoof(const std::vector<std::vector<Vec2>>& loops, double pitch) {
  const auto a = isolated(
      1,
      [&](std::size_t, int turn) {
        const SkeletonRoof r = roofInProcess(loops, pitch, turn);
        return std::array<double, 4>{r.maxHeight, r.volume, r.roofArea, double(r.faces)};
      },
      kSkeletonSecondsPerQuery);
  if (!a[0]) throw std::runtime_error("CGAL's straight skeleton failed on this plan (" + describe(loops) + ")");
  const auto& v = *a[0];
  return {v[0], v[1], v[2], std::size_t(v[3])};
}

std::vector<std::optional<UnderProfile>> cgalUnderProfileIsolated(const std::vector<SkeletonQuery>& queries,
                                                                  double secondsPerQuery) {
  const auto a = isolated(
      queries.size(),
      [&](std::size_t k, int turn) -> std::array<double, 4> {
        if (queries[k].dieForTest || (queries[k].dieFirstForTest && turn == 0)) std::abort();
        if (queries[k].hangForTest)
          for (;;) pause();
        return underProfileInProcess(queries[k].loops, queries[k].profile, turn);
      },
      secondsPerQuery);
  std::vector<std::optional<UnderProfile>> out(queries.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k]) out[k] = UnderProfile{(*a[k])[0], (*a[k])[1]};
  return out;
}

UnderProfile cgalUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile) {
  const auto a = cgalUnderProfileIsolated({SkeletonQuery{loops, profile}}, kSkeletonSecondsPerQuery);
  if (!a[0]) throw std::runtime_error("CGAL's straight skeleton failed on this plan (" + describe(loops) + ")");
  return *a[0];
}

double cgalHeightUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile) {
  return cgalUnderProfile(loops, profile).height;
}

double cgalVolumeUnderProfile(const std::vector<std::vector<Vec2>>& loops, const std::vector<Vec2>& profile) {
  return cgalUnderProfile(loops, profile).volume;
}

}  // namespace corbel::extrude::test
