#pragma once
// Named numerical constants of the KIFS kernel (docs/kifs.md, "Tolerances").
namespace corbel::kifs {

// Curvilinear coordinates stretch by s_θ / radius; the radius used in that bound never drops
// below this (building units), so the bound stays finite on the axis.
inline constexpr double kMinRadius = 1e-6;
// Smallest hit threshold (world units), so a ray starting at the eye still moves.
inline constexpr double kMinHitDistance = 1e-7;
// The ray-bounds box is grown by this fraction of its diagonal, so hits on the outer shell
// itself are inside the marched interval.
inline constexpr double kBoundsMargin = 1e-3;

}  // namespace corbel::kifs
