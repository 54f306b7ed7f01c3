#include "statics/groin.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {
namespace {

void validateSpec(const GroinVaultSpec& s) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (s.voussoirs < 2 || s.voussoirs > 400) throw Error("groin vault: the number of voussoirs must be in 2..400");
  if (s.courses < 1 || s.courses > 400) throw Error("groin vault: the number of courses must be in 1..400");
  if (!positive(s.radius) || !positive(s.thickness) || s.thickness >= 2 * s.radius)
    throw Error("groin vault: radius and thickness must be positive, the thickness below the diameter");
  if (!positive(s.stretch) || s.stretch < 0.2 || s.stretch > 5) throw Error("groin vault: the stretch must be in [0.2, 5]");
  if (!std::isfinite(s.pierHeight) || s.pierHeight < 0) throw Error("groin vault: the pier height must be 0 or positive");
  if (s.pierHeight > 0 && (!positive(s.pierWidth) || s.pierWidth < s.thickness))
    throw Error("groin vault: the piers must be at least as wide as the vault is thick");
  if (s.pierHeight > 0 && (s.pierDrums < 1 || s.pierDrums > 1000)) throw Error("groin vault: the piers' drums must be in 1..1000");
  if (!positive(s.density)) throw Error("groin vault: the density must be a positive number");
  if (s.ribs) {
    const double c = std::cos(std::numbers::pi / (2 * s.voussoirs)), ri = s.radius - s.thickness / 2;
    if (s.voussoirs % 2) throw Error("groin vault: ribs need an even number of voussoirs");
    if (!positive(s.ribWidth) || s.ribWidth > s.thickness * std::sqrt(0.5) * (1 + 1e-12))
      throw Error("groin vault: the rib width must be positive and at most thickness·√2/2");
    if (!positive(s.ribDepth) || s.ribDepth >= 0.5 * ri * c) throw Error("groin vault: the rib depth must be positive and below half the intrados radius");
    if (s.pierHeight > 0 && s.pierWidth < s.thickness + 2 * s.ribDepth / c)
      throw Error("groin vault: the piers must be at least thickness + 2·ribDepth/cos(π/2N) wide to carry the ribs");
  }
}

// Turns (x, y) by a quarter turn q times, exactly.
Vec3 quarterTurn(const Vec3& p, int q) {
  switch (q & 3) {
    case 1: return Vec3(-p[1], p[0], p[2]);
    case 2: return Vec3(-p[0], -p[1], p[2]);
    case 3: return Vec3(p[1], -p[0], p[2]);
    default: return p;
  }
}

}  // namespace

std::vector<Block> groinVaultBlocks(const GroinVaultSpec& spec) {
  validateSpec(spec);
  const int n = spec.voussoirs, c = spec.courses;
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2;
  const double dth = std::numbers::pi / n;
  const double eps = 1e-9 * ro;
  // The web of +x, in rows of its arch.
  std::vector<Block> web;
  for (int k = 0; k < n; ++k) {
    const double a0 = k * dth, a1 = (k + 1) * dth, mid = (a0 + a1) / 2;
    // cos and sin of the joint angles, exact at 0, π/2 and π so the springings lie on z = 0
    // and a crown joint on y = 0.
    auto cs = [&](int j) {
      if (2 * j == n) return Vec2(0.0, 1.0);
      if (j == 0) return Vec2(1.0, 0.0);
      if (j == n) return Vec2(-1.0, 0.0);
      return Vec2(std::cos(j * dth), std::sin(j * dth));
    };
    const Vec2 e0 = cs(k), e1 = cs(k + 1);
    std::vector<HalfSpace> section = {
        {Vec3(0.0, e0[1], -e0[0]), 0.0},                                                          // joint at θ_k
        {Vec3(0.0, -e1[1], e1[0]), 0.0},                                                          // joint at θ_k+1
        {Vec3(0.0, std::cos(mid), std::sin(mid)), ro * std::cos(dth / 2)},                        // extrados chord
        {Vec3(0.0, -std::cos(mid), -std::sin(mid)), -ri * std::cos(dth / 2)}};                    // intrados chord
    double maxAbs = 0, maxY = -ro, minY = ro;
    for (const Vec2& e : {e0, e1})
      for (double r : {ri, ro}) {
        maxAbs = std::max(maxAbs, std::abs(r * e[0]));
        maxY = std::max(maxY, r * e[0]);
        minY = std::min(minY, r * e[0]);
      }
    int first = 0;  // the first transverse plane at or beyond max |y|
    while (first < c && ro * first / c < maxAbs - eps) ++first;
    const std::string row = "row " + std::to_string(k);
    std::vector<HalfSpace> groin = section;
    groin.push_back({Vec3(1.0, 0.0, 0.0), ro * first / c});
    if (maxY > eps) groin.push_back({Vec3(-1.0, 1.0, 0.0), 0.0});    // x ≥ y
    if (minY < -eps) groin.push_back({Vec3(-1.0, -1.0, 0.0), 0.0});  // x ≥ −y
    web.push_back(halfspaceBlock(row + " groin", groin, spec.density));
    for (int j = first; j < c; ++j) {
      std::vector<HalfSpace> straight = section;
      straight.push_back({Vec3(-1.0, 0.0, 0.0), -ro * j / c});
      straight.push_back({Vec3(1.0, 0.0, 0.0), ro * (j + 1) / c});
      web.push_back(halfspaceBlock(row + " course " + std::to_string(j - first + 1), straight, spec.density));
    }
  }
  // The rib of the quadrant x, y > 0: halves under the web of +x (a) and their mirrors in
  // x = y (b), rows 0 .. N/2 − 1.
  std::vector<Block> rib;
  if (spec.ribs) {
    const double c = std::cos(dth / 2), delta = spec.ribWidth * std::sqrt(0.5);
    for (int k = 0; 2 * k < n; ++k) {
      const double a0 = k * dth, a1 = (k + 1) * dth, mid = (a0 + a1) / 2;
      const Vec2 e0 = k == 0 ? Vec2(1.0, 0.0) : Vec2(std::cos(a0), std::sin(a0));
      const Vec2 e1 = 2 * (k + 1) == n ? Vec2(0.0, 1.0) : Vec2(std::cos(a1), std::sin(a1));
      const std::vector<HalfSpace> hs = {{Vec3(0.0, e0[1], -e0[0]), 0.0},
                                         {Vec3(0.0, -e1[1], e1[0]), 0.0},
                                         {Vec3(0.0, std::cos(mid), std::sin(mid)), ri * c},
                                         {Vec3(0.0, -std::cos(mid), -std::sin(mid)), -(ri * c - spec.ribDepth)},
                                         {Vec3(-1.0, 1.0, 0.0), 0.0},
                                         {Vec3(1.0, -1.0, 0.0), delta}};
      Block a = halfspaceBlock("row " + std::to_string(k) + " a", hs, spec.density);
      Block b = a;
      b.name = "row " + std::to_string(k) + " b";
      for (Vec3& v : b.vertices) std::swap(v[0], v[1]);
      for (auto& f : b.faces) std::reverse(f.begin(), f.end());
      rib.push_back(std::move(a));
      rib.push_back(std::move(b));
    }
  }
  static const char* names[4] = {"web +x", "web +y", "web -x", "web -y"};
  static const char* ribNames[4] = {"rib +x+y", "rib -x+y", "rib -x-y", "rib +x-y"};
  std::vector<Block> out;
  auto add = [&](Block b, int q, const std::string& prefix) {
    for (Vec3& v : b.vertices) {
      v = quarterTurn(v, q);
      v[0] *= spec.stretch;
    }
    b.name = prefix + " " + b.name;
    out.push_back(std::move(b));
  };
  for (int q = 0; q < 4; ++q)
    for (const Block& b : web) add(b, q, names[q]);
  for (int q = 0; q < 4; ++q)
    for (const Block& b : rib) add(b, q, ribNames[q]);
  return out;
}

double groinVaultRibVolume(const GroinVaultSpec& spec) {
  if (!spec.ribs) return 0;
  const int n = spec.voussoirs;
  const double c = std::cos(std::numbers::pi / (2 * n)), ri = spec.radius - spec.thickness / 2;
  const double h1 = ri * c, h0 = h1 - spec.ribDepth;
  return spec.stretch * 4 * n * spec.ribWidth * std::sqrt(0.5) * std::tan(std::numbers::pi / (2 * n)) * (h1 * h1 - h0 * h0);
}

std::vector<Block> groinVaultPiers(const GroinVaultSpec& spec) {
  validateSpec(spec);
  std::vector<Block> out;
  if (spec.pierHeight == 0) return out;
  const double hx = spec.pierWidth * spec.stretch / 2, hy = spec.pierWidth / 2;
  static const char* names[4] = {"pier +x+y", "pier -x+y", "pier -x-y", "pier +x-y"};
  const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
  for (int p = 0; p < 4; ++p) {
    const double cx = sx[p] * spec.stretch * spec.radius, cy = sy[p] * spec.radius;
    for (int d = 0; d < spec.pierDrums; ++d) {
      const double z0 = spec.pierHeight * d / spec.pierDrums, z1 = spec.pierHeight * (d + 1) / spec.pierDrums;
      out.push_back(boxBlock(std::string(names[p]) + " drum " + std::to_string(d), Vec3(cx - hx, cy - hy, z0),
                             Vec3(cx + hx, cy + hy, z1), spec.density));
    }
  }
  return out;
}

Assembly groinVault(const GroinVaultSpec& spec) {
  Assembly as;
  as.blocks = placed(groinVaultBlocks(spec), Vec3(0.0, 0.0, spec.pierHeight), "vault");
  for (Block& b : groinVaultPiers(spec)) as.blocks.push_back(std::move(b));
  const double reach = spec.radius + spec.thickness / 2 + std::max(spec.pierWidth, spec.thickness) + 0.5;
  as.blocks.push_back(boxBlock("ground", Vec3(-reach * spec.stretch, -reach, -1.0), Vec3(reach * spec.stretch, reach, 0.0), 1.0, true));
  return as;
}

double groinVaultShellVolume(const GroinVaultSpec& spec) {
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2;
  return spec.stretch * (2 * std::numbers::pi * ro * (ro * ro - ri * ri) - 8.0 / 3.0 * (ro * ro * ro - ri * ri * ri));
}

}  // namespace corbel::statics
