#pragma once
// Where the data files that ship with corbel live (assets/: presets, styles, examples).
#include <string>

namespace corbel {

// The assets folder: $CORBEL_ASSETS_DIR when it is set and not empty, else the source tree's
// assets/ (fixed at configure time; corbel has no install step yet).
std::string assetsDir();

}  // namespace corbel
