// Compares an editor screenshot of a project with one of an empty project (same window size
// and layout): the 3D viewport must show the model — enough of its pixels differ from the
// empty scene — and the screenshot must not be blank. An optional RIGHT_PANE width leaves a
// panel right of the viewport out of the comparison, so only the 3D view counts.
#include "render/image.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: corbel_screenshot_check MODEL.png EMPTY.png MIN_FRACTION [RIGHT_PANE]\n");
    return 2;
  }
  try {
    const auto model = corbel::render::readPng(argv[1]);
    const auto empty = corbel::render::readPng(argv[2]);
    const double minFraction = std::atof(argv[3]);
    const int rightPane = argc == 5 ? std::atoi(argv[4]) : 0;
    if (model.width != empty.width || model.height != empty.height) {
      std::fprintf(stderr, "screenshots differ in size\n");
      return 1;
    }
    // Not blank: luminance varies.
    double sum = 0, sum2 = 0;
    const double n = double(model.width) * model.height;
    for (int y = 0; y < model.height; ++y)
      for (int x = 0; x < model.width; ++x) {
        const auto* p = model.at(x, y);
        const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        sum += l;
        sum2 += l * l;
      }
    const double stddev = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
    // The viewport: right of the 320-pixel panel (and left of a right pane), between the menu bar
    // and the status bar.
    const int x0 = 330, y0 = 30, x1 = model.width - 10 - rightPane, y1 = model.height - 130;
    std::size_t changed = 0, total = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x, ++total) {
        const auto* a = model.at(x, y);
        const auto* b = empty.at(x, y);
        int d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
        if (d > 30) ++changed;
      }
    const double fraction = total ? double(changed) / total : 0.0;
    std::printf("luminance stddev %.1f, model covers %.1f%% of the viewport\n", stddev, fraction * 100);
    if (stddev < 10) {
      std::fprintf(stderr, "screenshot looks blank\n");
      return 1;
    }
    if (fraction < minFraction) {
      std::fprintf(stderr, "the model covers less than %.1f%% of the viewport\n", minFraction * 100);
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
