#include "compose/stone_extrusion.h"

#include "core/error.h"
#include "extrude/extrude.h"
#include "statics/pier_loads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <tuple>

namespace corbel::statics {

namespace {

// A bay or recess: a natural step at the ground whose walls join the plan (expanded instance
// `instance` of steps[source]), on input edge `edge` over [from, to], its front `depth` out
// (negative: in) and `cant` narrower on each side.
struct PlanBay {
  int instance = -1, source = -1, edge = -1;
  double from = 0, to = 0, depth = 0, cant = 0;
  double top = 0;      // its walls' height (m)
  bool lower = false;  // lower than the house's walls: the wall above spans its mouth
  std::string field, who;
};

// A plan of walls: the input loop, broken where the given bays open an edge, with each bay's
// cheeks and front between the pieces.
struct BrokenPlan {
  std::vector<Vec2> points;
  std::vector<int> source;                 // per edge: the input edge, or -1 for a bay's wall
  std::vector<double> offset;              // per edge: where along its input edge it starts (m)
  std::vector<std::array<int, 2>> bayEdge; // per edge: (index into the bays, side 0-2), or -1s

  double length(std::size_t k) const { return (points[(k + 1) % points.size()] - points[k]).norm(); }
  // The piece of input edge e holding [from, to] (m along e), or -1.
  int pieceOf(int e, double from, double to) const {
    for (std::size_t k = 0; k < points.size(); ++k)
      if (source[k] == e && from >= offset[k] - 1e-9 && to <= offset[k] + length(k) + 1e-9) return int(k);
    return -1;
  }
};

BrokenPlan brokenPlan(const PlanLoop& loop, const std::vector<PlanBay>& bays, bool lowerToo) {
  BrokenPlan plan;
  const std::size_t n = loop.points.size();
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 p0 = loop.points[e], v = loop.points[(e + 1) % n] - p0;
    const Vec2 d = v / v.norm(), out(d[1], -d[0]);  // out: right of the edge, out of the plan
    plan.points.push_back(p0);
    plan.source.push_back(int(e));
    plan.offset.push_back(0.0);
    plan.bayEdge.push_back({-1, -1});
    for (std::size_t k = 0; k < bays.size(); ++k) {
      const PlanBay& b = bays[k];
      if (b.edge != int(e) || (b.lower && !lowerToo)) continue;
      const std::array<Vec2, 4> corners = {p0 + d * b.from, p0 + d * (b.from + b.cant) + out * b.depth,
                                           p0 + d * (b.to - b.cant) + out * b.depth, p0 + d * b.to};
      for (int j = 0; j < 3; ++j) {
        plan.points.push_back(corners[std::size_t(j)]);
        plan.source.push_back(-1);
        plan.offset.push_back(0.0);
        plan.bayEdge.push_back({int(k), j});
      }
      plan.points.push_back(corners[3]);
      plan.source.push_back(int(e));
      plan.offset.push_back(b.to);
      plan.bayEdge.push_back({-1, -1});
    }
  }
  return plan;
}

// Where a natural step's anchor lies: the input edge of its wall's run nearest the anchor
// point and how far along it (m).
std::pair<int, double> stepPlace(const ExtrusionSpec& spec, const PlanStep& st, const std::string& field,
                                 const std::string& who) {
  const PlanLoop& loop = spec.loops[0];
  const std::size_t n = loop.points.size();
  const std::optional<Vec2> at = anchorPoint(spec, st.anchor);
  if (!at) throw InputError(field, who + " is anchored to no edge of the plan");
  int edge = -1;
  double u = 0, best = std::numeric_limits<double>::infinity();
  for (int e : wallRun(spec, 0, st.anchor.edge).edges) {
    const Vec2 p0 = loop.points[std::size_t(e)], p1 = loop.points[(std::size_t(e) + 1) % n];
    const double len = (p1 - p0).norm();
    const double along = std::clamp(dot(*at - p0, (p1 - p0) / len), 0.0, len);
    const double off = (p0 + (p1 - p0) * (along / len) - *at).norm();
    if (off < best) best = off, edge = e, u = along;
  }
  if (edge < 0) throw InputError(field, who + " is anchored to no edge of the plan");
  return {edge, u};
}

// The height of a profile's first, vertical segment, or a refusal naming `field`.
double wallHeightOf(const Profile& p, const std::string& field, const std::string& what) {
  if (p.points.size() < 2 || p.points[1][0] != 0 || !(p.points[1][1] > 0))
    throw InputError(field, what + " \"" + p.name + "\" does not start with a vertical wall");
  return p.points[1][1];
}

}  // namespace

StoneHouse stoneHouseOf(const ExtrusionSpec& spec) {
  if (spec.loops.size() != 1) throw InputError("plan.loops", "a stone house is built on one plan loop (no holes or islands)");
  if (!spec.offsets.empty()) throw InputError("offsets", "offset events are not built in stone yet");
  const PlanLoop& loop = spec.loops[0];
  StoneHouse house;
  house.walls.base = spec.baseZ;
  double height = -1;
  for (std::size_t e = 0; e < loop.profile.size(); ++e) {
    const Profile& p = spec.profiles.at(std::size_t(loop.profile[e]));
    if (p.points.size() < 2 || p.points[0][0] != 0 || p.points[1][0] != 0 || !(p.points[1][1] > 0))
      throw InputError("masonry", "the profile \"" + p.name + "\" of edge " + std::to_string(e) +
                                      " does not start with a vertical wall; only walls are built in stone");
    if (height < 0) height = p.points[1][1];
    if (std::abs(p.points[1][1] - height) > 1e-9)
      throw InputError("masonry", "edge " + std::to_string(e) + "'s wall is " + std::to_string(p.points[1][1]) +
                                      " m high and edge 0's " + std::to_string(height) + " m: the walls must have one height");
  }
  house.walls.height = height;
  const std::size_t n = loop.points.size();
  auto edgeLength = [&](std::size_t e) { return (loop.points[(e + 1) % n] - loop.points[e]).norm(); };

  // The natural steps (every instance of a repeat): buttresses stand against the walls, bays
  // and recesses join the plan; anything else is refused by name.
  const ExpandedSpec expanded = expandRepeats(spec);
  struct PlacedButtress {
    WallButtress b;  // on an input edge; moved onto the coursed plan below
    int source;
  };
  std::vector<PlacedButtress> buttresses;
  std::vector<PlanBay> bays;
  for (std::size_t i = 0; i < expanded.spec.steps.size(); ++i) {
    const PlanStep& st = expanded.spec.steps[i];
    const int source = expanded.stepSource[i];
    const std::string field = "steps[" + std::to_string(source) + "]";
    const std::string who = "the step \"" + st.name + "\"";
    if (st.shape == StepShape::Forced)
      throw InputError(field, who + " is a forced step; only buttresses, bays and recesses are built in stone yet");
    if (std::abs(st.anchor.height) > 1e-9 || st.anchor.loop != 0)
      throw InputError(field, who + " does not stand on the ground of the plan; only steps from the foot of the "
                                    "walls (buttresses, bays, recesses) are built in stone");
    if (!(st.depth != 0)) throw InputError(field, who + " has no depth");
    const double front = wallHeightOf(spec.profiles.at(std::size_t(st.frontProfile)), field, who + "'s front profile");
    const auto [edge, u] = stepPlace(spec, st, field, who);
    if (st.shape == StepShape::Rectangle && st.depth > 0) {
      WallButtress b;
      b.name = st.name.empty() ? field : st.name;
      b.edge = edge;
      b.from = u - st.width / 2;
      b.to = u + st.width / 2;
      b.depth = st.depth;
      b.top = std::min(front, height);
      buttresses.push_back({b, source});
      continue;
    }
    // A bay (or a rectangle reaching in: a recess): its cheeks and front are walls of the plan,
    // as high as their profiles' first, vertical segments, at most the house's.
    const double side = wallHeightOf(spec.profiles.at(std::size_t(st.sideProfile)), field, who + "'s side profile");
    const char* kind = st.depth > 0 ? "bay" : "recess";
    if (std::abs(front - side) > 1e-9)
      throw InputError(field, who + " is a " + kind + " whose front rises " + std::to_string(front) +
                                  " m and whose cheeks rise " + std::to_string(side) +
                                  " m (their profiles' first segments); its walls must have one height");
    if (front > height + 1e-9)
      throw InputError(field, who + " is a " + kind + " whose walls rise " + std::to_string(front) +
                                  " m, above the house's " + std::to_string(height) + " m; not built in stone");
    PlanBay bay;
    bay.top = std::min(front, height);
    bay.lower = front < height - 1e-9;
    bay.instance = int(i);
    bay.source = source;
    bay.edge = edge;
    bay.from = u - st.width / 2;
    bay.to = u + st.width / 2;
    bay.depth = st.depth;
    bay.cant = st.shape == StepShape::Bay ? st.cant : 0.0;
    bay.field = field;
    bay.who = who;
    if (!(bay.from > 1e-9 && bay.to < edgeLength(std::size_t(edge)) - 1e-9))
      throw InputError(field, who + " reaches past the end of its plan edge " + std::to_string(edge) +
                                  "; a " + kind + " in stone opens one edge's wall");
    bays.push_back(bay);
  }
  std::sort(bays.begin(), bays.end(), [](const PlanBay& a, const PlanBay& b) { return std::tie(a.edge, a.from) < std::tie(b.edge, b.from); });
  for (std::size_t k = 1; k < bays.size(); ++k)
    if (bays[k].edge == bays[k - 1].edge && bays[k].from < bays[k - 1].to + 1e-9)
      throw InputError(bays[k].field, bays[k].who + " meets " + bays[k - 1].who + " on plan edge " +
                                          std::to_string(bays[k].edge));

  // Bays lower than the walls all rise to one height, where the wall above spans their mouths
  // (the first in the file sets it).
  const PlanBay* setter = nullptr;
  for (const PlanBay& b : bays)
    if (b.lower && (!setter || b.instance < setter->instance)) setter = &b;
  if (setter) house.bayTop = setter->top;
  for (const PlanBay& b : bays)
    if (b.lower && std::abs(b.top - house.bayTop) > 1e-9)
      throw InputError(b.field, b.who + "'s walls rise " + std::to_string(b.top) + " m and " + setter->who + "'s " +
                                    std::to_string(house.bayTop) + " m: the bays and recesses lower than the walls "
                                    "must have one height");
  const bool banded = house.bayTop > 0;

  // The coursed plans: at the ground with every bay; above the lower bays' head without them.
  const BrokenPlan ground = brokenPlan(loop, bays, true);
  house.walls.plan = ground.points;
  house.edgeSource = ground.source;
  house.edgeOffset = ground.offset;
  for (const PlanBay& b : bays) house.bayStep.push_back(b.source);
  BrokenPlan above;
  if (banded) {
    above = brokenPlan(loop, bays, false);
    house.upper.plan = above.points;
    house.upper.base = spec.baseZ;
    house.upper.height = height;
    house.upperSource = above.source;
    house.upperOffset = above.offset;
  }
  const std::size_t m = ground.points.size();
  auto bayAcross = [&](int e, double from, double to) -> const PlanBay* {
    for (const PlanBay& b : bays)
      if (b.edge == e && from < b.to && b.from < to) return &b;
    return nullptr;
  };

  // The roof from the extrusion with its bays and recesses (without buttresses: they stand
  // against the walls): a main edge's faces bear on its wall (spread evenly along its pieces,
  // above the lower bays where there are some), a bay's on the bay's wall that traced them.
  ExtrusionSpec roofed = spec;  // its anchors as written (their repeats expanded by extrude)
  roofed.steps.clear();
  for (const PlanBay& b : bays) roofed.steps.push_back(expanded.spec.steps[std::size_t(b.instance)]);
  const extrude::ExtrusionResult shell = extrude::extrude(roofed);
  house.roofArea.assign(m, 0.0);
  house.thrustArea.assign(m, 0.0);
  house.upperRoofArea.assign(above.points.size(), 0.0);
  house.upperThrustArea.assign(above.points.size(), 0.0);
  constexpr double kFlat = 5.0 * std::numbers::pi / 180.0;
  for (const extrude::ShellFace& f : shell.shell.faces) {
    if (f.base || f.segment < 1 || !(f.normal[2] > 1e-6)) continue;
    const bool onBay = f.step >= 0 && std::size_t(f.step) < bays.size() && f.sourceEdge >= 0 && f.sourceEdge < 3;
    const bool onMain = f.step < 0 && f.sourceLoop == 0 && f.sourceEdge >= 0 && std::size_t(f.sourceEdge) < n;
    if (!onBay && !onMain) continue;
    const bool up = banded && !(onBay && bays[std::size_t(f.step)].lower);
    const BrokenPlan& plan = up ? above : ground;
    std::vector<double>& area = up ? house.upperRoofArea : house.roofArea;
    std::vector<double>& thrust = up ? house.upperThrustArea : house.thrustArea;
    std::vector<std::pair<std::size_t, double>> shares;  // (edge of the plan, fraction)
    double along = 0;
    for (std::size_t k = 0; k < plan.points.size(); ++k)
      if (onMain && plan.source[k] == f.sourceEdge) along += plan.length(k);
    for (std::size_t k = 0; k < plan.points.size(); ++k) {
      if (onBay && plan.bayEdge[k][0] == f.step && plan.bayEdge[k][1] == f.sourceEdge) shares.emplace_back(k, 1.0);
      if (onMain && plan.source[k] == f.sourceEdge) shares.emplace_back(k, plan.length(k) / along);
    }
    const double a = extrude::faceArea(shell.shell, f);
    const double pitch = std::acos(std::clamp(f.normal[2], -1.0, 1.0));
    for (const auto& [k, share] : shares) {
      area[k] += a * share;
      if (pitch >= kFlat) thrust[k] += a * share / (2 * std::tan(pitch));
    }
    house.roofPitchDeg = std::max(house.roofPitchDeg, pitch * 180 / std::numbers::pi);
  }

  // Openings at door and window anchors (every instance of a repeat), placed on the extrusion
  // without its steps, on the piece of their edge that holds them; one over a lower bay's
  // mouth goes on the wall above it.
  ExtrusionSpec bare = spec;
  bare.steps.clear();
  const extrude::ExtrusionResult anchored = bays.empty() ? shell : extrude::extrude(bare);
  for (const extrude::AnchorFrame& a : anchored.anchors) {
    if (!a.instanced || a.source < 0) continue;
    const MeshAnchor& ma = spec.anchors[std::size_t(a.source)];
    if (ma.feature != FeatureKind::Door && ma.feature != FeatureKind::Window) continue;
    const int e = ma.anchor.edge;
    if (ma.anchor.loop != 0 || e < 0 || std::size_t(e) >= n) continue;
    const Vec2 p0 = loop.points[std::size_t(e)], d = (loop.points[(std::size_t(e) + 1) % n] - p0) / edgeLength(std::size_t(e));
    const double u = dot(Vec2(a.position[0], a.position[1]) - p0, d);
    WallOpening o;
    o.name = a.name;
    o.from = u - ma.size.width / 2;
    o.to = u + ma.size.width / 2;
    o.bottom = a.position[2] - spec.baseZ;
    o.top = o.bottom + ma.size.height;
    const char* what = ma.feature == FeatureKind::Door ? "door" : "window";
    o.edge = ground.pieceOf(e, o.from, o.to);
    if (o.edge >= 0) {
      o.from -= ground.offset[std::size_t(o.edge)];
      o.to -= ground.offset[std::size_t(o.edge)];
      house.walls.openings.push_back(o);
      continue;
    }
    const PlanBay* b = bayAcross(e, o.from, o.to);
    const int piece = banded && b && b->lower ? above.pieceOf(e, o.from, o.to) : -1;
    if (piece < 0)
      throw InputError(b ? b->field : "masonry.openings." + ma.name,
                       (b ? b->who + " opens the wall where " : std::string("")) + "the " + what + " \"" + a.name +
                           "\" is" + (b ? "" : " (it leaves its wall)"));
    o.edge = piece;
    o.from -= above.offset[std::size_t(piece)];
    o.to -= above.offset[std::size_t(piece)];
    house.upper.openings.push_back(o);
  }

  // The lower bays' mouths: the wall above spans each on a lintel.
  for (const PlanBay& b : bays) {
    if (!b.lower) continue;
    const int piece = above.pieceOf(b.edge, b.from, b.to);
    if (piece < 0) throw InputError(b.field, b.who + " is not on one wall of the plan above it");
    WallOpening mouth;
    mouth.name = "the mouth of " + b.field;
    mouth.edge = piece;
    mouth.from = b.from - above.offset[std::size_t(piece)];
    mouth.to = b.to - above.offset[std::size_t(piece)];
    mouth.bottom = -b.top;
    mouth.top = 0;
    house.mouths.push_back(mouth);
  }

  // Buttresses on the pieces of their edges.
  for (PlacedButtress& p : buttresses) {
    const int piece = ground.pieceOf(p.b.edge, p.b.from, p.b.to);
    if (piece < 0) {
      const PlanBay* b = bayAcross(p.b.edge, p.b.from, p.b.to);
      throw InputError("steps[" + std::to_string(p.source) + "]",
                       "the buttress \"" + p.b.name + "\" " +
                           (b ? "stands where " + b->who + " opens the wall" : std::string("leaves its plan edge")));
    }
    p.b.from -= ground.offset[std::size_t(piece)];
    p.b.to -= ground.offset[std::size_t(piece)];
    p.b.edge = piece;
    house.walls.buttresses.push_back(p.b);
    house.buttressStep.push_back(p.source);
  }
  return house;
}

std::vector<WallButtress> proposedButtresses(const StoneHouse& house, double blockLength, double courseHeight,
                                             double thickness) {
  const std::vector<Vec2>& plan = house.walls.plan;
  const std::size_t n = plan.size();
  const double b = blockLength, width = blockLength, clearance = courseHeight + 0.75 * b, sliver = b / 4;
  auto direction = [&](std::size_t e) {
    const Vec2 v = plan[(e + 1) % n] - plan[e];
    return Vec2(v / v.norm());
  };
  // How far a corner's square reaches along both faces: t·tan(turn / 2).
  auto square = [&](std::size_t corner) {
    const Vec2 in = direction((corner + n - 1) % n), out = direction(corner);
    const double turn = std::atan2(in[0] * out[1] - in[1] * out[0], dot(in, out));
    return thickness * std::tan(std::max(0.0, turn) / 2);
  };
  std::vector<WallButtress> kept;
  for (std::size_t e = 0; e < n; ++e) {
    if (e < house.edgeSource.size() && house.edgeSource[e] < 0) continue;  // a bay's own wall
    const double length = (plan[(e + 1) % n] - plan[e]).norm();
    const double lo = square(e) + sliver, hi = length - square((e + 1) % n) - sliver;
    const int m = std::max(1, int(std::floor(length / house.walls.height)));
    // What a pier keeps clear of: the openings of this wall and the lintels over lower bays'
    // mouths beside it, on the wall above (in this wall's coordinates).
    std::vector<WallOpening> keepOut;
    for (const WallOpening& o : house.walls.openings)
      if (o.edge == int(e)) keepOut.push_back(o);
    for (WallOpening o : house.mouths) {
      if (e >= house.edgeSource.size() || house.upperSource[std::size_t(o.edge)] != house.edgeSource[e]) continue;
      const double shift = house.upperOffset[std::size_t(o.edge)] - house.edgeOffset[e];
      o.from += shift;
      o.to += shift;
      keepOut.push_back(o);
    }
    std::vector<std::pair<double, int>> centres;  // (centre, how many times moved)
    for (int k = 1; k <= m; ++k) centres.emplace_back(length * k / (m + 1), 0);
    int index = 0;
    for (std::size_t c = 0; c < centres.size(); ++c) {
      const auto [centre, moved] = centres[c];
      const double from = centre - width / 2, to = centre + width / 2;
      bool clear = from >= lo && to <= hi;
      for (const WallOpening& o : keepOut) {
        if (!(from < o.to + clearance && o.from - clearance < to)) continue;
        clear = false;
        if (moved < 2) {
          centres.emplace_back(o.from - clearance - width / 2, moved + 1);
          centres.emplace_back(o.to + clearance + width / 2, moved + 1);
        }
        break;
      }
      for (const WallButtress& k : kept)
        clear = clear && !(k.edge == int(e) && from < k.to + sliver && k.from - sliver < to);
      if (!clear) continue;
      WallButtress w;
      w.name = "buttress " + std::to_string(e) + "." + std::to_string(index++);
      w.edge = int(e);
      w.from = from;
      w.to = to;
      w.depth = 0;
      w.top = house.walls.height;
      kept.push_back(w);
    }
  }
  return kept;
}

namespace {

std::vector<HeadLoad> headLoads(const std::vector<Vec2>& plan, const std::vector<double>& area,
                                const std::vector<double>& thrust, double coveringWeight, bool ties) {
  std::vector<HeadLoad> loads(plan.size());
  for (std::size_t e = 0; e < plan.size(); ++e) {
    const double length = (plan[(e + 1) % plan.size()] - plan[e]).norm();
    loads[e].down = coveringWeight * area[e] / length;
    loads[e].out = ties ? 0.0 : coveringWeight * thrust[e] / length;
  }
  return loads;
}

}  // namespace

std::vector<HeadLoad> roofLoads(const StoneHouse& house, double coveringWeight, bool ties) {
  return headLoads(house.walls.plan, house.roofArea, house.thrustArea, coveringWeight, ties);
}

namespace {

// The buttresses at the model's values: the extrusion's own scaled to `buttressDepth` (deepest
// being their deepest), or proposed ones of that depth where it has none.
std::vector<WallButtress> buttressesAt(const StoneHouse& house, double deepest, const ParameterSet& p) {
  const double depth = p["buttressDepth"];
  std::vector<WallButtress> out;
  if (deepest > 0) {
    out = house.walls.buttresses;
    for (WallButtress& b : out) b.depth *= depth / deepest;
  } else if (depth >= kMinButtressDepth) {
    out = proposedButtresses(house, p["blockLength"], p["courseHeight"], p["thickness"]);
    for (WallButtress& b : out) b.depth = depth;
  }
  return out;
}

// The walls of a house with bays lower than its walls in two bands, from the ground plan's
// spec `s` (the model's numbers set): below the bays' head (snapped to a course joint, at
// least one course each side) the ground plan with every opening, buttress and bay; above it
// the plan without the lower bays, going on with the courses' bond, the wall spanning each
// lower bay's mouth on a lintel, with the openings over the mouths and the parts of the others
// and of the buttresses that reach it.
std::pair<CoursingSpec, CoursingSpec> bands(const StoneHouse& house, const CoursingSpec& s) {
  if (!(std::isfinite(s.courseHeight) && s.courseHeight > 0 && std::isfinite(s.height) && s.height > 0))
    throw Error("coursing: height and course height must be positive numbers");
  const int courses = std::max(1, int(std::lround(s.height / s.courseHeight)));
  if (courses < 2) throw Error("stone house: a bay lower than the walls needs at least two courses");
  const double ch = s.height / courses;
  const int kb = std::clamp(int(std::lround(house.bayTop / ch)), 1, courses - 1);
  const double zb = kb * ch;
  CoursingSpec lower = s, upper = s;
  lower.height = zb;
  lower.courseHeight = ch;
  lower.openings.clear();
  upper.plan = house.upper.plan;
  upper.base = s.base + zb;
  upper.height = s.height - zb;
  upper.courseHeight = ch;
  upper.firstCourse = kb;
  upper.openings.clear();
  upper.buttresses.clear();
  // From a piece of the ground plan to the piece of the plan above that holds [from, to].
  auto lifted = [&](int edge, double& from, double& to, const std::string& who) {
    const int source = house.edgeSource[std::size_t(edge)];
    const double at = house.edgeOffset[std::size_t(edge)];
    for (std::size_t k = 0; k < house.upperSource.size(); ++k) {
      const double len = (upper.plan[(k + 1) % upper.plan.size()] - upper.plan[k]).norm();
      if (house.upperSource[k] == source && at + from >= house.upperOffset[k] - 1e-9 &&
          at + to <= house.upperOffset[k] + len + 1e-9) {
        from += at - house.upperOffset[k];
        to += at - house.upperOffset[k];
        return int(k);
      }
    }
    throw Error("stone house: " + who + " reaches above the bays' head on no wall");
  };
  for (const WallOpening& o : s.openings) {
    const int sill = std::max(0, int(std::lround(o.bottom / ch)));
    const int head = std::max(int(std::lround(o.top / ch)), sill + 1);
    if (head < kb) {  // below the bays' head, with its own
      lower.openings.push_back(o);
      continue;
    }
    WallOpening up = o;
    up.edge = lifted(o.edge, up.from, up.to, "opening \"" + o.name + "\"");
    up.bottom = sill < kb ? -zb : o.bottom - zb;
    up.top = (head - kb) * ch;
    upper.openings.push_back(up);
    if (sill < kb) {
      WallOpening low = o;
      low.throughHead = true;
      lower.openings.push_back(low);
    }
  }
  for (WallOpening o : house.upper.openings) {
    if (int(std::lround(o.bottom / ch)) < kb)
      throw Error("stone house: the opening \"" + o.name + "\" over a bay's mouth starts below the bay's head");
    o.bottom -= zb;
    o.top -= zb;
    upper.openings.push_back(o);
  }
  for (WallOpening mouth : house.mouths) {
    mouth.bottom = -zb;
    upper.openings.push_back(mouth);
  }
  for (const WallButtress& b : s.buttresses) {
    if (std::clamp(int(std::lround(b.top / ch)), 1, courses) <= kb) continue;
    WallButtress up = b;
    up.edge = lifted(b.edge, up.from, up.to, "buttress \"" + b.name + "\"");
    up.top = b.top - zb;
    upper.buttresses.push_back(up);
  }
  return {lower, upper};
}

}  // namespace

ParametricModel stoneModel(const ExtrusionSpec& spec) {
  if (!spec.masonry) throw InputError("masonry", "the extrusion has no masonry section");
  const StoneWalls& m = *spec.masonry;
  StoneHouse house = stoneHouseOf(spec);
  // Heads by anchor name; every name must be a door or window anchor.
  std::set<std::string> named;
  for (const MeshAnchor& a : spec.anchors)
    if (a.feature == FeatureKind::Door || a.feature == FeatureKind::Window) named.insert(a.name);
  for (const StoneOpening& o : m.openings) {
    if (!named.count(o.anchor))
      throw InputError("masonry.openings." + o.anchor, "no door or window anchor named \"" + o.anchor + "\"");
    for (WallOpening& w : house.walls.openings)
      if (w.name == o.anchor || w.name.rfind(o.anchor + " (", 0) == 0) w.head = o.head;
  }
  // The ranges follow the input plan's shortest edge (a bay's short cheeks are checked where
  // the walls are coursed).
  const std::vector<Vec2>& input = spec.loops[0].points;
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < input.size(); ++e)
    shortest = std::min(shortest, (input[(e + 1) % input.size()] - input[e]).norm());
  ParametricModel model;
  model.name = kStoneModelName;
  model.description = "the extrusion's walls coursed in stone, loaded by its roof";
  auto add = [&](const char* name, double value, double lo, double hi, bool continuous, const char* what) {
    if (value < lo || value > hi)
      throw InputError(std::string("masonry.") + name, std::to_string(value) + " is outside [" + std::to_string(lo) +
                                                           ", " + std::to_string(hi) + "]");
    model.parameters.add({name, value, lo, hi, continuous, what});
  };
  add("thickness", m.thickness, 0.05, shortest / 3, true, "wall thickness, m");
  add("courseHeight", m.courseHeight, 0.05, house.walls.height, true, "course height, m");
  add("blockLength", m.blockLength, 0.1, shortest, true, "block length, m");
  add("coveringWeight", m.coveringWeight, 0.0, 1e6, true, "roof covering weight, N/m²");
  add("density", m.density, 1.0, 1e5, true, "wall stone density, kg/m³");
  add("ties", m.ties ? 1.0 : 0.0, 0.0, 1.0, false, "1: tie beams, no roof thrust");
  add("windPressure", m.windPressure, 0.0, 1e5, true, "wind pressure on the walls, N/m²");
  add("windDirection", m.windDirection, -360.0, 360.0, true, "the way the wind blows, degrees from +x");
  double deepest = 0;
  for (const WallButtress& b : house.walls.buttresses) deepest = std::max(deepest, b.depth);
  add("buttressDepth", deepest, deepest > 0 ? std::min(deepest, kMinButtressDepth) : 0.0, std::max(deepest, house.walls.height), true,
      "the deepest buttress's depth, m (others in proportion); 0: none, more adds buttresses");
  model.build = [house, deepest](const ParameterSet& p) {
    CoursingSpec s = house.walls;
    s.thickness = p["thickness"];
    s.courseHeight = p["courseHeight"];
    s.blockLength = p["blockLength"];
    s.density = p["density"];
    s.buttresses = buttressesAt(house, deepest, p);
    const double towards = p["windDirection"] * std::numbers::pi / 180;
    const Vec2 wind(std::cos(towards), std::sin(towards));
    Assembly as;
    if (house.bayTop <= 0) {
      CoursedWalls w = courseWalls(s);
      loadHeadsOnPiers(s, w, roofLoads(house, p["coveringWeight"], p["ties"] != 0));
      loadWind(s, w, p["windPressure"], wind);
      as.blocks = std::move(w.blocks);
    } else {
      auto [lower, upper] = bands(house, s);
      CoursedWalls below = courseWalls(lower), above = courseWalls(upper);
      loadHeadsOnPiers(lower, below, roofLoads(house, p["coveringWeight"], p["ties"] != 0));
      loadHeadsOnPiers(upper, above,
                    headLoads(upper.plan, house.upperRoofArea, house.upperThrustArea, p["coveringWeight"], p["ties"] != 0));
      loadWind(lower, below, p["windPressure"], wind);
      loadWind(upper, above, p["windPressure"], wind);
      as.blocks = std::move(below.blocks);
      as.blocks.insert(as.blocks.end(), above.blocks.begin(), above.blocks.end());
    }
    BBox box;
    for (const Vec2& q : s.plan) box.add(Vec3(q[0], q[1], 0.0));
    as.blocks.push_back(boxBlock("ground", Vec3(box.lo[0] - 1, box.lo[1] - 1, s.base - 1),
                                 Vec3(box.hi[0] + 1, box.hi[1] + 1, s.base), 1.0, true));
    return as;
  };
  model.suggestedFree = {{"thickness", m.thickness, std::min(shortest / 3, 3 * m.thickness)}};
  if (deepest > 0) model.suggestedFree.push_back({"buttressDepth", deepest, std::max(deepest, house.walls.height)});
  return model;
}

StoneWalls stoneWallsAt(const StoneWalls& section, const ParameterSet& values) {
  StoneWalls m = section;
  auto take = [&](const char* name, double& out) {
    if (values.has(name)) out = values[name];
  };
  take("thickness", m.thickness);
  take("courseHeight", m.courseHeight);
  take("blockLength", m.blockLength);
  take("coveringWeight", m.coveringWeight);
  take("density", m.density);
  take("windPressure", m.windPressure);
  take("windDirection", m.windDirection);
  if (values.has("ties")) m.ties = values["ties"] != 0;
  return m;
}

}  // namespace corbel::statics

namespace corbel::statics {

ExtrusionSpec stoneSpecAt(const ExtrusionSpec& spec, const ParameterSet& values) {
  if (!spec.masonry) throw InputError("masonry", "the extrusion has no masonry section");
  ExtrusionSpec out = spec;
  out.masonry = stoneWallsAt(*spec.masonry, values);
  if (!values.has("buttressDepth")) return out;
  const StoneHouse house = stoneHouseOf(spec);
  double deepest = 0;
  for (const WallButtress& b : house.walls.buttresses) deepest = std::max(deepest, b.depth);
  const double depth = values["buttressDepth"];
  if (deepest > 0) {
    std::set<int> scaled;
    for (int step : house.buttressStep)
      if (scaled.insert(step).second) out.steps[std::size_t(step)].depth *= depth / deepest;
    return out;
  }
  if (depth < kMinButtressDepth) return out;
  const std::vector<WallButtress> proposed =
      proposedButtresses(house, out.masonry->blockLength, out.masonry->courseHeight, out.masonry->thickness);
  if (proposed.empty()) return out;
  // A profile of their own: vertical to the wall head, then leaning in at 60° (a weathering).
  std::string name = "buttress";
  for (int k = 2; std::any_of(out.profiles.begin(), out.profiles.end(), [&](const Profile& p) { return p.name == name; }); ++k)
    name = "buttress " + std::to_string(k);
  const double h = house.walls.height;
  out.profiles.push_back({name, {Vec2(0, 0), Vec2(0, h), Vec2(1, h + std::sqrt(3.0))}, {"buttress", "buttress slope"}});
  const int profile = int(out.profiles.size()) - 1;
  for (const WallButtress& b : proposed) {
    // Back from the coursed plan's piece to the input edge it lies on.
    const int edge = house.edgeSource[std::size_t(b.edge)];
    const double offset = house.edgeOffset[std::size_t(b.edge)];
    const WallRun run = wallRun(out, 0, edge);
    PlanStep st;
    st.name = b.name;
    st.anchor = Anchor{0, edge, false, alongWall(out, 0, edge, offset + 0.5 * (b.from + b.to)) / run.length, 0.0};
    st.shape = StepShape::Rectangle;
    st.width = out.masonry->blockLength;  // as proposedButtresses lays them
    st.depth = depth;
    st.frontProfile = st.sideProfile = profile;
    out.steps.push_back(st);
  }
  return out;
}

}  // namespace corbel::statics
