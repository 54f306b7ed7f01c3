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

double OrbitCamera::nearPlane() const { return std::max(distance * 0.01, 1e-3); }

double OrbitCamera::halfHeight() const { return distance * std::tan(0.5 * fov_deg * kDeg); }

glm::dmat4 OrbitCamera::projection(double aspect) const {
  const double farPlane = distance * 20.0 + 100.0;
  if (orthographic) {
    const double h = halfHeight(), w = h * std::max(aspect, 1e-3);
    const double depth = farPlane + 1000.0;  // linear depth: a kilometre more costs no precision worth having
    return glm::ortho(-w, w, -h, h, -depth, depth);
  }
  return glm::perspective(fov_deg * kDeg, std::max(aspect, 1e-3), nearPlane(), farPlane);
}

void OrbitCamera::frame(const BBox& box, double aspect) {
  if (box.empty()) {
    target = Vec3(0.0);
    distance = 30.0;
    return;
  }
  target = box.center();
  // The smallest distance at which all eight corners fall inside the frustum for the current
  // view direction: for a corner at (r, u, f) in the camera's right/up/forward frame relative
  // to the target, |r| ≤ (d − f)·tan(half horizontal fov) and likewise for u.
  const double a = azimuth_deg * kDeg, e = elevation_deg * kDeg;
  const Vec3 back(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));  // target → eye
  Vec3 right = OpenMesh::cross(Vec3(0, 0, 1), back);
  if (right.norm() < 1e-9) right = Vec3(-std::sin(a), std::cos(a), 0.0);
  right.normalize();
  const Vec3 up = OpenMesh::cross(back, right);
  const double tanV = std::tan(0.5 * fov_deg * kDeg), tanH = tanV * std::max(aspect, 1e-3);
  double d = 0.5;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c((k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1], (k & 4) ? box.hi[2] : box.lo[2]);
    const Vec3 q = c - target;
    const double f = OpenMesh::dot(q, back);  // towards the eye
    // Orthographic: the depth f does not shrink anything, only the half height d·tanV counts.
    const double depth = orthographic ? 0.0 : f;
    d = std::max({d, depth + std::abs(OpenMesh::dot(q, right)) / tanH, depth + std::abs(OpenMesh::dot(q, up)) / tanV});
  }
  distance = d * 1.08;
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
    case CameraPreset::Back: c.azimuth_deg = 90.0, c.elevation_deg = 0.0; break;
    case CameraPreset::Left: c.azimuth_deg = 180.0, c.elevation_deg = 0.0; break;
    case CameraPreset::Bottom: c.azimuth_deg = -90.0, c.elevation_deg = -90.0; break;
  }
}

}  // namespace corbel::render
