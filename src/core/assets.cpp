#include "core/assets.h"

#include <cstdlib>

namespace corbel {

std::string assetsDir() {
  if (const char* env = std::getenv("CORBEL_ASSETS_DIR"); env && *env) return env;
  return CORBEL_ASSETS_DIR;
}

}  // namespace corbel
