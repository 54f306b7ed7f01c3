// Geometry sizing (Sec. 7.3.4). See sizing.h.
#include "growth/sizing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace corbel::growth {

namespace {

struct Score {
  double narrow = 0;  // Σ over sub-unit rectangles of how much narrower than the room width they are
  double worst = 0, squares = 0;
  bool operator<(const Score& o) const {
    if (narrow < o.narrow - 1e-12) return true;
    if (narrow > o.narrow + 1e-12) return false;
    if (worst < o.worst - 1e-12) return true;
    if (worst > o.worst + 1e-12) return false;
    return squares < o.squares - 1e-12;
  }
};

struct Box2 {
  double x0, y0, x1, y1;
};

Box2 boundsOf(const Layout& l) {
  Box2 b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const PlanRect& r : l.rects)
    b = {std::min(b.x0, r.x0), std::min(b.y0, r.y0), std::max(b.x1, r.x1), std::max(b.y1, r.y1)};
  return b;
}

double target(const Layout& l) {
  const Box2 b = boundsOf(l);
  return (b.x1 - b.x0) * (b.y1 - b.y0) / std::max(1, l.subUnits());
}

double rectError(const Layout& l, std::size_t i, double M, double m) {
  const double a = l.rects[i].area();
  return l.unit[i] >= 0 ? std::abs(a - M) / M : std::max(0.0, a - m) / M;
}

Score score(const Layout& l, double M, double m, double roomWidth) {
  Score s;
  for (std::size_t i = 0; i < l.rects.size(); ++i) {
    const double e = rectError(l, i, M, m);
    if (l.unit[i] >= 0) s.worst = std::max(s.worst, e);
    s.squares += e * e;
  }
  s.narrow = roomShortfall(l, roomWidth);
  return s;
}

// Coordinates of a rectangle along an axis: axis 0 moves x sides, 1 moves y sides.
double& lowSide(PlanRect& r, int axis) { return axis == 0 ? r.x0 : r.y0; }
double& highSide(PlanRect& r, int axis) { return axis == 0 ? r.x1 : r.y1; }
double lowAcross(const PlanRect& r, int axis) { return axis == 0 ? r.y0 : r.x0; }
double highAcross(const PlanRect& r, int axis) { return axis == 0 ? r.y1 : r.x1; }

// A maximal segment: the rectangles whose high side (before) or low side (after) lies on it.
struct Segment {
  int axis = 0;
  std::vector<std::size_t> before, after;
  double from = 0, to = 0;  // its extent across while it is being found
};

std::vector<Segment> segmentsOf(const Layout& l, const Box2& box) {
  std::vector<Segment> out;
  for (int axis = 0; axis < 2; ++axis) {
    // Sides by coordinate, then merged into connected runs along the line.
    std::map<double, std::vector<std::pair<std::size_t, bool>>> byLine;  // (rect, is its high side)
    for (std::size_t i = 0; i < l.rects.size(); ++i) {
      PlanRect r = l.rects[i];
      byLine[lowSide(r, axis)].push_back({i, false});
      byLine[highSide(r, axis)].push_back({i, true});
    }
    const double edge0 = axis == 0 ? box.x0 : box.y0, edge1 = axis == 0 ? box.x1 : box.y1;
    for (auto& [c, sides] : byLine) {
      if (c == edge0 || c == edge1) continue;
      std::sort(sides.begin(), sides.end(), [&](auto& a, auto& b) {
        return lowAcross(l.rects[a.first], axis) < lowAcross(l.rects[b.first], axis);
      });
      Segment cur;
      cur.axis = axis;
      bool open = false;
      for (const auto& [i, high] : sides) {
        const double a = lowAcross(l.rects[i], axis), b = highAcross(l.rects[i], axis);
        if (open && a > cur.to) {
          out.push_back(cur);
          cur = Segment{axis, {}, {}, 0, 0};
          open = false;
        }
        if (!open) cur.from = a, cur.to = b, open = true;
        cur.to = std::max(cur.to, b);
        (high ? cur.before : cur.after).push_back(i);
      }
      if (open) out.push_back(cur);
    }
  }
  return out;
}

// How far a segment may move: its neighbouring rectangles keep minWidth (sub-unit rectangles
// roomWidth, when larger; one already narrower may only widen), and its ends stay between the
// nearest other corners on the lines they lie on.
std::pair<double, double> range(const Layout& l, const Segment& s, double minWidth, double roomWidth = 0) {
  auto widthOf = [&](std::size_t i) { return l.unit[i] >= 0 ? std::max(minWidth, roomWidth) : minWidth; };
  PlanRect any = l.rects[s.before.empty() ? s.after[0] : s.before[0]];
  const double c = s.before.empty() ? lowSide(any, s.axis) : highSide(any, s.axis);
  // Its ends now (the segments it ends on may have moved since it was found).
  double from = INFINITY, to = -INFINITY;
  for (const auto* side : {&s.before, &s.after})
    for (std::size_t i : *side)
      from = std::min(from, lowAcross(l.rects[i], s.axis)), to = std::max(to, highAcross(l.rects[i], s.axis));
  double lo = -INFINITY, hi = INFINITY;
  for (std::size_t i : s.before) {
    PlanRect r = l.rects[i];
    lo = std::max(lo, lowSide(r, s.axis) + widthOf(i));
  }
  for (std::size_t i : s.after) {
    PlanRect r = l.rects[i];
    hi = std::min(hi, highSide(r, s.axis) - widthOf(i));
  }
  for (const PlanRect& r0 : l.rects) {
    PlanRect r = r0;
    for (double across : {lowAcross(r, s.axis), highAcross(r, s.axis)}) {
      if (across != from && across != to) continue;
      for (double along : {lowSide(r, s.axis), highSide(r, s.axis)}) {
        if (along < c) lo = std::max(lo, along + minWidth);
        if (along > c) hi = std::min(hi, along - minWidth);
      }
    }
  }
  return {lo - c, hi - c};
}

void shift(Layout& l, const Segment& s, double d) {
  for (std::size_t i : s.before) highSide(l.rects[i], s.axis) += d;
  for (std::size_t i : s.after) lowSide(l.rects[i], s.axis) += d;
}

double position(const Layout& l, const Segment& s) {
  PlanRect any = l.rects[s.before.empty() ? s.after[0] : s.before[0]];
  return s.before.empty() ? lowSide(any, s.axis) : highSide(any, s.axis);
}

// The segment of every rectangle side: side[i][2·axis + (high ? 1 : 0)], -1 on the box.
struct SegmentIndex {
  std::vector<Segment> segs;
  std::vector<std::array<int, 4>> side;
};

SegmentIndex indexSegments(const Layout& l, const Box2& box) {
  SegmentIndex ix;
  ix.segs = segmentsOf(l, box);
  ix.side.assign(l.rects.size(), {-1, -1, -1, -1});
  for (std::size_t k = 0; k < ix.segs.size(); ++k) {
    const Segment& s = ix.segs[k];
    for (std::size_t i : s.before) ix.side[i][std::size_t(2 * s.axis + 1)] = int(k);
    for (std::size_t i : s.after) ix.side[i][std::size_t(2 * s.axis)] = int(k);
  }
  return ix;
}

// Moves segment k to `want` (dir > 0: at least that far up the axis, dir < 0: at most),
// first pushing whatever is in the way as far as it needs to go.
bool pushTo(Layout& l, const SegmentIndex& ix, int k, double want, int dir, double minWidth, int depth) {
  if (k < 0 || depth > int(ix.segs.size())) return false;
  const Segment& s = ix.segs[std::size_t(k)];
  const int ax = s.axis;
  const double c = position(l, s);
  if (dir > 0 ? c >= want : c <= want) return true;
  double from = INFINITY, to = -INFINITY;
  for (const auto* side : {&s.before, &s.after})
    for (std::size_t i : *side)
      from = std::min(from, lowAcross(l.rects[i], ax)), to = std::max(to, highAcross(l.rects[i], ax));
  const double gap = dir > 0 ? minWidth : -minWidth;
  // Cascading: the far sides of the rectangles being squeezed.
  std::vector<std::pair<int, double>> ahead;  // (segment, where that side is now)
  for (std::size_t i : dir > 0 ? s.after : s.before) {
    PlanRect r = l.rects[i];
    ahead.push_back({ix.side[i][std::size_t(2 * ax + (dir > 0 ? 1 : 0))], dir > 0 ? highSide(r, ax) : lowSide(r, ax)});
  }
  // Staircase: sides with a corner ahead on the segments this one ends on.
  for (std::size_t i = 0; i < l.rects.size(); ++i) {
    PlanRect r = l.rects[i];
    if (lowAcross(r, ax) != from && lowAcross(r, ax) != to && highAcross(r, ax) != from && highAcross(r, ax) != to)
      continue;
    for (int high = 0; high < 2; ++high) {
      const double along = high ? highSide(r, ax) : lowSide(r, ax);
      if (dir > 0 ? (along > c && along < want + minWidth) : (along < c && along > want - minWidth))
        ahead.push_back({ix.side[i][std::size_t(2 * ax + high)], along});
    }
  }
  for (const auto& [k2, now] : ahead) {
    if (k2 == k || (dir > 0 ? now >= want + gap : now <= want + gap)) continue;
    if (!pushTo(l, ix, k2, want + gap, dir, minWidth, depth + 1)) return false;
  }
  const auto [lo, hi] = range(l, s, minWidth);
  const double d = want - c;
  if (d > hi + 1e-9 || d < lo - 1e-9) return false;
  shift(l, s, d);
  return true;
}

}  // namespace

bool realizeBySegments(Layout& l, const std::vector<Correspondence>& targets, double minWidth, std::string* why) {
  if (!respectsRelations(l.rects, targets, why)) return false;
  const Layout original = l;
  const SegmentIndex ix = indexSegments(l, boundsOf(l));
  for (int round = 0; round < 8; ++round) {
    bool placed = true;
    for (const Correspondence& t : targets) {
      for (int axis = 0; axis < 2; ++axis) {
        const int corner = t.corner.corner;
        const bool high = axis == 0 ? (corner == 1 || corner == 2) : (corner >= 2);
        const auto at = cornerAt(l.rects, t.corner);
        const double d = (axis == 0 ? t.x : t.y) - at[std::size_t(axis)];
        if (std::abs(d) < 1e-9) continue;
        placed = false;
        const int k = ix.side[std::size_t(t.corner.rect)][std::size_t(2 * axis + (high ? 1 : 0))];
        if (!pushTo(l, ix, k, at[std::size_t(axis)] + d, d > 0 ? 1 : -1, minWidth, 0)) {
          l = original;
          if (why) *why = k < 0 ? "a corner on the bounding box cannot move" : "the moves would reach the bounding box";
          return false;
        }
      }
    }
    if (placed) return true;
  }
  l = original;
  if (why) *why = "the targets pull the corners against each other";
  return false;
}

Layout Layout::of(const Cartogram& c) {
  Layout l;
  l.rects = c.geometry();
  for (const Cartogram::Rect& r : c.rects) l.unit.push_back(r.unit);
  return l;
}

int Layout::subUnits() const {
  return int(std::count_if(unit.begin(), unit.end(), [](int u) { return u >= 0; }));
}

double roomShortfall(const Layout& l, double roomWidth) {
  double sum = 0;
  for (std::size_t i = 0; i < l.rects.size(); ++i)
    if (l.unit[i] >= 0) sum += std::max(0.0, roomWidth - std::min(l.rects[i].x1 - l.rects[i].x0, l.rects[i].y1 - l.rects[i].y0));
  return sum;
}

double maxAreaError(const Layout& l) {
  const double M = target(l);
  double worst = 0;
  for (std::size_t i = 0; i < l.rects.size(); ++i)
    if (l.unit[i] >= 0) worst = std::max(worst, std::abs(l.rects[i].area() - M) / M);
  return worst;
}

SizingResult sizeGeometry(Layout& l, const SizingOptions& o) {
  SizingResult out;
  if (l.rects.empty()) return out;
  const Box2 box = boundsOf(l);
  const double M = target(l), m = o.seaShare * M;
  out.before = maxAreaError(l);
  const std::vector<Segment> segs = segmentsOf(l, box);  // the arrangement never changes
  out.segments = int(segs.size());
  Score now = score(l, M, m, o.roomWidth);
  double delta = 0.125 * std::min(box.x1 - box.x0, box.y1 - box.y0);
  const double stop = 1e-4 * std::max(box.x1 - box.x0, box.y1 - box.y0);
  while (out.passes < o.maxPasses && delta > stop) {
    ++out.passes;
    // Segments next to the worst rectangles first.
    std::vector<double> priority(segs.size(), 0);
    for (std::size_t k = 0; k < segs.size(); ++k)
      for (const auto* side : {&segs[k].before, &segs[k].after})
        for (std::size_t i : *side) priority[k] = std::max(priority[k], rectError(l, i, M, m));
    std::vector<std::size_t> order(segs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
    bool moved = false;
    for (std::size_t k : order) {
      const Segment& s = segs[k];
      const auto [lo, hi] = range(l, s, o.minWidth, o.roomWidth);
      double bestD = 0;
      Score best = now;
      for (double step : {delta, -delta}) {
        const double d = std::clamp(step, std::min(0.0, lo), std::max(0.0, hi));
        if (d == 0) continue;
        shift(l, s, d);
        const Score sc = score(l, M, m, o.roomWidth);
        shift(l, s, -d);
        if (sc < best) best = sc, bestD = d;
      }
      if (bestD != 0) {
        shift(l, s, bestD);
        now = best;
        moved = true;
        ++out.moves;
      }
    }
    if (!moved) delta *= 0.5;
  }
  out.after = maxAreaError(l);
  return out;
}

void fitToRegion(Cartogram& c, const PlanRect& region) {
  auto stretch = [](std::vector<double>& v, double a, double b) {
    const double v0 = v.front(), v1 = v.back();
    for (double& x : v) x = a + (b - a) * (x - v0) / (v1 - v0);
    v.front() = a;
    v.back() = b;
  };
  stretch(c.xs, region.x0, region.x1);
  stretch(c.ys, region.y0, region.y1);
}

std::vector<Unit> sizedUnits(const Layout& l, int units, double z0, double storeyHeight) {
  std::vector<Unit> out(std::size_t(std::max(0, units)));
  for (int u = 0; u < units; ++u) out[std::size_t(u)].id = u + 1;
  for (std::size_t i = 0; i < l.rects.size(); ++i) {
    const int u = l.unit[i];
    if (u < 0 || u >= units) continue;
    const PlanRect& r = l.rects[i];
    out[std::size_t(u)].parts.push_back({{r.x0, r.y0, z0}, {r.x1, r.y1, z0 + storeyHeight}});
  }
  return out;
}

}  // namespace corbel::growth
