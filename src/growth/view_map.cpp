#include "growth/view_map.h"

#include "growth/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

namespace corbel::growth {

namespace {
int planeAxis(ViewDirection d) { return int(d) < 2 ? 1 : 0; }  // the horizontal axis seen across
int depthAxis(ViewDirection d) { return int(d) < 2 ? 0 : 1; }
bool toPositive(ViewDirection d) { return int(d) % 2 == 0; }
}  // namespace

Rect projectBox(const Box& b, ViewDirection d) {
  const int a = planeAxis(d);
  return {b.lo[a], b.lo[2], b.hi[a], b.hi[2]};
}

double frontDepth(const Box& b, ViewDirection d) {
  const int k = depthAxis(d);
  return toPositive(d) ? b.hi[k] : -b.lo[k];
}

Rect projectFrame(const Box& frame, ViewDirection d) { return projectBox(frame, d); }

void ViewGain::add(const ViewGain& g) {
  gain += g.gain;
  for (const auto& [id, a] : g.taken) taken[id] += a;
}

ViewMap::ViewMap(std::vector<double> uEdges, std::vector<double> vEdges)
    : u_(std::move(uEdges)), v_(std::move(vEdges)) {
  const std::size_t n = std::size_t(columns()) * rows();
  id_.assign(n, kEmptyId);
  depth_.assign(n, -std::numeric_limits<double>::infinity());
}

ViewMap ViewMap::uniform(const Rect& frame, int columns, int rows) {
  std::vector<double> u(columns + 1), v(rows + 1);
  for (int i = 0; i <= columns; ++i) u[i] = frame.u0 + (frame.u1 - frame.u0) * i / columns;
  for (int j = 0; j <= rows; ++j) v[j] = frame.v0 + (frame.v1 - frame.v0) * j / rows;
  return ViewMap(std::move(u), std::move(v));
}

void ViewMap::offer(int i, int j, std::uint32_t id, double depth) {
  const std::size_t k = index(i, j);
  if (depth > depth_[k]) {
    depth_[k] = depth;
    id_[k] = id;
  }
}

void ViewMap::finish() {
  areas_.clear();
  for (int j = 0; j < rows(); ++j)
    for (int i = 0; i < columns(); ++i) {
      const std::uint32_t id = id_[index(i, j)];
      if (id != kEmptyId) areas_[id] += (u_[i + 1] - u_[i]) * (v_[j + 1] - v_[j]);
    }
}

double ViewMap::area(std::uint32_t id) const {
  auto it = areas_.find(id);
  return it == areas_.end() ? 0.0 : it->second;
}

ViewGain ViewMap::gain(const Rect& r, double depth, std::uint32_t self) const {
  ViewGain g;
  if (u_.size() < 2 || v_.size() < 2) return g;
  // The cells whose spans overlap r's.
  const int i0 = std::max(0, int(std::upper_bound(u_.begin(), u_.end(), r.u0) - u_.begin()) - 1);
  const int j0 = std::max(0, int(std::upper_bound(v_.begin(), v_.end(), r.v0) - v_.begin()) - 1);
  for (int j = j0; j < rows() && v_[j] < r.v1; ++j) {
    const double h = overlapLength(v_[j], v_[j + 1], r.v0, r.v1);
    if (h <= 0) continue;
    for (int i = i0; i < columns() && u_[i] < r.u1; ++i) {
      const double w = overlapLength(u_[i], u_[i + 1], r.u0, r.u1);
      if (w <= 0) continue;
      const std::size_t k = index(i, j);
      const std::uint32_t id = id_[k];
      if (id == self || (id != kEmptyId && depth_[k] >= depth - kEps)) continue;
      g.gain += w * h;
      if (id != kEmptyId && id != kObstacleId) g.taken[id] += w * h;
    }
  }
  return g;
}

double ViewMaps::view(std::uint32_t id) const {
  double s = 0;
  for (const ViewMap& m : maps) s += m.area(id);
  return s;
}

ViewGain ViewMaps::gain(const Box& added, std::uint32_t self) const {
  ViewGain g;
  for (ViewDirection d : kViewDirections) g.add((*this)[d].gain(projectBox(added, d), frontDepth(added, d), self));
  return g;
}

namespace {

std::vector<double> uniqueSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// From this many boxes the exact maps are made on two threads (below, a thread costs more than
// it saves: grown Alpha's 195 boxes take about 50 µs).
constexpr std::size_t kParallelBoxes = 1000;

int edgeIndex(const std::vector<double>& edges, double x) {
  return int(std::lower_bound(edges.begin(), edges.end(), x) - edges.begin());
}

}  // namespace

ViewMaps ExactViewMapper::render(const std::vector<ViewBox>& boxes, const Box& frame) {
  ViewMaps out;
  auto one = [&](ViewDirection d) {
    const Rect f = projectFrame(frame, d);
    std::vector<double> u{f.u0, f.u1}, v{f.v0, f.v1};
    for (const ViewBox& b : boxes) {
      const Rect r = projectBox(b.box, d);
      u.push_back(std::clamp(r.u0, f.u0, f.u1));
      u.push_back(std::clamp(r.u1, f.u0, f.u1));
      v.push_back(std::clamp(r.v0, f.v0, f.v1));
      v.push_back(std::clamp(r.v1, f.v0, f.v1));
    }
    ViewMap m(uniqueSorted(std::move(u)), uniqueSorted(std::move(v)));
    for (const ViewBox& b : boxes) {
      const Rect r = projectBox(b.box, d);
      const double depth = frontDepth(b.box, d);
      const int i1 = edgeIndex(m.uEdges(), std::clamp(r.u1, f.u0, f.u1));
      const int j1 = edgeIndex(m.vEdges(), std::clamp(r.v1, f.v0, f.v1));
      for (int j = edgeIndex(m.vEdges(), std::clamp(r.v0, f.v0, f.v1)); j < j1; ++j)
        for (int i = edgeIndex(m.uEdges(), std::clamp(r.u0, f.u0, f.u1)); i < i1; ++i) m.offer(i, j, b.id, depth);
    }
    m.finish();
    out[d] = std::move(m);
  };
  // The four maps are independent: on a large model, ±x on a second thread while this one
  // does ±y (each map is the same whichever thread makes it).
  if (boxes.size() >= kParallelBoxes) {
    std::thread x([&] {
      one(ViewDirection::PosX);
      one(ViewDirection::NegX);
    });
    one(ViewDirection::PosY);
    one(ViewDirection::NegY);
    x.join();
  } else {
    for (ViewDirection d : kViewDirections) one(d);
  }
  return out;
}

std::pair<int, int> pixelSpan(double a, double b, double origin, double pixel, int count) {
  // Pixel i's centre is origin + (i + ½) pixel; it lies in [a, b) for i in [first, last).
  const int first = std::clamp(int(std::ceil((a - origin) / pixel - 0.5)), 0, count);
  const int last = std::clamp(int(std::ceil((b - origin) / pixel - 0.5)), 0, count);
  return {first, std::max(first, last)};
}

ViewMaps RasterViewMapper::render(const std::vector<ViewBox>& boxes, const Box& frame) {
  ViewMaps out;
  for (ViewDirection d : kViewDirections) {
    const Rect f = projectFrame(frame, d);
    const int cols = std::max(1, int(std::ceil((f.u1 - f.u0) / pixel_ - 1e-9)));
    const int rows = std::max(1, int(std::ceil((f.v1 - f.v0) / pixel_ - 1e-9)));
    ViewMap m = ViewMap::uniform({f.u0, f.v0, f.u0 + cols * pixel_, f.v0 + rows * pixel_}, cols, rows);
    for (const ViewBox& b : boxes) {
      const Rect r = projectBox(b.box, d);
      const double depth = frontDepth(b.box, d);
      const auto [i0, i1] = pixelSpan(r.u0, r.u1, f.u0, pixel_, cols);
      const auto [j0, j1] = pixelSpan(r.v0, r.v1, f.v0, pixel_, rows);
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) m.offer(i, j, b.id, depth);
    }
    m.finish();
    out[d] = std::move(m);
  }
  return out;
}

}  // namespace corbel::growth
