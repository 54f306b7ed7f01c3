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
//
// This file runs the stages; the changes at a seam, the shell's seams, the anchors and the
// plan's exact regions are in files of their own (stager.h lists them).
#include "extrude/stager.h"

#include "core/error.h"
#include "extrude/walls.h"
#include "extrude/winding.h"

#include <algorithm>
#include <cmath>

namespace corbel::extrude::staging {

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
  cleanUpShell(out, tol_);
  // The top of what the faces use: a corner the clean-up took out of every face (a spur's tip,
  // a fold's corners) is no part of the shell.
  for (const ShellFace& f : out.faces)
    for (const auto& loop : f.loops)
      for (int v : loop) out.maxHeight = std::max(out.maxHeight, out.points[v][2]);
  out.warnings = std::move(warnings_);
  out.events = events_;
  result.anchors = std::move(frames_);
  return result;
}


}  // namespace corbel::extrude::staging

namespace corbel::extrude {

using staging::Stager;

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
