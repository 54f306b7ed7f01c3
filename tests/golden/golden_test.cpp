// Golden images: every example in assets/examples/ rendered headless must match its
// tests/golden/<name>.png. On a mismatch the actual, expected and diff images are written to
// <build>/tests/golden/out/. Regenerate after an intended change with scripts/update-goldens
// (CORBEL_UPDATE_GOLDENS=1), then look at the new images before committing them.
#include "extrude/kernel.h"
#include "golden_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace corbel::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 640, kHeight = 480;
constexpr int kChannelTolerance = 24;        // per channel, 0..255
constexpr double kMaxDifferingFraction = 0.002;

std::vector<std::string> examples() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(CORBEL_SOURCE_DIR) / "assets/examples"))
    if (e.path().extension() == ".corbel") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

render::Image renderExample(const std::string& name) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name + ".corbel");
  Scene scene;
  SceneSync sync;
  extrude::registerKernel(sync);
  sync.update(p.document, scene);
  for (const auto& [id, st] : sync.status()) EXPECT_EQ(st.error, "") << name;
  render::RenderSettings settings;
  settings.visible = [&](ObjectId id) { return p.document.find(id)->visible; };
  BBox box;
  for (const auto& o : p.document.objects)
    if (o.visible) box.add(scene.bounds(o.id));
  render::OrbitCamera camera;
  camera.frame(box, double(kWidth) / kHeight);
  return render::renderImage(sharedRenderer(), scene, camera, kWidth, kHeight, settings);
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesReferenceImage) {
  const std::string name = GetParam();
  const render::Image actual = renderExample(name);
  const std::string goldenPath = std::string(CORBEL_SOURCE_DIR) + "/tests/golden/" + name + ".png";
  const char* update = std::getenv("CORBEL_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    render::writePng(actual, goldenPath);
    GTEST_SUCCEED() << "updated " << goldenPath;
    return;
  }
  ASSERT_TRUE(fs::exists(goldenPath)) << "no golden image for example '" << name
                                      << "': run scripts/update-goldens and inspect " << goldenPath;
  const render::Image expected = render::readPng(goldenPath);
  const render::ImageDiff diff = render::compareImages(expected, actual, kChannelTolerance);
  if (diff.differingFraction > kMaxDifferingFraction) {
    fs::create_directories(CORBEL_GOLDEN_OUT);
    const std::string base = std::string(CORBEL_GOLDEN_OUT) + "/" + name;
    render::writePng(actual, base + ".actual.png");
    render::writePng(expected, base + ".expected.png");
    render::writePng(diff.visual, base + ".diff.png");
    ADD_FAILURE() << name << ": " << diff.differing << " pixels (" << diff.differingFraction * 100
                  << "%) differ by more than " << kChannelTolerance << "; see " << base << ".{actual,expected,diff}.png";
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, Golden, ::testing::ValuesIn(examples()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

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
