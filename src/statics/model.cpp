#include "statics/model.h"

#include "core/error.h"

#include <cmath>
#include <map>
#include <utility>

namespace corbel::statics {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

std::string blockLabel(const Block& b, std::size_t index) {
  return "block " + std::to_string(index) + (b.name.empty() ? "" : " \"" + b.name + "\"");
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
    // Convexity: the whole block lies behind every face's plane.
    for (std::size_t fi = 0; fi < b.faces.size(); ++fi) {
      std::vector<Vec3> poly;
      for (int i : b.faces[fi]) poly.push_back(b.vertices[std::size_t(i)]);
      const Vec3 n = newellNormal(poly).normalized();
      for (std::size_t i = 0; i < b.vertices.size(); ++i)
        if (dot(b.vertices[i] - poly[0], n) > tolerance)
          throw Error(who + ": not convex (vertex " + std::to_string(i) + " lies outside the plane of face " +
                      std::to_string(fi) + ")");
    }
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
