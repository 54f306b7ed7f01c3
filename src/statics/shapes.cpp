#include "statics/shapes.h"

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
