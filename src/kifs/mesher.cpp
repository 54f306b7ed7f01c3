#include "kifs/mesher.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace corbel::kifs {

namespace {

// The six tetrahedra of the unit cube around its diagonal (0,0,0)-(1,1,1): one per order of
// the axes, so neighbouring cubes cut their shared faces the same way.
constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

// Edge points are placed at least this fraction of an edge from its ends, so no triangle
// collapses onto a grid vertex.
constexpr double kEdgeClamp = 1e-4;

struct Grid {
  glm::dvec3 origin;
  double h;
  int nx, ny, nz;  // cells
  std::int64_t vertex(int i, int j, int k) const {
    return i + static_cast<std::int64_t>(nx + 1) * (j + static_cast<std::int64_t>(ny + 1) * k);
  }
};

}  // namespace

MeshData meshIsosurface(const std::function<double(const glm::dvec3&)>& field, const Aabb& box, int resolution,
                        Progress* progress) {
  if (resolution < 1 || resolution > kMaxMeshResolution)
    throw Error("mesh resolution: must be in 1.." + std::to_string(kMaxMeshResolution) + ", got " +
                std::to_string(resolution));
  const glm::dvec3 size = box.size();
  Grid g;
  g.h = std::max({size.x, size.y, size.z}) / resolution;
  g.origin = box.lo - g.h;
  g.nx = static_cast<int>(std::ceil(size.x / g.h)) + 2;
  g.ny = static_cast<int>(std::ceil(size.y / g.h)) + 2;
  g.nz = static_cast<int>(std::ceil(size.z / g.h)) + 2;
  const int layer = (g.nx + 1) * (g.ny + 1);
  // Samples one layer, its rows shared among the cores (the field must be safe to call from
  // several threads; Building::evaluate is).
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 16);
  auto sampleLayer = [&](int k, std::vector<double>& out) {
    out.resize(layer);
    auto rows = [&](int first) {
      for (int j = first; j <= g.ny; j += threads)
        for (int i = 0; i <= g.nx; ++i) out[i + (g.nx + 1) * j] = field(g.origin + g.h * glm::dvec3(i, j, k));
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(rows, t);
    rows(0);
    for (auto& th : pool) th.join();
  };

  MeshData mesh;
  std::unordered_map<std::int64_t, int> below, current;  // edge key → point; `below`: edges within layer k
  std::vector<double> lower, upper;
  sampleLayer(0, lower);
  for (int k = 0; k < g.nz; ++k) {
    if (progress) {
      if (progress->cancelled()) throw Cancelled();
      progress->report(double(k) / g.nz, "meshing");
    }
    sampleLayer(k + 1, upper);
    current.clear();
    auto value = [&](int i, int j, int kk) { return (kk == k ? lower : upper)[i + (g.nx + 1) * j]; };
    auto edgePoint = [&](const std::array<int, 3>& a, const std::array<int, 3>& b) {
      std::int64_t va = g.vertex(a[0], a[1], a[2]), vb = g.vertex(b[0], b[1], b[2]);
      if (va > vb) std::swap(va, vb);
      const std::int64_t key = va * (static_cast<std::int64_t>(layer) * (g.nz + 1)) + vb;
      const bool inBelow = a[2] == k && b[2] == k;
      auto& map = inBelow ? below : current;
      auto it = map.find(key);
      if (it != map.end()) return it->second;
      const double fa = value(a[0], a[1], a[2]), fb = value(b[0], b[1], b[2]);
      const double t = std::clamp(fa / (fa - fb), kEdgeClamp, 1.0 - kEdgeClamp);
      const glm::dvec3 pa = g.origin + g.h * glm::dvec3(a[0], a[1], a[2]);
      const glm::dvec3 pb = g.origin + g.h * glm::dvec3(b[0], b[1], b[2]);
      const glm::dvec3 p = pa + t * (pb - pa);
      const int index = mesh.addPoint(Vec3(p.x, p.y, p.z));
      map.emplace(key, index);
      return index;
    };
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        for (const auto& order : kAxisOrders) {
          std::array<std::array<int, 3>, 4> v;
          v[0] = {i, j, k};
          for (int s = 0; s < 3; ++s) {
            v[s + 1] = v[s];
            ++v[s + 1][order[s]];
          }
          std::array<bool, 4> in;
          int inside = 0;
          for (int s = 0; s < 4; ++s) inside += in[s] = value(v[s][0], v[s][1], v[s][2]) < 0;
          if (inside == 0 || inside == 4) continue;
          std::vector<int> ins, outs;
          for (int s = 0; s < 4; ++s) (in[s] ? ins : outs).push_back(s);
          // Outward: from the inside corners towards the outside ones.
          glm::dvec3 dir(0.0);
          for (int s : outs) dir += glm::dvec3(v[s][0], v[s][1], v[s][2]) / double(outs.size());
          for (int s : ins) dir -= glm::dvec3(v[s][0], v[s][1], v[s][2]) / double(ins.size());
          auto emit = [&](int a, int b, int c) {
            const Vec3 &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c];
            const Vec3 n = OpenMesh::cross(pb - pa, pc - pa);
            if (n[0] * dir.x + n[1] * dir.y + n[2] * dir.z < 0) std::swap(b, c);
            mesh.addFace({a, b, c});
          };
          if (ins.size() == 1 || outs.size() == 1) {
            const bool one = ins.size() == 1;
            const int apex = one ? ins[0] : outs[0];
            const std::vector<int>& others = one ? outs : ins;
            emit(edgePoint(v[apex], v[others[0]]), edgePoint(v[apex], v[others[1]]),
                 edgePoint(v[apex], v[others[2]]));
          } else {  // two in, two out: a quad, split along one diagonal inside the tetrahedron
            const int p0 = edgePoint(v[ins[0]], v[outs[0]]), p1 = edgePoint(v[ins[0]], v[outs[1]]);
            const int p2 = edgePoint(v[ins[1]], v[outs[1]]), p3 = edgePoint(v[ins[1]], v[outs[0]]);
            emit(p0, p1, p2);
            emit(p0, p2, p3);
          }
        }
    // Edges within layer k + 1 are shared with the next slab; the rest are done with.
    below.clear();
    const std::int64_t firstOfUpper = static_cast<std::int64_t>(layer) * (k + 1);
    for (const auto& [key, index] : current) {
      const std::int64_t va = key / (static_cast<std::int64_t>(layer) * (g.nz + 1));
      if (va >= firstOfUpper) below.emplace(key, index);
    }
    lower.swap(upper);
  }
  if (progress) progress->report(1.0, "meshing");
  return mesh;
}

MeshData meshBuilding(const Building& building, int resolution, Progress* progress) {
  const glm::dvec3 size = building.worldBounds().size();
  const double offset = kMeshOffset * std::max({size.x, size.y, size.z}) / std::max(resolution, 1);
  MeshData m = meshIsosurface([&](const glm::dvec3& p) { return building.evaluate(p).surface - offset; },
                              building.worldBounds(), resolution, progress);
  const int tag = m.addTag("kifs");
  std::fill(m.faceTag.begin(), m.faceTag.end(), tag);
  return m;
}

}  // namespace corbel::kifs
