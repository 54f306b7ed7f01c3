#include "statics/arch.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

void checkCommon(double radius, double thickness, double depth, double tiltDeg, double density, const char* what) {
  const std::string w = what;
  if (!std::isfinite(radius) || radius <= 0) throw Error(w + ": the radius must be a positive number");
  if (!std::isfinite(thickness) || thickness <= 0 || thickness >= 2 * radius)
    throw Error(w + ": the thickness must be positive and less than the diameter");
  if (!std::isfinite(depth) || depth <= 0) throw Error(w + ": the depth must be a positive number");
  if (!std::isfinite(tiltDeg) || std::abs(tiltDeg) >= 90) throw Error(w + ": the tilt must be within ±90°");
  if (!std::isfinite(density) || density <= 0) throw Error(w + ": the density must be a positive number");
}

// The arch's blocks on a fixed ground slab under its springings, gravity tilted by `tiltDeg`.
Assembly onGround(std::vector<Block> blocks, double reach, double thickness, double depth, double tiltDeg) {
  Assembly as;
  as.blocks = std::move(blocks);
  as.blocks.push_back(boxBlock("ground", Vec3(-reach, -depth, -thickness), Vec3(reach, depth, 0.0), 1.0, true));
  const double tilt = tiltDeg * std::numbers::pi / 180.0;
  as.gravity = Vec3(std::sin(tilt), 0.0, -std::cos(tilt));
  return as;
}

}  // namespace

std::vector<Block> voussoirs(const std::vector<ArchJoint>& joints, double y0, double y1, double density) {
  std::vector<Block> out;
  for (std::size_t i = 0; i + 1 < joints.size(); ++i) {
    const ArchJoint &j = joints[i], &k = joints[i + 1];
    const std::vector<Vec3> base = {Vec3(j.inner[0], y0, j.inner[1]), Vec3(j.outer[0], y0, j.outer[1]),
                                    Vec3(k.outer[0], y0, k.outer[1]), Vec3(k.inner[0], y0, k.inner[1])};
    out.push_back(prismBlock("voussoir " + std::to_string(i), base, Vec3(0.0, y1 - y0, 0.0), density));
  }
  return out;
}

void validateArchSpec(const ArchSpec& spec) {
  if (spec.blocks < 1 || spec.blocks > 100000) throw Error("arch: the number of voussoirs must be in 1..100000");
  checkCommon(spec.radius, spec.thickness, spec.depth, spec.tiltDeg, spec.density, "arch");
}

std::vector<ArchJoint> semicircularJoints(const ArchSpec& spec) {
  validateArchSpec(spec);
  const int n = spec.blocks;
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2;
  std::vector<ArchJoint> joints(std::size_t(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double th = std::numbers::pi * k / n;
    // Exact at the springings, so the end faces lie on z = 0.
    const double cs = k == 0 ? 1.0 : k == n ? -1.0 : std::cos(th);
    const double sn = (k == 0 || k == n) ? 0.0 : std::sin(th);
    joints[std::size_t(k)] = {Vec2(ri * cs, ri * sn), Vec2(ro * cs, ro * sn)};
  }
  return joints;
}

std::vector<Block> semicircularArchBlocks(const ArchSpec& spec) {
  return voussoirs(semicircularJoints(spec), -spec.depth / 2, spec.depth / 2, spec.density);
}

Assembly semicircularArch(const ArchSpec& spec) {
  std::vector<Block> blocks = semicircularArchBlocks(spec);
  return onGround(std::move(blocks), spec.radius + 1.5 * spec.thickness, spec.thickness, spec.depth, spec.tiltDeg);
}

std::vector<ArchJoint> pointedJoints(const PointedArchSpec& spec) {
  if (spec.blocks < 2 || spec.blocks % 2 || spec.blocks > 100000)
    throw Error("pointed arch: the number of voussoirs must be even, in 2..100000");
  if (!std::isfinite(spec.radiusRatio) || spec.radiusRatio < 1 || spec.radiusRatio > 100)
    throw Error("pointed arch: the radius ratio must be in [1, 100]");
  checkCommon(spec.radius, spec.thickness, spec.depth, spec.tiltDeg, spec.density, "pointed arch");
  const int m = spec.blocks / 2;
  const double rho = spec.radiusRatio * spec.radius, d = rho - spec.radius;
  const double ri = rho - spec.thickness / 2, ro = rho + spec.thickness / 2;
  // The right half, centre (−d, 0): radial joints from the springing (angle 0) towards the
  // crown, spread up to the angle where the intrados meets x = 0 (the centreline and extrados
  // meet it at larger angles), so no joint crosses the crown plane.
  const double apex = std::acos(d / ri);
  std::vector<ArchJoint> right(std::size_t(m) + 1);
  for (int k = 0; k < m; ++k) {
    const double phi = apex * k / m;
    const double cs = k == 0 ? 1.0 : std::cos(phi), sn = k == 0 ? 0.0 : std::sin(phi);
    right[std::size_t(k)] = {Vec2(-d + ri * cs, ri * sn), Vec2(-d + ro * cs, ro * sn)};
  }
  right[std::size_t(m)] = {Vec2(0.0, std::sqrt(ri * ri - d * d)), Vec2(0.0, std::sqrt(ro * ro - d * d))};
  // From the left springing to the right one.
  std::vector<ArchJoint> joints;
  for (int k = 0; k < m; ++k) {
    const ArchJoint& j = right[std::size_t(k)];
    joints.push_back({Vec2(-j.inner[0], j.inner[1]), Vec2(-j.outer[0], j.outer[1])});
  }
  for (int k = m; k >= 0; --k) joints.push_back(right[std::size_t(k)]);
  return joints;
}

std::vector<Block> pointedArchBlocks(const PointedArchSpec& spec) {
  return voussoirs(pointedJoints(spec), -spec.depth / 2, spec.depth / 2, spec.density);
}

Assembly pointedArch(const PointedArchSpec& spec) {
  std::vector<Block> blocks = pointedArchBlocks(spec);
  return onGround(std::move(blocks), spec.radius + 1.5 * spec.thickness, spec.thickness, spec.depth, spec.tiltDeg);
}

namespace {

// The unscaled centreline and its derivative at parameter u.
Vec2 bezierPoint(const BezierArchSpec& s, double u) {
  const Vec2 p0(-s.radius, 0.0), p1(s.x1, 1.0), p2(s.x2, 1.0), p3(s.radius, 0.0);
  const double v = 1 - u;
  return p0 * (v * v * v) + p1 * (3 * v * v * u) + p2 * (3 * v * u * u) + p3 * (u * u * u);
}
Vec2 bezierTangent(const BezierArchSpec& s, double u) {
  const Vec2 p0(-s.radius, 0.0), p1(s.x1, 1.0), p2(s.x2, 1.0), p3(s.radius, 0.0);
  const double v = 1 - u;
  return (p1 - p0) * (3 * v * v) + (p2 - p1) * (6 * v * u) + (p3 - p2) * (3 * u * u);
}

}  // namespace

std::vector<ArchJoint> bezierJoints(const BezierArchSpec& spec) {
  if (spec.blocks < 2 || spec.blocks > 100000) throw Error("Bezier arch: the number of voussoirs must be in 2..100000");
  checkCommon(spec.radius, spec.thickness, spec.depth, 0.0, spec.density, "Bezier arch");
  if (!std::isfinite(spec.height) || spec.height <= 0) throw Error("Bezier arch: the height must be a positive number");
  if (!std::isfinite(spec.x1) || !std::isfinite(spec.x2)) throw Error("Bezier arch: the control points must be finite");
  // Height scale: the unscaled curve's highest point (the control points are at z = 1, the
  // curve peaks at most 3/4 there), found on a fine sampling.
  double top = 0;
  for (int i = 0; i <= 2000; ++i) top = std::max(top, bezierPoint(spec, i / 2000.0)[1]);
  const double scale = spec.height / top;
  const int n = spec.blocks;
  std::vector<ArchJoint> joints(std::size_t(n) + 1);
  const double h = spec.thickness / 2;
  joints[0] = {Vec2(-spec.radius + h, 0.0), Vec2(-spec.radius - h, 0.0)};
  joints[std::size_t(n)] = {Vec2(spec.radius - h, 0.0), Vec2(spec.radius + h, 0.0)};
  for (int k = 1; k < n; ++k) {
    const double u = double(k) / n;
    Vec2 c = bezierPoint(spec, u), t = bezierTangent(spec, u);
    c[1] *= scale;
    t[1] *= scale;
    Vec2 inward(t[1], -t[0]);  // the tangent turned clockwise: towards the intrados
    inward /= inward.norm();
    joints[std::size_t(k)] = {c + inward * h, c - inward * h};
  }
  return joints;
}

std::vector<Block> bezierArchBlocks(const BezierArchSpec& spec) {
  return voussoirs(bezierJoints(spec), -spec.depth / 2, spec.depth / 2, spec.density);
}

Assembly bezierArch(const BezierArchSpec& spec) {
  return onGround(bezierArchBlocks(spec), spec.radius + 1.5 * spec.thickness, spec.thickness, spec.depth, 0.0);
}

}  // namespace corbel::statics
