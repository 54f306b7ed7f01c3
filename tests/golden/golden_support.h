#pragma once
// Shared by the golden and renderer tests: one OSMesa context per test binary.
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "render/headless_context.h"

#include <memory>

namespace corbel::test {

inline render::Renderer& sharedRenderer() {
  static render::HeadlessContext context;
  static render::Renderer renderer;
  return renderer;
}

}  // namespace corbel::test
