// Golden images: every example in assets/examples/ rendered headless (KIFS buildings ray-marched
// over the Scene, as corbel-cli render draws them) must match its
// tests/golden/<name>.png. On a mismatch the actual, expected and diff images are written to
// <build>/tests/golden/out/. Regenerate after an intended change with scripts/update-goldens
// (CORBEL_UPDATE_GOLDENS=1), then look at the new images before committing them.
#include "extrude/kernel.h"
#include "city/kernel.h"
#include "growth/kernel.h"
#include "kifs/kernel.h"
#include "render/kifs_pass.h"
#include "statics/kernel.h"
#include "golden_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace corbel::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 640, kHeight = 480;

std::vector<std::string> examples() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(CORBEL_SOURCE_DIR) / "assets/examples"))
    if (e.path().extension() == ".corbel") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

// With `textures`, the renderer's textured mode and the town styles' tag textures.
render::Image renderExample(const std::string& name, bool textures = false) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name + ".corbel");
  Scene scene;
  SceneSync sync;
  extrude::registerKernel(sync);
  statics::registerKernel(sync);
  kifs::registerKernel(sync);
  growth::registerKernel(sync);
  const auto towns = city::registerKernel(sync);
  sync.update(p.document, scene);
  for (const auto& [id, st] : sync.status()) EXPECT_EQ(st.error, "") << name;
  render::RenderSettings settings;
  settings.visible = [&](ObjectId id) { return p.document.find(id)->visible; };
  settings.textures = textures;
  if (textures) settings.tagTextures = towns->tagTextures();
  BBox box;
  for (const auto& o : p.document.objects)
    if (o.visible) box.add(scene.bounds(o.id));
  const render::RaymarchedKifs kifs =
      render::raymarchedKifs(p.document, settings.visible, &scene, city::buildingMeshes(towns));
  for (const std::string& e : kifs.errors) ADD_FAILURE() << name << ": " << e;
  box.add(kifs.bounds);
  render::OrbitCamera camera;
  camera.frame(box, double(kWidth) / kHeight);
  return render::renderSceneWithKifs(sharedRenderer(), scene, kifs.buildings, camera, kWidth, kHeight, settings,
                                     kifs.placements, kifs.masses);
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesReferenceImage) {
  const std::string name = GetParam();
  expectMatchesGolden(renderExample(name), name);
}

INSTANTIATE_TEST_SUITE_P(Examples, Golden, ::testing::ValuesIn(examples()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// The old town in the renderer's textured mode (docs/city.md): plaster, brick, roof tiles and
// slate by material, timber gables by tag_materials, timber soffits and metal dormer roofs by
// tag_textures. The only textured golden: the others are of colours.
TEST(TexturedGolden, OldTownMatchesReferenceImage) {
  expectMatchesGolden(renderExample("town-oldtown", true), "town-oldtown-textured");
}

// Rendering is deterministic: two renders of each example in a row are byte-identical.
TEST(GoldenStability, TwoRendersInARowAreIdentical) {
  for (const std::string& name : examples()) {
    const render::Image a = renderExample(name);
    const render::Image b = renderExample(name);
    EXPECT_EQ(a.rgba, b.rgba) << name;
  }
}

}  // namespace
}  // namespace corbel::test
