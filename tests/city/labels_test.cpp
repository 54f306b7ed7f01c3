// Edge labels on footprints whose answers are worked out by hand.
#include "city/labels.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace corbel;
using namespace corbel::city;

namespace {

Building box(const std::string& id, double x0, double y0, double w, double h) {
  Building b;
  b.id = id;
  b.loops = {{{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}};
  b.area = w * h;
  return b;
}

}  // namespace

TEST(Labels, RectangleFacingAStreetToItsSouth) {
  Town t;
  t.buildings.push_back(box("a", 0, 0, 14, 3));
  t.streets.push_back({"s", {{-50, -10}, {50, -10}}});
  const auto L = labelTown(t);
  ASSERT_EQ(L[0].edges.size(), 4u);
  EXPECT_TRUE(L[0].fromStreet);
  EXPECT_NEAR(L[0].front[0], 0, 1e-12);
  EXPECT_NEAR(L[0].front[1], -1, 1e-12);
  // Edge 0 runs along y = 0 and faces south: the street, angle 0.
  const EdgeLabel& s = L[0].edges[0];
  EXPECT_EQ(s.orientation, Orientation::Street);
  EXPECT_NEAR(s.angle, 0, 1e-9);
  EXPECT_EQ(s.length_class, LengthClass::Long);  // 14 m ≥ 12 m
  // Edge 1 faces east; with the front turned up (south → up) east is on the left: -90°.
  EXPECT_EQ(L[0].edges[1].orientation, Orientation::Side);
  EXPECT_NEAR(L[0].edges[1].angle, -90, 1e-9);
  EXPECT_EQ(L[0].edges[1].length_class, LengthClass::Short);  // 3 m < 4 m
  // Edge 2 faces north, away from the street.
  EXPECT_EQ(L[0].edges[2].orientation, Orientation::Back);
  EXPECT_NEAR(std::abs(L[0].edges[2].angle), 180, 1e-9);
  EXPECT_NEAR(L[0].edges[3].angle, 90, 1e-9);
  for (const auto& e : L[0].edges) {
    EXPECT_NEAR(e.disk.norm(), 1, 1e-12);
    EXPECT_NEAR(std::atan2(e.disk[0], e.disk[1]) * 180 / 3.14159265358979, e.angle, 1e-9);
  }
  EXPECT_EQ(L[0].longestStreetEdge, 0u);
}

TEST(Labels, ADiagonalEdgeIsLabelledByItsNormalsAngle) {
  // A right triangle with its hypotenuse facing north-east; the front is north (street above).
  Town t;
  Building b;
  b.id = "tri";
  b.loops = {{{0, 0}, {10, 0}, {0, 10}}};
  b.area = 50;
  t.buildings.push_back(b);
  t.streets.push_back({"s", {{-50, 40}, {50, 40}}});
  const auto L = labelTown(t);
  // Hypotenuse (10,0)→(0,10): normal (1,1)/√2, 45° clockwise of north: +45, still street.
  EXPECT_NEAR(L[0].edges[1].angle, 45, 1e-9);
  EXPECT_EQ(L[0].edges[1].orientation, Orientation::Street);
  EXPECT_NEAR(L[0].edges[1].length, 10 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(L[0].edges[1].length_class, LengthClass::Long);
  EXPECT_EQ(L[0].edges[0].orientation, Orientation::Back);  // faces south
  EXPECT_EQ(L[0].edges[2].orientation, Orientation::Side);  // faces west: -90
  EXPECT_NEAR(L[0].edges[2].angle, -90, 1e-9);
}

TEST(Labels, WithoutStreetsTheFrontLooksOverTheWidestGap) {
  // A terrace of three 8 × 10 houses 1 m apart, and a second terrace 9 m behind them (north):
  // the middle house has neighbours 1 m east and west and 9 m north, and open ground south.
  Town t;
  for (int i = 0; i < 3; ++i) t.buildings.push_back(box("front" + std::to_string(i), i * 9.0, 0, 8, 10));
  for (int i = 0; i < 3; ++i) t.buildings.push_back(box("back" + std::to_string(i), i * 9.0, 19, 8, 10));
  const auto L = labelTown(t);
  EXPECT_FALSE(L[1].fromStreet);
  EXPECT_NEAR(L[1].front[1], -1, 1e-12);  // south
  EXPECT_EQ(L[1].edges[0].orientation, Orientation::Street);
  EXPECT_EQ(L[1].edges[2].orientation, Orientation::Back);
  // The middle house of the back row looks north, away from the front row.
  EXPECT_NEAR(L[4].front[1], 1, 1e-12);
}

TEST(Labels, LengthClassesFollowTheThresholds) {
  LabelOptions o;
  o.shortBelow = 5;
  o.longFrom = 9;
  const auto e = labelEdges({{{0, 0}, {4.99, 0}, {4.99, 9}, {0, 9}}}, {0, -1}, o);
  EXPECT_EQ(e[0].length_class, LengthClass::Short);
  EXPECT_EQ(e[1].length_class, LengthClass::Long);  // 9 m: long from 9
}

TEST(Labels, ThreadsDoNotChangeTheLabels) {
  const Town t = readTownFile(std::string(CORBEL_FOOTPRINTS) + "/kathmandu_np.geojson");
  const auto one = labelTown(t, {}, 1), two = labelTown(t, {}, 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].front, two[i].front) << t.buildings[i].id;
    ASSERT_EQ(one[i].edges.size(), two[i].edges.size());
    for (std::size_t k = 0; k < one[i].edges.size(); ++k) EXPECT_EQ(one[i].edges[k].angle, two[i].edges[k].angle);
  }
}

// A street drawn far past the town (a diagonal 2e9 m long, and one of 1e9 m beyond it) labels
// the buildings as the same street drawn 200 m long does: only what lies within reach of a
// building is gridded, and a diagonal costs cells along its length, not its bounding box.
TEST(Labels, AStreetFarLongerThanTheTownLabelsAsAShortOne) {
  Town near, far;
  for (Town* t : {&near, &far}) {
    t->buildings.push_back(box("a", 0, 0, 14, 8));
    t->buildings.push_back(box("b", 30, 40, 10, 10));
  }
  near.streets.push_back({"s", {{-100, -110}, {100, 90}}});
  far.streets.push_back({"s", {{-1e9, -1e9 - 10}, {1e9, 1e9 - 10}}});
  far.streets.push_back({"t", {{5e8, 0}, {1.5e9, 0}}});
  const auto a = labelTown(near), b = labelTown(far);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(b[i].fromStreet);
    EXPECT_NEAR((a[i].front - b[i].front).norm(), 0, 1e-6) << i;  // rounding along 2e9 m
    ASSERT_EQ(a[i].edges.size(), b[i].edges.size());
    for (std::size_t k = 0; k < a[i].edges.size(); ++k) EXPECT_EQ(a[i].edges[k].orientation, b[i].edges[k].orientation);
  }
}
