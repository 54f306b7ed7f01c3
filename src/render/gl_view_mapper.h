#pragma once
// The growth kernel's view maps rendered with OpenGL (Sec. 5.2): for each of the four
// projections, every box's face toward the viewer is drawn orthographically with depth test,
// its colour the box's index + 1 packed into RGBA bytes (32 bits: any number of units).
// Reading the ids back, each pixel takes the unit id and the exact depth of its box, so the
// maps answer gain queries like the CPU ones. Pixels are square, `pixelSize` meters, on the
// same grid as growth::RasterViewMapper (a pixel shows what covers its centre).
#include "growth/view_map.h"

#include <memory>
#include <mutex>

namespace corbel::render {

class GlViewMapper : public growth::ViewMapper {
 public:
  // Needs a current GL 3.3 core context (HeadlessContext, or the editor's window).
  explicit GlViewMapper(double pixelSize);
  ~GlViewMapper() override;
  GlViewMapper(const GlViewMapper&) = delete;
  GlViewMapper& operator=(const GlViewMapper&) = delete;

  // Renders into framebuffers of its own and leaves the context's state as it found it: the
  // bound draw and read framebuffers, renderbuffer, program, vertex array and array buffer,
  // the viewport, depth test, function and mask, blending, face culling, multisampling, the
  // scissor test, colour mask, clear colour and depth, and the pack alignment. So it may run in
  // the middle of a frame of the editor's window.
  // Throws corbel::Error when a projection needs more pixels than GL allows per side.
  growth::ViewMaps render(const std::vector<growth::ViewBox>& boxes, const growth::Box& frame) override;
  double pixelSize() const { return pixel_; }
  void setPixelSize(double pixelSize);  // throws corbel::Error unless positive

 private:
  double pixel_;
  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
};

// Makes one GL context current on the calling thread and puts back what was current there
// before: a hidden GLFW window's context in the editor, an OSMesa one in tests.
class GlContextLease {
 public:
  virtual ~GlContextLease() = default;
  virtual void enter() = 0;  // the context is current on this thread until leave()
  virtual void leave() = 0;  // what was current on this thread at enter() is again
};

// GL view maps from any thread, on a context of their own: each render takes the lease (one
// render at a time), makes the GlViewMapper on first use, renders and gives the context back.
// The editor's growth builds and its view-map inspector run off the UI thread, where the
// window's context cannot be current; this is how they use GL anyway.
class ContextViewMapper : public growth::ViewMapper {
 public:
  ContextViewMapper(std::unique_ptr<GlContextLease> lease, double pixelSize);
  ~ContextViewMapper() override;  // deletes the GL objects in their context
  ContextViewMapper(const ContextViewMapper&) = delete;
  ContextViewMapper& operator=(const ContextViewMapper&) = delete;
  growth::ViewMaps render(const std::vector<growth::ViewBox>& boxes, const growth::Box& frame) override;
  double pixelSize() const;
  // The next render's pixels (a render running meanwhile finishes on the old ones); throws
  // corbel::Error unless positive.
  void setPixelSize(double pixelSize);

 private:
  mutable std::mutex mutex_;
  std::unique_ptr<GlContextLease> lease_;
  double pixel_;
  std::unique_ptr<GlViewMapper> gl_;
};

}  // namespace corbel::render
