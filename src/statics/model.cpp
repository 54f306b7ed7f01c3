#include "statics/model.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace corbel::statics {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

std::string blockLabel(const Block& b, std::size_t index) {
  return "block " + std::to_string(index) + (b.name.empty() ? "" : " \"" + b.name + "\"");
}

// The distance between segments pq and rs in space (0 when they cross).
double segmentDistance(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  const Vec3 d1 = q - p, d2 = s - r, w = p - r;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, w);
  double t = 0, u = 0;
  if (a <= 0 && e <= 0) return (p - r).norm();
  if (a <= 0) {
    u = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, w);
    if (e <= 0) {
      t = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), den = a * e - b * b;
      t = den > 0 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
      u = (b * t + f) / e;
      if (u < 0) {
        u = 0;
        t = std::clamp(-c / a, 0.0, 1.0);
      } else if (u > 1) {
        u = 1;
        t = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p + d1 * t) - (r + d2 * u)).norm();
}

}  // namespace

std::vector<BlockProperties> validateAssembly(const Assembly& assembly, double tolerance) {
  if (assembly.blocks.empty()) throw Error("statics: the assembly has no blocks");
  if (!finite(assembly.gravity) || assembly.gravity.norm() < 0.5 || assembly.gravity.norm() > 2.0)
    throw Error("statics: gravity must be a finite unit direction");
  if (!std::isfinite(assembly.g) || assembly.g <= 0) throw Error("statics: g must be a positive number");
  std::vector<BlockProperties> props;
  props.reserve(assembly.blocks.size());
  for (std::size_t bi = 0; bi < assembly.blocks.size(); ++bi) {
    const Block& b = assembly.blocks[bi];
    const std::string who = blockLabel(b, bi);
    if (b.vertices.size() < 4 || b.faces.size() < 4) throw Error(who + ": a block needs at least 4 vertices and 4 faces");
    for (std::size_t i = 0; i < b.vertices.size(); ++i)
      if (!finite(b.vertices[i])) throw Error(who + ": vertex " + std::to_string(i) + " is not a finite point");
    if (!b.fixed && !(std::isfinite(b.density) && b.density > 0))
      throw Error(who + ": density must be a positive number");
    if (!finite(b.liveLoad)) throw Error(who + ": the live load must be finite");

    BlockProperties p;
    for (const Vec3& v : b.vertices) p.bounds.add(v);
    // Closed surface: every directed edge appears once and its reverse once.
    std::map<std::pair<int, int>, int> edges;
    const int nv = int(b.vertices.size());
    for (std::size_t fi = 0; fi < b.faces.size(); ++fi) {
      const auto& f = b.faces[fi];
      if (f.size() < 3) throw Error(who + ": face " + std::to_string(fi) + " has fewer than 3 vertices");
      for (std::size_t k = 0; k < f.size(); ++k) {
        const int u = f[k], w = f[(k + 1) % f.size()];
        if (u < 0 || u >= nv || w < 0 || w >= nv)
          throw Error(who + ": face " + std::to_string(fi) + " names a vertex that does not exist");
        if (++edges[{u, w}] > 1) throw Error(who + ": edge " + std::to_string(u) + "-" + std::to_string(w) +
                                             " is used twice in one direction (faces not consistently oriented)");
      }
    }
    for (const auto& [e, count] : edges)
      if (!edges.count({e.second, e.first}))
        throw Error(who + ": the surface is not closed (edge " + std::to_string(e.first) + "-" +
                    std::to_string(e.second) + " has one face)");

    // Volume and centroid by tetrahedra from a reference point (the first vertex).
    const Vec3 o = b.vertices[0];
    double vol6 = 0;
    Vec3 moment(0.0);
    for (std::size_t fi = 0; fi < b.faces.size(); ++fi) {
      const auto& f = b.faces[fi];
      std::vector<Vec3> poly;
      for (int i : f) poly.push_back(b.vertices[i]);
      const Vec3 nn = newellNormal(poly);
      const double area2 = nn.norm();
      if (area2 <= tolerance * tolerance) throw Error(who + ": face " + std::to_string(fi) + " has no area");
      const Vec3 n = nn / area2;
      for (const Vec3& q : poly)
        if (std::abs(dot(q - poly[0], n)) > tolerance)
          throw Error(who + ": face " + std::to_string(fi) + " is not planar");
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
        const Vec3 a = poly[0] - o, c = poly[k] - o, d = poly[k + 1] - o;
        const double v = dot(a, cross(c, d));
        vol6 += v;
        moment += (a + c + d) * (v / 4.0);
      }
    }
    p.volume = vol6 / 6.0;
    if (!(p.volume > tolerance * tolerance * tolerance))
      throw Error(who + (vol6 < 0 ? ": faces point inwards (negative volume)" : ": the block has no volume"));
    p.centroid = o + moment / vol6;
    // Convexity of each face (every turn the same way about its normal) and of the block (the
    // whole block behind every face's plane); a non-convex face must still be simple.
    p.convexFaces.assign(b.faces.size(), true);
    for (std::size_t fi = 0; fi < b.faces.size(); ++fi) {
      std::vector<Vec3> poly;
      for (int i : b.faces[fi]) poly.push_back(b.vertices[std::size_t(i)]);
      const Vec3 n = newellNormal(poly).normalized();
      const std::size_t m = poly.size();
      for (std::size_t k = 0; k < m; ++k) {
        const Vec3 e0 = poly[k] - poly[(k + m - 1) % m], e1 = poly[(k + 1) % m] - poly[k];
        if (dot(cross(e0, e1), n) < -tolerance * std::max(e0.norm(), e1.norm())) p.convexFaces[fi] = false;
      }
      if (!p.convexFaces[fi]) {
        // Simple: no two edges that are not neighbours meet (within the tolerance).
        for (std::size_t i = 0; i < m; ++i)
          for (std::size_t j = i + 1; j < m; ++j) {
            if (j == i + 1 || (i == 0 && j == m - 1)) continue;
            if (segmentDistance(poly[i], poly[(i + 1) % m], poly[j], poly[(j + 1) % m]) <= tolerance)
              throw Error(who + ": face " + std::to_string(fi) + " is not a simple polygon (edges " +
                          std::to_string(i) + " and " + std::to_string(j) + " cross or touch)");
          }
      }
      for (std::size_t i = 0; i < b.vertices.size() && p.convex; ++i)
        if (dot(b.vertices[i] - poly[0], n) > tolerance) p.convex = false;
    }
    for (const PointLoad& l : b.pointLoads)
      if (!finite(l.at) || !finite(l.force)) throw Error(who + ": a point load is not finite");
    props.push_back(p);
  }
  return props;
}

Block boxBlock(std::string name, const Vec3& lo, const Vec3& hi, double density, bool fixed) {
  Block b;
  b.name = std::move(name);
  b.density = density;
  b.fixed = fixed;
  for (int k = 0; k < 8; ++k)
    b.vertices.emplace_back((k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]);
  // Outward, counter-clockwise seen from outside.
  b.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return b;
}

}  // namespace corbel::statics
