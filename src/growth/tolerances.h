#pragma once
// The growth kernel's tolerances and fixed limits, in one place (meters unless said).
namespace corbel::growth {

// Two coordinates closer than this are the same plane: faces touch, boxes do not overlap.
inline constexpr double kEps = 1e-7;
// The shortest advance the constraint enforcer commits when an obstacle is nearer than α
// (the face then stops at the obstacle: the "lock on collision" of Sec. 5.3).
inline constexpr double kMinAdvance = 0.01;
// Sub-units (parts) are at least this wide in plan in both directions (Sec. 5.3: 3 m × 3 m).
inline constexpr double kMinPartWidth = 3.0;
// A unit may have at most this many parts (each split adds one).
inline constexpr int kMaxParts = 8;
// Face Advance distances allowed for α (Sec. 5.1: "a conservative value of 0.2 m to 0.5 m").
inline constexpr double kMinAlpha = 0.2;
inline constexpr double kMaxAlpha = 0.5;
// A unit has a view in a direction when at least this much of its faces is visible that way
// (Table 8.1's "two views" and "three views"); a sliver is not a window.
inline constexpr double kMinViewArea = 2.0;

}  // namespace corbel::growth

namespace corbel::growth {
// Outdoor space (Table 8.1): another unit's roof counts as a unit's garden when at least this
// much of it is open above and it meets the unit's floor level along a door's width.
inline constexpr double kMinGardenArea = 4.0;
inline constexpr double kMinDoorWidth = 1.0;
}  // namespace corbel::growth
