#include "growth/plan_grid.h"

#include <algorithm>
#include <cmath>

namespace corbel::growth {

PlanGrid::PlanGrid(const Rect& bounds, double cell) : bounds_(bounds) {
  const double w = std::max(bounds.u1 - bounds.u0, 1e-9), h = std::max(bounds.v1 - bounds.v0, 1e-9);
  columns_ = std::clamp(int(std::ceil(w / cell)), 1, 4096);
  rows_ = std::clamp(int(std::ceil(h / cell)), 1, 4096);
  cellU_ = w / columns_;
  cellV_ = h / rows_;
  cells_.assign(std::size_t(columns_) * rows_, {});
}

int PlanGrid::column(double x) const {
  const double c = std::floor((x - bounds_.u0) / cellU_);
  if (!(c >= 0)) return 0;  // NaN too
  return c >= columns_ ? columns_ - 1 : int(c);
}

int PlanGrid::row(double y) const {
  const double r = std::floor((y - bounds_.v0) / cellV_);
  if (!(r >= 0)) return 0;
  return r >= rows_ ? rows_ - 1 : int(r);
}

// A coordinate on a cell edge belongs to both cells (closed rectangles touching there meet).
PlanGrid::Span PlanGrid::spanOf(const Rect& r) const {
  constexpr double kSlack = 1e-6;  // far above rounding, far below a cell
  return {column(r.u0 - kSlack), row(r.v0 - kSlack), column(r.u1 + kSlack), row(r.v1 + kSlack)};
}

void PlanGrid::insert(std::uint64_t key, const Rect& r) {
  if (columns_ == 0) return;
  erase(key);
  const Span s = spanOf(r);
  for (int j = s.j0; j <= s.j1; ++j)
    for (int i = s.i0; i <= s.i1; ++i) cells_[std::size_t(j) * columns_ + i].push_back(key);
  spans_[key] = s;
}

void PlanGrid::erase(std::uint64_t key) {
  const auto it = spans_.find(key);
  if (it == spans_.end()) return;
  const Span s = it->second;
  for (int j = s.j0; j <= s.j1; ++j)
    for (int i = s.i0; i <= s.i1; ++i) {
      auto& c = cells_[std::size_t(j) * columns_ + i];
      c.erase(std::find(c.begin(), c.end(), key));
    }
  spans_.erase(it);
}

void PlanGrid::query(const Rect& r, std::vector<std::uint64_t>& out) const {
  out.clear();
  if (columns_ == 0) return;
  const Span s = spanOf(r);
  for (int j = s.j0; j <= s.j1; ++j)
    for (int i = s.i0; i <= s.i1; ++i) {
      const auto& c = cells_[std::size_t(j) * columns_ + i];
      out.insert(out.end(), c.begin(), c.end());
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace corbel::growth
