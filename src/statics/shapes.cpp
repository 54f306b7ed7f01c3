#include "statics/shapes.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace corbel::statics {

Block convexBlock(std::string name, std::vector<Vec3> vertices, std::vector<std::vector<int>> faces, double density) {
  Block b;
  b.name = std::move(name);
  b.density = density;
  b.vertices = std::move(vertices);
  b.faces = std::move(faces);
  Vec3 c(0.0);
  for (const Vec3& v : b.vertices) c += v;
  c /= double(b.vertices.size());
  for (auto& f : b.faces) {
    std::vector<Vec3> poly;
    Vec3 fc(0.0);
    for (int i : f) {
      poly.push_back(b.vertices[std::size_t(i)]);
      fc += b.vertices[std::size_t(i)];
    }
    fc /= double(f.size());
    if (dot(newellNormal(poly), fc - c) < 0) std::reverse(f.begin(), f.end());
  }
  return b;
}

Block prismBlock(std::string name, const std::vector<Vec3>& base, const Vec3& extent, double density) {
  const int n = int(base.size());
  std::vector<Vec3> v = base;
  for (const Vec3& p : base) v.push_back(p + extent);
  std::vector<std::vector<int>> faces(2);
  for (int i = 0; i < n; ++i) {
    faces[0].push_back(i);
    faces[1].push_back(n + i);
    faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  return convexBlock(std::move(name), std::move(v), std::move(faces), density);
}

Block halfspaceBlock(std::string name, const std::vector<HalfSpace>& halfspaces, double density) {
  // Unit normals; planes repeated (same normal and offset) count once.
  std::vector<HalfSpace> hs;
  double scale = 1.0;
  for (const HalfSpace& h : halfspaces) {
    const double len = h.n.norm();
    if (!(len > 0) || !std::isfinite(h.d)) throw Error("halfspaceBlock: " + name + ": a half-space has no normal");
    scale = std::max(scale, std::abs(h.d / len));
  }
  const double tol = 1e-9 * scale;
  for (const HalfSpace& h : halfspaces) {
    const HalfSpace u{h.n / h.n.norm(), h.d / h.n.norm()};
    bool repeated = false;
    for (const HalfSpace& q : hs) repeated = repeated || ((q.n - u.n).norm() < 1e-12 && std::abs(q.d - u.d) <= tol);
    if (!repeated) hs.push_back(u);
  }
  const std::size_t m = hs.size();
  std::vector<Vec3> verts;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        const Vec3 jk = cross(hs[j].n, hs[k].n), ki = cross(hs[k].n, hs[i].n), ij = cross(hs[i].n, hs[j].n);
        const double det = dot(hs[i].n, jk);
        if (std::abs(det) < 1e-10) continue;
        const Vec3 p = (jk * hs[i].d + ki * hs[j].d + ij * hs[k].d) / det;
        bool inside = true;
        for (const HalfSpace& h : hs) inside = inside && dot(h.n, p) <= h.d + tol;
        if (!inside) continue;
        bool known = false;
        for (const Vec3& v : verts) known = known || (v - p).norm() <= 4 * tol;
        if (!known) verts.push_back(p);
      }
  Block b;
  b.name = std::move(name);
  b.density = density;
  b.vertices = verts;
  for (const HalfSpace& h : hs) {
    std::vector<int> on;
    Vec3 c(0.0);
    for (std::size_t i = 0; i < verts.size(); ++i)
      if (std::abs(dot(h.n, verts[i]) - h.d) <= 4 * tol) {
        on.push_back(int(i));
        c += verts[i];
      }
    if (on.size() < 3) continue;
    c /= double(on.size());
    Vec3 u = verts[std::size_t(on[0])] - c;
    u -= h.n * dot(u, h.n);
    if (!(u.norm() > 0)) continue;
    u.normalize();
    const Vec3 v = cross(h.n, u);
    std::vector<std::pair<double, int>> ring;
    for (int i : on) {
      const Vec3 d = verts[std::size_t(i)] - c;
      ring.emplace_back(std::atan2(dot(d, v), dot(d, u)), i);
    }
    std::sort(ring.begin(), ring.end());
    std::vector<int> face;
    std::vector<Vec3> poly;
    for (const auto& [angle, i] : ring) {
      face.push_back(i);
      poly.push_back(verts[std::size_t(i)]);
    }
    if (newellNormal(poly).norm() <= tol * tol) continue;  // an edge or a point: no face
    b.faces.push_back(std::move(face));
  }
  return b;
}

std::vector<Block> placed(std::vector<Block> blocks, const Vec3& offset, const std::string& prefix) {
  for (Block& b : blocks) {
    for (Vec3& v : b.vertices) v += offset;
    if (!prefix.empty()) b.name = prefix + "/" + b.name;
  }
  return blocks;
}

std::vector<Block> rotatedZ(std::vector<Block> blocks, double radians) {
  const double c = std::cos(radians), sn = std::sin(radians);
  auto turn = [&](Vec3& v) { v = Vec3(c * v[0] - sn * v[1], sn * v[0] + c * v[1], v[2]); };
  for (Block& b : blocks) {
    for (Vec3& v : b.vertices) turn(v);
    turn(b.liveLoad);
  }
  return blocks;
}

std::vector<Block> mirroredX(std::vector<Block> blocks) {
  for (Block& b : blocks) {
    for (Vec3& v : b.vertices) v[0] = -v[0];
    for (auto& f : b.faces) std::reverse(f.begin(), f.end());
    b.liveLoad[0] = -b.liveLoad[0];
  }
  return blocks;
}

}  // namespace corbel::statics
