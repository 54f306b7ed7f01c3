#include "kifs/facings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace corbel::kifs {

namespace {

constexpr double kQuarter = std::numbers::pi / 2;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The turn that lays a plan normal at angle `psi` on the nearest axis: in [−45°, 45°].
double turnOf(double psi) {
  const double t = psi - std::round(psi / kQuarter) * kQuarter;
  return std::abs(t) < 1e-9 ? 0.0 : t;
}

// The difference of two turns modulo 90°, in [−45°, 45°].
double turnDifference(double a, double b) { return turnOf(a - b); }

glm::dvec2 turned(const glm::dvec2& p, double angle) {  // p turned by −angle
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x + s * p.y, -s * p.x + c * p.y};
}

double segmentDistance(const glm::dvec2& p, const PlanWall& w) {
  const glm::dvec2 ab = w.b - w.a, ap = p - w.a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(ap - t * ab);
}

struct Line {
  double psi = 0;  // the plan normal's angle
  double offset = 0;
  std::vector<std::pair<double, double>> spans;  // along the line's tangent
};

}  // namespace

Facings facingsOf(const TriangleSoup& soup, const glm::dvec3& origin, const glm::dvec2& axis, double shortest) {
  auto plan = [&](const glm::dvec3& world) {
    const glm::dvec3 d = world - origin;
    return glm::dvec3(axis.x * d.x + axis.y * d.y, -axis.y * d.x + axis.x * d.y, d.z);
  };
  // Wall triangles gathered by the line they lie on in plan (normal angle and offset to 1 mm).
  std::map<std::pair<long long, long long>, Line> lines;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto c = soup.corners(t);
    const glm::dvec3 p0 = plan(c[0]), p1 = plan(c[1]), p2 = plan(c[2]);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    const double horizontal = std::hypot(n.x, n.y), length = glm::length(n);
    if (!(length > 1e-12) || horizontal < std::sqrt(0.5) * length) continue;  // within 45° of horizontal
    const double psi = std::atan2(n.y, n.x);
    const glm::dvec2 normal(n.x / horizontal, n.y / horizontal), tangent(-normal.y, normal.x);
    double lo = kInf, hi = -kInf, offset = 0;
    for (const glm::dvec3& p : {p0, p1, p2}) {
      const double s = glm::dot(glm::dvec2(p), tangent);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      offset += glm::dot(glm::dvec2(p), normal) / 3;
    }
    Line& line = lines[{std::llround(psi * 1000), std::llround(offset * 1000)}];
    line.psi = psi;
    line.offset = offset;
    line.spans.emplace_back(lo, hi);
  }
  // Each line's spans merged where they overlap or touch: its walls.
  struct Wall {
    PlanWall plan;
    double turn = 0, length = 0;
  };
  std::vector<Wall> walls;
  for (auto& [key, line] : lines) {
    std::sort(line.spans.begin(), line.spans.end());
    const glm::dvec2 normal(std::cos(line.psi), std::sin(line.psi)), tangent(-normal.y, normal.x);
    auto add = [&](double lo, double hi) {
      if (hi - lo < shortest) return;
      walls.push_back({{line.offset * normal + lo * tangent, line.offset * normal + hi * tangent, 0}, turnOf(line.psi), hi - lo});
    };
    double lo = line.spans[0].first, hi = line.spans[0].second;
    for (const auto& [a, b] : line.spans) {
      if (a > hi + 1e-3) {
        add(lo, hi);
        lo = a;
      }
      hi = std::max(hi, b);
    }
    add(lo, hi);
  }
  std::stable_sort(walls.begin(), walls.end(), [](const Wall& a, const Wall& b) { return a.length > b.length; });
  // Facings, longest walls first: a wall within the tolerance of a facing's turn joins it.
  std::vector<double> turns;
  const double tolerance = kFacingToleranceDeg * std::numbers::pi / 180;
  for (Wall& w : walls) {
    int best = -1;
    double nearest = kInf;
    for (std::size_t f = 0; f < turns.size(); ++f) {
      const double d = std::abs(turnDifference(w.turn, turns[f]));
      if (d < nearest) nearest = d, best = int(f);
    }
    if (best < 0 || (nearest > tolerance && int(turns.size()) < kMaxFacings)) {
      best = int(turns.size());
      turns.push_back(w.turn);
    }
    w.plan.facing = best;
  }
  Facings out;
  if (turns.empty()) return out;
  out.main = turns[0];
  if (turns.size() == 1) return out;
  for (double t : turns) out.turns.push_back(turnDifference(t, out.main));
  // Each wall shortened by kWallEndTrim at both ends: walls meeting at a corner share an end,
  // and every point beyond the corner would be equally near both (a tie over an area, which
  // float and double break differently); trimmed, the corner splits along a line.
  for (const Wall& w : walls) {
    if (out.walls.size() == std::size_t(kMaxWalls)) break;
    const glm::dvec2 trim = (w.plan.b - w.plan.a) * (kWallEndTrim / w.length);
    out.walls.push_back({turned(w.plan.a + trim, out.main), turned(w.plan.b - trim, out.main), w.plan.facing});
  }
  return out;
}

void setFrame(MassField& field, const glm::dvec3& origin, const glm::dvec2& axis, const Facings& facings) {
  field.frameOrigin = origin;
  const double c = std::cos(facings.main), s = std::sin(facings.main);
  field.frameAxis = {axis.x * c - axis.y * s, axis.y * c + axis.x * s};
  field.walls = facings.walls;
  field.facings.clear();
  for (double t : facings.turns) {  // the frame's turn and the facing's, one rotation from world
    const double ct = std::cos(t), st = std::sin(t);
    const glm::dvec2 f = field.frameAxis;
    field.facings.emplace_back(f.x * ct - f.y * st, f.y * ct + f.x * st);
  }
}

MassField::FacingAt MassField::facingAt(const glm::dvec2& p) const {
  std::array<double, kMaxFacings> nearest;
  nearest.fill(kInf);
  for (const PlanWall& w : walls) nearest[w.facing] = std::min(nearest[w.facing], segmentDistance(p, w));
  // The three nearest facings, in order (a, b, c; −1: none).
  int a = -1, b = -1, c = -1;
  double da = kInf, db = kInf, dc = kInf;
  for (int f = 0; f < int(facings.size()); ++f) {
    const double d = nearest[f];
    if (a < 0 || d < da) {
      c = b, dc = db, b = a, db = da, a = f, da = d;
    } else if (b < 0 || d < db) {
      c = b, dc = db, b = f, db = d;
    } else if (c < 0 || d < dc) {
      c = f, dc = d;
    }
  }
  FacingAt out;
  out.facing = std::max(a, 0);
  out.other = b < 0 ? out.facing : b;
  out.gap = b < 0 ? kInf : 0.5 * (db - da);
  out.beyond = c < 0 ? kInf : 0.5 * (dc - da);
  return out;
}

}  // namespace corbel::kifs
