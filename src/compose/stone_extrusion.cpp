#include "compose/stone_extrusion.h"

#include "core/error.h"
#include "extrude/extrude.h"

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
  std::string field, who;
};

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
    // as high as the house's.
    const double side = wallHeightOf(spec.profiles.at(std::size_t(st.sideProfile)), field, who + "'s side profile");
    const char* kind = st.depth > 0 ? "bay" : "recess";
    if (std::abs(front - height) > 1e-9 || std::abs(side - height) > 1e-9)
      throw InputError(field, who + " is a " + kind + " whose walls rise " + std::to_string(std::min(front, side)) +
                                  " m (its front and side profiles' first segments) and the house's " +
                                  std::to_string(height) + " m; only " + kind +
                                  "s as high as the walls are built in stone (a lower one needs the wall over "
                                  "its mouth carried)");
    PlanBay bay;
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

  // The coursed plan: each input edge, broken where a bay or recess opens it, with the bay's
  // cheeks and front between the pieces.
  std::vector<std::array<int, 2>> bayEdge;  // per coursed edge: (index into bays, side 0-2) or -1
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 p0 = loop.points[e], d = (loop.points[(e + 1) % n] - p0) / edgeLength(e);
    const Vec2 out(d[1], -d[0]);  // outward, right of the edge
    house.walls.plan.push_back(p0);
    house.edgeSource.push_back(int(e));
    house.edgeOffset.push_back(0.0);
    bayEdge.push_back({-1, -1});
    for (std::size_t k = 0; k < bays.size(); ++k) {
      const PlanBay& b = bays[k];
      if (b.edge != int(e)) continue;
      const std::array<Vec2, 4> corners = {p0 + d * b.from, p0 + d * (b.from + b.cant) + out * b.depth,
                                           p0 + d * (b.to - b.cant) + out * b.depth, p0 + d * b.to};
      for (int j = 0; j < 3; ++j) {
        house.walls.plan.push_back(corners[std::size_t(j)]);
        house.edgeSource.push_back(-1);
        house.edgeOffset.push_back(0.0);
        bayEdge.push_back({int(k), j});
      }
      house.walls.plan.push_back(corners[3]);
      house.edgeSource.push_back(int(e));
      house.edgeOffset.push_back(b.to);
      bayEdge.push_back({-1, -1});
    }
  }
  for (const PlanBay& b : bays) house.bayStep.push_back(b.source);
  const std::size_t m = house.walls.plan.size();
  auto pieceLength = [&](std::size_t k) { return (house.walls.plan[(k + 1) % m] - house.walls.plan[k]).norm(); };
  // The piece of input edge e holding [from, to], or -1.
  auto pieceOf = [&](int e, double from, double to) {
    for (std::size_t k = 0; k < m; ++k)
      if (house.edgeSource[k] == e && from >= house.edgeOffset[k] - 1e-9 &&
          to <= house.edgeOffset[k] + pieceLength(k) + 1e-9)
        return int(k);
    return -1;
  };
  auto bayAcross = [&](int e, double from, double to) -> const PlanBay* {
    for (const PlanBay& b : bays)
      if (b.edge == e && from < b.to && b.from < to) return &b;
    return nullptr;
  };

  // The roof from the extrusion with its bays and recesses (without buttresses: they stand
  // against the walls): the main shell's faces bear on the walls of the edge that traced them,
  // spread evenly along its pieces; a bay's roof faces on the bay's wall that traced them.
  ExtrusionSpec roofed = spec;  // its anchors as written (their repeats expanded by extrude)
  roofed.steps.clear();
  for (const PlanBay& b : bays) roofed.steps.push_back(expanded.spec.steps[std::size_t(b.instance)]);
  const extrude::ExtrusionResult shell = extrude::extrude(roofed);
  house.roofArea.assign(m, 0.0);
  house.thrustArea.assign(m, 0.0);
  std::vector<double> sourceLength(n, 0.0);
  for (std::size_t k = 0; k < m; ++k)
    if (house.edgeSource[k] >= 0) sourceLength[std::size_t(house.edgeSource[k])] += pieceLength(k);
  constexpr double kFlat = 5.0 * std::numbers::pi / 180.0;
  for (const extrude::ShellFace& f : shell.shell.faces) {
    if (f.base || f.segment < 1 || !(f.normal[2] > 1e-6)) continue;
    std::vector<std::pair<std::size_t, double>> shares;  // (coursed edge, fraction)
    if (f.step >= 0 && std::size_t(f.step) < bays.size() && f.sourceEdge >= 0 && f.sourceEdge < 3) {
      for (std::size_t k = 0; k < m; ++k)
        if (bayEdge[k][0] == f.step && bayEdge[k][1] == f.sourceEdge) shares.emplace_back(k, 1.0);
    } else if (f.step < 0 && f.sourceLoop == 0 && f.sourceEdge >= 0 && std::size_t(f.sourceEdge) < n) {
      for (std::size_t k = 0; k < m; ++k)
        if (house.edgeSource[k] == f.sourceEdge)
          shares.emplace_back(k, pieceLength(k) / sourceLength[std::size_t(f.sourceEdge)]);
    }
    if (shares.empty()) continue;
    const double area = extrude::faceArea(shell.shell, f);
    const double pitch = std::acos(std::clamp(f.normal[2], -1.0, 1.0));
    for (const auto& [k, share] : shares) {
      house.roofArea[k] += area * share;
      if (pitch >= kFlat) house.thrustArea[k] += area * share / (2 * std::tan(pitch));
    }
    house.roofPitchDeg = std::max(house.roofPitchDeg, pitch * 180 / std::numbers::pi);
  }

  // Openings at door and window anchors (every instance of a repeat), placed on the extrusion
  // without its steps, on the piece of their edge that holds them.
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
    o.edge = pieceOf(e, o.from, o.to);
    if (o.edge < 0) {
      const PlanBay* b = bayAcross(e, o.from, o.to);
      throw InputError(b ? b->field : "masonry.openings." + ma.name,
                       (b ? b->who + " opens the wall where " : std::string("")) + "the " +
                           (ma.feature == FeatureKind::Door ? "door" : "window") + " \"" + a.name + "\" is" +
                           (b ? "" : " (it leaves its wall)"));
    }
    o.from -= house.edgeOffset[std::size_t(o.edge)];
    o.to -= house.edgeOffset[std::size_t(o.edge)];
    house.walls.openings.push_back(o);
  }

  // Buttresses on the pieces of their edges.
  for (PlacedButtress& p : buttresses) {
    const int piece = pieceOf(p.b.edge, p.b.from, p.b.to);
    if (piece < 0) {
      const PlanBay* b = bayAcross(p.b.edge, p.b.from, p.b.to);
      throw InputError("steps[" + std::to_string(p.source) + "]",
                       "the buttress \"" + p.b.name + "\" " +
                           (b ? "stands where " + b->who + " opens the wall" : std::string("leaves its plan edge")));
    }
    p.b.from -= house.edgeOffset[std::size_t(piece)];
    p.b.to -= house.edgeOffset[std::size_t(piece)];
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
    std::vector<std::pair<double, int>> centres;  // (centre, how many times moved)
    for (int k = 1; k <= m; ++k) centres.emplace_back(length * k / (m + 1), 0);
    int index = 0;
    for (std::size_t c = 0; c < centres.size(); ++c) {
      const auto [centre, moved] = centres[c];
      const double from = centre - width / 2, to = centre + width / 2;
      bool clear = from >= lo && to <= hi;
      for (const WallOpening& o : house.walls.openings) {
        if (o.edge != int(e) || !(from < o.to + clearance && o.from - clearance < to)) continue;
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

std::vector<HeadLoad> roofLoads(const StoneHouse& house, double coveringWeight, bool ties) {
  const std::vector<Vec2>& plan = house.walls.plan;
  std::vector<HeadLoad> loads(plan.size());
  for (std::size_t e = 0; e < plan.size(); ++e) {
    const double length = (plan[(e + 1) % plan.size()] - plan[e]).norm();
    loads[e].down = coveringWeight * house.roofArea[e] / length;
    loads[e].out = ties ? 0.0 : coveringWeight * house.thrustArea[e] / length;
  }
  return loads;
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
    CoursedWalls w = courseWalls(s);
    loadWallHeads(s, w, roofLoads(house, p["coveringWeight"], p["ties"] != 0));
    const double towards = p["windDirection"] * std::numbers::pi / 180;
    loadWind(s, w, p["windPressure"], Vec2(std::cos(towards), std::sin(towards)));
    BBox box;
    for (const Vec2& q : s.plan) box.add(Vec3(q[0], q[1], 0.0));
    Assembly as;
    as.blocks = std::move(w.blocks);
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
