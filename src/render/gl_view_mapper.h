#pragma once
// The growth kernel's view maps rendered with OpenGL (Sec. 5.2): for each of the four
// projections, every box's face toward the viewer is drawn orthographically with depth test,
// its colour the box's index + 1 packed into RGBA bytes (32 bits: any number of units).
// Reading the ids back, each pixel takes the unit id and the exact depth of its box, so the
// maps answer gain queries like the CPU ones. Pixels are square, `pixelSize` meters, on the
// same grid as growth::RasterViewMapper (a pixel shows what covers its centre).
#include "growth/view_map.h"

namespace corbel::render {

class GlViewMapper : public growth::ViewMapper {
 public:
  // Needs a current GL 3.3 core context (HeadlessContext, or the editor's window).
  explicit GlViewMapper(double pixelSize);
  ~GlViewMapper() override;
  GlViewMapper(const GlViewMapper&) = delete;
  GlViewMapper& operator=(const GlViewMapper&) = delete;

  // Throws corbel::Error when a projection needs more pixels than GL allows per side.
  growth::ViewMaps render(const std::vector<growth::ViewBox>& boxes, const growth::Box& frame) override;

 private:
  double pixel_;
  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
};

}  // namespace corbel::render
