#pragma once
// Axis-aligned boxes and plan rectangles: the vocabulary of units, cores and circulation.
// corbel is Z up, so the paper's horizontal axes x and z (it is Y up) are our x and y.
#include "core/geometry.h"

#include <array>
#include <string_view>
#include <vector>

namespace corbel::growth {

// A closed axis-aligned box lo ≤ hi (meters).
struct Box {
  Vec3 lo{0.0};
  Vec3 hi{0.0};
  double size(int axis) const { return hi[axis] - lo[axis]; }
  double volume() const { return size(0) * size(1) * size(2); }
  double footprintArea() const { return size(0) * size(1); }
  bool operator==(const Box&) const = default;
};

// A rectangle in some plane: [u0, u1] × [v0, v1] (may be degenerate: a segment).
struct Rect {
  double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
  double area() const { return (u1 - u0) * (v1 - v0); }
  bool operator==(const Rect&) const = default;
};

// The six sides of a box, named by their outward normal.
enum class Side { NegX = 0, PosX = 1, NegY = 2, PosY = 3, Bottom = 4, Top = 5 };
inline constexpr std::array<Side, 6> kAllSides{Side::NegX, Side::PosX, Side::NegY, Side::PosY, Side::Bottom, Side::Top};
inline constexpr std::array<Side, 4> kVerticalSides{Side::NegX, Side::PosX, Side::NegY, Side::PosY};
inline int sideAxis(Side s) { return static_cast<int>(s) / 2; }
inline double sideSign(Side s) { return static_cast<int>(s) % 2 ? 1.0 : -1.0; }
inline Side sideOf(int axis, bool positive) { return static_cast<Side>(axis * 2 + (positive ? 1 : 0)); }
inline Side opposite(Side s) { return static_cast<Side>(static_cast<int>(s) ^ 1); }
std::string_view sideName(Side s);  // "-x", "+x", "-y", "+y", "bottom", "top"
bool sideFromName(std::string_view name, Side& out);

// The coordinate of side s of b along its axis.
inline double sideCoord(const Box& b, Side s) { return sideSign(s) > 0 ? b.hi[sideAxis(s)] : b.lo[sideAxis(s)]; }

// Length of [a0, a1] ∩ [b0, b1] (0 when they are disjoint or touch).
inline double overlapLength(double a0, double a1, double b0, double b1) {
  const double d = std::min(a1, b1) - std::max(a0, b0);
  return d > 0 ? d : 0.0;
}
// Interiors meet (every axis overlaps by more than `eps`).
bool interiorsOverlap(const Box& a, const Box& b, double eps);
// The region Advance adds when side s of b moves out by d.
Box sweptRegion(const Box& b, Side s, double d);
// b grown by g in x and y (not z).
Box grownInPlan(const Box& b, double g);
Rect footprint(const Box& b);
Rect grown(const Rect& r, double g);
// Intersection; nullopt-like: returns false when the rectangles do not meet (touching counts
// as meeting, giving a degenerate rectangle, when `closed`).
bool intersect(const Rect& a, const Rect& b, bool closed, Rect& out);
// from − r, as disjoint rectangles (each of positive area).
std::vector<Rect> subtract(const std::vector<Rect>& from, const Rect& r);
double totalArea(const std::vector<Rect>& rects);
// L∞ distance between two plan rectangles (0 when they meet).
double planGap(const Rect& a, const Rect& b);

}  // namespace corbel::growth
