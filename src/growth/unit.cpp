#include "growth/unit.h"

#include "growth/tolerances.h"

#include <algorithm>
#include <map>

namespace corbel::growth {

double Unit::floorArea() const {
  double a = 0;
  for (const Box& p : parts) a += p.footprintArea();
  return a;
}

double Unit::volume() const {
  double v = 0;
  for (const Box& p : parts) v += p.volume();
  return v;
}

Box Unit::bounds() const {
  Box b = parts.front();
  for (const Box& p : parts)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], p.lo[k]);
      b.hi[k] = std::max(b.hi[k], p.hi[k]);
    }
  return b;
}

bool sideTouchesOwnPart(const Unit& u, int part, Side s) {
  const Box& b = u.parts[part];
  const int k = sideAxis(s);
  const double c = sideCoord(b, s);
  for (int i = 0; i < int(u.parts.size()); ++i) {
    if (i == part) continue;
    const Box& o = u.parts[i];
    if (std::abs(sideCoord(o, opposite(s)) - c) > kEps) continue;
    bool meets = true;
    for (int j = 0; j < 3; ++j)
      if (j != k && overlapLength(b.lo[j], b.hi[j], o.lo[j], o.hi[j]) <= kEps) meets = false;
    if (meets) return true;
  }
  return false;
}

void applyMove(Unit& u, const Move& m) {
  if (m.type == Move::Type::StairBase) {
    u.parts.push_back(m.box);
    return;
  }
  Box& b = u.parts[m.part];
  if (m.type == Move::Type::Advance) {
    const int k = sideAxis(m.side);
    if (sideSign(m.side) > 0)
      b.hi[k] += m.distance;
    else
      b.lo[k] -= m.distance;
    return;
  }
  Box high = b;
  b.hi[m.axis] = m.at;
  high.lo[m.axis] = m.at;
  u.parts.push_back(high);
}

MeshData unitMesh(const Unit& u) {
  // Coordinates of every part boundary, per axis (merged within kEps).
  std::array<std::vector<double>, 3> c;
  for (const Box& p : u.parts)
    for (int k = 0; k < 3; ++k) {
      c[k].push_back(p.lo[k]);
      c[k].push_back(p.hi[k]);
    }
  for (auto& v : c) {
    std::sort(v.begin(), v.end());
    std::vector<double> merged;
    for (double x : v)
      if (merged.empty() || x - merged.back() > kEps) merged.push_back(x);
    v = merged;
  }
  const int n[3] = {int(c[0].size()) - 1, int(c[1].size()) - 1, int(c[2].size()) - 1};
  auto index = [&](int k, double x) {
    return int(std::lower_bound(c[k].begin(), c[k].end(), x - kEps) - c[k].begin());
  };
  std::vector<char> full(std::size_t(n[0]) * n[1] * n[2], 0);
  auto cell = [&](int i, int j, int l) -> char {
    if (i < 0 || j < 0 || l < 0 || i >= n[0] || j >= n[1] || l >= n[2]) return 0;
    return full[(std::size_t(l) * n[1] + j) * n[0] + i];
  };
  for (const Box& p : u.parts) {
    const int i0 = index(0, p.lo[0]), i1 = index(0, p.hi[0]);
    const int j0 = index(1, p.lo[1]), j1 = index(1, p.hi[1]);
    const int l0 = index(2, p.lo[2]), l1 = index(2, p.hi[2]);
    for (int l = l0; l < l1; ++l)
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) full[(std::size_t(l) * n[1] + j) * n[0] + i] = 1;
  }
  MeshData mesh;
  const int wall = mesh.addTag("wall"), roof = mesh.addTag("roof"), floor = mesh.addTag("floor");
  std::map<std::array<int, 3>, int> corner;
  auto point = [&](int i, int j, int l) {
    auto [it, added] = corner.try_emplace({i, j, l}, 0);
    if (added) it->second = mesh.addPoint(Vec3(c[0][i], c[1][j], c[2][l]));
    return it->second;
  };
  for (int l = 0; l < n[2]; ++l)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (!cell(i, j, l)) continue;
        // Each exposed side as a quad, counter-clockwise seen from outside.
        if (!cell(i - 1, j, l))
          mesh.addFace({point(i, j, l), point(i, j, l + 1), point(i, j + 1, l + 1), point(i, j + 1, l)}, wall);
        if (!cell(i + 1, j, l))
          mesh.addFace({point(i + 1, j, l), point(i + 1, j + 1, l), point(i + 1, j + 1, l + 1), point(i + 1, j, l + 1)},
                       wall);
        if (!cell(i, j - 1, l))
          mesh.addFace({point(i, j, l), point(i + 1, j, l), point(i + 1, j, l + 1), point(i, j, l + 1)}, wall);
        if (!cell(i, j + 1, l))
          mesh.addFace({point(i, j + 1, l), point(i, j + 1, l + 1), point(i + 1, j + 1, l + 1), point(i + 1, j + 1, l)},
                       wall);
        if (!cell(i, j, l - 1))
          mesh.addFace({point(i, j, l), point(i, j + 1, l), point(i + 1, j + 1, l), point(i + 1, j, l)}, floor);
        if (!cell(i, j, l + 1))
          mesh.addFace({point(i, j, l + 1), point(i + 1, j, l + 1), point(i + 1, j + 1, l + 1), point(i, j + 1, l + 1)},
                       roof);
      }
  return mesh;
}

}  // namespace corbel::growth
