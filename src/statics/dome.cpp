#include "statics/dome.h"

#include "core/error.h"
#include "statics/shapes.h"

#include <cmath>
#include <numbers>
#include <string>

namespace corbel::statics {

std::vector<Block> domeBlocks(const DomeSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (spec.rings < 1 || spec.rings > 1000) throw Error("dome: the number of rings must be in 1..1000");
  if (spec.segments < 3 || spec.segments > 4096) throw Error("dome: the number of segments must be in 3..4096");
  if (!positive(spec.radius) || !positive(spec.thickness) || spec.thickness >= 2 * spec.radius)
    throw Error("dome: radius and thickness must be positive, the thickness below the diameter");
  if (!std::isfinite(spec.oculusDeg) || spec.oculusDeg <= 0 || spec.oculusDeg >= 90)
    throw Error("dome: the oculus angle must be in (0°, 90°)");
  if (!positive(spec.density)) throw Error("dome: the density must be a positive number");
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2;
  const double top = (90.0 - spec.oculusDeg) * std::numbers::pi / 180.0;
  auto point = [&](double r, int i, int j) {
    const double phi = top * i / spec.rings;
    const double th = 2 * std::numbers::pi * (j % spec.segments) / spec.segments;
    const double c = i == 0 ? 1.0 : std::cos(phi), s = i == 0 ? 0.0 : std::sin(phi);
    return Vec3(r * c * std::cos(th), r * c * std::sin(th), r * s);
  };
  std::vector<Block> out;
  for (int i = 0; i < spec.rings; ++i)
    for (int j = 0; j < spec.segments; ++j) {
      // Corners: inner/outer × lower/upper latitude × first/second meridian.
      std::vector<Vec3> v = {point(ri, i, j), point(ri, i, j + 1), point(ri, i + 1, j + 1), point(ri, i + 1, j),
                             point(ro, i, j), point(ro, i, j + 1), point(ro, i + 1, j + 1), point(ro, i + 1, j)};
      std::vector<std::vector<int>> faces = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
      out.push_back(convexBlock("ring " + std::to_string(i) + " voussoir " + std::to_string(j), std::move(v), std::move(faces),
                                spec.density));
    }
  return out;
}

std::vector<Block> drumBlocks(const DrumSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (spec.courses < 1 || spec.courses > 1000) throw Error("drum: the number of courses must be in 1..1000");
  if (spec.segments < 3 || spec.segments > 4096) throw Error("drum: the number of segments must be in 3..4096");
  if (!positive(spec.radius) || !positive(spec.thickness) || spec.thickness >= 2 * spec.radius)
    throw Error("drum: radius and thickness must be positive, the thickness below the diameter");
  if (!positive(spec.height)) throw Error("drum: the height must be a positive number");
  if (!positive(spec.density)) throw Error("drum: the density must be a positive number");
  const double ri = spec.radius - spec.thickness / 2, ro = spec.radius + spec.thickness / 2, h = spec.height / spec.courses;
  const double half = std::numbers::pi / spec.segments;  // half a segment's angle
  const bool windows = spec.windowWidth != 0;
  if (windows) {
    if (!positive(spec.windowWidth)) throw Error("drum: the window width must be a positive number (0: no windows)");
    if (spec.bond)
      throw Error("drum: windows need stack bond (a running bond would put a joint in every other opening)");
    if (spec.windowEvery < 1 || spec.windowEvery > spec.segments)
      throw Error("drum: windows must be in every 1st to every " + std::to_string(spec.segments) + "th segment");
    if (spec.windowSill < 0 || spec.windowHead <= spec.windowSill || spec.windowHead >= spec.courses)
      throw Error("drum: windows need 0 ≤ sill < head < courses (the head course holds the lintels)");
    const double chord = 2 * ri * std::sin(half);
    if (spec.windowWidth > 0.9 * chord)
      throw Error("drum: a window of " + std::to_string(spec.windowWidth) + " m leaves jambs thinner than 5 % of the " +
                  std::to_string(chord) + " m inner chord of a segment");
  }
  std::vector<Block> out;
  for (int c = 0; c < spec.courses; ++c) {
    const double shift = spec.bond && c % 2 ? 0.5 : 0.0;
    for (int j = 0; j < spec.segments; ++j) {
      const std::string name = "course " + std::to_string(c) + " block " + std::to_string(j);
      if (windows && j % spec.windowEvery == spec.windowEvery / 2 && c >= spec.windowSill && c < spec.windowHead) {
        // The two jambs in the segment's own frame: u along its mid-plane, v across it; the
        // faces are the chords u = ri cos(half), ro cos(half).
        const double mid = 2 * std::numbers::pi * (j + 0.5) / spec.segments, w = spec.windowWidth / 2;
        const Vec3 u(std::cos(mid), std::sin(mid), 0.0), v(-std::sin(mid), std::cos(mid), 0.0);
        auto at = [&](double a, double b) { return a * u + b * v + Vec3(0.0, 0.0, c * h); };
        const double ui = ri * std::cos(half), uo = ro * std::cos(half), si = ri * std::sin(half),
                     so = ro * std::sin(half);
        out.push_back(prismBlock(name + " jamb 0", {at(ui, -si), at(uo, -so), at(uo, -w), at(ui, -w)},
                                 Vec3(0.0, 0.0, h), spec.density));
        out.push_back(prismBlock(name + " jamb 1", {at(ui, w), at(uo, w), at(uo, so), at(ui, si)}, Vec3(0.0, 0.0, h),
                                 spec.density));
        continue;
      }
      const double a0 = 2 * std::numbers::pi * (j + shift) / spec.segments, a1 = 2 * std::numbers::pi * (j + 1 + shift) / spec.segments;
      const std::vector<Vec3> base = {Vec3(ri * std::cos(a0), ri * std::sin(a0), c * h), Vec3(ro * std::cos(a0), ro * std::sin(a0), c * h),
                                      Vec3(ro * std::cos(a1), ro * std::sin(a1), c * h), Vec3(ri * std::cos(a1), ri * std::sin(a1), c * h)};
      out.push_back(prismBlock(name, base, Vec3(0.0, 0.0, h), spec.density));
    }
  }
  return out;
}

}  // namespace corbel::statics
