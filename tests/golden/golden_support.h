#pragma once
// Shared by the golden and renderer tests: one OSMesa context per test binary, and the
// comparison with a golden image.
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "render/headless_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

namespace corbel::test {

inline render::Renderer& sharedRenderer() {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  return renderer;
}

inline constexpr int kChannelTolerance = 24;  // per channel, 0..255
inline constexpr double kMaxDifferingFraction = 0.002;

// Compares `actual` with tests/golden/<name>.png. On a mismatch the actual, expected and diff
// images are written to <build>/tests/golden/out/. CORBEL_UPDATE_GOLDENS=1 rewrites the golden
// instead (scripts/update-goldens); look at the new image before committing it.
inline void expectMatchesGolden(const render::Image& actual, const std::string& name) {
  namespace fs = std::filesystem;
  const std::string goldenPath = std::string(CORBEL_SOURCE_DIR) + "/tests/golden/" + name + ".png";
  const char* update = std::getenv("CORBEL_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    render::writePng(actual, goldenPath);
    GTEST_SUCCEED() << "updated " << goldenPath;
    return;
  }
  ASSERT_TRUE(fs::exists(goldenPath)) << "no golden image '" << name << "': run scripts/update-goldens and inspect "
                                      << goldenPath;
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

}  // namespace corbel::test
