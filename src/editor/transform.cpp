#include "editor/transform.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace corbel::editor {

namespace {
double snapTo(double v, double step) { return std::round(v / step) * step; }

// Where the ray meets the plane through `p` with normal `n`, if it does in front.
std::optional<Vec3> hitPlane(const Ray& r, const Vec3& p, const Vec3& n) {
  const double den = OpenMesh::dot(r.direction, n);
  if (std::abs(den) < 1e-9) return std::nullopt;
  const double t = OpenMesh::dot(p - r.origin, n) / den;
  if (t <= 0) return std::nullopt;
  return r.origin + t * r.direction;
}
}  // namespace

void Transform::begin(Mode mode, const std::map<ObjectId, Placement>& objects, const Vec3& pivot, const Ray& ray) {
  mode_ = objects.empty() ? Mode::None : mode;
  axis_ = Axis::Free;
  start_ = objects;
  pivot_ = pivot;
  startRay_ = ray_ = ray;
  viewDir_ = ray.direction;
  typed_.clear();
  movingFaces_.clear();
  targets_.reset();
  faceTolerance_ = 0;
  faceSnapOn_ = true;
}

void Transform::setFaceSnap(std::vector<AxisFace> moving, std::shared_ptr<const FaceSnapTargets> targets, double tolerance) {
  movingFaces_ = std::move(moving);
  targets_ = std::move(targets);
  faceTolerance_ = tolerance;
}

FaceSnap Transform::faceSnap() const {
  if (mode_ != Mode::Move || !faceSnapOn_ || snap_ || !targets_ || typed_.value()) return {};
  std::array<bool, 3> free{};
  switch (axis_) {
    case Axis::X: free = {true, false, false}; break;
    case Axis::Y: free = {false, true, false}; break;
    case Axis::Z: free = {false, false, true}; break;
    case Axis::Free: free = {true, true, false}; break;
    case Axis::XZ: free = {true, false, true}; break;
    case Axis::YZ: free = {false, true, true}; break;
  }
  return snapFaces(movingFaces_, *targets_, pointerOffset(), free, faceTolerance_);
}

void Transform::pointer(const Ray& ray) { ray_ = ray; }

void Transform::setAxis(Axis axis) {
  if (mode_ == Mode::Rotate) return;  // turns are about z
  axis_ = axis_ == axis ? Axis::Free : axis;
}

// Moves along z happen on the vertical plane through the pivot that faces the camera, moves on
// an upright plane (XZ, YZ) on that plane; every other move on the horizontal plane through the
// pivot, as a building is moved on the ground.
std::optional<Vec3> Transform::planeHit(const Ray& r) const {
  if (mode_ == Mode::Move && axis_ == Axis::Z) {
    Vec3 n(viewDir_[0], viewDir_[1], 0);
    if (n.norm() < 1e-9) n = Vec3(1, 0, 0);
    return hitPlane(r, pivot_, n.normalized());
  }
  if (mode_ == Mode::Move && axis_ == Axis::XZ) return hitPlane(r, pivot_, Vec3(0, 1, 0));
  if (mode_ == Mode::Move && axis_ == Axis::YZ) return hitPlane(r, pivot_, Vec3(1, 0, 0));
  return hitPlane(r, pivot_, Vec3(0, 0, 1));
}

Vec3 Transform::offset() const {
  if (mode_ != Mode::Move) return Vec3(0, 0, 0);
  return pointerOffset() + faceSnap().delta;
}

Vec3 Transform::pointerOffset() const {
  if (mode_ != Mode::Move) return Vec3(0, 0, 0);
  const auto a = planeHit(startRay_), b = planeHit(ray_);
  Vec3 d = a && b ? *b - *a : Vec3(0, 0, 0);
  switch (axis_) {
    case Axis::X: d = Vec3(d[0], 0, 0); break;
    case Axis::Y: d = Vec3(0, d[1], 0); break;
    case Axis::Z: d = Vec3(0, 0, d[2]); break;
    case Axis::Free: d[2] = 0; break;
    case Axis::XZ: d[1] = 0; break;
    case Axis::YZ: d[0] = 0; break;
  }
  if (const std::optional<double> typed = typed_.value()) {
    const double v = *typed;
    // Along the constrained axis; free, along the way the pointer went (x when it has not moved).
    switch (axis_) {
      case Axis::X: return Vec3(v, 0, 0);
      case Axis::Y: return Vec3(0, v, 0);
      case Axis::Z: return Vec3(0, 0, v);
      case Axis::Free:
      case Axis::XZ: return d.norm() > 1e-9 ? d.normalized() * v : Vec3(v, 0, 0);
      case Axis::YZ: return d.norm() > 1e-9 ? d.normalized() * v : Vec3(0, v, 0);
    }
  }
  if (snap_)
    for (int k = 0; k < 3; ++k) d[k] = snapTo(d[k], kMoveSnap);
  return d;
}

double Transform::angle() const {
  if (mode_ != Mode::Rotate) return 0;
  if (const std::optional<double> typed = typed_.value()) return *typed;
  const auto a = planeHit(startRay_), b = planeHit(ray_);
  if (!a || !b) return 0;
  const Vec3 u = *a - pivot_, v = *b - pivot_;
  if (std::hypot(u[0], u[1]) < 1e-9 || std::hypot(v[0], v[1]) < 1e-9) return 0;
  double deg = (std::atan2(v[1], v[0]) - std::atan2(u[1], u[0])) * 180.0 / M_PI;
  if (deg > 180) deg -= 360;
  if (deg < -180) deg += 360;
  return snap_ ? snapTo(deg, kRotateSnap) : deg;
}

std::map<ObjectId, Placement> Transform::placements() const {
  std::map<ObjectId, Placement> out = start_;
  if (mode_ == Mode::Move) {
    const Vec3 d = offset();
    for (auto& [id, p] : out) p.translation += d;
  } else if (mode_ == Mode::Rotate) {
    // Each object turns about the pivot: its translation goes round it, its rotation grows.
    Placement turn;
    turn.rotation_deg = angle();
    for (auto& [id, p] : out) {
      p.translation = pivot_ + turn.applyDirection(p.translation - pivot_);
      p.rotation_deg += turn.rotation_deg;
    }
  }
  return out;
}

std::string Transform::describe() const {
  char buf[160];
  const char* axis = axis_ == Axis::X    ? " X"
                     : axis_ == Axis::Y  ? " Y"
                     : axis_ == Axis::Z  ? " Z"
                     : axis_ == Axis::XZ ? " on XZ"
                     : axis_ == Axis::YZ ? " on YZ"
                                         : "";
  const std::string typed = typed_.text().empty() ? "" : " (typed " + typed_.text() + ")";
  if (mode_ == Mode::Move) {
    const Vec3 d = offset();
    std::snprintf(buf, sizeof buf, "Move%s: %.3f, %.3f, %.3f m", axis, d[0], d[1], d[2]);
    if (const FaceSnap f = faceSnap(); f.any()) {
      std::string on = " (face on face:";
      for (int k = 0; k < 3; ++k)
        if (f.onto[k]) on += std::string(" ") + "xyz"[k];
      return buf + on + ")" + typed + "  — Alt moves freely, X/Y/Z axis, type a value, Ctrl snaps to the grid, Enter or click to confirm, Esc cancels";
    }
  } else if (mode_ == Mode::Rotate) {
    std::snprintf(buf, sizeof buf, "Rotate about z: %.2f°", angle());
  } else {
    return {};
  }
  return buf + typed + "  — X/Y/Z axis, type a value, Ctrl snaps, Enter or click to confirm, Esc cancels";
}

}  // namespace corbel::editor
