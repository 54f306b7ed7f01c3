// View maps (Sec. 5.2) against visible areas computed by hand.
#include "growth/view_map.h"
#include "support.h"

#include <gtest/gtest.h>

#include <memory>

namespace corbel::growth {
namespace {

using test::box;
using D = ViewDirection;

const Box kFrame = box(0, 0, 0, 40, 40, 9);

// A unit in the open, one hidden behind a taller unit, one half hidden behind an obstacle,
// and two stacked units (ids 1..6; the obstacle is kObstacleId).
std::vector<ViewBox> handScene() {
  return {
      {box(10, 10, 0, 16, 14, 3), 1},  // in the open in -y (nothing south of it)
      {box(20, 10, 0, 26, 14, 6), 2},  // tall, east of unit 1: hides 1's +x face entirely
      {box(2, 20, 0, 5, 26, 3), 3},    // its +x face half hidden by the obstacle
      {box(10, 23, 0, 12, 30, 3), kObstacleId},
      {box(30, 30, 0, 36, 34, 3), 5},  // stacked pair
      {box(30, 30, 3, 36, 34, 6), 6},
  };
}

struct Expected {
  std::uint32_t id;
  D d;
  double area;
};

// Each value from the scene's geometry: face size minus what lies in front of it.
const std::vector<Expected> kExpected = {
    {1, D::PosX, 0.0},                       // unit 2 (y 10..14, z 0..6) covers the whole 4 x 3 face
    {1, D::NegX, 12.0},                      // 4 x 3, nothing west in y 10..14
    {1, D::PosY, 12.0},                      // 6 x 3 minus the obstacle's x 10..12 north of it
    {1, D::NegY, 18.0},                      // 6 x 3
    {2, D::PosX, 24.0},                      // 4 x 6
    {2, D::NegX, 12.0},                      // 4 x 6 minus unit 1's 4 x 3 in front
    {2, D::PosY, 36.0},                      // 6 x 6
    {2, D::NegY, 36.0}, {3, D::PosX, 9.0},   // 6 x 3 face, the obstacle covers y 23..26: half
    {3, D::NegX, 18.0}, {3, D::PosY, 9.0},   // 3 x 3
    {3, D::NegY, 9.0},  {5, D::PosX, 12.0},  // stacking hides no vertical face
    {6, D::PosX, 12.0}, {5, D::NegY, 18.0}, {6, D::PosY, 18.0},
};

TEST(ViewMap, ExactMapperGivesHandComputedVisibleAreas) {
  ExactViewMapper mapper;
  const ViewMaps maps = mapper.render(handScene(), kFrame);
  for (const Expected& e : kExpected)
    EXPECT_NEAR(maps.view(e.id, e.d), e.area, 1e-9) << "unit " << e.id << " direction " << int(e.d);
  EXPECT_NEAR(maps.view(1), 0 + 12 + 12 + 18, 1e-9);
}

TEST(ViewMap, RasterMapperErrorIsBoundedByThePixelSize) {
  const std::vector<ViewBox> scene = handScene();
  ExactViewMapper exact;
  const ViewMaps truth = exact.render(scene, kFrame);
  for (double pixel : {0.7, 0.37, 0.13, 0.05}) {
    RasterViewMapper raster(pixel);
    const ViewMaps maps = raster.render(scene, kFrame);
    for (std::uint32_t id : {1u, 2u, 3u, 5u, 6u})
      for (D d : kViewDirections) {
        // Each visible region is a few rectangles; the pixel-centre rule moves each edge by at
        // most half a pixel, so the error is below (its perimeter) x pixel.
        const double err = std::abs(maps.view(id, d) - truth.view(id, d));
        double own = 0;
        for (const ViewBox& b : scene)
          if (b.id == id) {
            const Rect r = projectBox(b.box, d);
            own += 2 * ((r.u1 - r.u0) + (r.v1 - r.v0));
          }
        EXPECT_LE(err, own * pixel + 1e-9) << "pixel " << pixel << " unit " << id << " dir " << int(d);
      }
  }
}

TEST(ViewMap, PixelAlignedSceneIsExactInRaster) {
  // Coordinates on a 0.5 m grid: a 0.5 m raster samples every cell exactly.
  const std::vector<ViewBox> scene = handScene();
  RasterViewMapper raster(0.5);
  ExactViewMapper exact;
  const ViewMaps a = raster.render(scene, kFrame), b = exact.render(scene, kFrame);
  for (std::uint32_t id : {1u, 2u, 3u, 5u, 6u})
    for (D d : kViewDirections) EXPECT_NEAR(a.view(id, d), b.view(id, d), 1e-9);
}

TEST(ViewMap, FarMoreThan255UnitsKeepTheirOwnIds) {
  std::vector<ViewBox> scene;
  const int n = 1000;
  for (int i = 0; i < n; ++i) scene.push_back({box(i * 0.1, 5, 0, i * 0.1 + 0.1, 6, 3), std::uint32_t(i + 1)});
  const Box frame = box(0, 0, 0, n * 0.1, 10, 3);
  ExactViewMapper exact;
  const ViewMaps maps = exact.render(scene, frame);
  for (int i = 0; i < n; ++i) ASSERT_NEAR(maps.view(std::uint32_t(i + 1), D::NegY), 0.3, 1e-9) << i;
  RasterViewMapper raster(0.05);
  const ViewMaps r = raster.render(scene, frame);
  for (int i = 0; i < n; ++i) ASSERT_NEAR(r.view(std::uint32_t(i + 1), D::NegY), 0.3, 1e-9) << i;
}

TEST(ViewMap, GainInViewCountsOnlyNewlySeenAreaAndWhatItTakes) {
  // Unit 1 in the open; unit 2 north-east of it, its -x face (y 14..17) seen from the west.
  const std::vector<ViewBox> scene{{box(10, 10, 0, 16, 14, 3), 1}, {box(20, 14, 0, 26, 17, 3), 2}};
  ExactViewMapper exact;
  const ViewMaps maps = exact.render(scene, kFrame);
  ASSERT_NEAR(maps.view(2, D::NegX), 9.0, 1e-9);
  // Advance(+x, 0.5) of unit 1: its ±y faces grow by 0.5 x 3 each, both in the open.
  ViewGain g = maps.gain(sweptRegion(scene[0].box, Side::PosX, 0.5), 1);
  EXPECT_NEAR(g.gain, 3.0, 1e-9);
  EXPECT_TRUE(g.taken.empty());
  // Advance(+y, 0.5): the strip's -x side (y 14..14.5) is seen from the west in front of
  // unit 2's face, which loses 0.5 x 3; its +x side is behind unit 2 (hidden); its +y side
  // covers unit 1's own face (no gain).
  g = maps.gain(sweptRegion(scene[0].box, Side::PosY, 0.5), 1);
  EXPECT_NEAR(g.gain, 1.5, 1e-9);
  ASSERT_EQ(g.taken.size(), 1u);
  EXPECT_NEAR(g.taken.at(2), 1.5, 1e-9);
}

}  // namespace
}  // namespace corbel::growth
