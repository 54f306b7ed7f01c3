#pragma once
// Orbit camera around a target, Z up: azimuth from +X towards +Y, elevation above the ground.
// Perspective or orthographic; an orthographic view shows at the target the same height a
// perspective one would (2 · distance · tan(fov / 2)), so toggling keeps the model's size.
#include "core/geometry.h"

#include <glm/glm.hpp>

namespace corbel::render {

struct OrbitCamera {
  Vec3 target{0.0, 0.0, 0.0};
  double azimuth_deg = -60.0;
  double elevation_deg = 28.0;
  double distance = 30.0;
  double fov_deg = 40.0;
  bool orthographic = false;

  Vec3 eye() const;
  glm::dmat4 view() const;
  // Near/far from the distance; orthographic: the planes lie as far before the eye as behind
  // it, so zooming in (a shorter distance) never cuts the model off.
  glm::dmat4 projection(double aspect) const;
  double nearPlane() const;                    // projection's near plane distance
  // Half the height the view shows at the target (metres).
  double halfHeight() const;
  // Frames a bounding box so it fills the view from the current direction.
  void frame(const BBox& box, double aspect = 1.0);
  // Mouse helpers (pixels → motion).
  void orbit(double dxPixels, double dyPixels);
  void pan(double dxPixels, double dyPixels, int viewportHeight);
  void zoom(double wheelSteps);
};

// Named presets for the View menu: an angled view and the six sides (Front looks along +Y,
// Right along −X, Top down; Back, Left and Bottom the opposite ways).
enum class CameraPreset { Perspective, Front, Right, Top, Back, Left, Bottom };
void applyPreset(OrbitCamera& camera, CameraPreset preset);

}  // namespace corbel::render
