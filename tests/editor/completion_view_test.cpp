// editor/completion_view.h: the plan-to-cell map keeps the aspect, centres the plan, turns y
// down, and inverts exactly; a thumbnail draws every ShapeTree box of the form inside its cell.
#include "editor/completion_view.h"

#include "growth/completion.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

TEST(CompletionView, ThePlanIsCentredInTheCellWithItsAspectAndYDown) {
  const CellMap m = fitInCell({0, 0, 20, 10}, {100, 50, 100, 100}, 0);
  float x, y;
  m.apply(0, 0, x, y);  // the plan's lower left: the cell's left side, below the middle
  EXPECT_FLOAT_EQ(x, 100);
  EXPECT_FLOAT_EQ(y, 125);
  m.apply(20, 10, x, y);  // upper right
  EXPECT_FLOAT_EQ(x, 200);
  EXPECT_FLOAT_EQ(y, 75);
  double px, py;
  m.invert(150, 100, px, py);
  EXPECT_DOUBLE_EQ(px, 10);
  EXPECT_DOUBLE_EQ(py, 5);
}

TEST(CompletionView, AThumbnailHoldsEveryBoxOfTheFormInsideTheCell) {
  const growth::Floorplan row = growth::canonicalRow(2, 10);  // 20 × 10
  const auto rects = thumbnailRects(row, {0, 0, 100, 100}, 0);
  ASSERT_EQ(rects.size(), 2u);
  EXPECT_EQ(rects[0].unit, 0);
  EXPECT_FLOAT_EQ(rects[0].x0, 0);
  EXPECT_FLOAT_EQ(rects[0].x1, 50);
  EXPECT_FLOAT_EQ(rects[0].y0, 25);
  EXPECT_FLOAT_EQ(rects[0].y1, 75);
  EXPECT_EQ(rects[1].unit, 1);
  EXPECT_FLOAT_EQ(rects[1].x0, 50);
  EXPECT_FLOAT_EQ(rects[1].x1, 100);

  growth::FormRequest rq;
  rq.seeds = 6;
  rq.count = 3;
  const Cell cell{10, 20, 120, 80};
  for (const growth::Form& f : growth::generateForms(rq).forms) {
    std::size_t boxes = 0;
    for (const growth::ShapeTree& t : f.plan.units()) boxes += t.boxes().size();
    const auto r = thumbnailRects(f.plan, cell, 5);
    EXPECT_EQ(r.size(), boxes);
    double area = 0;
    for (const CellRect& c : r) {
      EXPECT_LT(c.x0, c.x1);
      EXPECT_LT(c.y0, c.y1);
      EXPECT_GE(c.x0, cell.x + 5 - 1e-3);
      EXPECT_LE(c.x1, cell.x + cell.w - 5 + 1e-3);
      EXPECT_GE(c.y0, cell.y + 5 - 1e-3);
      EXPECT_LE(c.y1, cell.y + cell.h - 5 + 1e-3);
      area += double(c.x1 - c.x0) * (c.y1 - c.y0);
    }
    // The boxes' area in the plan, scaled by the map's factor squared.
    double planArea = 0;
    for (const growth::ShapeTree& t : f.plan.units()) planArea += double(t.area());
    const growth::GridRect b = f.plan.bounds();
    const CellMap m = fitInCell({double(b.x0), double(b.y0), double(b.x1), double(b.y1)}, cell, 5);
    EXPECT_NEAR(area, planArea * m.s * m.s, 1e-3 * area);
  }
}

}  // namespace
}  // namespace corbel::editor
