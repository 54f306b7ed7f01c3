#include "city/street.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::city {

std::vector<Vec2> catmullRom(const std::vector<Vec2>& c, int perSpan) {
  if (c.size() < 2) throw InputError("street", "a street needs at least two points");
  std::vector<Vec2> out;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const Vec2& p0 = c[i == 0 ? 0 : i - 1];
    const Vec2& p1 = c[i];
    const Vec2& p2 = c[i + 1];
    const Vec2& p3 = c[std::min(i + 2, c.size() - 1)];
    for (int k = 0; k < perSpan; ++k) {
      const double t = double(k) / perSpan, t2 = t * t, t3 = t2 * t;
      out.push_back(0.5 *
                    (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3));
    }
  }
  out.push_back(c.back());
  return out;
}

Town streetTown(const std::vector<Vec2>& control, const PlotOptions& o) {
  for (std::size_t i = 0; i + 1 < control.size(); ++i)
    if (control[i] == control[i + 1])
      throw InputError("street[" + std::to_string(i + 1) + "]", "repeats the point before it");
  Town town;
  town.frame.how = "a street drawn in metres";
  const std::vector<Vec2> line = catmullRom(control);
  town.streets.push_back({"street", line});
  // Arc length and the unit normal (to the left) at every sample.
  const std::size_t n = line.size();
  std::vector<double> s(n, 0.0);
  std::vector<Vec2> normal(n);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + (line[i] - line[i - 1]).norm();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 d = line[std::min(i + 1, n - 1)] - line[i == 0 ? 0 : i - 1];
    normal[i] = Vec2(-d[1], d[0]).normalized();
  }
  // The centreline point and normal at arc length t (linear between samples).
  auto at = [&](double t, Vec2& p, Vec2& nm) {
    const std::size_t k = std::min<std::size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin(), n - 1);
    const std::size_t a = k == 0 ? 0 : k - 1;
    const double f = s[k] > s[a] ? (t - s[a]) / (s[k] - s[a]) : 0.0;
    p = line[a] + (line[k] - line[a]) * f;
    nm = (normal[a] * (1 - f) + normal[k] * f).normalized();
  };
  const double length = s.back();
  const int count = std::max(1, static_cast<int>(std::floor(length / o.plotWidth)));
  const double front = o.streetWidth / 2 + o.setback, back = front + o.depth;
  for (int side = 0; side < (o.bothSides ? 2 : 1); ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    for (int k = 0; k < count; ++k) {
      const double t0 = length * k / count, t1 = length * (k + 1) / count;
      // Stations: the plot's two ends and every spline sample between them.
      std::vector<double> ts{t0};
      for (double t : s)
        if (t > t0 + 1e-9 && t < t1 - 1e-9) ts.push_back(t);
      ts.push_back(t1);
      std::vector<Vec2> ps, ns;
      for (double t : ts) {
        Vec2 p, nm;
        at(t, p, nm);
        ps.push_back(p);
        ns.push_back(nm * sign);
      }
      // On the inside of a bend the normals meet: the plot's back stays short of where two
      // neighbouring normals cross (at 80 % of that distance), so it never folds over itself.
      double fold = INFINITY;
      for (std::size_t i = 0; i + 1 < ps.size(); ++i) {
        const Vec2 d = ps[i + 1] - ps[i];
        const double den = ns[i][0] * ns[i + 1][1] - ns[i][1] * ns[i + 1][0];
        if (std::abs(den) < 1e-12) continue;
        const double t = (d[0] * ns[i + 1][1] - d[1] * ns[i + 1][0]) / den;
        if (t > 0) fold = std::min(fold, t);
      }
      const double reach = std::min(back, 0.8 * fold);
      std::vector<Vec2> fronts, backs;
      for (std::size_t i = 0; i < ps.size(); ++i) {
        fronts.push_back(ps[i] + ns[i] * front);
        backs.push_back(ps[i] + ns[i] * reach);
      }
      // Fronts then backs back again: counter-clockwise on the left side, clockwise on the right.
      std::vector<Vec2> ring = fronts;
      ring.insert(ring.end(), backs.rbegin(), backs.rend());
      if (side == 1) std::reverse(ring.begin(), ring.end());
      Building b;
      b.id = std::string(side == 0 ? "left/" : "right/") + std::to_string(k);
      b.properties = {{"side", side == 0 ? "left" : "right"}, {"index", k}, {"plot", true}};
      b.loops.push_back(std::move(ring));
      if (reach - front < 3)
        b.problem = "the street bends too sharply here: a plot would be " + std::to_string(reach - front) +
                    " m deep before its back folds";
      else
        cleanBuilding(b);
      town.buildings.push_back(std::move(b));
    }
  }
  return town;
}

}  // namespace corbel::city
