// The GL view mapper (OSMesa) against the exact CPU mapper and the CPU rasterizer.
#include "render/gl_view_mapper.h"
#include "growth/engine.h"
#include "render/headless_context.h"
#include "support.h"

#include <gtest/gtest.h>

namespace corbel::growth {
namespace {

using test::box;

std::vector<ViewBox> scene() {
  return {{box(10, 10, 0, 16, 14, 3), 1},           {box(20, 10, 0, 26, 14, 6), 2}, {box(2, 20, 0, 5, 26, 3), 3},
          {box(10, 23, 0, 12, 30, 3), kObstacleId}, {box(30, 30, 0, 36, 34, 3), 5}, {box(30, 30, 3, 36, 34, 6), 6},
          {box(7.3, 3.1, 3, 13.9, 7.7, 6), 7}};  // off the 0.5 m grid
}
const Box kFrame = box(0, 0, 0, 40, 40, 9);

TEST(GlViewMapper, MatchesExactAreasWithinThePixelBound) {
  render::HeadlessContext context;
  ExactViewMapper exact;
  const ViewMaps truth = exact.render(scene(), kFrame);
  for (double pixel : {0.5, 0.23, 0.1}) {
    render::GlViewMapper gl(pixel);
    RasterViewMapper cpu(pixel);
    const ViewMaps maps = gl.render(scene(), kFrame), raster = cpu.render(scene(), kFrame);
    for (std::uint32_t id : {1u, 2u, 3u, 5u, 6u, 7u})
      for (ViewDirection d : kViewDirections) {
        double perimeter = 0;
        for (const ViewBox& b : scene())
          if (b.id == id) {
            const Rect r = projectBox(b.box, d);
            perimeter += 2 * ((r.u1 - r.u0) + (r.v1 - r.v0));
          }
        EXPECT_LE(std::abs(maps.view(id, d) - truth.view(id, d)), perimeter * pixel + 1e-9)
            << "pixel " << pixel << " unit " << id << " direction " << int(d);
        // Same pixel grid and centre rule as the CPU rasterizer: at most a row or column of
        // pixels apart where an edge passes exactly through centres.
        EXPECT_LE(std::abs(maps.view(id, d) - raster.view(id, d)), perimeter / 2 * pixel + 1e-9);
      }
  }
}

TEST(GlViewMapper, PixelAlignedSceneIsExact) {
  render::HeadlessContext context;
  render::GlViewMapper gl(0.5);
  ExactViewMapper exact;
  std::vector<ViewBox> s = scene();
  s.pop_back();  // the off-grid box
  const ViewMaps a = gl.render(s, kFrame), b = exact.render(s, kFrame);
  for (std::uint32_t id : {1u, 2u, 3u, 5u, 6u})
    for (ViewDirection d : kViewDirections) EXPECT_NEAR(a.view(id, d), b.view(id, d), 1e-9) << id << " " << int(d);
}

TEST(GlViewMapper, TensOfThousandsOfIdsSurviveTheRgbaPacking) {
  render::HeadlessContext context;
  // 70,000 boxes of 0.5 m x 0.5 m in a 280 x 250 wall: more than 2^16 ids, so three of the
  // four bytes carry bits, each box exactly one 0.5 m pixel.
  std::vector<ViewBox> s;
  const int n = 70000, columns = 280;
  for (int i = 0; i < n; ++i) {
    const double x = (i % columns) * 0.5, z = (i / columns) * 0.5;
    s.push_back({box(x, 5, z, x + 0.5, 6, z + 0.5), std::uint32_t(i + 1)});
  }
  render::GlViewMapper gl(0.5);
  const ViewMaps maps = gl.render(s, box(0, 0, 0, columns * 0.5, 10, n / columns * 0.5));
  int wrong = 0;
  for (int i = 0; i < n; ++i)
    if (std::abs(maps.view(std::uint32_t(i + 1), ViewDirection::NegY) - 0.25) > 1e-9) ++wrong;
  EXPECT_EQ(wrong, 0);
}

TEST(GlViewMapper, AGrowthRunWithGlMapsEqualsOneWithTheCpuRasterizer) {
  render::HeadlessContext context;
  Site site = test::openSite(40, 30, 2);
  site.cores = {{18, 13, 22, 17}};
  site.coreClearance = 0.5;
  site.circulation = {box(22.5, 14, 0, 26, 16, 3), box(22.5, 14, 3, 26, 16, 6)};
  site.seeds = {test::seedAt(26, 14, 0, 60), test::seedAt(23, 16, 0, 45), test::seedAt(23, 11, 1, 50),
                test::seedAt(26, 13, 1, 70)};
  render::GlViewMapper gl(0.25);
  RasterViewMapper cpu(0.25);
  GrowthEngine a(site, {}, &gl), b(site, {}, &cpu);
  a.run(1000);
  b.run(1000);
  ASSERT_GT(a.commits(), 50u);
  const std::vector<Unit> ua = a.units(), ub = b.units();
  for (std::size_t i = 0; i < ua.size(); ++i) EXPECT_EQ(ua[i].parts, ub[i].parts) << "unit " << ua[i].id;
}

}  // namespace
}  // namespace corbel::growth
