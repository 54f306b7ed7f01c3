#pragma once
// Helpers shared by the extrusion tests: building specs from plain polygons, reading saved ones.
#include "core/project_io.h"
#include "extrude/extrude.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

namespace corbel::extrude::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// The extrusion spec of a saved one-object project; a relative path is under the source tree.
inline ExtrusionSpec savedSpec(const std::filesystem::path& file) {
  const std::filesystem::path path = file.is_absolute() ? file : std::filesystem::path(CORBEL_SOURCE_DIR) / file;
  const Document d = loadProject(path.string()).document;
  return std::get<ExtrusionSpec>(d.objects.at(0).spec);
}

// One profile for every edge.
inline ExtrusionSpec uniformSpec(const std::vector<std::vector<Vec2>>& loops, const Profile& profile) {
  ExtrusionSpec s;
  s.profiles.push_back(profile);
  for (const auto& l : loops) {
    PlanLoop pl;
    pl.points = l;
    pl.profile.assign(l.size(), 0);
    s.loops.push_back(pl);
  }
  return s;
}

// A named profile through the points, with per-segment tags.
inline Profile polyline(std::string name, std::vector<Vec2> pts, std::vector<std::string> tags = {}) {
  Profile p;
  p.name = std::move(name);
  p.points = std::move(pts);
  p.tags = std::move(tags);
  return p;
}

// Volume under a height field f(x, y) over a rectangle by the midpoint rule on an nx × ny grid:
// an oracle that knows nothing of the sweep.
inline double integrate(double x0, double x1, double y0, double y1, int nx, int ny,
                        const std::function<double(double, double)>& f) {
  const double hx = (x1 - x0) / nx, hy = (y1 - y0) / ny;
  double s = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) s += f(x0 + (i + 0.5) * hx, y0 + (j + 0.5) * hy);
  return s * hx * hy;
}

inline std::vector<Vec2> rectangle(double w, double h, double x0 = 0, double y0 = 0) {
  return {Vec2(x0, y0), Vec2(x0 + w, y0), Vec2(x0 + w, y0 + h), Vec2(x0, y0 + h)};
}

inline std::vector<Vec2> regularPolygon(int n, double r, double phase = 0) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * std::numbers::pi * i / n;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

inline double shoelace(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 &u = p[i], &v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return a / 2;
}

inline std::vector<Vec2> reversed(std::vector<Vec2> p) {
  std::reverse(p.begin(), p.end());
  return p;
}

// Adds a face of one loop to a hand-built shell (the clean-up passes' tests).
inline void addFace(SweepOutput& shell, std::vector<int> loop, const Vec3& normal) {
  ShellFace f;
  f.loops = {std::move(loop)};
  f.normal = normal;
  shell.faces.push_back(std::move(f));
}

// A face's area seen from above (its area times the up part of its normal).
inline double topArea(const SweepOutput& shell, std::size_t face) {
  return faceArea(shell, shell.faces[face]) * shell.faces[face].normal[2];
}

}  // namespace corbel::extrude::test
