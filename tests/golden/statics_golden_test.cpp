// Golden images of the statics pictures that corbel-cli draws headless (cli/statics_png.h):
// the example arch on columns as analysed (blocks by their share of tension, compression red,
// tension blue, ground reactions green) and its energy landscape over its two free parameters
// (Fig. 8, standing samples red). Regenerate with scripts/update-goldens and look at them.
#include "golden_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace corbel::test {
namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& s) { return "'" + s + "'"; }  // paths of the build have no quotes

// Runs `corbel-cli statics ARGS` and returns the PNG it wrote to `png` (under the golden out folder).
render::Image cliPicture(const std::string& args, const std::string& png) {
  fs::create_directories(CORBEL_GOLDEN_OUT);
  const std::string path = std::string(CORBEL_GOLDEN_OUT) + "/" + png;
  fs::remove(path);
  const std::string command = quote(CORBEL_CLI) + " statics " +
                              quote(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-arch.corbel") + " " +
                              args + " " + quote(path) + " >/dev/null";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  return render::readPng(path);
}

TEST(StaticsGolden, TheExampleArchAsAnalysed) {
  expectMatchesGolden(cliPicture("--size 640x480 --render", "statics-arch.render.png"), "statics-arch");
}

TEST(StaticsGolden, TheExampleArchsEnergyLandscape) {
  expectMatchesGolden(cliPicture("--samples 21 --landscape thickness columnWidth", "statics-arch-landscape.render.png"),
                      "statics-arch-landscape");
}

}  // namespace
}  // namespace corbel::test
