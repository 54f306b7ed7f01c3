#pragma once
// One 1200 × 800 PNG of a Scene from an orbit camera framed on it, in the current GL context
// (the CLI's OSMesa one). Shared by grow and complete.
#include "core/scene.h"
#include "core/textures.h"

#include <string>

namespace corbel::cli {

struct SceneView {
  double azimuthDeg = -75, elevationDeg = 30, zoom = 0.95;  // zoom scales the framed distance
  bool textures = false;                                    // RenderSettings::textures
  TagTextures tagTextures = {};                             // RenderSettings::tagTextures
};
void writeScenePng(const Scene& scene, const SceneView& view, const std::string& png);

}  // namespace corbel::cli
