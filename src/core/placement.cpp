#include "core/placement.h"

#include <cmath>

namespace corbel {

std::pair<double, double> cosSinDegrees(double degrees) {
  const double turns = degrees / 90.0;
  if (std::isfinite(turns) && turns == std::round(turns)) {
    switch (((static_cast<long long>(std::fmod(turns, 4.0)) % 4) + 4) % 4) {
      case 0: return {1.0, 0.0};
      case 1: return {0.0, 1.0};
      case 2: return {-1.0, 0.0};
      default: return {0.0, -1.0};
    }
  }
  const double r = degrees * M_PI / 180.0;
  return {std::cos(r), std::sin(r)};
}

Vec3 Placement::applyDirection(const Vec3& d) const {
  const auto [c, s] = cosSinDegrees(rotation_deg);
  return Vec3(scale * (c * d[0] - s * d[1]), scale * (s * d[0] + c * d[1]), scale * d[2]);
}

Vec3 Placement::unapplyDirection(const Vec3& d) const {
  const auto [c, s] = cosSinDegrees(rotation_deg);
  return Vec3((c * d[0] + s * d[1]) / scale, (-s * d[0] + c * d[1]) / scale, d[2] / scale);
}

Vec3 Placement::apply(const Vec3& p) const { return translation + applyDirection(p); }
Vec3 Placement::unapply(const Vec3& p) const { return unapplyDirection(p - translation); }

void applyPlacement(MeshData& mesh, const Placement& placement) {
  if (placement.identity()) return;
  for (Vec3& p : mesh.points) p = placement.apply(p);
}

std::optional<std::string> checkPlacement(const Placement& p) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(p.translation[k]) || std::abs(p.translation[k]) > 1e7)
      return "translation: each coordinate must be finite and within 1e7 m of the origin";
  if (!std::isfinite(p.rotation_deg) || std::abs(p.rotation_deg) > 1e6) return "rotation: must be a finite angle in degrees";
  if (!(p.scale >= 1e-4 && p.scale <= 1e4)) return "scale: must be in [1e-4, 1e4]";
  return std::nullopt;
}

}  // namespace corbel
