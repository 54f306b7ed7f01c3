#pragma once
// Orbit camera around a target, Z up: azimuth from +X towards +Y, elevation above the ground.
#include "core/geometry.h"

#include <glm/glm.hpp>

namespace corbel::render {

struct OrbitCamera {
  Vec3 target{0.0, 0.0, 0.0};
  double azimuth_deg = -60.0;
  double elevation_deg = 28.0;
  double distance = 30.0;
  double fov_deg = 40.0;

  Vec3 eye() const;
  glm::dmat4 view() const;
  glm::dmat4 projection(double aspect) const;  // near/far from the distance
  double nearPlane() const;                    // projection's near plane distance
  // Frames a bounding box so it fills the view at any azimuth.
  void frame(const BBox& box, double aspect = 1.0);
  // Mouse helpers (pixels → motion).
  void orbit(double dxPixels, double dyPixels);
  void pan(double dxPixels, double dyPixels, int viewportHeight);
  void zoom(double wheelSteps);
};

// Named presets for the View menu.
enum class CameraPreset { Perspective, Front, Right, Top };
void applyPreset(OrbitCamera& camera, CameraPreset preset);

}  // namespace corbel::render
