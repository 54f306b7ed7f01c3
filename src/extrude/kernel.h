#pragma once
// Registers the procedural-extrusion kernel with a SceneSync, so extrusion objects of a
// Document become shells in the Scene.
#include "core/scene_sync.h"

namespace corbel::extrude {

// A building that takes longer than this in the editor is given up with an error (its last
// good shell stays): no degenerate plan can keep a background build busy for ever.
inline constexpr double kEditTimeLimitSeconds = 30.0;

void registerKernel(SceneSync& sync);

}  // namespace corbel::extrude
