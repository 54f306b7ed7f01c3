#include "cli/scene_png.h"

#include "render/headless_context.h"
#include "render/renderer.h"

namespace corbel::cli {

void writeScenePng(const Scene& scene, const SceneView& view, const std::string& png) {
  render::Renderer renderer;
  render::OrbitCamera camera;
  camera.frame(scene.bounds(), 1200.0 / 800.0);
  camera.azimuth_deg = view.azimuthDeg;
  camera.elevation_deg = view.elevationDeg;
  camera.distance *= view.zoom;
  render::RenderSettings settings;
  settings.textures = view.textures;
  settings.tagTextures = view.tagTextures;
  render::writePng(render::renderImage(renderer, scene, camera, 1200, 800, settings), png);
}

}  // namespace corbel::cli
