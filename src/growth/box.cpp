#include "growth/box.h"

#include <algorithm>

namespace corbel::growth {

std::string_view sideName(Side s) {
  static constexpr std::array<std::string_view, 6> names{"-x", "+x", "-y", "+y", "bottom", "top"};
  return names[static_cast<int>(s)];
}

bool sideFromName(std::string_view name, Side& out) {
  for (Side s : kAllSides)
    if (sideName(s) == name) {
      out = s;
      return true;
    }
  return false;
}

bool interiorsOverlap(const Box& a, const Box& b, double eps) {
  for (int k = 0; k < 3; ++k)
    if (overlapLength(a.lo[k], a.hi[k], b.lo[k], b.hi[k]) <= eps) return false;
  return true;
}

Box sweptRegion(const Box& b, Side s, double d) {
  Box r = b;
  const int k = sideAxis(s);
  if (sideSign(s) > 0) {
    r.lo[k] = b.hi[k];
    r.hi[k] = b.hi[k] + d;
  } else {
    r.hi[k] = b.lo[k];
    r.lo[k] = b.lo[k] - d;
  }
  return r;
}

Box grownInPlan(const Box& b, double g) {
  Box r = b;
  for (int k = 0; k < 2; ++k) {
    r.lo[k] -= g;
    r.hi[k] += g;
  }
  return r;
}

Rect footprint(const Box& b) { return {b.lo[0], b.lo[1], b.hi[0], b.hi[1]}; }
Rect grown(const Rect& r, double g) { return {r.u0 - g, r.v0 - g, r.u1 + g, r.v1 + g}; }

bool intersect(const Rect& a, const Rect& b, bool closed, Rect& out) {
  out = {std::max(a.u0, b.u0), std::max(a.v0, b.v0), std::min(a.u1, b.u1), std::min(a.v1, b.v1)};
  return closed ? (out.u0 <= out.u1 && out.v0 <= out.v1) : (out.u0 < out.u1 && out.v0 < out.v1);
}

std::vector<Rect> subtract(const std::vector<Rect>& from, const Rect& r) {
  std::vector<Rect> out;
  out.reserve(from.size() + 4);
  for (const Rect& a : from) {
    Rect c;
    if (!intersect(a, r, false, c)) {
      out.push_back(a);
      continue;
    }
    // Up to four pieces around the cut-out c: below, above (full width), left, right.
    if (c.v0 > a.v0) out.push_back({a.u0, a.v0, a.u1, c.v0});
    if (c.v1 < a.v1) out.push_back({a.u0, c.v1, a.u1, a.v1});
    if (c.u0 > a.u0) out.push_back({a.u0, c.v0, c.u0, c.v1});
    if (c.u1 < a.u1) out.push_back({c.u1, c.v0, a.u1, c.v1});
  }
  return out;
}

double totalArea(const std::vector<Rect>& rects) {
  double s = 0;
  for (const Rect& r : rects) s += r.area();
  return s;
}

double planGap(const Rect& a, const Rect& b) {
  const double gu = std::max({0.0, a.u0 - b.u1, b.u0 - a.u1});
  const double gv = std::max({0.0, a.v0 - b.v1, b.v0 - a.v1});
  return std::max(gu, gv);
}

}  // namespace corbel::growth
