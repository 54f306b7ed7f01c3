#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace corbel::render {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

Vec3 OrbitCamera::eye() const {
  const double a = azimuth_deg * kDeg, e = elevation_deg * kDeg;
  return target + distance * Vec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}

glm::dmat4 OrbitCamera::view() const {
  const Vec3 p = eye();
  // Straight down (top view) needs another up vector.
  const glm::dvec3 up = std::abs(elevation_deg) > 89.9
                            ? glm::dvec3(-std::cos(azimuth_deg * kDeg), -std::sin(azimuth_deg * kDeg), 0.0)
                            : glm::dvec3(0, 0, 1);
  return glm::lookAt(glm::dvec3(p[0], p[1], p[2]), glm::dvec3(target[0], target[1], target[2]), up);
}

glm::dmat4 OrbitCamera::projection(double aspect) const {
  const double nearPlane = std::max(distance * 0.01, 1e-3);
  const double farPlane = distance * 20.0 + 100.0;
  return glm::perspective(fov_deg * kDeg, std::max(aspect, 1e-3), nearPlane, farPlane);
}

void OrbitCamera::frame(const BBox& box, double aspect) {
  if (box.empty()) {
    target = Vec3(0.0);
    distance = 30.0;
    return;
  }
  target = box.center();
  const double radius = std::max(0.5 * box.diagonal(), 0.5);
  const double halfFov = 0.5 * fov_deg * kDeg;
  const double horizontalHalf = std::atan(std::tan(halfFov) * std::min(aspect, 1.0));
  distance = radius / std::sin(std::min(halfFov, horizontalHalf)) * 1.05;
}

void OrbitCamera::orbit(double dx, double dy) {
  azimuth_deg = std::fmod(azimuth_deg - dx * 0.4, 360.0);
  elevation_deg = std::clamp(elevation_deg + dy * 0.4, -89.0, 90.0);
}

void OrbitCamera::pan(double dx, double dy, int viewportHeight) {
  const double a = azimuth_deg * kDeg, e = elevation_deg * kDeg;
  const Vec3 right(-std::sin(a), std::cos(a), 0.0);
  const Vec3 up(-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e));
  const double metersPerPixel = 2.0 * distance * std::tan(0.5 * fov_deg * kDeg) / std::max(viewportHeight, 1);
  target += (-dx * right + dy * up) * metersPerPixel;
}

void OrbitCamera::zoom(double steps) { distance = std::clamp(distance * std::pow(0.88, steps), 0.05, 1e6); }

void applyPreset(OrbitCamera& c, CameraPreset preset) {
  switch (preset) {
    case CameraPreset::Perspective: c.azimuth_deg = -60.0, c.elevation_deg = 28.0; break;
    case CameraPreset::Front: c.azimuth_deg = -90.0, c.elevation_deg = 0.0; break;
    case CameraPreset::Right: c.azimuth_deg = 0.0, c.elevation_deg = 0.0; break;
    case CameraPreset::Top: c.azimuth_deg = -90.0, c.elevation_deg = 90.0; break;
  }
}

}  // namespace corbel::render
