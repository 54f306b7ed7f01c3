#include "city/labels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>
#include <unordered_map>

namespace corbel::city {

namespace {

constexpr std::string_view kLengths[] = {"short", "medium", "long"};
constexpr std::string_view kOrientations[] = {"street", "side", "back"};

// A uniform grid of points or segments, for neighbour searches.
template <class T>
class Grid {
 public:
  explicit Grid(double cell) : cell_(cell) {}
  // The item in every cell the segment ab passes through (column by column), so a long diagonal
  // costs cells in proportion to its length, not to its bounding box.
  void addSegment(const Vec2& a, const Vec2& b, const T& item) {
    const Vec2 &p = a[0] <= b[0] ? a : b, &q = a[0] <= b[0] ? b : a;
    const double slope = q[0] > p[0] ? (q[1] - p[1]) / (q[0] - p[0]) : 0;
    const double pad = cell_ * 1e-9;  // a cell boundary crossed within rounding counts on both sides
    for (long x = key(p[0]); x <= key(q[0]); ++x) {
      const double from = std::max(p[0], static_cast<double>(x) * cell_), to = std::min(q[0], static_cast<double>(x + 1) * cell_);
      double y0 = p[1] + slope * (from - p[0]), y1 = p[1] + slope * (to - p[0]);
      if (q[0] == p[0]) y0 = p[1], y1 = q[1];
      for (long y = key(std::min(y0, y1) - pad); y <= key(std::max(y0, y1) + pad); ++y) cells_[pack(x, y)].push_back(item);
    }
  }
  template <class F>
  void near(const Vec2& p, double reach, F&& f) const {
    for (long x = key(p[0] - reach); x <= key(p[0] + reach); ++x)
      for (long y = key(p[1] - reach); y <= key(p[1] + reach); ++y)
        if (auto it = cells_.find(pack(x, y)); it != cells_.end())
          for (const T& item : it->second) f(item);
  }

 private:
  long key(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static long long pack(long x, long y) { return (static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL); }
  double cell_;
  std::unordered_map<long long, std::vector<T>> cells_;
};

Vec2 centroid(const std::vector<Vec2>& ring) {
  double a = 0;
  Vec2 c{0, 0};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    const double w = p[0] * q[1] - p[1] * q[0];
    a += w;
    c += (p + q) * w;
  }
  if (a == 0) return ring.front();
  return c / (3 * a);
}

Vec2 outwardNormal(const Vec2& p, const Vec2& q) {
  const Vec2 d = q - p;
  const double n = d.norm();
  return n > 0 ? Vec2(d[1] / n, -d[0] / n) : Vec2(0, 1);
}

Vec2 closestOnSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double l2 = d.sqrnorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return a + d * t;
}

}  // namespace

std::string_view lengthName(LengthClass c) { return kLengths[static_cast<int>(c)]; }
std::string_view orientationName(Orientation o) { return kOrientations[static_cast<int>(o)]; }
std::optional<LengthClass> lengthFromName(std::string_view n) {
  for (int i = 0; i < 3; ++i)
    if (kLengths[i] == n) return static_cast<LengthClass>(i);
  return std::nullopt;
}
std::optional<Orientation> orientationFromName(std::string_view n) {
  for (int i = 0; i < 3; ++i)
    if (kOrientations[i] == n) return static_cast<Orientation>(i);
  return std::nullopt;
}

std::vector<EdgeLabel> labelEdges(const std::vector<std::vector<Vec2>>& loops, const Vec2& front,
                                  const LabelOptions& o) {
  std::vector<EdgeLabel> out;
  const double streetCos = std::cos(o.streetDegrees * std::numbers::pi / 180);
  for (std::size_t li = 0; li < loops.size(); ++li) {
    const auto& ring = loops[li];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
      EdgeLabel e;
      e.loop = static_cast<int>(li);
      e.edge = static_cast<int>(i);
      e.length = (q - p).norm();
      e.length_class = e.length < o.shortBelow  ? LengthClass::Short
                       : e.length >= o.longFrom ? LengthClass::Long
                                                : LengthClass::Medium;
      const Vec2 n = outwardNormal(p, q);
      const double c = front.dot(n);
      const double s = n[0] * front[1] - n[1] * front[0];  // > 0: n lies clockwise of the front
      e.angle = std::atan2(s, c) * 180 / std::numbers::pi;
      if (e.angle <= -180) e.angle += 360;
      e.disk = {s, c};
      e.orientation = c >= streetCos - 1e-12    ? Orientation::Street
                      : c <= -streetCos + 1e-12 ? Orientation::Back
                                                : Orientation::Side;
      out.push_back(e);
    }
  }
  return out;
}

std::vector<BuildingLabels> labelTown(const Town& town, const LabelOptions& o, unsigned jobsWanted,
                                      const std::vector<std::size_t>* only) {
  const auto& bs = town.buildings;
  std::vector<BuildingLabels> out(bs.size());
  struct Segment {
    std::size_t building;
    Vec2 a, b;
  };
  Grid<Segment> walls(o.gapReach / 2);
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);  // the usable buildings' corners
  for (std::size_t i = 0; i < bs.size(); ++i)
    if (bs[i].problem.empty()) {
      const auto& r = bs[i].loops[0];
      for (std::size_t k = 0; k < r.size(); ++k) {
        const Vec2 &a = r[k], &b = r[(k + 1) % r.size()];
        walls.addSegment(a, b, {i, a, b});
        lo = lo.min(a);
        hi = hi.max(a);
      }
    }
  // Streets only matter within reach of a building: each segment is clipped to the buildings'
  // box widened by the reach (Liang-Barsky), so a street drawn far past the town costs nothing.
  Grid<Segment> streets(50.0);
  lo -= Vec2(o.streetReach + 1, o.streetReach + 1);
  hi += Vec2(o.streetReach + 1, o.streetReach + 1);
  for (const Street& s : town.streets)
    for (std::size_t k = 0; k + 1 < s.points.size() && lo[0] <= hi[0]; ++k) {
      const Vec2 &a = s.points[k], &b = s.points[k + 1], d = b - a;
      double t0 = 0, t1 = 1;
      for (int axis = 0; axis < 2 && t0 <= t1; ++axis) {
        if (d[axis] == 0) {
          if (a[axis] < lo[axis] || a[axis] > hi[axis]) t0 = 2;
          continue;
        }
        double ta = (lo[axis] - a[axis]) / d[axis], tb = (hi[axis] - a[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (t0 <= t1) streets.addSegment(a + d * t0, a + d * t1, {0, a, b});
    }

  // Each building's labels depend only on the grids, which are read-only from here: the
  // buildings are shared out between threads.
  auto labelOne = [&](std::size_t i) {
    const Building& b = bs[i];
    if (!b.problem.empty()) return;
    BuildingLabels& L = out[i];
    const auto& ring = b.loops[0];
    // The nearest street, from the outline's centroid.
    const Vec2 c = centroid(ring);
    double best = o.streetReach;
    Vec2 toStreet{0, 0};
    if (!town.streets.empty())
      streets.near(c, o.streetReach, [&](const Segment& s) {
        const Vec2 q = closestOnSegment(c, s.a, s.b);
        const double d = (q - c).norm();
        if (d < best && d > 0) {
          best = d;
          toStreet = (q - c) / d;
        }
      });
    if (toStreet.sqrnorm() > 0) {
      L.front = toStreet;
      L.fromStreet = true;
    } else {
      // No street: the front is the edge that looks over the widest gap to the neighbours: the
      // nearest wall of another building hit by three rays from the edge's middle (along its
      // normal and 30° to either side); a tie goes to the longer edge.
      double bestClear = -1, bestLen = 0;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 &p = ring[k], &q = ring[(k + 1) % ring.size()];
        const Vec2 m = (p + q) / 2, n = outwardNormal(p, q);
        const double c30 = std::cos(std::numbers::pi / 6), s30 = 0.5;
        const Vec2 rays[3] = {
            n, {c30 * n[0] - s30 * n[1], s30 * n[0] + c30 * n[1]}, {c30 * n[0] + s30 * n[1], -s30 * n[0] + c30 * n[1]}};
        double clear = o.gapReach;
        walls.near(m, o.gapReach, [&](const Segment& w) {
          if (w.building == i) return;
          for (const Vec2& r : rays) {
            // m + t r = a + u (b - a), t > 0, u in [0, 1].
            const Vec2 e = w.b - w.a, g = w.a - m;
            const double den = r[0] * e[1] - r[1] * e[0];
            if (std::abs(den) < 1e-12) continue;
            const double t = (g[0] * e[1] - g[1] * e[0]) / den;
            const double u = (g[0] * r[1] - g[1] * r[0]) / den;
            if (t > 0 && u >= 0 && u <= 1) clear = std::min(clear, t);
          }
        });
        const double len = (q - p).norm();
        if (clear > bestClear + 1e-9 || (std::abs(clear - bestClear) <= 1e-9 && len > bestLen)) {
          bestClear = clear;
          bestLen = len;
          L.front = n;
        }
      }
    }
    L.edges = labelEdges(b.loops, L.front, o);
    double longest = -1;
    for (std::size_t k = 0; k < L.edges.size(); ++k)
      if (L.edges[k].loop == 0 && L.edges[k].orientation == Orientation::Street && L.edges[k].length > longest) {
        longest = L.edges[k].length;
        L.longestStreetEdge = k;
      }
  };
  const std::size_t count = only ? only->size() : bs.size();
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < count;) labelOne(only ? (*only)[k] : k);
  };
  const unsigned jobs = static_cast<unsigned>(std::min<std::size_t>(
      jobsWanted ? jobsWanted : std::max(1u, std::thread::hardware_concurrency()), count / 256 + 1));
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace corbel::city
