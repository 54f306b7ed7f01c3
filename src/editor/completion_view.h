#pragma once
// What the completion panel draws, as pure geometry (no ImGui): a plan rectangle mapped into a
// cell of the window (aspect kept, centred, y down), and a form's thumbnail, its floorplan's
// rectangles (the ShapeTrees' boxes, Sec. 6.5) in that cell, one colour per unit.
#include "growth/cartogram.h"
#include "growth/floorplan.h"

#include <vector>

namespace corbel::editor {

struct Cell {
  float x = 0, y = 0, w = 0, h = 0;  // window pixels, top-left origin
};

// Plan → cell: x' = ox + s·x, y' = oy − s·y (plan y up, window y down).
struct CellMap {
  double s = 1, ox = 0, oy = 0;
  void apply(double x, double y, float& px, float& py) const {
    px = float(ox + s * x);
    py = float(oy - s * y);
  }
  void invert(float px, float py, double& x, double& y) const {
    x = (px - ox) / s;
    y = (oy - py) / s;
  }
};
// The largest map that puts `bounds` inside the cell less `margin` pixels on each side, centred.
CellMap fitInCell(const growth::PlanRect& bounds, const Cell& cell, float margin);

struct CellRect {
  float x0, y0, x1, y1;  // x0 < x1, y0 < y1 in window pixels
  int unit;
};
// Every box of every unit of the plan, mapped by fitInCell of the plan's bounds.
std::vector<CellRect> thumbnailRects(const growth::Floorplan& plan, const Cell& cell, float margin);

}  // namespace corbel::editor
