#pragma once
// A headless OpenGL 3.3+ core context through OSMesa (llvmpipe): no X server needed.
#include "render/renderer.h"

#include <memory>
#include <vector>

namespace corbel::render {

class HeadlessContext {
 public:
  // Throws corbel::Error if OSMesa cannot give a core profile context.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

 private:
  void* context_ = nullptr;
  std::vector<unsigned char> buffer_;  // OSMesa needs a bound buffer even for FBO rendering
};

// Renders a scene into an image with a fresh offscreen target (one call, one picture).
Image renderImage(Renderer& renderer, const Scene& scene, const OrbitCamera& camera, int width, int height,
                  const RenderSettings& settings);

}  // namespace corbel::render
