#include "render/headless_context.h"

#include "core/error.h"
#include "render/gl.h"

#include <GL/osmesa.h>

namespace corbel::render {

HeadlessContext::HeadlessContext() {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) throw Error("OSMesa could not create an OpenGL 3.3 core profile context");
  context_ = ctx;
  buffer_.assign(4 * 4 * 4, 0);
  if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, 4, 4)) {
    OSMesaDestroyContext(ctx);
    throw Error("OSMesa could not make its context current");
  }
}

HeadlessContext::~HeadlessContext() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

Image renderImage(Renderer& renderer, const Scene& scene, const OrbitCamera& camera, int width, int height,
                  const RenderSettings& settings) {
  OffscreenTarget target(width, height);
  target.bind();
  renderer.setScene(scene, settings);
  renderer.draw(camera, 0, 0, width, height, settings);
  glFinish();
  return target.read();
}

}  // namespace corbel::render
