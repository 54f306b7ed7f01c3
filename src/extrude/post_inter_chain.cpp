// The post inter-chain check (Sec. 4.4): the corners an event made must keep the active plan
// simple just above it. Where they do not, the sweep warns, or stops there for the winding
// rule (extrude/winding.h) when SweepInput::stopAtOverlap asks it to.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::extrude::sweeping {

void Sweeper::postInterChain(std::size_t firstMade, int vl, const Vec2& l, double z) {
  // Post inter-chain validation (Sec. 4.4): the corners made at l must keep the plan simple
  // just above it, below the next event. Where they do not, an earlier configuration was
  // already degenerate; the sweep says so.
  std::vector<int>& made = made_;
  made.clear();
  for (std::size_t ci = firstMade; ci < corners_.size(); ++ci)
    if (corners_[ci].alive && corners_[ci].vertex == vl) made.push_back(static_cast<int>(ci));
  if (traceOn()) {
    for (int ci : liveCorners_) {
      if (!corners_[ci].alive) continue;
      const Vec2 p = cornerAt(ci, z);
      SWEEP_TRACE("    live corner %d: edges %d -> %d at (%.9g, %.9g) v=(%g, %g)", ci, corners_[ci].prev, corners_[ci].next, p[0], p[1],
                  corners_[ci].v[0], corners_[ci].v[1]);
    }
  }
  const double next = queue_.empty() ? std::numeric_limits<double>::infinity() : queue_.top().z;
  if (next - z > 1e3 * tol_.height && !locallySimple(made, l, z, 0.25 * (next - z))) {
    SWEEP_TRACE("  post inter-chain check: the plan overlaps itself above (%g, %g, %g)", l[0], l[1], z);
    if (in_.stopAtOverlap && !stoppedAtOverlap_) {
      // Stop halfway to whatever comes next (an event, an edge direction event, the stop
      // height), where the overlap has grown but nothing else has happened yet: the stager
      // rebuilds the plan there by the winding rule and sweeps on from it.
      double upto = std::min(next, stopZ_);
      for (double d : directionHeights_)
        if (d > z + tol_.height) upto = std::min(upto, d);
      if (!std::isfinite(upto)) upto = z + 1e-3 * (tol_.cluster / 1e-8);
      stopZ_ = z + 0.5 * (upto - z);
      stoppedAtOverlap_ = true;
      SWEEP_TRACE("  stopping at %.12g for the winding rule", stopZ_);
    } else if (overlaps_++ == 0) {
      firstOverlap_ = Vec3(l[0], l[1], z);
    }
  }
}

bool Sweeper::locallySimple(const std::vector<int>& made, const Vec2& l, double z, double maxRise) const {
  if (made.size() < 2) return true;
  // Within R (half the shortest edge of the made corners) only their edges matter, and each
  // corner's neighbourhood is a wedge: its apex moves from l with the corner, its sides are
  // its two edges.
  double R = std::numeric_limits<double>::infinity(), speed = 0;
  for (int ci : made) {
    const Corner& c = corners_[ci];
    R = std::min(R, (cornerAt(edges_[c.prev].start, z) - l).norm());
    R = std::min(R, (cornerAt(edges_[c.next].end, z) - l).norm());
    speed = std::max(speed, c.speed);
  }
  R *= 0.5;
  if (!(R > 10 * tol_.cluster) || !(speed > 0)) return true;
  struct Wedge {
    Vec2 p, a, b, v;  // apex, arriving and leaving directions, apex velocity
    bool convex;
  };
  std::vector<Wedge> w;
  std::vector<double> angles;  // every side's direction from l
  for (int ci : made) {
    const Corner& c = corners_[ci];
    const Vec2 a = edges_[c.prev].d, b = edges_[c.next].d;
    // A spike sharper than about 0.1° races along its ridge: its wedge says nothing reliable.
    if (std::abs(cross2(a, b)) <= 2e-3 && OpenMesh::dot(a, b) < 0) return true;
    w.push_back({Vec2(0.0, 0.0), a, b, c.v, cross2(a, b) >= 0});
    angles.push_back(std::atan2(-a[1], -a[0]));
    angles.push_back(std::atan2(b[1], b[0]));
  }
  std::sort(angles.begin(), angles.end());
  // The apexes may spread only a small part of the narrowest sector at the sampling radius, so
  // the samples see the wedges' order around l, not the noise of where their apexes are.
  const double rho = 0.1 * R;
  double narrowest = 2 * std::numbers::pi;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double gap = (i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * std::numbers::pi) - angles[i];
    if (gap > 1e-9) narrowest = std::min(narrowest, gap);
  }
  const double h = std::min(maxRise, 1e-3 * rho * narrowest / speed);
  for (Wedge& k : w) k.p = k.v * h;  // relative to l, so tiny offsets keep their digits
  auto inside = [](const Wedge& k, const Vec2& q) {
    const double s1 = cross2(k.a, q - k.p), s2 = cross2(k.b, q - k.p);
    return k.convex ? (s1 > 0 && s2 > 0) : (s1 > 0 || s2 > 0);
  };
  auto covered = [&](const Vec2& q) {
    int n = 0;
    for (const Wedge& k : w) n += inside(k, q);
    return n;
  };
  // Far samples: between every two sides, on a circle of radius rho around l (the origin).
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double a0 = angles[i], a1 = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * std::numbers::pi;
    if (a1 - a0 <= 1e-9) continue;
    const double m = 0.5 * (a0 + a1);
    if (covered(Vec2(std::cos(m), std::sin(m)) * rho) > 1) return false;
  }
  // Near samples: just inside each apex, on its bisector (colinear sides that overlap).
  double spread = 0;
  for (const Wedge& k : w) spread = std::max(spread, k.p.norm());
  if (spread > 0)
    for (const Wedge& k : w) {
      Vec2 bis = leftOf(k.a) + leftOf(k.b);
      if (bis.norm() < 1e-9) bis = leftOf(k.a);
      bis.normalize();
      if (covered(k.p + bis * (1e-2 * spread)) > 1) return false;
    }
  return true;
}

}  // namespace corbel::extrude::sweeping
