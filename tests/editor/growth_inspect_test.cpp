// editor/growth_inspect.h: the statistics table, the view-map images and the slice of a grown
// model, against figures computed by hand for boxes in the open.
#include "editor/growth_inspect.h"

#include "growth/unit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace corbel::editor {
namespace {

// Two seeds on a 20 × 20 m site of one 3 m storey, not grown (steps 0): A at (0, 0), 10 × 9 m
// (90 m², type A), B at (12, 11), 8 × 8 m (64 m², type B). Nothing hides anything: each side
// of a box is seen whole.
GrowthSpec twoSeeds() {
  GrowthSpec s;
  s.site =
      R"({"envelope": {"origin": [0, 0], "size": [20, 20]}, "storeys": 1, "storey_height": 3, "seeds": [)"
      R"({"at": [0, 0], "size": [10, 9], "target_area": 50}, {"at": [12, 11], "size": [8, 8], "target_area": 50}]})";
  return s;
}

TEST(GrowthInspect, TheStatisticsTableOfTwoBoxesInTheOpen) {
  const GrowthInspection in = inspectGrowth(twoSeeds());
  ASSERT_EQ(in.grown.units.size(), 2u);
  std::map<std::string, std::string> rows;
  for (auto& [k, v] : statisticsRows(in.stats)) rows[k] = v;
  EXPECT_EQ(rows["site area"], "400 m², 1 storey");
  EXPECT_EQ(rows["units"], "2");
  EXPECT_EQ(rows["occupants"], "8");             // five in A, three in B
  EXPECT_EQ(rows["occupancy ratio"], "0.0200");  // 8 / (400 m² × 1)
  EXPECT_EQ(rows["type A / B / C"], "1 / 1 / 0");
  // A: 9 × 3 m seen along ±x, 10 × 3 m along ±y: 114 m²; B: 8 × 3 m four times: 96 m².
  EXPECT_EQ(rows["average view"], "105.0 m²");
  EXPECT_EQ(rows["two / three views"], "0 / 0 (2 with four)");
  EXPECT_EQ(rows["average floor area"], "77.0 m²");  // (90 + 64) / 2
  EXPECT_EQ(rows["double volume"], "0");
  EXPECT_EQ(rows["outdoor space"], "0");
  EXPECT_EQ(rows.size(), 10u);
}

TEST(GrowthInspect, ViewMapImagesShowEachUnitWhereItIsSeenFromOutside) {
  const GrowthInspection in = inspectGrowth(twoSeeds());
  // ±x maps: u = y over [0, 20], v = z over [0, 3]; 20 pixels across are 1 m each, 3 rows.
  const ViewMapImage px = viewMapImage(in.views[growth::ViewDirection::PosX], growth::ViewDirection::PosX, 20);
  ASSERT_EQ(px.width, 20);
  ASSERT_EQ(px.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 20; ++x) {
      // Seen from +x (looking along -x) y grows to the right: A on y < 9, B on 11 < y < 19.
      const std::uint32_t expected = x < 9 ? 1u : (x >= 11 && x < 19) ? 2u : growth::kEmptyId;
      EXPECT_EQ(px.idAt(x, y), expected) << x << ", " << y;
    }
  // From -x the picture is mirrored: B on the left (pixels 1..8), A on the right (11..19).
  const ViewMapImage nx = viewMapImage(in.views[growth::ViewDirection::NegX], growth::ViewDirection::NegX, 20);
  for (int x = 0; x < 20; ++x) {
    const std::uint32_t expected = x >= 11 ? 1u : (x >= 1 && x < 9) ? 2u : growth::kEmptyId;
    EXPECT_EQ(nx.idAt(x, 1), expected) << x;
  }
  // Pixels take their id's colour; the ids' colours differ from each other and from nothing.
  const auto c1 = idColour(1), c2 = idColour(2), c0 = idColour(growth::kEmptyId), co = idColour(growth::kObstacleId);
  EXPECT_EQ(px.rgba[0], c1[0]);
  EXPECT_EQ(px.rgba[1], c1[1]);
  EXPECT_EQ(px.rgba[2], c1[2]);
  EXPECT_EQ(px.rgba[3], 255);
  EXPECT_NE(c1, c2);
  EXPECT_NE(c1, c0);
  EXPECT_NE(c2, co);
  EXPECT_NE(c0, co);
}

TEST(GrowthInspect, DepthImagesShowTheNearestFaceWhiteAndTheFarthestDarkest) {
  const GrowthInspection in = inspectGrowth(twoSeeds());
  const auto grey = [](const ViewMapImage& img, int x, int y) {
    const std::size_t k = 4 * (std::size_t(y) * img.width + x);
    EXPECT_EQ(img.depthRgba[k], img.depthRgba[k + 1]);
    EXPECT_EQ(img.depthRgba[k], img.depthRgba[k + 2]);
    EXPECT_EQ(img.depthRgba[k + 3], 255);
    return int(img.depthRgba[k]);
  };
  const auto empty = idColour(growth::kEmptyId);
  // From +x the faces seen are A's at x = 10 and B's at x = 20 (depth = x): B nearest.
  const ViewMapImage px = viewMapImage(in.views[growth::ViewDirection::PosX], growth::ViewDirection::PosX, 20);
  for (int x = 0; x < 20; ++x) {
    const bool a = x < 9, b = x >= 11 && x < 19;
    if (a) {
      EXPECT_DOUBLE_EQ(px.depthAt(x, 1), 10.0) << x;
      EXPECT_EQ(grey(px, x, 1), kFarthestGrey) << x;
    } else if (b) {
      EXPECT_DOUBLE_EQ(px.depthAt(x, 1), 20.0) << x;
      EXPECT_EQ(grey(px, x, 1), 255) << x;
    } else {
      EXPECT_EQ(px.depthRgba[4 * std::size_t(20 + x)], empty[0]) << x;
    }
  }
  // From -x A's face at x = 0 is the nearer (depth = -x: 0 against B's -12): the greys swap.
  const ViewMapImage nx = viewMapImage(in.views[growth::ViewDirection::NegX], growth::ViewDirection::NegX, 20);
  EXPECT_EQ(grey(nx, 15, 1), 255);           // A, on the right when seen from -x
  EXPECT_EQ(grey(nx, 4, 1), kFarthestGrey);  // B
  EXPECT_DOUBLE_EQ(nx.depthAt(4, 1), -12.0);
}

double area(const MeshData& m, std::size_t f) {
  Vec3 n(0.0);
  const auto& loop = m.faces[f];
  for (std::size_t k = 0; k < loop.size(); ++k) n += m.points[loop[k]] % m.points[loop[(k + 1) % loop.size()]];
  return n.norm() / 2;
}

double totalArea(const MeshData& m) {
  double a = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) a += area(m, f);
  return a;
}

growth::Unit box(int id, double x, double y, double z0, double z1, double w) {
  growth::Unit u;
  u.id = id;
  u.parts = {{{x, y, z0}, {x + w, y + w, z1}}};
  return u;
}

TEST(GrowthInspect, SlicingHidesExactlyTheUnitsWhoseFloorIsAtOrAboveTheHeight) {
  // 3 × 3 m units on storeys 0, 1 and 2 (3 m each), and a 2 × 2 m core 9 m high.
  const std::vector<growth::Unit> units{box(1, 0, 0, 0, 3, 3), box(2, 5, 0, 3, 6, 3), box(3, 10, 0, 6, 9, 3)};
  MeshData all;
  for (const growth::Unit& u : units) all.append(growth::unitMesh(u));
  all.append(growth::unitMesh(box(4, 15, 0, 0, 9, 2)));
  EXPECT_DOUBLE_EQ(totalArea(all), 3 * 54 + (2 * 4 + 4 * 18));

  // At 6 m: unit 1 whole (54 m²), unit 2 without its ceiling (45), unit 3 gone (its floor lies in
  // the cut), the core's floor and walls up to 6 m (4 + 4 × 12 = 52).
  const MeshData at6 = sliceBelow(all, 6);
  EXPECT_DOUBLE_EQ(totalArea(at6), 54 + 45 + 52);
  for (const Vec3& p : at6.points) EXPECT_LE(p[2], 6 + 1e-12);
  EXPECT_EQ(at6.faces.size(), 6u + 5u + 5u);
  EXPECT_EQ(unitsBelow(units, 6), (std::vector<std::size_t>{0, 1}));
  // Mid-storey at 4.5 m: unit 2's floor and 1.5 m of its walls (9 + 18), the core to 4.5 m (4 + 36).
  const MeshData at45 = sliceBelow(all, 4.5);
  EXPECT_DOUBLE_EQ(totalArea(at45), 54 + 27 + 40);
  EXPECT_EQ(unitsBelow(units, 4.5), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(unitsBelow(units, 3), (std::vector<std::size_t>{0}));
  // Above everything nothing changes; at the ground nothing is left.
  EXPECT_DOUBLE_EQ(totalArea(sliceBelow(all, 9)), totalArea(all) - 9 - 4);  // the tops at 9 m lie in the cut
  EXPECT_DOUBLE_EQ(totalArea(sliceBelow(all, 10)), totalArea(all));
  EXPECT_TRUE(sliceBelow(all, 0).faces.empty());
}

TEST(GrowthInspect, AnObjectsFacesComeBackFromTheScene) {
  MeshData m = growth::unitMesh(box(1, 0, 0, 0, 3, 3));
  const int mat = m.addMaterial("plaster");
  for (int& f : m.faceMaterial) f = mat;
  Scene scene;
  scene.replaceObject(7, Kind::Unit, "site", m);
  const MeshData back = objectMesh(scene, 7);
  EXPECT_EQ(back.faces.size(), 6u);
  EXPECT_EQ(back.points.size(), 8u);
  EXPECT_DOUBLE_EQ(totalArea(back), 54);
  for (int f : back.faceMaterial) EXPECT_EQ(back.materials[f], "plaster");
}

}  // namespace
}  // namespace corbel::editor
