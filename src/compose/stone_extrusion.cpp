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
  if (!spec.steps.empty()) throw InputError("steps", "steps are not built in stone yet; remove them or the masonry section");
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

  const extrude::ExtrusionResult shell = extrude::extrude(spec);
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
  return house;
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
  model.build = [house](const ParameterSet& p) {
    CoursingSpec s = house.walls;
    s.thickness = p["thickness"];
    s.courseHeight = p["courseHeight"];
    s.blockLength = p["blockLength"];
    s.density = p["density"];
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
