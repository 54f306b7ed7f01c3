#include "editor/completion_view.h"

#include <algorithm>

namespace corbel::editor {

CellMap fitInCell(const growth::PlanRect& b, const Cell& cell, float margin) {
  const double w = std::max(1e-9, b.x1 - b.x0), h = std::max(1e-9, b.y1 - b.y0);
  const double aw = std::max(1.0, double(cell.w) - 2.0 * margin), ah = std::max(1.0, double(cell.h) - 2.0 * margin);
  CellMap m;
  m.s = std::min(aw / w, ah / h);
  const double cx = cell.x + 0.5 * cell.w, cy = cell.y + 0.5 * cell.h;
  m.ox = cx - m.s * 0.5 * (b.x0 + b.x1);
  m.oy = cy + m.s * 0.5 * (b.y0 + b.y1);
  return m;
}

std::vector<CellRect> thumbnailRects(const growth::Floorplan& plan, const Cell& cell, float margin) {
  const growth::GridRect g = plan.bounds();
  const CellMap m = fitInCell({double(g.x0), double(g.y0), double(g.x1), double(g.y1)}, cell, margin);
  std::vector<CellRect> out;
  for (int u = 0; u < int(plan.units().size()); ++u)
    for (const growth::GridRect& r : plan.unit(u).boxes()) {
      CellRect c{};
      m.apply(double(r.x0), double(r.y1), c.x0, c.y0);
      m.apply(double(r.x1), double(r.y0), c.x1, c.y1);
      c.unit = u;
      out.push_back(c);
    }
  return out;
}

}  // namespace corbel::editor
