#pragma once
// The staged extrusion's state (Sec. 4.5.2, 4.6, 4.7), shared by the files that implement it;
// private to src/extrude. stages.cpp runs the stages; docs/extrude.md maps the paper's steps to
// the files.
#include "extrude/extrude.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace corbel::extrude::staging {


using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EPolygon = CGAL::Polygon_2<EK>;
using EPolygonH = CGAL::Polygon_with_holes_2<EK>;
using EPolygonSet = CGAL::Polygon_set_2<EK>;

inline double segmentAngle(const Vec2& a, const Vec2& b) { return std::atan2(b[0] - a[0], b[1] - a[1]); }
inline Vec2 leftOf(const Vec2& d) { return Vec2(-d[1], d[0]); }

// An edge of the active plan at a seam, leaving `start`.
struct Active {
  Vec2 start;
  int vertex = -1;  // its shell vertex at the seam (-1: not made yet)
  int profile = 0;
  double z0 = 0;    // the absolute height of the profile's first point
  int sourceLoop = -1, sourceEdge = -1, step = -1;
};
using Plan = std::vector<std::vector<Active>>;

// Appends a corner to a loop being built at a seam, dropping the edge before it where the two
// welded into one vertex (a zero-length edge).
inline void pushCorner(std::vector<Active>& loop, const Active& a) {
  if (!loop.empty() && loop.back().vertex == a.vertex) loop.pop_back();
  loop.push_back(a);
}

// Drops the closing edge of such a loop while it has no length; true where a loop is left.
inline bool closeLoop(std::vector<Active>& loop) {
  while (loop.size() > 1 && loop.back().vertex == loop.front().vertex) loop.pop_back();
  return loop.size() >= 3;
}

// A profile segment in absolute heights.
struct Seg {
  double lo, hi;  // hi = +inf for the last one
  double angle;   // θ; for horizontal segments ±π/2
  double dw;      // horizontal segments: the inward move
  bool horizontal;
  int index;
};

// A profile segment before it is placed on an edge (Stager::segs adds the edge's z0): what
// does not depend on the edge, worked out once per profile instead of at every look.
struct SegShape {
  double qz, rz, z0;  // the segment's ends' heights and the profile's first point's
  bool last;
  double angle, dw;
  bool horizontal;
  int index;
};

// The segments of one edge's profile, placed at its z0, as a range of Seg values.
class SegRange {
 public:
  SegRange(const std::vector<SegShape>& shapes, double z0) : shapes_(&shapes), z0_(z0) {}
  class Iterator {
   public:
    Iterator(const SegShape* s, double z0) : s_(s), z0_(z0) {}
    Seg operator*() const {
      Seg g;
      g.lo = z0_ + s_->qz - s_->z0;
      g.hi = s_->last ? std::numeric_limits<double>::infinity() : z0_ + s_->rz - s_->z0;
      g.horizontal = s_->horizontal;
      g.dw = s_->dw;
      g.angle = s_->angle;
      g.index = s_->index;
      return g;
    }
    Iterator& operator++() {
      ++s_;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return s_ != o.s_; }

   private:
    const SegShape* s_;
    double z0_;
  };
  Iterator begin() const { return {shapes_->data(), z0_}; }
  Iterator end() const { return {shapes_->data() + shapes_->size(), z0_}; }

 private:
  const std::vector<SegShape>* shapes_;
  double z0_;
};

struct Located {
  int loop = -1, index = -1;
  double t = 0;  // metres from the edge's start
  double length = 0;
  Vec2 at, d;
};

// An edge of the plan in a change at one height (Stager::change): what it will be in the new
// plan and its move over the recursive extrusion's unit height (Sec. 4.5.2).
struct EdgeMove {
  Active a;
  double k = 0;
  int segment = -1;  // its first horizontal profile segment there
};
using EdgeMoves = std::vector<std::vector<EdgeMove>>;

// A natural step at its anchor's height, located on the active plan (Sec. 4.7).
struct PlacedStep {
  std::size_t si;  // index into spec.steps
  Located at;
};

// A natural step's λ-sized protrusion: a flat face of the seam.
struct Protrusion {
  std::vector<int> loop;
  ShellFace info;
  bool up;
};

class Stager {
 public:
  Stager(const ExtrusionSpec& spec, const Tolerances& tol, Progress* progress, double timeLimit, bool windingRule,
         std::chrono::steady_clock::time_point started)
      : spec_(spec), tol_(tol), progress_(progress), timeLimit_(timeLimit), windingRule_(windingRule), started_(started) {
    shapes_.resize(spec_.profiles.size());
    for (std::size_t k = 0; k < spec_.profiles.size(); ++k) {
      const auto& pts = spec_.profiles[k].points;
      for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
        const Vec2 &q = pts[s], &r = pts[s + 1];
        SegShape g;
        g.qz = q[1];
        g.rz = r[1];
        g.z0 = pts[0][1];
        g.last = s + 2 == pts.size();
        g.horizontal = r[1] == q[1];
        g.dw = g.horizontal ? r[0] - q[0] : 0.0;
        g.angle = g.horizontal ? std::copysign(std::numbers::pi / 2, g.dw) : segmentAngle(q, r);
        g.index = static_cast<int>(s);
        shapes_[k].push_back(g);
      }
    }
  }

  ExtrusionResult run(double scale);

 private:
  SegRange segs(const Active& a) const { return {shapes_[a.profile], a.z0}; }
  std::vector<std::vector<SegShape>> shapes_;  // per profile of the spec
  // Sec. 4.8's priority of the segment g of a's profile (higher wins a colinear merge).
  double priorityOf(const Active& a, const Seg& g) const;
  SweepEdge sweepEdge(const Active& a, double za) const;
  double remaining() const;

  int weld(const Vec2& p, double seam);
  int point(const Vec3& p);
  void addFace(RawFace f);
  void addFlatFace(std::vector<int> loop, bool up, const ShellFace& info);

  // Sweeps from z towards `next`; `reached` says how far it got (below `next` where the plan
  // overlapped itself and is to be rebuilt by the winding rule there).
  Plan runStage(const Plan& plan, double z, double next, bool first, double& reached);
  Plan windingRebuild(const Plan& plan, double h);
  // Runs one sweep (a stage or a recursive extrusion) under the remaining time, keeping its
  // faces raw; its events, divergence and warnings (with `context` appended) join the shell's.
  SweepOutput runSweep(SweepInput& in, const std::string& context);
  // Both take the plan by value and hand it back as it was where nothing happens at h.
  Plan change(Plan plan, double h, bool atBase);
  // change()'s steps (recursive_extrusion.cpp, natural_steps.cpp).
  bool changesAt(const Plan& plan, double h) const;
  EdgeMoves nearHorizontalMoves(const Plan& plan, double h, bool& any) const;
  std::vector<PlacedStep> placeNaturalSteps(const Plan& plan, double h);
  bool growNaturalSteps(EdgeMoves& loops, const std::vector<PlacedStep>& placed, double h, bool atBase,
                        std::vector<Protrusion>& tiny);
  SweepInput temporaryPlan(const EdgeMoves& loops, std::vector<const EdgeMove*>& flat) const;
  void projectOntoActivePlan(const EdgeMoves& loops, const SweepInput& in, SweepOutput& out, std::vector<int>& map,
                             double h);
  Plan replaceActivePlan(const SweepOutput& out, const std::vector<const EdgeMove*>& flat, const std::vector<int>& map,
                         bool atBase) const;
  Plan offset(const Plan& plan, double h, const OffsetEvent& ev, std::size_t index);
  Plan forcedSteps(Plan plan, double h, bool atBase);
  // plan_regions.cpp: the plan after a Boolean change, and a flat face over an exact region.
  Plan rebuild(const Plan& old, const EPolygonSet& next, double h, const std::function<Active(const Vec2&)>& other,
              bool atBase = false);
  void addFlatRegion(const EPolygonH& region, double h, bool up, const ShellFace& info);
  bool addFoldedFlats(const SweepInput& in, const SweepOutput& out, const std::vector<int>& map, double h);
  std::optional<Located> locate(const Plan& plan, const Anchor& a) const;
  void frame(const Plan& plan, double h);
  void fixTJunctions();

  const ExtrusionSpec& spec_;
  const Tolerances& tol_;
  Progress* progress_;
  double timeLimit_;
  bool windingRule_;  // ExtrudeOptions::windingRule
  std::chrono::steady_clock::time_point started_;

  std::vector<Vec3> points_;
  // Seam height → its vertices, bucketed on a grid of cell δ2 for welding.
  std::map<double, std::unordered_map<std::uint64_t, std::vector<int>>> seams_;
  bool diverged_ = false;  // a stage ran away: its shell is suspect, skip the edge splitting
  std::vector<RawFace> faces_;
  std::multimap<std::tuple<int, int, int, int, int>, int> byKey_;
  std::vector<std::string> warnings_;
  std::vector<AnchorFrame> frames_;
  std::vector<char> stepDone_;
  std::size_t events_ = 0;
  int repairs_ = 0;  // winding-rule rebuilds so far
};

// Exact regions of the plan (plan_regions.cpp).
EPolygon toPolygon(const std::vector<Vec2>& pts);  // counter-clockwise where simple
Vec2 toVec(const EK::Point_2& p);
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);
EPolygonSet planSet(const Plan& plan);  // the region the plan's simple loops bound

}  // namespace corbel::extrude::staging
