// Presets reproducing the looks of McGraw's figures (docs/kifs.md, "Presets").
#include "core/error.h"
#include "kifs/params.h"

#include <functional>
#include <map>
#include <numbers>

namespace corbel::kifs {

namespace {

KifsParams boxBuilding() {  // Fig. 1b and Fig. 7 (left): c = (0.93, 0.93, 0.33) on a box
  KifsParams p;
  p.centre = {0.93, 0.93, 0.33};
  p.facade.a2 = 2.0;
  p.facade.b2 = 0.1;
  return p;
}

KifsParams menger() {  // Fig. 1a: s = 3, c = (1, 1, 1), R1 = R2 = I on a box
  KifsParams p = boxBuilding();
  p.centre = {1.0, 1.0, 1.0};
  return p;
}

KifsParams tBuilding() {  // Fig. 8 (left): T footprint
  KifsParams p = boxBuilding();
  p.mass.footprint = Footprint::T;
  p.mass.halfWidth = 12.0;
  p.mass.halfDepth = 9.0;
  p.mass.wing = 3.5;
  p.mass.height = 18.0;
  p.r2.yDeg = 22.5;  // R2 = Ry(π/8), Fig. 2d
  return p;
}

KifsParams hBuilding() {  // Fig. 8 (right): H footprint, facade ids select fractal regions
  KifsParams p = boxBuilding();
  p.mass.footprint = Footprint::H;
  p.mass.halfWidth = 12.0;
  p.mass.halfDepth = 10.0;
  p.mass.wing = 3.5;
  p.mass.height = 15.0;
  p.facade.a1 = 0.5;
  p.facade.b1 = 0.15;
  return p;
}

KifsParams polarTower() {  // Fig. 7 (middle, right): curvilinear coordinates, a ring of a tower
  KifsParams p = boxBuilding();
  p.curvilinear.enabled = true;
  p.curvilinear.sTheta = 36.0 / std::numbers::pi;  // the circumference 2π·s_θ is 12 facade periods
  p.curvilinear.sR = 1.0;
  p.curvilinear.cR = -10.0;
  p.curvilinear.cTheta = 0.0;
  p.mass.halfWidth = 40.0;  // wider than s_θ·π: the whole ring, with no seam
  p.mass.halfDepth = 2.5;
  p.mass.shell = 1.0;
  p.mass.height = 30.0;
  return p;
}

const std::map<std::string, std::function<KifsParams()>>& table() {
  static const std::map<std::string, std::function<KifsParams()>> t = {
      {"box", boxBuilding}, {"menger", menger}, {"t", tBuilding}, {"h", hBuilding}, {"polar", polarTower}};
  return t;
}

}  // namespace

std::vector<std::string> presetNames() {
  std::vector<std::string> out;
  for (const auto& [name, make] : table()) out.push_back(name);
  return out;
}

KifsParams preset(const std::string& name) {
  auto it = table().find(name);
  if (it == table().end()) {
    std::string names;
    for (const auto& n : presetNames()) names += (names.empty() ? "" : ", ") + n;
    throw Error("no KIFS preset named '" + name + "' (presets: " + names + ")");
  }
  return it->second();
}

}  // namespace corbel::kifs
