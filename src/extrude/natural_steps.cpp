// Natural steps (Sec. 4.7, Fig. 20): a dormer, bay or buttress at its anchor's height enters
// the recursive extrusion as a protrusion λ times its size, which the recursion grows to full
// size; at a seam above the base the protrusion is a small flat face of its own.
#include "extrude/stager.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace corbel::extrude::staging {

// The natural steps standing at h, each located on the active plan as it arrives (warned and
// left out where its edge is gone), sorted from the last along each loop to the first so that
// inserting them one by one keeps the earlier places valid.
std::vector<PlacedStep> Stager::placeNaturalSteps(const Plan& plan, double h) {
  std::vector<PlacedStep> placed;
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
  std::sort(placed.begin(), placed.end(), [](const PlacedStep& x, const PlacedStep& y) {
    return std::tie(x.at.loop, x.at.index, x.at.t) > std::tie(y.at.loop, y.at.index, y.at.t);
  });
  return placed;
}

// Inserts each placed step's λ-sized protrusion into its edge's loop, its edges moving out to
// the step's full shape over the recursion's unit height; `tiny` gets the protrusions' flat
// faces (none at the base). True where a step went in.
bool Stager::growNaturalSteps(EdgeMoves& loops, const std::vector<PlacedStep>& placed, double h, bool atBase,
                              std::vector<Protrusion>& tiny) {
  bool any = false;
  const double epsilon = 100 * tol_.minEdge;  // 1e-5 of the plan's size
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
    const EdgeMove host = loops[at->loop][at->index];
    std::vector<EdgeMove> inserted;
    std::vector<Vec2> tinyPts;
    for (std::size_t j = 0; j < shape.size(); ++j) {
      const Vec2 p = world(shape[j] * lambda);
      tinyPts.push_back(p);
      if (j + 1 == shape.size()) break;
      EdgeMove it;
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
    EdgeMove after = host;
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
      tiny.push_back({ids, info, D < 0});
    }
    any = true;
  }
  return any;
}

}  // namespace corbel::extrude::staging
