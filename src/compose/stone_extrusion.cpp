#include "compose/stone_extrusion.h"

#include "core/error.h"
#include "extrude/extrude.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>

namespace corbel::statics {

StoneHouse stoneHouseOf(const ExtrusionSpec& spec) {
  if (spec.loops.size() != 1) throw InputError("plan.loops", "a stone house is built on one plan loop (no holes or islands)");
  if (!spec.offsets.empty()) throw InputError("offsets", "offset events are not built in stone yet");
  const PlanLoop& loop = spec.loops[0];
  StoneHouse house;
  house.walls.plan = loop.points;
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

  // The roof and the openings from the extrusion without its steps: the roof bears on the
  // main walls, the buttresses stand against them.
  ExtrusionSpec bare = spec;
  bare.steps.clear();
  const extrude::ExtrusionResult shell = extrude::extrude(bare);
  const std::size_t n = loop.points.size();
  house.roofArea.assign(n, 0.0);
  house.thrustArea.assign(n, 0.0);
  constexpr double kFlat = 5.0 * std::numbers::pi / 180.0;
  for (const extrude::ShellFace& f : shell.shell.faces) {
    if (f.base || f.segment < 1 || f.sourceLoop != 0 || f.step >= 0 || !(f.normal[2] > 1e-6)) continue;
    if (f.sourceEdge < 0 || std::size_t(f.sourceEdge) >= n) continue;
    const double area = extrude::faceArea(shell.shell, f);
    const double pitch = std::acos(std::clamp(f.normal[2], -1.0, 1.0));
    house.roofArea[std::size_t(f.sourceEdge)] += area;
    if (pitch >= kFlat) house.thrustArea[std::size_t(f.sourceEdge)] += area / (2 * std::tan(pitch));
    house.roofPitchDeg = std::max(house.roofPitchDeg, pitch * 180 / std::numbers::pi);
  }

  // Openings at door and window anchors (every instance of a repeat).
  for (const extrude::AnchorFrame& a : shell.anchors) {
    if (!a.instanced || a.source < 0) continue;
    const MeshAnchor& m = spec.anchors[std::size_t(a.source)];
    if (m.feature != FeatureKind::Door && m.feature != FeatureKind::Window) continue;
    WallOpening o;
    o.name = a.name;
    o.edge = m.anchor.edge;
    if (m.anchor.loop != 0 || o.edge < 0 || std::size_t(o.edge) >= n) continue;
    const Vec2 p0 = loop.points[std::size_t(o.edge)], p1 = loop.points[(std::size_t(o.edge) + 1) % n];
    const Vec2 d = (p1 - p0) / (p1 - p0).norm();
    const double u = dot(Vec2(a.position[0], a.position[1]) - p0, d);
    o.from = u - m.size.width / 2;
    o.to = u + m.size.width / 2;
    o.bottom = a.position[2] - spec.baseZ;
    o.top = o.bottom + m.size.height;
    house.walls.openings.push_back(o);
  }

  // Buttresses: the rectangle steps standing on the ground, every instance.
  const ExpandedSpec expanded = expandRepeats(spec);
  for (std::size_t i = 0; i < expanded.spec.steps.size(); ++i) {
    const PlanStep& st = expanded.spec.steps[i];
    const int source = expanded.stepSource[i];
    const std::string field = "steps[" + std::to_string(source) + "]";
    const std::string who = "the step \"" + st.name + "\"";
    if (st.shape != StepShape::Rectangle)
      throw InputError(field, who + " is a " + (st.shape == StepShape::Bay ? "bay" : "forced step") +
                                  "; only rectangle steps (buttresses) are built in stone yet");
    if (!(st.depth > 0)) throw InputError(field, who + " is a recess; only buttresses (depth > 0) are built in stone");
    if (std::abs(st.anchor.height) > 1e-9 || st.anchor.loop != 0)
      throw InputError(field, who + " does not stand on the ground of the plan; only buttresses from the foot of "
                                    "the walls are built in stone");
    const Profile& front = spec.profiles.at(std::size_t(st.frontProfile));
    if (front.points.size() < 2 || front.points[1][0] != 0 || !(front.points[1][1] > 0))
      throw InputError(field, who + "'s front profile \"" + front.name + "\" does not start with a vertical wall");
    const std::optional<Vec2> at = anchorPoint(spec, st.anchor);
    if (!at) throw InputError(field, who + " is anchored to no edge of the plan");
    // The edge of its wall's run that holds the anchor point.
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
    WallButtress b;
    b.name = st.name.empty() ? field : st.name;
    b.edge = edge;
    b.from = u - st.width / 2;
    b.to = u + st.width / 2;
    b.depth = st.depth;
    b.top = std::min(front.points[1][1], height);
    house.walls.buttresses.push_back(b);
    house.buttressStep.push_back(source);
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
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < house.walls.plan.size(); ++e)
    shortest = std::min(shortest, (house.walls.plan[(e + 1) % house.walls.plan.size()] - house.walls.plan[e]).norm());
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
    const WallRun run = wallRun(out, 0, b.edge);
    PlanStep st;
    st.name = b.name;
    st.anchor = Anchor{0, b.edge, false, alongWall(out, 0, b.edge, 0.5 * (b.from + b.to)) / run.length, 0.0};
    st.shape = StepShape::Rectangle;
    st.width = out.masonry->blockLength;  // as proposedButtresses lays them
    st.depth = depth;
    st.frontProfile = st.sideProfile = profile;
    out.steps.push_back(st);
  }
  return out;
}

}  // namespace corbel::statics
