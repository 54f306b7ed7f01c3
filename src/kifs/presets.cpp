// Presets reproducing the looks of McGraw's figures (docs/kifs.md, "Presets").
#include "core/error.h"
#include "kifs/params.h"

#include <functional>
#include <map>
#include <numbers>

namespace corbel::kifs {

namespace {

// Fig. 1b and Fig. 7 (left): c = (0.93, 0.93, 0.33) on a box. With r = 0 Algorithm 2 is the
// plain triangle wave, so each 6 m bay shows the fractal's face once, mirrored, and each 3 m
// storey the upper half of its slab (s = a2 = 1: isotropic, 3 m per fractal unit).
KifsParams boxBuilding() {
  KifsParams p;
  p.centre = {0.93, 0.93, 0.33};
  p.facade.r = {0.0, 0.0, 0.0};
  p.facade.a2 = 1.0;
  p.facade.b2 = 0.0;
  // The roof cuts the eighth storey at 0.6 of its height: a parapet, not the fractal's dusty top
  // face (the paper leaves roofs open, Sec. 4).
  p.mass.height = 22.8;
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
  return p;
}

// Fig. 8 (right) and Fig. 6: H footprint; r = (0.25, 0.125, 0.4) of Fig. 6 divides each bay
// into id regions, and s = a1·id + a2, t = b1·id + b2 give each its own part of the fractal.
KifsParams hBuilding() {
  KifsParams p = boxBuilding();
  p.facade.r = {0.25, 0.125, 0.4};
  p.mass.footprint = Footprint::H;
  p.mass.halfWidth = 12.0;
  p.mass.halfDepth = 10.0;
  p.mass.wing = 3.5;
  p.mass.height = 15.0;
  p.facade.a1 = 0.5;
  p.facade.a2 = 1.5;
  p.facade.b1 = 0.2;
  return p;
}

// Fig. 7 (right): curvilinear coordinates (Eq. 5-6) closing into a round tower.
KifsParams polarTower() {
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

// Fig. 7 (middle) and Fig. 6b: a curved building, an arc of a quarter turn.
KifsParams curvedBuilding() {
  KifsParams p = boxBuilding();
  p.curvilinear.enabled = true;
  p.curvilinear.sTheta = 14.0;
  p.curvilinear.cR = -16.0;
  p.mass.halfWidth = 14.0 * std::numbers::pi / 4;  // θ in [−π/4, π/4]
  p.mass.halfDepth = 4.0;
  p.mass.height = 21.0;
  return p;
}

// Fig. 2a-d on the box: s = 3.5 (sparse, disconnected), R1 = Ry(π/25) (crumbling),
// R1 = Ry(π/4), R2 = Ry(π/8) (polygonal, star-like).
KifsParams sparse() {
  KifsParams p = boxBuilding();
  p.scale = 3.5;
  return p;
}
KifsParams crumbling() {
  KifsParams p = boxBuilding();
  p.r1.yDeg = 180.0 / 25.0;
  return p;
}
KifsParams turned() {
  KifsParams p = boxBuilding();
  p.r1.yDeg = 45.0;
  return p;
}
KifsParams star() {
  KifsParams p = boxBuilding();
  p.r2.yDeg = 22.5;
  return p;
}

const std::map<std::string, std::function<KifsParams()>>& table() {
  static const std::map<std::string, std::function<KifsParams()>> t = {
      {"box", boxBuilding}, {"menger", menger}, {"t", tBuilding}, {"h", hBuilding}, {"polar", polarTower}, {"curved", curvedBuilding},
      {"sparse", sparse},   {"crumbling", crumbling}, {"turned", turned}, {"star", star}};
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
