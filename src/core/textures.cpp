#include "core/textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

namespace corbel {

namespace {

constexpr int kSize = 128;

// A hash of integer coordinates into [0, 1): white noise that is seamless when its inputs are
// taken modulo the tile.
double hash01(int x, int y, int salt) {
  std::uint32_t h = 2166136261u;
  for (int v : {x, y, salt}) h = (h ^ static_cast<std::uint32_t>(v)) * 16777619u, h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffff) / double(0x1000000);
}

int wrap(int v, int n) { return ((v % n) + n) % n; }

// Value noise with a lattice of `cell` pixels; kSize must be a multiple of cell, so it tiles.
double smooth(int x, int y, int cell, int salt) {
  const int n = kSize / cell;
  const double fx = double(x) / cell, fy = double(y) / cell;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  auto at = [&](int i, int j) { return hash01(wrap(i, n), wrap(j, n), salt); };
  const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  const double a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * sx;
  const double b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * sx;
  return a + (b - a) * sy;
}

struct Rgbd {
  double r, g, b;
};

Rgbd scale(Rgbd c, double k) { return {c.r * k, c.g * k, c.b * k}; }

// A running bond: rows of `rows` per tile, `perRow` units per row, every other row shifted by
// half a unit; `mortar` pixels of joint. Returns the shade of pixel (x, y): a joint, or a
// unit's own random tone.
struct Bond {
  int rows, perRow, mortar;
  bool joint = false;
  double tone = 0;
  void at(int x, int y, int salt) {
    const int rh = kSize / rows, uw = kSize / perRow;
    const int row = y / rh, shift = (row % 2) * uw / 2;
    const int xs = wrap(x + shift, kSize), unit = xs / uw;
    joint = (y % rh) < mortar || (xs % uw) < mortar;
    tone = hash01(unit, row, salt);
  }
};

MaterialTexture make(const std::string& name) {
  MaterialTexture t;
  t.size = kSize;
  t.rgb.resize(kSize * kSize * 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double grain = hash01(x, y, 1) - 0.5, cloud = smooth(x, y, 16, 2) - 0.5;
      Rgbd c{0.5, 0.5, 0.5};
      Bond bond{};
      if (name == "brick") {  // 1.28 m: 16 courses of 80 mm, bricks 320 mm with 10 mm joints
        t.metres = 1.28;
        bond = {16, 4, 1};
        bond.at(x, y, 3);
        c = bond.joint ? Rgbd{0.78, 0.75, 0.70} : scale({0.66, 0.33, 0.24}, 0.85 + 0.3 * bond.tone + 0.1 * grain);
      } else if (name == "stone") {  // 2.4 m: 8 courses of ashlar, blocks 0.6 m
        t.metres = 2.4;
        bond = {8, 4, 1};
        bond.at(x, y, 4);
        c = bond.joint ? Rgbd{0.55, 0.52, 0.47}
                       : scale({0.72, 0.68, 0.60}, 0.9 + 0.15 * bond.tone + 0.15 * cloud + 0.06 * grain);
      } else if (name == "roof_tile") {  // 2 m: 8 rows of 250 mm, tiles 250 mm, a shadow at each row's foot
        t.metres = 2.0;
        bond = {8, 8, 1};
        bond.at(x, y, 5);
        const double inRow = double(y % (kSize / 8)) / (kSize / 8);
        c = scale({0.58, 0.24, 0.18},
                  (bond.joint ? 0.6 : 0.85 + 0.25 * bond.tone) * (0.8 + 0.25 * inRow) + 0.05 * grain);
      } else if (name == "slate") {  // 2 m: 10 rows of 200 mm, slates 250 mm
        t.metres = 2.0;
        bond = {16, 8, 1};
        bond.at(x, y, 6);
        c = scale({0.34, 0.37, 0.42}, bond.joint ? 0.6 : 0.85 + 0.3 * bond.tone + 0.08 * grain);
      } else if (name == "plaster") {  // 2 m of render: soft clouds and grain
        t.metres = 2.0;
        c = scale({0.86, 0.82, 0.74}, 0.97 + 0.12 * cloud + 0.06 * grain);
      } else if (name == "concrete") {  // 3.2 m panels with a joint, clouds and pores
        t.metres = 3.2;
        const bool joint = x % kSize < 1 || y % kSize < 1;
        c = scale({0.62, 0.62, 0.60}, joint ? 0.7 : 0.96 + 0.12 * cloud + 0.08 * grain);
      } else if (name == "timber") {  // 1.28 m: vertical boards 160 mm wide with grain along them
        t.metres = 1.28;
        const int board = x / 16;
        const double ring = smooth(x * 8 % kSize, y, 32, 7 + board) - 0.5;
        c = scale({0.55, 0.40, 0.25}, (x % 16 == 0 ? 0.55 : 0.9 + 0.2 * hash01(board, 0, 8) + 0.2 * ring));
      } else if (name == "glass") {  // 1.6 m: four panes with frames
        t.metres = 1.6;
        const bool frame = x % 64 < 3 || y % 64 < 3;
        c = frame ? Rgbd{0.85, 0.85, 0.82} : scale({0.45, 0.62, 0.75}, 0.85 + 0.3 * double(y % 64) / 64);
      } else if (name == "metal") {  // 2 m: standing seams every 500 mm
        t.metres = 2.0;
        const int s = x % 32;
        c = scale({0.55, 0.58, 0.62}, s < 2 ? 1.2 : s < 4 ? 0.75 : 0.95 + 0.06 * cloud + 0.03 * grain);
      } else if (name == "grass") {
        t.metres = 4.0;
        c = scale({0.42, 0.58, 0.30}, 0.9 + 0.25 * cloud + 0.2 * grain);
      }
      unsigned char* p = &t.rgb[(y * kSize + x) * 3];
      for (int k = 0; k < 3; ++k) {
        const double v = k == 0 ? c.r : k == 1 ? c.g : c.b;
        p[k] = static_cast<unsigned char>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
      }
    }
  return t;
}

}  // namespace

const std::vector<std::string_view>& builtinTextureNames() {
  static const std::vector<std::string_view> names = {"plaster",  "stone",  "brick", "roof_tile", "slate",
                                                      "concrete", "timber", "glass", "metal",     "grass"};
  return names;
}

const MaterialTexture* materialTexture(std::string_view name) {
  static const std::map<std::string, MaterialTexture, std::less<>> table = [] {
    std::map<std::string, MaterialTexture, std::less<>> m;
    for (std::string_view n : builtinTextureNames()) m[std::string(n)] = make(std::string(n));
    return m;
  }();
  const auto it = table.find(name);
  return it == table.end() ? nullptr : &it->second;
}

Vec2 planeUv(const Vec3& p, const Vec3& n) {
  if (std::abs(n[2]) > 0.999) return Vec2(p[0], p[1]);
  Vec3 t(-n[1], n[0], 0.0);  // z × n: along the contour, to the right seen from outside
  t /= t.norm();
  const Vec3 s = n % t;  // n × t: up the face
  return Vec2(p | t, p | s);
}

TextureUse textureFor(const SurfaceTexture* own, std::string_view material) {
  TextureUse use;
  if (own && !own->name.empty() && (use.texture = materialTexture(own->name))) {
    use.name = own->name;
    use.metres = own->metres > 0 ? own->metres : use.texture->metres;
    use.own = true;
  } else if (!material.empty() && (use.texture = materialTexture(material))) {
    use.name = material;
    use.metres = use.texture->metres;
  }
  return use;
}

void faceTextureCoordinates(const std::vector<Vec3>& poly, const Vec3& n, double metres, std::vector<Vec2>& out) {
  out.clear();
  double uLo = 1e300, vHi = -1e300;
  for (const Vec3& p : poly) {
    out.push_back(planeUv(p, n) / metres);
    uLo = std::min(uLo, out.back()[0]);
    vHi = std::max(vHi, out.back()[1]);
  }
  const double u0 = std::floor(uLo), v0 = std::ceil(vHi);
  for (Vec2& t : out) t = Vec2(t[0] - u0, v0 - t[1]);
}

}  // namespace corbel
