// editor/masonry_loads.h: what a click on a block places, against hand-placed rays on one
// square block whose faces are known.
#include "editor/masonry_loads.h"

#include "editor/masonry_edits.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::editor {
namespace {

// One square drum 0.4 m wide and 2 m tall on the ground: x, y ∈ [−0.2, 0.2], z ∈ [0, 2].
MasonryView squareBlock() {
  MasonrySpec s;
  s.model = "column";
  s.parameters = {{"drums", 1}, {"height", 2.0}, {"radius", 0.4 / std::sqrt(2.0)}, {"sides", 4}};
  MasonryView v = analyseMasonry(s);
  EXPECT_TRUE(v.error.empty()) << v.error;
  return v;
}

// A ray along −x at height 1.5 meets the block's +x face at x = 0.2: the weight placed there acts
// at that point (its offset from the block's centre (0, 0, 1) is (0.2, 0.1, 0.5)), a pressure goes
// on that face, whose outward normal is +x.
TEST(MasonryLoads, AClickPlacesAWeightAtThePointAndWindOnTheFace) {
  const MasonryView v = squareBlock();
  const auto hit = firstBlockHit(v, Vec3(5, 0.1, 1.5), Vec3(-1, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(v.blockNames[std::size_t(hit->block)], "column/drum 0");
  EXPECT_NEAR(hit->distance, 4.8, 1e-12);
  EXPECT_NEAR((hit->point - Vec3(0.2, 0.1, 1.5)).norm(), 0, 1e-12);
  const Vec3 n = newellNormal(v.blockFaces[std::size_t(hit->block)][std::size_t(hit->face)]).normalized();
  EXPECT_NEAR(n[0], 1, 1e-12);

  const MasonryLoad w = loadAt(v, *hit, LoadKind::Weight, 500);
  EXPECT_EQ(w.face, -1);
  EXPECT_NEAR((w.offset - Vec3(0.2, 0.1, 0.5)).norm(), 0, 1e-12);
  EXPECT_NEAR(w.force[2], -500 * kGravity, 1e-9);
  EXPECT_NEAR(loadMass(w), 500, 1e-9);
  const MasonryLoad p = loadAt(v, *hit, LoadKind::Pressure, 600);
  EXPECT_EQ(p.face, hit->face);
  EXPECT_EQ(p.pressure, 600);
}

// The ground is not a place for a load, a ray that misses finds nothing, and of two blocks on a
// ray the nearer is hit.
TEST(MasonryLoads, TheGroundAndMissesPlaceNothingAndTheNearerBlockIsHit) {
  const MasonryView v = squareBlock();
  EXPECT_FALSE(firstBlockHit(v, Vec3(0.6, 0, 5), Vec3(0, 0, -1))) << "beside the block, onto the ground";
  EXPECT_TRUE(firstBlockHit(v, Vec3(0.6, 0, 5), Vec3(0, 0, -1), true)) << "the ground itself when asked";
  EXPECT_FALSE(firstBlockHit(v, Vec3(5, 0, 1), Vec3(1, 0, 0))) << "pointing away";
  MasonrySpec two;
  two.model = "column";
  two.parameters = {{"drums", 2}, {"height", 2.0}, {"radius", 0.3}, {"sides", 4}};
  const MasonryView t = analyseMasonry(two);
  const auto down = firstBlockHit(t, Vec3(0, 0, 5), Vec3(0, 0, -1));
  ASSERT_TRUE(down);
  EXPECT_EQ(t.blockNames[std::size_t(down->block)], "column/drum 1") << "the upper drum, met first";
  EXPECT_NEAR(down->point[2], 2.0, 1e-12);
}

// A placed load is drawn: an amber arrow whose tip is where it acts.
TEST(MasonryLoads, APlacedLoadIsDrawnAsAnArrowEndingWhereItActs) {
  MasonrySpec s;
  s.model = "column";
  s.parameters = {{"drums", 1}, {"height", 2.0}, {"radius", 0.4 / std::sqrt(2.0)}, {"sides", 4}};
  s.loads = {{"bell", "column/drum 0", Vec3(0, 0, 1), Vec3(0, 0, -5000), -1, 0.0}};
  const MasonryView v = analyseMasonry(s);
  ASSERT_TRUE(v.error.empty()) << v.error;
  const MasonryPicture pic = masonryPicture(v, true, false);
  ASSERT_EQ(pic.arrows.size(), 1u) << "the load only: force arrows are off";
  EXPECT_TRUE(pic.arrows[0].load);
  EXPECT_NEAR((pic.arrows[0].to - Vec3(0, 0, 2)).norm(), 0, 1e-12);
  EXPECT_GT(pic.arrows[0].from[2], 2.0) << "it points down onto the block";
}

}  // namespace
}  // namespace corbel::editor
