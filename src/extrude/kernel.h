#pragma once
// Registers the procedural-extrusion kernel with a SceneSync, so extrusion objects of a
// Document become shells in the Scene.
#include "core/scene_sync.h"

namespace corbel::extrude {

void registerKernel(SceneSync& sync);

}  // namespace corbel::extrude
