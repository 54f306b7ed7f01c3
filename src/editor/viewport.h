#pragma once
// The 3D view: its camera and the rectangle of the window it fills (what the panels leave).
// Window points become rays into the scene here, for picking and for tools. No GL.
#include "core/geometry.h"
#include "render/camera.h"

#include <utility>

namespace corbel::editor {

// A ray into the scene: an origin on the near plane and a unit direction.
struct Ray {
  Vec3 origin{0.0, 0.0, 0.0};
  Vec3 direction{0.0, 0.0, -1.0};
};

class Viewport {
 public:
  render::OrbitCamera camera;

  // The view's rectangle in window pixels, top-left origin (at least 1 × 1).
  void setRect(float x, float y, float width, float height);
  float x() const { return x_; }
  float y() const { return y_; }
  float width() const { return w_; }
  float height() const { return h_; }
  double aspect() const { return double(w_) / double(h_); }
  bool contains(float px, float py) const { return px >= x_ && px < x_ + w_ && py >= y_ && py < y_ + h_; }

  // The ray through window point (px, py).
  Ray ray(float px, float py) const;
  // Fits `box` in the view from the current direction (an empty box: the origin, 30 m away).
  void frame(const BBox& box) { camera.frame(box, aspect()); }

 private:
  float x_ = 0, y_ = 0, w_ = 1, h_ = 1;
};

}  // namespace corbel::editor
