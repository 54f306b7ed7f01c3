// Progressive refinement (render/kifs_layer.h): the cached layer composited over a Scene gives
// exactly the picture of marching the building straight into it (full size), a coarse layer
// is the picture of a march at 1/scale of the size with each texel blown up to scale × scale
// pixels, and the layer marches only when its key, size or scale change.
#include "golden_support.h"
#include "core/massing.h"
#include "render/gl.h"
#include "render/kifs_layer.h"
#include "render/kifs_pass.h"

#include <gtest/gtest.h>

namespace corbel::test {
namespace {

constexpr int kW = 160, kH = 120;

struct View {
  kifs::KifsParams params;
  render::OrbitCamera camera;
  Scene scene;
  render::RenderSettings settings;
};

// The H preset behind a box that hides part of it, so depth composition matters.
View hWithABoxInFront() {
  View v;
  const kifs::KifsParams p = kifs::preset("h");
  v.camera = render::kifsCamera(kifs::Building(p), double(kW) / kH);
  v.params = render::kifsForView(p, v.camera, kH);
  const Vec3 eye = v.camera.eye(), target = v.camera.target;
  const Vec3 mid = target + (eye - target) * 0.35;
  BoxSpec box;
  box.origin = Vec3(mid[0] - 3, mid[1] - 3, 0);
  box.size = Vec3(6, 6, 12);
  v.scene.replaceObject(1, Kind::Mass, "box", buildBoxes(box));
  v.settings.edges = false;
  return v;
}

render::Image direct(const View& v, int w, int h, const kifs::KifsParams& params,
                     render::KifsMode mode = render::KifsMode::Shaded) {
  render::Renderer& renderer = sharedRenderer();
  static render::KifsPass pass;
  render::OffscreenTarget target(w, h, 1);
  target.bind();
  renderer.setScene(v.scene, v.settings);
  renderer.draw(v.camera, 0, 0, w, h, v.settings);
  pass.draw(kifs::Building(params), v.camera, 0, 0, w, h, mode);
  glFinish();
  return target.read();
}

render::Image layered(const View& v, render::KifsLayer& layer, int scale, const std::string& key, bool* marched = nullptr) {
  render::Renderer& renderer = sharedRenderer();
  static render::KifsPass pass;
  render::OffscreenTarget target(kW, kH, 1);
  target.bind();
  renderer.setScene(v.scene, v.settings);
  renderer.draw(v.camera, 0, 0, kW, kH, v.settings);
  const bool m = layer.update(pass, {v.params}, v.camera, kW, kH, scale, render::KifsMode::Shaded, key);
  if (marched) *marched = m;
  layer.composite(0, 0, kW, kH);
  glFinish();
  return target.read();
}

TEST(KifsLayer, FullSizeLayerComposesExactlyAsADirectMarch) {
  const View v = hWithABoxInFront();
  sharedRenderer();
  render::KifsLayer layer;
  const render::Image a = layered(v, layer, 1, "h");
  const render::Image b = direct(v, kW, kH, v.params);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_EQ(a.rgba, b.rgba);
}

// At scale 4 a texel is what a march of a 40 × 30 view (hit threshold 4× wider) sees; the
// building's pixels must be those texels, each covering 4 × 4 pixels. Compared where the
// building is in front in both (the Scene is drawn at full size in one and not the other).
TEST(KifsLayer, CoarseLayerIsASmallerMarchBlownUp) {
  View v = hWithABoxInFront();
  v.scene = Scene();  // the building alone over the sky
  sharedRenderer();
  render::KifsLayer layer;
  const render::Image coarse = layered(v, layer, 4, "h coarse");
  kifs::KifsParams small = v.params;
  small.trace.pixelAngle *= 4;
  // Coarse frames are previews: no soft shadow, no occlusion (render/kifs_pass.h).
  const render::Image reference = direct(v, kW / 4, kH / 4, small, render::KifsMode::Preview);
  const render::Image sky = [&] {  // the Scene's sky and grid alone
    render::Renderer& renderer = sharedRenderer();
    render::OffscreenTarget target(kW, kH, 1);
    target.bind();
    renderer.setScene(v.scene, v.settings);
    renderer.draw(v.camera, 0, 0, kW, kH, v.settings);
    glFinish();
    return target.read();
  }();
  int compared = 0, equal = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = 4 * (std::size_t(y) * kW + x);
      const std::size_t j = 4 * (std::size_t(y / 4) * (kW / 4) + x / 4);
      // Only pixels the building covers in the coarse picture (not sky).
      if (coarse.rgba[i] == sky.rgba[i] && coarse.rgba[i + 1] == sky.rgba[i + 1] && coarse.rgba[i + 2] == sky.rgba[i + 2]) continue;
      ++compared;
      equal += coarse.rgba[i] == reference.rgba[j] && coarse.rgba[i + 1] == reference.rgba[j + 1] &&
               coarse.rgba[i + 2] == reference.rgba[j + 2];
    }
  EXPECT_GT(compared, kW * kH / 10);
  EXPECT_EQ(equal, compared);
}

TEST(KifsLayer, MarchesOnlyWhenTheKeySizeOrScaleChange) {
  const View v = hWithABoxInFront();
  sharedRenderer();
  render::KifsLayer layer;
  bool marched = false;
  layered(v, layer, 4, "a", &marched);
  EXPECT_TRUE(marched);
  layered(v, layer, 4, "a", &marched);
  EXPECT_FALSE(marched);
  layered(v, layer, 1, "a", &marched);
  EXPECT_TRUE(marched) << "a new scale";
  layered(v, layer, 1, "b", &marched);
  EXPECT_TRUE(marched) << "a new key";
  layer.invalidate();
  layered(v, layer, 1, "b", &marched);
  EXPECT_TRUE(marched) << "after invalidate";
}

}  // namespace
}  // namespace corbel::test
