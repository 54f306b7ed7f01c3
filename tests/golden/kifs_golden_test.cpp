// Golden images of KIFS buildings (McGraw): every preset shaded (the box is the look of Fig. 7,
// left) and with its facade ids (Fig. 6, 8), raymarched by shaders/kifs.frag.glsl over
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

// Every preset shaded and with its facade ids (the "shaded and ids modes").
std::vector<Case> allCases() {
  std::vector<Case> out;
  for (const std::string& name : kifs::presetNames()) {
    out.push_back({name, render::KifsMode::Shaded, "kifs-preset-" + name});
    out.push_back({name, render::KifsMode::Facades, "kifs-preset-" + name + "-facades"});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(KifsPresets, KifsGolden, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string n = info.param.golden;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

}  // namespace
}  // namespace corbel::test
