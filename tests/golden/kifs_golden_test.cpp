// Golden images of KIFS buildings (McGraw): the box preset shaded (the look of Fig. 7, left)
// and the H preset with its facade ids (Fig. 6, 8), raymarched by shaders/kifs.frag.glsl over
// the renderer's sky and grid. Same conventions as golden_test.cpp (scripts/update-goldens).
#include "golden_support.h"
#include "render/kifs_pass.h"

#include <gtest/gtest.h>

namespace corbel::test {
namespace {

constexpr int kSize = 320;

struct Case {
  std::string preset;
  render::KifsMode mode;
  std::string golden;
};

class KifsGolden : public ::testing::TestWithParam<Case> {};

render::Image renderPreset(const Case& c) {
  render::Renderer& renderer = sharedRenderer();  // makes the context current first
  static render::KifsPass pass;
  const kifs::KifsParams params = kifs::preset(c.preset);
  const render::OrbitCamera camera = render::kifsCamera(kifs::Building(params), 1.0);
  const kifs::Building building(render::kifsForView(params, camera, kSize));
  render::RenderSettings settings;
  settings.edges = false;
  return render::renderKifsImage(renderer, pass, building, Scene(), camera, kSize, kSize, c.mode, settings);
}

TEST_P(KifsGolden, MatchesReferenceImage) { expectMatchesGolden(renderPreset(GetParam()), GetParam().golden); }

// The march is deterministic: two renders in a row are byte-identical.
TEST_P(KifsGolden, TwoRendersInARowAreIdentical) { EXPECT_EQ(renderPreset(GetParam()).rgba, renderPreset(GetParam()).rgba); }

INSTANTIATE_TEST_SUITE_P(KifsPresets, KifsGolden,
                         ::testing::Values(Case{"box", render::KifsMode::Shaded, "kifs-box"},
                                           Case{"h", render::KifsMode::Facades, "kifs-h-facades"}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string n = info.param.golden;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

}  // namespace
}  // namespace corbel::test
