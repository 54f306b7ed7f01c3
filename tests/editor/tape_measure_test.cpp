// editor/tape_measure.h: where the tape's ends land and what it reads. A 4 × 3 × 2 m box at the
// origin is measured with rays aimed by hand: its corners, edge midpoints and edges are known,
// so is where a vertical ray meets its top, and where a slanted ray meets the ground.
#include "editor/tape_measure.h"

#include <gtest/gtest.h>

#include <cmath>

namespace corbel::editor {
namespace {

Scene boxScene() {
  MeshData m;
  const double X = 4, Y = 3, Z = 2;
  const int v[8] = {m.addPoint(Vec3(0, 0, 0)), m.addPoint(Vec3(X, 0, 0)), m.addPoint(Vec3(X, Y, 0)), m.addPoint(Vec3(0, Y, 0)),
                    m.addPoint(Vec3(0, 0, Z)), m.addPoint(Vec3(X, 0, Z)), m.addPoint(Vec3(X, Y, Z)), m.addPoint(Vec3(0, Y, Z))};
  // Outward, counter-clockwise seen from outside.
  m.addFace({v[0], v[3], v[2], v[1]});
  m.addFace({v[4], v[5], v[6], v[7]});
  m.addFace({v[0], v[1], v[5], v[4]});
  m.addFace({v[1], v[2], v[6], v[5]});
  m.addFace({v[2], v[3], v[7], v[6]});
  m.addFace({v[3], v[0], v[4], v[7]});
  Scene s;
  s.replaceObject(7, Kind::Mass, "box", m);
  return s;
}

// A vertical ray down onto (x, y), a snapping tolerance of 0.1 m everywhere.
std::optional<TapePoint> down(const Scene& s, double x, double y) {
  return tapePoint(s, Ray{Vec3(x, y, 10), Vec3(0, 0, -1)}, [](const Vec3&) { return 0.1; });
}

void expectAt(const std::optional<TapePoint>& p, const Vec3& at, TapePoint::Snap snap) {
  ASSERT_TRUE(p);
  EXPECT_EQ(int(p->snap), int(snap)) << snapName(p->snap);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p->at[k], at[k], 1e-12) << "coordinate " << k;
}

TEST(TapeMeasurePoint, SnapsToCornerThenMidpointThenEdgeThenFace) {
  const Scene s = boxScene();
  expectAt(down(s, 3.95, 2.95), Vec3(4, 3, 2), TapePoint::Snap::Corner);    // 0.07 m from the corner
  expectAt(down(s, 2.05, 0.05), Vec3(2, 0, 2), TapePoint::Snap::Midpoint);  // 0.07 m from the midpoint
  expectAt(down(s, 1.0, 0.05), Vec3(1, 0, 2), TapePoint::Snap::Edge);       // 0.05 m from the edge, 1 m from the midpoint
  expectAt(down(s, 1.0, 1.0), Vec3(1, 1, 2), TapePoint::Snap::Face);        // 1 m from every edge
  EXPECT_EQ(down(s, 1, 1)->object, ObjectId(7));
}

TEST(TapeMeasurePoint, TheToleranceIsTheCallersAtTheHitPoint) {
  const Scene s = boxScene();
  // The same point 0.07 m from a corner: a corner under 0.1 m, only the face under 0.05 m.
  const Ray r{Vec3(3.95, 2.95, 10), Vec3(0, 0, -1)};
  Vec3 askedAt(0, 0, 0);
  const auto tight = tapePoint(s, r, [&](const Vec3& p) {
    askedAt = p;
    return 0.04;
  });
  expectAt(tight, Vec3(3.95, 2.95, 2), TapePoint::Snap::Face);
  EXPECT_NEAR(askedAt[2], 2.0, 1e-12);  // asked at the hit on the top face
}

TEST(TapeMeasurePoint, TheGroundWhereNoFaceIsMetAndNothingInTheSky) {
  const Scene s = boxScene();
  // From (10, 10, 10) along (1, 1, −1): the ground at (20, 20, 0), the box behind.
  expectAt(tapePoint(s, Ray{Vec3(10, 10, 10), Vec3(1, 1, -1)}, [](const Vec3&) { return 0.1; }), Vec3(20, 20, 0),
           TapePoint::Snap::Ground);
  EXPECT_FALSE(tapePoint(s, Ray{Vec3(10, 10, 10), Vec3(0, 0, 1)}, [](const Vec3&) { return 0.1; }));
  // A hidden object is looked through: the ray down onto the box's top meets the ground.
  expectAt(tapePoint(s, Ray{Vec3(1, 1, 10), Vec3(0, 0, -1)}, [](const Vec3&) { return 0.1; },
                     [](ObjectId) { return false; }),
           Vec3(1, 1, 0), TapePoint::Snap::Ground);
}

TEST(TapeMeasure, ReadsTheDistanceAndItsRunsBetweenTwoClicks) {
  const Scene s = boxScene();
  TapeMeasure t;
  EXPECT_EQ(t.describe(), "");
  t.click(*down(s, 0.02, 0.02));  // corner (0, 0, 2)
  EXPECT_TRUE(t.measuring());
  // The free end follows the pointer: the corner (4, 3, 2) under it.
  t.hover(down(s, 3.97, 2.97));
  ASSERT_TRUE(t.span());
  EXPECT_NEAR(t.span()->norm(), 5.0, 1e-12);  // 3-4-5
  EXPECT_EQ(t.axis(), -1);
  // Ended on the ground corner below the start: a vertical run of 2 m, in z's colour.
  t.click(TapePoint{Vec3(0, 0, 0), TapePoint::Snap::Ground, 0});
  EXPECT_TRUE(t.done());
  EXPECT_EQ(t.describe(), "2.000 m  (x 0.000, y 0.000, z 2.000)");
  EXPECT_EQ(t.axis(), 2);
  t.hover(down(s, 2, 2));  // the pointer moves on: a finished tape stays
  EXPECT_NEAR(t.span()->norm(), 2.0, 1e-12);
  // The next click begins a new tape.
  t.click(*down(s, 2.02, 0.02));
  EXPECT_TRUE(t.measuring());
  EXPECT_NEAR(t.start()->at[0], 2.0, 1e-12);
  t.clear();
  EXPECT_FALSE(t.start());
  EXPECT_FALSE(t.span());
}

TEST(TapeMeasure, AnAxisOnlyWhenTheSpanIsParallelToIt) {
  TapeMeasure t;
  t.click(TapePoint{Vec3(0, 0, 0)});
  t.click(TapePoint{Vec3(10, 0, 0)});
  EXPECT_EQ(t.axis(), 0);
  // 10 m along x with 1 mm across: 0.0057° off x, still x; 5 mm across is 0.029°, not x.
  t.click(TapePoint{Vec3(0, 0, 0)});
  t.click(TapePoint{Vec3(10, 0.001, 0)});
  EXPECT_EQ(t.axis(), 0);
  t.click(TapePoint{Vec3(0, 0, 0)});
  t.click(TapePoint{Vec3(10, 0.005, 0)});
  EXPECT_EQ(t.axis(), -1);
}

}  // namespace
}  // namespace corbel::editor
