#include "editor/viewport.h"

#include <algorithm>

namespace corbel::editor {

void Viewport::setRect(float x, float y, float width, float height) {
  x_ = x;
  y_ = y;
  w_ = std::max(1.0f, width);
  h_ = std::max(1.0f, height);
}

Ray Viewport::ray(float px, float py) const {
  // Normalised device coordinates of the point, unprojected at the near and far planes.
  const double x = 2.0 * (px - x_) / w_ - 1.0, y = 1.0 - 2.0 * (py - y_) / h_;
  const glm::dmat4 inv = glm::inverse(camera.projection(aspect()) * camera.view());
  glm::dvec4 a = inv * glm::dvec4(x, y, -1.0, 1.0), b = inv * glm::dvec4(x, y, 1.0, 1.0);
  a /= a.w;
  b /= b.w;
  Vec3 dir(b.x - a.x, b.y - a.y, b.z - a.z);
  dir.normalize();
  return {Vec3(a.x, a.y, a.z), dir};
}

}  // namespace corbel::editor
