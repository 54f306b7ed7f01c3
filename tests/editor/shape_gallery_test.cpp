// editor/shape_gallery.h and plan_crossings.h: the gallery's plans against their areas by hand,
// the kernel's orientation rules and its build; crossings found where a hand drawing puts them.
#include "editor/plan_crossings.h"
#include "editor/shape_gallery.h"

#include "core/scene.h"
#include "core/scene_sync.h"
#include "extrude/kernel.h"
#include "extrude/plan_check.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

double signedArea(const std::vector<Vec2>& l) {
  double a = 0;
  for (std::size_t i = 0; i < l.size(); ++i) {
    const Vec2 &p = l[i], &q = l[(i + 1) % l.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

TEST(ShapeGallery, PlansHaveTheirAreasByHand) {
  // Rectangle 12·8; L 12·10 − 6·5; T 14·5 + 6·7; U 14·10 − 6·6; courtyard 16·16 − 8·8.
  const std::pair<GalleryShape, double> expected[] = {{GalleryShape::Rectangle, 96},
                                                      {GalleryShape::L, 90},
                                                      {GalleryShape::T, 112},
                                                      {GalleryShape::U, 104},
                                                      {GalleryShape::Courtyard, 192}};
  for (const auto& [shape, area] : expected) {
    const auto loops = galleryLoops(shape, Vec2(30, -7));  // anywhere: areas do not move
    double total = 0;
    for (const auto& l : loops) total += signedArea(l);  // holes clockwise: negative
    EXPECT_NEAR(total, area, 1e-9) << galleryInfo(shape).label;
    EXPECT_GT(signedArea(loops[0]), 0) << "outer loop counter-clockwise";
    EXPECT_TRUE(planCrossings(loops).empty()) << galleryInfo(shape).label;
    EXPECT_FALSE(extrude::checkPlanTopology(loops)) << galleryInfo(shape).label;
  }
  const auto court = galleryLoops(GalleryShape::Courtyard);
  ASSERT_EQ(court.size(), 2u);
  EXPECT_NEAR(signedArea(court[1]), -64, 1e-9);
}

TEST(ShapeGallery, EveryShapeBuildsAClosedShell) {
  SceneSync sync;
  extrude::registerKernel(sync);
  Document doc;
  std::vector<ObjectId> ids;
  double x = 0;
  for (GalleryShape shape : kGalleryShapes) {
    ids.push_back(doc.add(galleryInfo(shape).label, galleryExtrusion(shape, Vec2(x, 0))));
    x += 25;
  }
  Scene scene;
  sync.update(doc, scene);
  for (ObjectId id : ids) {
    const auto it = sync.status().find(id);
    EXPECT_TRUE(it == sync.status().end() || it->second.error.empty()) << it->second.error;
    const ValidityReport r = scene.validate(id);
    EXPECT_TRUE(r.closedManifold()) << doc.find(id)->name;
    // The hip roof rises 3 m over 3 m walls: the shell is 3 m at the eaves and higher inside.
    EXPECT_GT(scene.bounds(id).hi[2], 3.0) << doc.find(id)->name;
  }
}

TEST(PlanCrossings, ABowTieCrossesAtItsMiddle) {
  // (0,0) → (4,4) crosses (4,0) → (0,4) at (2,2): edges 0 and 2.
  const auto c = planCrossings({{Vec2(0, 0), Vec2(4, 4), Vec2(4, 0), Vec2(0, 4)}});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].edgeA, 0);
  EXPECT_EQ(c[0].edgeB, 2);
  EXPECT_NEAR(c[0].at[0], 2, 1e-12);
  EXPECT_NEAR(c[0].at[1], 2, 1e-12);
}

TEST(PlanCrossings, CornerOnAnEdgeTouchesAndNeighboursFoldingBackCount) {
  // A corner (5, 0) dragged onto the edge (0, 0)–(10, 0)? Here the square's corner 2 is moved
  // to (5, 0) on edge 0: edges 1 (10,0)→(5,0) folds back along edge 0, edge 2 (5,0)→(0,10)
  // touches edge 0 at (5, 0).
  const auto c = planCrossings({{Vec2(0, 0), Vec2(10, 0), Vec2(5, 0), Vec2(0, 10)}});
  ASSERT_FALSE(c.empty());
  bool fold = false, touch = false;
  for (const auto& x : c) {
    if (x.edgeA == 0 && x.edgeB == 1) fold = true;  // overlap from (5,0) to (10,0): middle (7.5, 0)
    if (x.edgeA == 0 && x.edgeB == 2) touch = std::abs(x.at[0] - 5) < 1e-9 && std::abs(x.at[1]) < 1e-9;
  }
  EXPECT_TRUE(fold);
  EXPECT_TRUE(touch);
  // Two loops: a hole poking out of its outer loop crosses it twice, at (10, 4) and (10, 6).
  const auto two = planCrossings({{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)},
                                  {Vec2(8, 4), Vec2(8, 6), Vec2(12, 6), Vec2(12, 4)}});
  ASSERT_EQ(two.size(), 2u);
  for (const auto& x : two) {
    EXPECT_EQ(x.loopA, 0);
    EXPECT_EQ(x.loopB, 1);
    EXPECT_NEAR(x.at[0], 10, 1e-12);
  }
  EXPECT_TRUE(planCrossings({{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)}}).empty());
}

}  // namespace
}  // namespace corbel::editor
