// core/scene_pick.h: the face a ray meets first, with its distance by hand.
#include "core/massing.h"
#include "core/scene_pick.h"

#include <gtest/gtest.h>

namespace corbel {
namespace {

MeshData cube(double x, double y, double side) {
  BoxSpec b;
  b.origin = Vec3(x, y, 0);
  b.size = Vec3(side, side, side);
  return buildBoxes(b);
}

// Box A spans x −1–1, box B x 4–6, both y −1–1 and z 0–2 (box.origin is the base's centre).
Scene twoBoxes() {
  Scene s;
  s.replaceObject(1, Kind::Mass, "A", cube(0, 0, 2));
  s.replaceObject(2, Kind::Mass, "B", cube(5, 0, 2));
  return s;
}

TEST(ScenePick, TheNearestFaceAlongTheRayWins) {
  const Scene s = twoBoxes();
  // From x = 10 looking down −x at (y, z) = (0.5, 1): B's face x = 6 at t = 4, then A's at t = 9.
  const auto p = pickScene(s, Vec3(10, 0.5, 1), Vec3(-1, 0, 0));
  ASSERT_TRUE(p);
  EXPECT_EQ(p->object, 2u);
  EXPECT_NEAR(p->t, 4.0, 1e-12);
  // From x = −4 looking down +x, A is first: its face x = −1 at t = 3.
  const auto q = pickScene(s, Vec3(-4, 0.5, 1), Vec3(1, 0, 0));
  ASSERT_TRUE(q);
  EXPECT_EQ(q->object, 1u);
  EXPECT_NEAR(q->t, 3.0, 1e-12);
  // A direction of length 2 halves t.
  EXPECT_NEAR(pickScene(s, Vec3(-4, 0.5, 1), Vec3(2, 0, 0))->t, 1.5, 1e-12);
}

TEST(ScenePick, HiddenObjectsAndMissesGiveNothingOrWhatIsBehind) {
  const Scene s = twoBoxes();
  const auto p = pickScene(s, Vec3(10, 0.5, 1), Vec3(-1, 0, 0), [](ObjectId id) { return id != 2; });
  ASSERT_TRUE(p);
  EXPECT_EQ(p->object, 1u);  // B hidden: the ray goes on to A
  EXPECT_NEAR(p->t, 9.0, 1e-12);
  EXPECT_FALSE(pickScene(s, Vec3(10, 0.5, 3), Vec3(-1, 0, 0)));   // above both (z = 3)
  EXPECT_FALSE(pickScene(s, Vec3(2.5, 0.5, 5), Vec3(0, 0, -1)));  // down between them
  EXPECT_FALSE(pickScene(s, Vec3(10, 0.5, 1), Vec3(1, 0, 0)));    // away from both
  const auto down = pickScene(s, Vec3(5, 0.5, 5), Vec3(0, 0, -1));  // onto B's top, z = 2
  ASSERT_TRUE(down);
  EXPECT_EQ(down->object, 2u);
  EXPECT_NEAR(down->t, 3.0, 1e-12);
  EXPECT_FALSE(pickScene(Scene(), Vec3(0, 0, 0), Vec3(1, 0, 0)));
}

}  // namespace
}  // namespace corbel
