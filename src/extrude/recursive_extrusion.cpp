// The discrete changes at a seam by one recursive extrusion (Sec. 4.5.2, 4.7, Fig. 16, 20):
// horizontal profile segments move their edges, natural steps (natural_steps.cpp) grow from a
// small protrusion, and the extrusion's faces, flattened, are the ledges and soffits at that
// height.
#include "extrude/stager.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace corbel::extrude::staging {

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
// one recursive extrusion (Sec. 4.5.2, 4.7). The steps: is there a change here; each edge's
// move (near-horizontal direction events); the natural steps placed and grown from their
// protrusions; the temporary plan swept over unit height; its faces projected onto the active
// plan at h; the temporary plan's top replacing the active plan.
Plan Stager::change(Plan plan, double h, bool atBase) {
  frame(plan, h);
  if (!changesAt(plan, h)) return plan;
  bool any = false;
  EdgeMoves loops = nearHorizontalMoves(plan, h, any);
  if (any) checkMitre(loops, h, spec_.baseZ);
  std::vector<Protrusion> tiny;
  if (growNaturalSteps(loops, placeNaturalSteps(plan, h), h, atBase, tiny)) any = true;
  if (!any) return plan;
  for (const Protrusion& t : tiny) addFlatFace(t.loop, t.up, t.info);
  std::vector<const EdgeMove*> flat;
  SweepInput in = temporaryPlan(loops, flat);
  SweepOutput out = runSweep(in, " (in the recursive extrusion at height " + std::to_string(h) + ")");
  std::vector<int> map(out.points.size(), -1);
  if (!atBase) projectOntoActivePlan(loops, in, out, map, h);
  return replaceActivePlan(out, flat, map, atBase);
}

// Most heights (every stage of a plain roof) change nothing: no edge moves there and no
// natural step stands there.
bool Stager::changesAt(const Plan& plan, double h) const {
  auto moves = [&](const Active& a) {
    double k = 0;
    for (const Seg& g : segs(a))
      if (g.horizontal && std::abs(g.lo - h) <= tol_.height) k += g.dw;
    return k != 0;
  };
  const bool stepHere = std::any_of(spec_.steps.begin(), spec_.steps.end(), [&](const PlanStep& st) {
    return st.shape != StepShape::Forced && std::abs(spec_.baseZ + st.anchor.height - h) <= tol_.height;
  });
  return stepHere ||
         std::any_of(plan.begin(), plan.end(), [&](const auto& l) { return std::any_of(l.begin(), l.end(), moves); });
}

// Each edge with its move at h (a near-horizontal direction event, Sec. 4.5.2): the sum of its
// profile's horizontal segments there, its speed in the recursive extrusion; `any` is set
// where one moves.
EdgeMoves Stager::nearHorizontalMoves(const Plan& plan, double h, bool& any) const {
  EdgeMoves loops;
  for (const auto& loop : plan) {
    std::vector<EdgeMove> l;
    for (const Active& a : loop) {
      EdgeMove it;
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
  return loops;
}

// The temporary plan (Sec. 4.5.2): every edge swept over unit height at the slope of its move;
// `flat` lists the moves in the order of its edges.
SweepInput Stager::temporaryPlan(const EdgeMoves& loops, std::vector<const EdgeMove*>& flat) const {
  SweepInput in;
  in.baseZ = 0;
  in.stopZ = 1;
  in.emitBase = false;
  for (const auto& l : loops) {
    std::vector<SweepEdge> sl;
    for (const EdgeMove& it : l) {
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
  return in;
}

// The recursive extrusion's faces, projected onto the active plan at height h, are the ledges
// (up) and soffits (down) of the change; `map` takes its points to the seam's welded vertices.
void Stager::projectOntoActivePlan(const EdgeMoves& loops, const SweepInput& in, SweepOutput& out,
                                   std::vector<int>& map, double h) {
  for (std::size_t i = 0; i < out.points.size(); ++i) map[i] = weld(Vec2(out.points[i][0], out.points[i][1]), h);
  // Edges moving both ways can sweep over one another (a dormer's front stepping in while
  // its sides step out): their flattened faces then overlap, up over down, and the shell
  // would be non-manifold there. Such changes take their flat faces from the plans instead.
  bool inward = false, outward = false;
  for (const auto& l : loops)
    for (const EdgeMove& it : l) {
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

// The temporary plan at the recursion's top replaces the active plan, its edges carrying on as
// the moves they came from; corners that welded into one are merged.
Plan Stager::replaceActivePlan(const SweepOutput& out, const std::vector<const EdgeMove*>& flat,
                               const std::vector<int>& map, bool atBase) const {
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

}  // namespace corbel::extrude::staging
