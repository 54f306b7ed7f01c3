// Staged extrusion. The sweep (sweep.cpp) runs between the heights where the active plan
// changes discretely: horizontal profile segments (near-horizontal edge direction events,
// Sec. 4.5.2), plan steps (natural steps, Sec. 4.7) and offset events (Sec. 4.6); mesh
// anchors (Sec. 3.4) read the plan at their height without stopping the sweep. Each change
// is a recursive extrusion of the active plan for one unit of height in which only the
// changing edges move (Fig. 16, 20): its plan at the top replaces the active plan, and its
// faces, flattened onto the sweep plane, are the horizontal faces at that height — ledges
// facing up where an edge moved inward, soffits facing down where it moved outward.
//
// The pieces of the shell meet along the seams between stages. Vertices at a seam are welded
// by position, every boundary piece at a seam is split at the seam's vertices that lie on it
// (no T-junctions), and the faces of one edge and profile segment that continue across a
// seam in one plane are joined into one face.
#include "core/error.h"
#include "extrude/extrude.h"
#include "extrude/walls.h"
#include "extrude/winding.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <cstdint>
#include <tuple>
#include <unordered_map>

namespace corbel::extrude {

namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EPolygon = CGAL::Polygon_2<EK>;
using EPolygonH = CGAL::Polygon_with_holes_2<EK>;
using EPolygonSet = CGAL::Polygon_set_2<EK>;

double segmentAngle(const Vec2& a, const Vec2& b) { return std::atan2(b[0] - a[0], b[1] - a[1]); }
Vec2 leftOf(const Vec2& d) { return Vec2(-d[1], d[0]); }

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
void pushCorner(std::vector<Active>& loop, const Active& a) {
  if (!loop.empty() && loop.back().vertex == a.vertex) loop.pop_back();
  loop.push_back(a);
}

// Drops the closing edge of such a loop while it has no length; true where a loop is left.
bool closeLoop(std::vector<Active>& loop) {
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
  Plan offset(const Plan& plan, double h, const OffsetEvent& ev, std::size_t index);
  Plan forcedSteps(Plan plan, double h, bool atBase);
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

// A plan that keeps overlapping itself after this many winding-rule rebuilds is swept on with
// the post inter-chain warning instead (each rebuild costs a stage; real plans need none).
constexpr int kMaxRepairs = 16;

double Stager::priorityOf(const Active& a, const Seg& g) const {
  switch (spec_.priority) {
    case Priority::MinimiseVolume: return g.angle;
    case Priority::Manual: {
      const std::vector<std::string>& tags = spec_.profiles[a.profile].tags;
      const std::string& tag = static_cast<std::size_t>(g.index) < tags.size() ? tags[g.index] : std::string();
      const double rank = tag == "high" ? 1.0 : tag == "low" ? -1.0 : 0.0;
      return 10.0 * rank - g.angle;
    }
    case Priority::MaximiseVolume: break;
  }
  return -g.angle;  // Sec. 4.8: the lowest angle wins by default
}

SweepEdge Stager::sweepEdge(const Active& a, double za) const {
  SweepEdge e;
  e.start = a.start;
  e.sourceLoop = a.sourceLoop;
  e.sourceEdge = a.sourceEdge;
  e.profile = a.profile;
  e.step = a.step;
  e.steps.reserve(shapes_[a.profile].size());
  for (const Seg& g : segs(a)) {
    if (g.horizontal || g.hi <= za + tol_.height) continue;
    e.steps.push_back({std::max(g.lo, za), g.angle, g.index, priorityOf(a, g)});
  }
  if (e.steps.empty()) e.steps.push_back({za, 0.0, -1, 0.0});  // cannot happen for checked profiles
  e.steps.front().z = za;
  return e;
}

double Stager::remaining() const {
  if (timeLimit_ <= 0) return 0.0;
  const double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  if (used >= timeLimit_)
    throw Error("the extrusion took longer than its time limit of " + std::to_string(timeLimit_) + " s");
  return timeLimit_ - used;
}

int Stager::point(const Vec3& p) {
  points_.push_back(p);
  return static_cast<int>(points_.size()) - 1;
}

int Stager::weld(const Vec2& p, double seam) {
  auto& grid = seams_[seam];
  const double cell = tol_.cluster;
  const auto ix = static_cast<std::int64_t>(std::floor(p[0] / cell)), iy = static_cast<std::int64_t>(std::floor(p[1] / cell));
  auto key = [](std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^ static_cast<std::uint64_t>(y);
  };
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      auto it = grid.find(key(ix + dx, iy + dy));
      if (it == grid.end()) continue;
      for (int v : it->second)
        if (std::abs(points_[v][0] - p[0]) <= tol_.cluster && std::abs(points_[v][1] - p[1]) <= tol_.cluster) return v;
    }
  const int v = point(Vec3(p[0], p[1], seam));
  grid[key(ix, iy)].push_back(v);
  return v;
}

// Faces of one edge and profile segment in one plane are one face, whichever stage made them.
void Stager::addFace(RawFace f) {
  if (f.segments.empty()) return;
  const ShellFace& i = f.info;
  if (!i.base && (i.segment >= 0 || i.step >= 0)) {
    const auto key = std::make_tuple(i.sourceLoop, i.sourceEdge, i.step, i.profile, i.segment);
    const Vec3 p = points_[f.segments.front().first];
    auto range = byKey_.equal_range(key);
    for (auto it = range.first; it != range.second; ++it) {
      RawFace& g = faces_[it->second];
      const Vec3 q = points_[g.segments.front().first];
      if (OpenMesh::dot(g.info.normal, i.normal) > 1 - 1e-12 && std::abs(OpenMesh::dot(i.normal, p - q)) <= tol_.cluster) {
        g.segments.insert(g.segments.end(), f.segments.begin(), f.segments.end());
        return;
      }
    }
    byKey_.emplace(key, static_cast<int>(faces_.size()));
  }
  faces_.push_back(std::move(f));
}

void Stager::addFlatFace(std::vector<int> loop, bool up, const ShellFace& info) {
  double a = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 &p = points_[loop[k]], &q = points_[loop[(k + 1) % loop.size()]];
    a += p[0] * q[1] - p[1] * q[0];
  }
  if ((a > 0) != up) std::reverse(loop.begin(), loop.end());
  RawFace f;
  f.info = info;
  f.info.normal = Vec3(0, 0, up ? 1 : -1);
  for (std::size_t k = 0; k < loop.size(); ++k) f.segments.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  addFace(std::move(f));
}

SweepOutput Stager::runSweep(SweepInput& in, const std::string& context) {
  in.keepRaw = true;
  in.timeLimitSeconds = remaining();
  SweepOutput out = sweep(in, tol_, progress_);
  events_ += out.events;
  diverged_ = diverged_ || out.diverged;
  for (auto& w : out.warnings) warnings_.push_back(w + context);
  return out;
}

// One stage of the sweep from z up to `next`; returns the active plan at `next`.
Plan Stager::runStage(const Plan& plan, double z, double next, bool first, double& reached) {
  SweepInput in;
  in.baseZ = z;
  in.emitBase = first;
  in.stopZ = next;
  in.stopAtOverlap = windingRule_ && repairs_ < kMaxRepairs;
  std::vector<const Active*> flat;
  std::size_t edges = 0;
  for (const auto& loop : plan) edges += loop.size();
  flat.reserve(edges);
  in.loops.reserve(plan.size());
  for (const auto& loop : plan) {
    std::vector<SweepEdge> l;
    l.reserve(loop.size());
    for (const Active& a : loop) {
      l.push_back(sweepEdge(a, z));
      flat.push_back(&a);
    }
    in.loops.push_back(std::move(l));
  }
  // Mesh anchors inside the stage read the plan at their height without a seam there (a seam
  // just below an event would leave a sliver face).
  for (const MeshAnchor& m : spec_.anchors) {
    const double ha = spec_.baseZ + m.anchor.height;
    if (ha > z + tol_.height && ha < next - tol_.height &&
        std::none_of(in.probes.begin(), in.probes.end(), [&](double p) { return std::abs(p - ha) <= tol_.height; }))
      in.probes.push_back(ha);
  }
  std::sort(in.probes.begin(), in.probes.end());
  SweepOutput out = runSweep(in, "");
  for (std::size_t i = 0; i < out.probed.size(); ++i) {
    Plan probe;
    for (const auto& loop : out.probed[i]) {
      std::vector<Active> l;
      for (const PlanCorner& c : loop) {
        Active a = *flat[c.input];
        a.start = c.p;
        a.vertex = -1;
        l.push_back(a);
      }
      probe.push_back(std::move(l));
    }
    frame(probe, in.probes[i]);
  }
  const double top = std::isnan(out.stoppedAt) ? next : out.stoppedAt;
  reached = top;
  std::vector<int> map(out.points.size());
  points_.reserve(points_.size() + out.points.size());
  faces_.reserve(faces_.size() + out.raw.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Vec3& p = out.points[i];
    if (first && std::abs(p[2] - z) <= tol_.height) map[i] = point(p);  // the base: no seam below
    else if (std::abs(p[2] - z) <= tol_.height) map[i] = weld(Vec2(p[0], p[1]), z);
    else if (std::abs(p[2] - top) <= tol_.height) map[i] = weld(Vec2(p[0], p[1]), top);
    else map[i] = point(p);
  }
  for (RawFace& f : out.raw) {
    for (auto& [u, v] : f.segments) u = map[u], v = map[v];
    addFace(std::move(f));
  }
  Plan result;
  for (const auto& loop : out.plan) {
    std::vector<Active> l;
    l.reserve(loop.size());
    for (const PlanCorner& c : loop) {
      Active a = *flat[c.input];
      a.start = c.p;
      a.vertex = map[c.vertex];
      pushCorner(l, a);
    }
    if (closeLoop(l)) result.push_back(std::move(l));
    else if (top == next)  // (where the sweep stopped for the winding rule, it takes what is left)
      warnings_.push_back("a sliver of the plan vanished at height " + std::to_string(top));
  }
  return result;
}

// Post inter-chain repair (Sec. 4.4): the plan at h overlaps itself, so its valid region is
// taken by the winding rule. Its boundary is the new plan, each edge keeping the old edge it
// lies on (and so its direction plane and profile); the faces that ended inside the region,
// or in a part turned inside out, are closed by flat caps at h.
Plan Stager::windingRebuild(const Plan& plan, double h) {
  ++repairs_;
  std::vector<std::vector<Vec2>> loops;
  std::vector<const Active*> flat;
  for (const auto& loop : plan) {
    loops.emplace_back();
    for (const Active& a : loop) {
      loops.back().push_back(a.start);
      flat.push_back(&a);
    }
  }
  const WindingResult r = windingRule(loops);
  for (const WindingCap& cap : r.caps) {
    RawFace f;
    f.info.angle = cap.level > 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
    f.info.normal = Vec3(0, 0, cap.level > 0 ? 1 : -1);
    for (const auto& [a, b] : cap.pieces) {
      const int u = weld(a, h), v = weld(b, h);
      if (u != v) f.segments.emplace_back(u, v);
    }
    addFace(std::move(f));
  }
  Plan result;
  for (const auto& loop : r.loops) {
    std::vector<Active> l;
    for (const WindingEdge& e : loop) {
      Active a = *flat[e.source];
      a.start = e.start;
      a.vertex = weld(e.start, h);
      pushCorner(l, a);
    }
    if (closeLoop(l)) result.push_back(std::move(l));
  }
  return result;
}

std::optional<Located> Stager::locate(const Plan& plan, const Anchor& a) const {
  std::optional<Located> best;
  for (int li = 0; li < static_cast<int>(plan.size()); ++li) {
    const auto& loop = plan[li];
    for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
      const Active& e = loop[i];
      if (e.step != -1 || e.sourceLoop != a.loop || e.sourceEdge != a.edge) continue;
      Located l;
      l.loop = li;
      l.index = i;
      Vec2 d = loop[(i + 1) % loop.size()].start - e.start;
      l.length = d.norm();
      if (l.length <= tol_.minEdge) continue;
      l.d = d / l.length;
      if (a.absolute) {
        const auto& in = spec_.loops[a.loop].points;
        const Vec2 s = in[a.edge];
        Vec2 din = in[(a.edge + 1) % in.size()] - s;
        din.normalize();
        l.t = a.along - OpenMesh::dot(din, e.start - s);
        if (l.t < 0 || l.t > l.length) continue;
        l.at = e.start + l.d * l.t;
        return l;
      }
      l.t = a.along * l.length;
      l.at = e.start + l.d * l.t;
      if (!best || l.length > best->length) best = l;
    }
  }
  return best;
}

void Stager::frame(const Plan& plan, double h) {
  for (std::size_t k = 0; k < spec_.anchors.size(); ++k) {
    const MeshAnchor& m = spec_.anchors[k];
    if (std::abs(spec_.baseZ + m.anchor.height - h) > tol_.height) continue;
    AnchorFrame& f = frames_[k];
    const auto at = locate(plan, m.anchor);
    if (!at) continue;
    const Active& e = plan[at->loop][at->index];
    double angle = 0;
    for (const Seg& g : segs(e))
      if (!g.horizontal && g.hi > h + tol_.height) {
        angle = g.angle;
        break;
      }
    const Vec2 n = leftOf(at->d);
    f.instanced = true;
    f.position = Vec3(at->at[0], at->at[1], h);
    f.along = Vec3(at->d[0], at->d[1], 0);
    f.normal = Vec3(-n[0], -n[1], std::tan(angle));
    f.normal.normalize();
    f.up = OpenMesh::cross(f.normal, f.along);
  }
}

// An overhang pushes a sharp convex corner out by its move over the sine of half the corner's
// angle: a 1 m overhang on a 1° spike would reach 115 m out, a sliver no one wants (and a
// shell of needle faces). Beyond kMitreLimit times the move (a corner under about 5.7°), the
// edit is refused with the corner named, as offsetting tools do with their mitre limit.
template <class Item>
void checkMitre(const std::vector<std::vector<Item>>& loops, double h, double baseZ) {
  constexpr double kMitreLimit = 20.0;
  for (const auto& l : loops)
    for (std::size_t j = 0; j < l.size(); ++j) {
      const Item& a = l[(j + l.size() - 1) % l.size()];
      const Item& b = l[j];
      if (!(a.k < 0 || b.k < 0) || a.a.step >= 0 || b.a.step >= 0) continue;  // only outward moves
      Vec2 da = b.a.start - a.a.start, db = l[(j + 1) % l.size()].a.start - b.a.start;
      if (da.norm() == 0 || db.norm() == 0) continue;
      da.normalize();
      db.normalize();
      const double sine = da[0] * db[1] - da[1] * db[0];
      if (sine <= 0 || OpenMesh::dot(da, db) > 0) continue;  // a reflex or blunt corner
      // The corner's move: where the two moved lines meet (n·v = k for each, n inward).
      const Vec2 na(-da[1], da[0]), nb(-db[1], db[0]);
      const double det = na[0] * nb[1] - na[1] * nb[0];
      const Vec2 v((a.k * nb[1] - b.k * na[1]) / det, (na[0] * b.k - nb[0] * a.k) / det);
      const double move = std::max(std::abs(a.k), std::abs(b.k));
      if (v.norm() <= kMitreLimit * move) continue;
      const double degrees = std::atan2(sine, -OpenMesh::dot(da, db)) * 180 / std::numbers::pi;
      std::ostringstream m;
      m.precision(3);
      m << "at height " << h - baseZ << " m the " << move << " m overhang would push this " << degrees
        << "° corner " << v.norm() << " m out (more than " << kMitreLimit
        << " times the overhang): blunt the corner or take the overhang off its edges";
      const bool sameLoop = a.a.sourceLoop == b.a.sourceLoop && a.a.sourceLoop >= 0;
      std::ostringstream where;
      if (sameLoop) where << "loops[" << b.a.sourceLoop << "].points[" << b.a.sourceEdge << "]";
      else where << "loops[" << b.a.sourceLoop << "] edge " << b.a.sourceEdge;
      throw InputError(where.str(), m.str());
    }
}

// The discrete changes at height h: horizontal moves of edges and plan steps, made together by
// one recursive extrusion (Sec. 4.5.2, 4.7).
Plan Stager::change(Plan plan, double h, bool atBase) {
  frame(plan, h);
  // Most heights (every stage of a plain roof) change nothing: no edge moves there and no
  // natural step stands there.
  auto moves = [&](const Active& a) {
    double k = 0;
    for (const Seg& g : segs(a))
      if (g.horizontal && std::abs(g.lo - h) <= tol_.height) k += g.dw;
    return k != 0;
  };
  const bool stepHere = std::any_of(spec_.steps.begin(), spec_.steps.end(), [&](const PlanStep& st) {
    return st.shape != StepShape::Forced && std::abs(spec_.baseZ + st.anchor.height - h) <= tol_.height;
  });
  if (!stepHere && std::none_of(plan.begin(), plan.end(), [&](const auto& l) { return std::any_of(l.begin(), l.end(), moves); }))
    return plan;
  struct Item {
    Active a;      // what the edge will be in the new plan
    double k = 0;  // its move over the unit height of the recursive extrusion
    int segment = -1;
  };
  std::vector<std::vector<Item>> loops;
  bool any = false;
  for (const auto& loop : plan) {
    std::vector<Item> l;
    for (const Active& a : loop) {
      Item it;
      it.a = a;
      for (const Seg& g : segs(a))
        if (g.horizontal && std::abs(g.lo - h) <= tol_.height) {
          if (it.segment < 0) it.segment = g.index;
          it.k += g.dw;
        }
      any = any || it.k != 0;
      l.push_back(it);
    }
    loops.push_back(std::move(l));
  }
  if (any) checkMitre(loops, h, spec_.baseZ);
  // Natural steps: a protrusion λ times its size, grown to full size by the recursion.
  const double epsilon = 100 * tol_.minEdge;  // 1e-5 of the plan's size
  std::vector<std::pair<std::vector<int>, ShellFace>> tiny;  // the λ-sized protrusions' faces
  std::vector<bool> tinyUp;
  // Every step at this height is placed on the plan as it arrives, then inserted from the
  // last along each loop to the first so earlier places stay valid.
  struct Placed {
    std::size_t si;
    Located at;
  };
  std::vector<Placed> placed;
  for (std::size_t si = 0; si < spec_.steps.size(); ++si) {
    const PlanStep& st = spec_.steps[si];
    if (st.shape == StepShape::Forced || stepDone_[si] || std::abs(spec_.baseZ + st.anchor.height - h) > tol_.height)
      continue;
    stepDone_[si] = 1;
    const std::string name = "steps[" + std::to_string(si) + "]" + (st.name.empty() ? "" : " (" + st.name + ")");
    const auto at = locate(plan, st.anchor);
    if (!at) {
      warnings_.push_back(name + ": not placed: its edge is not in the active plan at height " + std::to_string(h));
      continue;
    }
    placed.push_back({si, *at});
  }
  std::sort(placed.begin(), placed.end(), [](const Placed& x, const Placed& y) {
    return std::tie(x.at.loop, x.at.index, x.at.t) > std::tie(y.at.loop, y.at.index, y.at.t);
  });
  double limit = std::numeric_limits<double>::infinity();  // where the previous step on this edge began
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const std::size_t si = placed[k].si;
    const Located* at = &placed[k].at;
    if (k == 0 || placed[k - 1].at.loop != at->loop || placed[k - 1].at.index != at->index) limit = at->length;
    const PlanStep& st = spec_.steps[si];
    const std::string name = "steps[" + std::to_string(si) + "]" + (st.name.empty() ? "" : " (" + st.name + ")");
    // The shape in the edge's frame (u along the edge, v outward), about the anchor.
    const double W = st.width, D = st.depth, c = st.shape == StepShape::Bay ? st.cant : 0.0;
    const std::vector<Vec2> shape = {Vec2(-W / 2, 0), Vec2(-W / 2 + c, D), Vec2(W / 2 - c, D), Vec2(W / 2, 0)};
    const double lambda = epsilon / std::max(W, std::abs(D));
    if (at->t - lambda * W / 2 <= 10 * tol_.minEdge || at->t + lambda * W / 2 >= limit - 10 * tol_.minEdge) {
      warnings_.push_back(name + ": not placed: its anchor is at the end of its active edge or on another step");
      continue;
    }
    limit = at->t - lambda * W / 2;
    const Vec2 o = -leftOf(at->d);
    auto world = [&](const Vec2& q) { return at->at + at->d * q[0] + o * q[1]; };
    const Item host = loops[at->loop][at->index];
    std::vector<Item> inserted;
    std::vector<Vec2> tinyPts;
    for (std::size_t j = 0; j < shape.size(); ++j) {
      const Vec2 p = world(shape[j] * lambda);
      tinyPts.push_back(p);
      if (j + 1 == shape.size()) break;
      Item it;
      it.a.start = p;
      it.a.vertex = -1;
      it.a.profile = j == 1 ? st.frontProfile : st.sideProfile;
      it.a.z0 = h;
      it.a.sourceLoop = -1;
      it.a.sourceEdge = static_cast<int>(j);
      it.a.step = static_cast<int>(si);
      // Grow from the λ-sized line to the full-sized one along the inward normal.
      const Vec2 q0 = world(shape[j]), q1 = world(shape[j + 1]);
      Vec2 dir = q1 - q0;
      dir.normalize();
      it.k = (1 - lambda) * OpenMesh::dot(leftOf(dir), q0 - at->at);
      inserted.push_back(it);
    }
    Item after = host;
    after.a.start = tinyPts.back();
    after.a.vertex = -1;
    inserted.push_back(after);
    auto& l = loops[at->loop];
    l.insert(l.begin() + at->index + 1, inserted.begin(), inserted.end());
    if (!atBase) {
      std::vector<int> ids;
      for (const Vec2& p : tinyPts) ids.push_back(weld(p, h));
      ShellFace info;
      info.step = static_cast<int>(si);
      info.sourceLoop = info.sourceEdge = -1;
      info.angle = D > 0 ? -std::numbers::pi / 2 : std::numbers::pi / 2;
      tiny.emplace_back(ids, info);
      tinyUp.push_back(D < 0);
    }
    any = true;
  }
  if (!any) return plan;
  for (std::size_t k = 0; k < tiny.size(); ++k) addFlatFace(tiny[k].first, tinyUp[k], tiny[k].second);

  SweepInput in;
  in.baseZ = 0;
  in.stopZ = 1;
  in.emitBase = false;
  std::vector<const Item*> flat;
  for (const auto& l : loops) {
    std::vector<SweepEdge> sl;
    for (const Item& it : l) {
      SweepEdge e;
      e.start = it.a.start;
      e.sourceLoop = it.a.sourceLoop;
      e.sourceEdge = it.a.sourceEdge;
      e.step = it.a.step;
      e.profile = it.a.step >= 0 ? -1 : it.a.profile;
      e.steps.push_back({0.0, std::atan(it.k), it.a.step >= 0 ? -1 : it.segment, 0.0});
      sl.push_back(e);
      flat.push_back(&it);
    }
    in.loops.push_back(std::move(sl));
  }
  SweepOutput out = runSweep(in, " (in the recursive extrusion at height " + std::to_string(h) + ")");
  std::vector<int> map(out.points.size(), -1);
  if (!atBase) {
    for (std::size_t i = 0; i < out.points.size(); ++i) map[i] = weld(Vec2(out.points[i][0], out.points[i][1]), h);
    // Edges moving both ways can sweep over one another (a dormer's front stepping in while
    // its sides step out): their flattened faces then overlap, up over down, and the shell
    // would be non-manifold there. Such changes take their flat faces from the plans instead.
    bool inward = false, outward = false;
    for (const auto& l : loops)
      for (const Item& it : l) {
        if (it.k > 0) inward = true;
        if (it.k < 0) outward = true;
      }
    const bool folded = inward && outward && addFoldedFlats(in, out, map, h);
    for (RawFace& f : out.raw) {
      if (folded) break;
      if (f.info.angle == 0) continue;  // an edge that did not move: a vertical sliver
      RawFace g;
      g.info = f.info;
      if (g.info.step >= 0) g.info.sourceEdge = -1;  // a step's soffit (or ledge) is one face
      const bool up = f.info.angle > 0;
      g.info.angle = up ? std::numbers::pi / 2 : -std::numbers::pi / 2;
      g.info.normal = Vec3(0, 0, up ? 1 : -1);
      for (auto [u, v] : f.segments)
        if (map[u] != map[v]) g.segments.emplace_back(map[u], map[v]);
      addFace(std::move(g));
    }
  }
  Plan result;
  for (const auto& loop : out.plan) {
    std::vector<Active> l;
    for (const PlanCorner& c : loop) {
      Active a = flat[c.input]->a;
      a.start = c.p;
      a.vertex = atBase ? -1 : map[c.vertex];
      if (!l.empty() && (atBase ? (l.back().start - a.start).norm() <= tol_.cluster : l.back().vertex == a.vertex))
        l.pop_back();
      l.push_back(a);
    }
    if (l.size() >= 3) result.push_back(std::move(l));
  }
  return result;
}

EPolygon toPolygon(const std::vector<Vec2>& pts) {
  EPolygon p;
  for (const Vec2& q : pts) p.push_back(EK::Point_2(q[0], q[1]));
  if (p.size() >= 3 && p.is_simple() && p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

Vec2 toVec(const EK::Point_2& p) { return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = OpenMesh::dot(d, d);
  const double t = len2 > 0 ? std::clamp(OpenMesh::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return (a + d * t - p).norm();
}

void Stager::addFlatRegion(const EPolygonH& region, double h, bool up, const ShellFace& info) {
  RawFace f;
  f.info = info;
  f.info.normal = Vec3(0, 0, up ? 1 : -1);
  auto add = [&](const EPolygon& p, [[maybe_unused]] bool ccw) {
    std::vector<int> ids;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) ids.push_back(weld(toVec(*v), h));
    // CGAL gives outer boundaries counter-clockwise and holes clockwise from above: right as
    // seen from outside for a face looking up; a face looking down is seen from below.
    if (!up) std::reverse(ids.begin(), ids.end());
    for (std::size_t k = 0; k < ids.size(); ++k) f.segments.emplace_back(ids[k], ids[(k + 1) % ids.size()]);
  };
  add(region.outer_boundary(), true);
  for (auto hole = region.holes_begin(); hole != region.holes_end(); ++hole) add(*hole, false);
  addFace(std::move(f));
}

// The flat faces of a change whose edges move both ways, from its plans: what the change takes
// from the plan (old minus new) looks up, what it adds (new minus old) looks down (Sec. 4.5.2).
// Each region is shared out among the recursive extrusion's faces that cover it, first come
// first served, so ledges and soffits keep the edge (and tags) that made them; whatever no face
// claims is added untagged, so the seam always closes. Returns false, adding nothing, where a
// plan is not simple: the faces are then taken as the sweep made them.
bool Stager::addFoldedFlats(const SweepInput& in, const SweepOutput& out, const std::vector<int>& map, double h) {
  auto setOf = [](const std::vector<std::vector<Vec2>>& loops, EPolygonSet& set) {
    for (const auto& pts : loops) {
      if (pts.size() < 3) continue;
      const EPolygon p = toPolygon(pts);
      if (!p.is_simple()) return false;
      set.symmetric_difference(p);
    }
    return true;
  };
  std::vector<std::vector<Vec2>> oldLoops, newLoops;
  for (const auto& l : in.loops) {
    oldLoops.emplace_back();
    for (const SweepEdge& e : l) oldLoops.back().push_back(e.start);
  }
  for (const auto& l : out.plan) {
    newLoops.emplace_back();
    for (const PlanCorner& c : l) newLoops.back().push_back(c.p);
  }
  EPolygonSet oldSet, newSet;
  if (!setOf(oldLoops, oldSet) || !setOf(newLoops, newSet)) return false;
  EPolygonSet up = oldSet, down = newSet;
  up.difference(newSet);
  down.difference(oldSet);
  auto emit = [&](const EPolygonSet& set, bool isUp, const ShellFace& info) {
    std::vector<EPolygonH> regions;
    set.polygons_with_holes(std::back_inserter(regions));
    for (const EPolygonH& r : regions) addFlatRegion(r, h, isUp, info);
  };
  for (const RawFace& f : out.raw) {
    if (f.info.angle == 0) continue;
    const bool isUp = f.info.angle > 0;
    EPolygonSet& rest = isUp ? up : down;
    if (rest.is_empty()) continue;
    // The face's outline, projected: its pieces chained into loops by welded vertex.
    std::unordered_map<int, int> next;
    bool ok = true;
    for (auto [u, v] : f.segments)
      if (map[u] != map[v] && !next.emplace(map[u], map[v]).second) ok = false;
    EPolygonSet region;
    while (ok && !next.empty()) {
      const int first = next.begin()->first;
      std::vector<Vec2> pts;
      int at = first;
      do {
        const auto it = next.find(at);
        if (it == next.end()) {
          ok = false;  // an open outline
          break;
        }
        pts.emplace_back(points_[at][0], points_[at][1]);
        at = it->second;
        next.erase(it);
      } while (at != first);
      if (ok && pts.size() >= 3) {
        const EPolygon p = toPolygon(pts);
        if (p.is_simple()) region.symmetric_difference(p);
      }
    }
    if (!ok || region.is_empty()) continue;
    EPolygonSet piece = region;
    piece.intersection(rest);
    if (piece.is_empty()) continue;
    rest.difference(region);
    ShellFace info = f.info;
    if (info.step >= 0) info.sourceEdge = -1;  // a step's soffit (or ledge) is one face
    info.angle = isUp ? std::numbers::pi / 2 : -std::numbers::pi / 2;
    emit(piece, isUp, info);
  }
  ShellFace rest;
  rest.sourceLoop = rest.sourceEdge = -1;
  rest.angle = std::numbers::pi / 2;
  emit(up, true, rest);
  rest.angle = -std::numbers::pi / 2;
  emit(down, false, rest);
  return true;
}

EPolygonSet planSet(const Plan& plan) {
  EPolygonSet set;
  for (const auto& loop : plan) {
    std::vector<Vec2> pts;
    for (const Active& a : loop) pts.push_back(a.start);
    const EPolygon p = toPolygon(pts);
    if (p.size() >= 3 && p.is_simple()) set.symmetric_difference(p);
  }
  return set;
}

// The active plan after a Boolean change: an edge lying on an edge of the old plan (same way
// round) keeps what that edge was; any other edge is what `other` says for its midpoint.
Plan Stager::rebuild(const Plan& old, const EPolygonSet& next, double h, const std::function<Active(const Vec2&)>& other,
                     bool atBase) {
  auto classify = [&](const Vec2& a, const Vec2& b) {
    const Vec2 mid = (a + b) * 0.5;
    Vec2 d = b - a;
    d.normalize();
    for (const auto& loop : old)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 &p = loop[i].start, &q = loop[(i + 1) % loop.size()].start;
        Vec2 e = q - p;
        if (e.norm() == 0) continue;
        e.normalize();
        if (OpenMesh::dot(d, e) > 1 - 1e-9 && distanceToSegment(mid, p, q) <= tol_.cluster) return loop[i];
      }
    return other(mid);
  };
  std::vector<EPolygonH> regions;
  next.polygons_with_holes(std::back_inserter(regions));
  Plan result;
  auto addLoop = [&](const EPolygon& p) {
    std::vector<Vec2> pts;
    for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) pts.push_back(toVec(*v));
    std::vector<Active> l;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Active a = classify(pts[i], pts[(i + 1) % pts.size()]);
      a.start = pts[i];
      a.vertex = atBase ? -1 : weld(pts[i], h);  // the base's vertices are made by the first stage
      l.push_back(a);
    }
    if (l.size() >= 3) result.push_back(std::move(l));
  };
  for (const EPolygonH& r : regions) {
    addLoop(r.outer_boundary());
    for (auto hole = r.holes_begin(); hole != r.holes_end(); ++hole) addLoop(*hole);
  }
  return result;
}

// Forced steps (Sec. 3.5, 4.7): arbitrary polygons, placed in the frame of their anchor,
// unioned with the active plan (exactly, so the plan never self-intersects); the part outside
// the old plan gets a soffit, the new edges the step's front profile.
Plan Stager::forcedSteps(Plan plan, double h, bool atBase) {
  struct Placed {
    std::size_t si;
    std::vector<Vec2> pts;
  };
  std::vector<Placed> placed;
  for (std::size_t si = 0; si < spec_.steps.size(); ++si) {
    const PlanStep& st = spec_.steps[si];
    if (st.shape != StepShape::Forced || stepDone_[si] || std::abs(spec_.baseZ + st.anchor.height - h) > tol_.height)
      continue;
    stepDone_[si] = 1;
    const auto at = locate(plan, st.anchor);
    if (!at) {
      warnings_.push_back("steps[" + std::to_string(si) + "]" + (st.name.empty() ? "" : " (" + st.name + ")") +
                          ": not placed: its edge is not in the active plan at height " + std::to_string(h));
      continue;
    }
    const Vec2 o = -leftOf(at->d);
    Placed p{si, {}};
    for (const Vec2& q : st.points) p.pts.push_back(at->at + at->d * q[0] + o * q[1]);
    placed.push_back(std::move(p));
  }
  if (placed.empty()) return plan;
  const EPolygonSet active = planSet(plan);
  EPolygonSet added;
  for (const Placed& p : placed) added.join(toPolygon(p.pts));
  EPolygonSet next = active, flats = added;
  next.join(added);
  flats.difference(active);
  std::vector<EPolygonH> regions;
  flats.polygons_with_holes(std::back_inserter(regions));
  for (const EPolygonH& r : regions) {
    if (atBase) break;  // the base face covers it
    ShellFace info;
    info.angle = -std::numbers::pi / 2;
    addFlatRegion(r, h, false, info);
  }
  return rebuild(plan, next, h, [&](const Vec2& mid) {
    Active n;
    n.z0 = h;
    n.profile = spec_.steps[placed.front().si].frontProfile;
    n.step = static_cast<int>(placed.front().si);
    double best = std::numeric_limits<double>::infinity();
    for (const Placed& p : placed)
      for (std::size_t k = 0; k < p.pts.size(); ++k) {
        const double dist = distanceToSegment(mid, p.pts[k], p.pts[(k + 1) % p.pts.size()]);
        if (dist >= best) continue;
        best = dist;
        n.profile = spec_.steps[p.si].frontProfile;
        n.step = static_cast<int>(p.si);
        n.sourceEdge = static_cast<int>(k);
      }
    return n;
  }, atBase);
}

// A profile offset event (Sec. 4.6): a recursive extrusion moves every listed edge out by its
// inside distance over the first unit of height and by its outside distance over the second
// (disabled edges stand still); its faces between the two heights, flattened, are the offset
// region R (Fig. 18). Outward, R joins the active plan and its underside is a soffit; inward,
// R is cut from the plan and its top is a ledge. The new plan's edges keep their profiles where
// they lie on the old plan; elsewhere they follow the inside, outside or side profile of the
// boundary they lie on. Booleans are CGAL's, exact.
Plan Stager::offset(const Plan& plan, double h, const OffsetEvent& ev, std::size_t index) {
  const bool outward = ev.edges.front().outside > 0;
  auto tupleOf = [&](const Active& a) -> const OffsetEdge* {
    for (const OffsetEdge& t : ev.edges)
      if (t.profile == a.profile) return &t;
    return nullptr;
  };
  SweepInput in;
  in.baseZ = 0;
  in.stopZ = 2;
  in.emitBase = false;
  std::vector<const Active*> flat;
  const EPolygonSet active = planSet(plan);
  for (const auto& loop : plan) {
    std::vector<SweepEdge> sl;
    for (const Active& a : loop) {
      const OffsetEdge* t = tupleOf(a);
      SweepEdge e;
      e.start = a.start;
      e.sourceLoop = -1;
      e.sourceEdge = static_cast<int>(flat.size());
      // Distances are outward; k = tan θ moves an edge inward per unit of height.
      e.steps.push_back({0.0, std::atan(t ? -t->inside : 0.0), 0, 0.0});
      e.steps.push_back({1.0, std::atan(t ? -t->outside : 0.0), 1, 0.0});
      sl.push_back(e);
      flat.push_back(&a);
    }
    in.loops.push_back(std::move(sl));
  }
  SweepOutput out = runSweep(in, " (in the offset event at height " + std::to_string(h) + ")");

  // R, and the pieces of its two boundaries by the edge they come from.
  struct Piece {
    Vec2 a, b;
    int edge;
    int boundary;  // 0 inside, 1 outside
  };
  std::vector<Piece> pieces;
  std::vector<RawFace> second;
  for (RawFace& f : out.raw) {
    const Active* a = flat[f.info.sourceEdge];
    if (f.info.segment != 1 || !tupleOf(*a)) continue;
    for (auto [u, v] : f.segments) {
      const Vec3 &p = out.points[u], &q = out.points[v];
      for (int b : {0, 1})
        if (std::abs(p[2] - (1 + b)) <= tol_.height && std::abs(q[2] - (1 + b)) <= tol_.height)
          pieces.push_back({Vec2(p[0], p[1]), Vec2(q[0], q[1]), f.info.sourceEdge, b});
    }
    second.push_back(std::move(f));
  }
  std::vector<ShellFace> faces;
  std::vector<std::string> ignored;
  traceFaces(out.points, second, tol_, faces, ignored);
  EPolygonSet region;
  for (const ShellFace& f : faces) {
    if (std::abs(f.normal[2]) < 1e-9) continue;  // vertical: the edge did not move
    for (const auto& loop : f.loops) {
      std::vector<Vec2> pts;
      for (int v : loop) pts.emplace_back(out.points[v][0], out.points[v][1]);
      const EPolygon p = toPolygon(pts);
      if (p.size() < 3 || !p.is_simple() || p.area() == 0) continue;
      EPolygonSet piece(p);
      region.join(piece);
    }
  }
  EPolygonSet next = active, flats = region;
  if (outward) {
    next.join(region);
    flats.difference(active);
  } else {
    next.difference(region);
    flats.intersection(active);
  }
  ShellFace info;
  info.angle = outward ? -std::numbers::pi / 2 : std::numbers::pi / 2;
  std::vector<EPolygonH> regions;
  flats.polygons_with_holes(std::back_inserter(regions));
  for (const EPolygonH& r : regions) addFlatRegion(r, h, !outward, info);

  // The new plan, edge by edge: edges off the old plan lie on a boundary piece.
  Plan result = rebuild(plan, next, h, [&](const Vec2& mid) {
    Active n;
    n.z0 = h;
    n.profile = ev.sideProfile;
    double best = tol_.cluster;
    for (const Piece& pc : pieces) {
      const double dist = distanceToSegment(mid, pc.a, pc.b);
      if (dist > best) continue;
      best = dist;
      const Active& src = *flat[pc.edge];
      const OffsetEdge* t = tupleOf(src);
      n.profile = pc.boundary == 0 ? t->insideProfile : t->outsideProfile;
      n.sourceLoop = src.sourceLoop;
      n.sourceEdge = src.sourceEdge;
      n.step = src.step;
    }
    return n;
  });
  if (result.empty())
    warnings_.push_back("offsets[" + std::to_string(index) + "]: the offset removed the whole plan at height " + std::to_string(h));
  return result;
}

// Every boundary piece is split at the shell's vertices that lie on it, so faces meet edge to
// edge: faces from different stages along a seam, and the pieces of one face where simultaneous
// events left a long top opposite several short ones (ambiguous events along one line,
// Fig. 22). A piece and its reverse then cancel when the face is traced.
void Stager::fixTJunctions() {
  // The vertices sorted by x and by y: a piece looks only among those within its bounding box
  // on the axis where the box is narrower (by x alone, the eaves of a ring of walls running
  // north-south scan a fifth of the shell each), and tests the box before the distance. Each
  // entry carries the vertex's coordinates, so the scan reads one array in order, and both
  // the search and the box test are free of branches that depend on the data (the scan runs
  // for every piece of every shell, and mispredicted branches were most of its time).
  struct Entry {
    double key;
    Vec3 p;
    int id;
  };
  std::array<std::vector<Entry>, 2> sorted;
  for (int axis = 0; axis < 2; ++axis) {
    sorted[axis].resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) sorted[axis][i] = {points_[i][axis], points_[i], static_cast<int>(i)};
    std::sort(sorted[axis].begin(), sorted[axis].end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  }
  // The first entry whose key is not below x (std::lower_bound, without the branches).
  auto firstFrom = [](const std::vector<Entry>& v, double x) {
    if (v.empty()) return v.data();
    const Entry* base = v.data();
    for (std::size_t n = v.size(); n > 1;) {
      const std::size_t half = n / 2;
      base = base[half].key < x ? base + half : base;
      n -= half;
    }
    return base + (base->key < x ? 1 : 0);
  };
  // A tenth of δ2: vertices of one event lie on their edges to rounding, seam vertices to
  // the weld; a wider net would split edges at vertices that merely pass close (measured on
  // the real footprints: at δ2 one roof's area identity degrades to 3e-9, at δ2/10 it stays
  // at 5e-11 and two footprints that failed before close).
  const double splitTol = 0.1 * tol_.cluster;

  // Pieces come in pairs, (u, v) in one face and (v, u) in its neighbour, and the box and so
  // the vertices that pass it are the same both ways: each undirected piece is scanned once
  // (pieces grouped by their lower vertex, a counting sort), and only where some vertex passes
  // the box is the distance measured, for each direction on its own as before.
  std::vector<int> first(points_.size() + 1, 0);
  std::size_t pieces = 0;
  for (const RawFace& f : faces_) {
    pieces += f.segments.size();
    for (auto [u, v] : f.segments) ++first[std::min(u, v) + 1];
  }
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  struct Piece {
    int u, v;  // as the face runs it
    int at;    // its place among all pieces, face by face
  };
  std::vector<Piece> byLow(pieces);
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    int at = 0;
    for (const RawFace& f : faces_)
      for (auto [u, v] : f.segments) byLow[fill[std::min(u, v)]++] = {u, v, at++};
  }
  // The vertices each piece is split at: (piece, t, vertex), sorted at the end.
  struct Split {
    int at;
    double t;
    int w;
    bool operator<(const Split& o) const { return std::tie(at, t, w) < std::tie(o.at, o.t, o.w); }
  };
  std::vector<Split> splits;
  std::vector<const Entry*> near;
  std::size_t visited = 0;
  for (std::size_t low = 0; low < points_.size(); ++low) {
    for (int i = first[low]; i < first[low + 1]; ++i) {
      const Piece& pc = byLow[i];
      const int high = std::max(pc.u, pc.v);
      // An earlier piece of this vertex with the same other end was scanned already.
      bool seen = false;
      for (int j = first[low]; j < i && !seen; ++j) seen = std::max(byLow[j].u, byLow[j].v) == high;
      if (seen) continue;
      // A runaway shell (a sweep that diverged far beyond its plan) can make this quadratic:
      // honour the time limit and cancellation here too.
      if ((++visited & 1023) == 0) {
        remaining();
        if (progress_ && progress_->cancelled()) throw Cancelled();
      }
      const Vec3 &pa = points_[pc.u], &pb = points_[pc.v];
      if (!((pb - pa).sqrnorm() > 0)) continue;
      // Every vertex within splitTol of the piece lies in its box widened by δ2 > splitTol.
      Vec3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(pa[k], pb[k]) - tol_.cluster;
        hi[k] = std::max(pa[k], pb[k]) + tol_.cluster;
      }
      const int axis = hi[1] - lo[1] < hi[0] - lo[0] ? 1 : 0;
      const std::vector<Entry>& order = sorted[axis];
      const Entry* const last = order.data() + order.size();
      near.clear();
      for (const Entry* e = firstFrom(order, lo[axis]); e != last && e->key <= hi[axis]; ++e) {
        const Vec3& p = e->p;
        const bool inBox = (p[0] >= lo[0]) & (p[0] <= hi[0]) & (p[1] >= lo[1]) & (p[1] <= hi[1]) & (p[2] >= lo[2]) &
                           (p[2] <= hi[2]) & (e->id != pc.u) & (e->id != pc.v);
        if (inBox) near.push_back(e);
      }
      if (near.empty()) continue;
      // Each piece on this line, each way, measured from its own start.
      for (int j = i; j < first[low + 1]; ++j) {
        const Piece& q = byLow[j];
        if (std::max(q.u, q.v) != high) continue;
        const Vec3 &a = points_[q.u], &b = points_[q.v];
        const Vec3 d = b - a;
        const double len2 = d.sqrnorm();
        for (const Entry* e : near) {
          const double t = OpenMesh::dot(e->p - a, d) / len2;
          if (t <= 0 || t >= 1) continue;
          if ((a + d * t - e->p).norm() <= splitTol) splits.push_back({q.at, t, e->id});
        }
      }
    }
  }
  if (splits.empty()) return;
  std::sort(splits.begin(), splits.end());
  std::vector<std::pair<int, int>> out;
  auto next = splits.begin();
  int at = 0;
  for (RawFace& f : faces_) {
    if (next == splits.end()) break;
    if (next->at >= at + static_cast<int>(f.segments.size())) {
      at += static_cast<int>(f.segments.size());
      continue;
    }
    out.clear();
    for (auto [u, v] : f.segments) {
      int prev = u;
      for (; next != splits.end() && next->at == at; ++next) {
        out.emplace_back(prev, next->w);
        prev = next->w;
      }
      out.emplace_back(prev, v);
      ++at;
    }
    f.segments = out;
  }
}

ExtrusionResult Stager::run(double scale) {
  ExtrusionResult result;
  result.scale = scale;
  frames_.resize(spec_.anchors.size());
  for (std::size_t k = 0; k < frames_.size(); ++k) frames_[k].name = spec_.anchors[k].name;
  stepDone_.assign(spec_.steps.size(), 0);

  Plan plan;
  for (std::size_t li = 0; li < spec_.loops.size(); ++li) {
    const PlanLoop& l = spec_.loops[li];
    std::vector<Active> loop;
    loop.reserve(l.points.size());
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      Active a;
      a.start = l.points[i];
      a.profile = l.profile[i];
      a.z0 = spec_.baseZ;
      a.sourceLoop = static_cast<int>(li);
      a.sourceEdge = static_cast<int>(i);
      loop.push_back(a);
    }
    plan.push_back(std::move(loop));
  }
  double z = spec_.baseZ;
  plan = change(std::move(plan), z, true);  // steps standing on the base (buttresses, bays)
  plan = forcedSteps(std::move(plan), z, true);
  bool first = true;
  while (!plan.empty()) {
    double next = std::numeric_limits<double>::infinity();
    for (const auto& loop : plan)
      for (const Active& a : loop)
        for (const Seg& g : segs(a))
          if (g.horizontal && g.lo > z + tol_.height) {
            next = std::min(next, g.lo);
            break;
          }
    for (std::size_t si = 0; si < spec_.steps.size(); ++si) {
      const double hs = spec_.baseZ + spec_.steps[si].anchor.height;
      if (!stepDone_[si] && hs > z + tol_.height) next = std::min(next, hs);
    }
    for (const OffsetEvent& o : spec_.offsets) {
      const double ho = spec_.baseZ + o.height;
      if (ho > z + tol_.height) next = std::min(next, ho);
    }
    double reached = next;
    plan = runStage(plan, z, next, first, reached);
    first = false;
    if (reached < next) {
      // The plan overlapped itself below `next`: rebuilt there, the sweep goes on from it.
      plan = windingRebuild(plan, reached);
      z = reached;
      continue;
    }
    if (!std::isfinite(next)) break;
    z = next;
    plan = change(std::move(plan), z, false);
    plan = forcedSteps(std::move(plan), z, false);
    for (std::size_t k = 0; k < spec_.offsets.size(); ++k)
      if (!plan.empty() && std::abs(spec_.baseZ + spec_.offsets[k].height - z) <= tol_.height)
        plan = offset(plan, z, spec_.offsets[k], k);
  }
  for (std::size_t si = 0; si < spec_.steps.size(); ++si)
    if (!stepDone_[si] && std::none_of(warnings_.begin(), warnings_.end(), [&](const std::string& w) {
          return w.rfind("steps[" + std::to_string(si) + "]", 0) == 0;
        }))
      warnings_.push_back("steps[" + std::to_string(si) + "]: not placed: the roof has closed below its height");
  if (!diverged_) fixTJunctions();

  SweepOutput& out = result.shell;
  traceFaces(points_, faces_, tol_, out.faces, warnings_);
  out.points = std::move(points_);
  collapseShortEdges(out, tol_.collapse, tol_.tinyFace);
  for (const Vec3& p : out.points) out.maxHeight = std::max(out.maxHeight, p[2]);
  out.warnings = std::move(warnings_);
  out.events = events_;
  result.anchors = std::move(frames_);
  return result;
}

}  // namespace

ExtrusionResult extrude(const ExtrusionSpec& spec, Progress* progress, const ExtrudeOptions& options) {
  const auto started = std::chrono::steady_clock::now();  // the time limit counts the checks too
  const double timeLimitSeconds = options.timeLimitSeconds;
  if (auto problem = checkSpec(spec)) {
    const auto colon = problem->find(": ");
    throw InputError(problem->substr(0, colon), colon == std::string::npos ? *problem : problem->substr(colon + 2));
  }
  BBox box;
  for (const auto& l : spec.loops)
    for (const Vec2& p : l.points) box.add(Vec3(p[0], p[1], 0));
  const Tolerances tol = Tolerances::forScale(box.diagonal(), options.toleranceFactor);
  // Repeats expand into single instances first (their columns counted along whole walls), then
  // walls of several edges join into kernel edges (extrude/walls.h). A spec with neither (most
  // of them, and every footprint of a batch) is used as it is, without a copy.
  const bool repeats = std::any_of(spec.steps.begin(), spec.steps.end(), [](const PlanStep& st) { return st.repeat.kind != RepeatKind::None; }) ||
                       std::any_of(spec.anchors.begin(), spec.anchors.end(), [](const MeshAnchor& m) { return m.repeat.kind != RepeatKind::None; });
  std::optional<ExpandedSpec> expanded;
  if (repeats) expanded = expandRepeats(spec);
  const ExtrusionSpec& unrolled = expanded ? expanded->spec : spec;
  const std::optional<KernelWalls> walls = kernelWalls(unrolled, 1e-9 * std::max(box.diagonal(), 1.0));
  ExtrusionResult r;
  try {
    Stager stager(walls ? walls->spec : unrolled, tol, progress, timeLimitSeconds, options.windingRule, started);
    r = stager.run(box.diagonal());
  } catch (const InputError& e) {
    if (!walls) throw;
    throw InputError(walls->inputPath(e.where), e.reason);  // the user's corners, not the kernel's
  }
  // A plan so thin that every edge meets its neighbours at once leaves nothing to build.
  if (r.shell.faces.empty())
    throw InputError("loops", "the plan is too thin to build: its walls meet each other at the ground (no faces)");
  for (std::size_t k = 0; k < r.anchors.size(); ++k)
    r.anchors[k].source = expanded ? expanded->anchorSource[k] : static_cast<int>(k);
  for (ShellFace& f : r.shell.faces) {
    if (walls && f.step < 0 && f.sourceLoop >= 0 && f.sourceLoop < static_cast<int>(walls->inputCorner.size()) &&
        f.sourceEdge >= 0 && f.sourceEdge < static_cast<int>(walls->inputCorner[f.sourceLoop].size()))
      f.sourceEdge = walls->inputCorner[f.sourceLoop][f.sourceEdge];
    if (expanded && f.step >= 0 && f.step < static_cast<int>(expanded->stepSource.size()))
      f.step = expanded->stepSource[f.step];
  }
  r.toleranceFactor = options.toleranceFactor;
  return r;
}

}  // namespace corbel::extrude
