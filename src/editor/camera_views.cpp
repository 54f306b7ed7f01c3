#include "editor/camera_views.h"

#include <algorithm>
#include <cmath>

namespace corbel::editor {

namespace {

// The camera's right and up directions on screen and its forward direction (eye → target), as
// the view matrix has them.
void cameraFrame(const render::OrbitCamera& c, glm::dvec3& right, glm::dvec3& up, glm::dvec3& forward) {
  const glm::dmat4 v = c.view();
  right = glm::dvec3(v[0][0], v[1][0], v[2][0]);
  up = glm::dvec3(v[0][1], v[1][1], v[2][1]);
  forward = -glm::dvec3(v[0][2], v[1][2], v[2][2]);
}

}  // namespace

void zoomTowards(render::OrbitCamera& camera, double ndcX, double ndcY, double aspect, double steps) {
  glm::dvec3 right, up, forward;
  cameraFrame(camera, right, up, forward);
  // The point under the pointer on the target's plane, as an offset from the target.
  const double h = camera.halfHeight();
  const glm::dvec3 offset = right * (ndcX * h * std::max(aspect, 1e-3)) + up * (ndcY * h);
  const double before = camera.distance;
  camera.zoom(steps);
  // The plane's half height scales with the distance: the same point stays at (ndcX, ndcY) when
  // the target moves towards it by the part of the offset the zoom removed.
  const double k = camera.distance / before;
  const glm::dvec3 move = (1.0 - k) * offset;
  camera.target += Vec3(move.x, move.y, move.z);
}

bool boxInView(const render::OrbitCamera& camera, double aspect, const BBox& box) {
  if (box.empty()) return true;
  const glm::dmat4 m = camera.projection(aspect) * camera.view();
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 p = m * glm::dvec4((k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1],
                                        (k & 4) ? box.hi[2] : box.lo[2], 1.0);
    if (p.w <= 0) return false;
    const double x = p.x / p.w, y = p.y / p.w, z = p.z / p.w;
    if (std::abs(x) > 1.0 || std::abs(y) > 1.0 || z < -1.0 || z > 1.0) return false;
  }
  return true;
}

std::array<AxisEnd, 6> axisEnds(const render::OrbitCamera& camera, float radius) {
  glm::dvec3 right, up, forward;
  cameraFrame(camera, right, up, forward);
  std::array<AxisEnd, 6> ends;
  for (int i = 0; i < 6; ++i) {
    glm::dvec3 d(0.0);
    d[i % 3] = i < 3 ? 1.0 : -1.0;
    AxisEnd& e = ends[i];
    e.axis = i % 3;
    e.positive = i < 3;
    e.dx = float(radius * glm::dot(d, right));
    e.dy = float(-radius * glm::dot(d, up));  // screen y grows downwards
    e.depth = -glm::dot(d, forward);
  }
  return ends;
}

std::optional<AxisEnd> axisEndAt(const render::OrbitCamera& camera, float dx, float dy) {
  std::optional<AxisEnd> best;
  for (const AxisEnd& e : axisEnds(camera))
    if (std::hypot(dx - e.dx, dy - e.dy) <= kAxisKnobRadius && (!best || e.depth > best->depth)) best = e;
  return best;
}

render::CameraPreset presetOfAxis(const AxisEnd& e) {
  using P = render::CameraPreset;
  switch (e.axis) {
    case 0: return e.positive ? P::Right : P::Left;
    case 1: return e.positive ? P::Back : P::Front;
    default: return e.positive ? P::Top : P::Bottom;
  }
}

}  // namespace corbel::editor
