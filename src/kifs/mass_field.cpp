#include "kifs/mass_field.h"

#include "core/error.h"
#include "core/geometry.h"
#include "core/progress.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <cstdint>
#include <string>
#include <thread>

namespace corbel::kifs {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using Side = CGAL::Side_of_triangle_mesh<Mesh, K>;

}  // namespace

TriangleSoup trianglesOf(const MeshData& mesh) {
  TriangleSoup out;
  for (const Vec3& p : mesh.points) out.points.emplace_back(p[0], p[1], p[2]);
  std::vector<Vec3> loop;
  for (const auto& face : mesh.faces) {
    loop.clear();
    for (int v : face) loop.push_back(mesh.points[v]);
    for (const auto& t : triangulatePolygon(loop)) out.triangles.push_back({face[t[0]], face[t[1]], face[t[2]]});
  }
  return out;
}

struct ShellDistance::Impl {
  Mesh whole;
  Tree tree;
  std::vector<Mesh> parts;               // the closed components
  std::vector<std::unique_ptr<Side>> sides;  // one per part
};

ShellDistance::ShellDistance(const TriangleSoup& soup) : impl_(std::make_unique<Impl>()) {
  if (soup.triangles.empty()) throw Error("empty (no triangles)");
  // The soup oriented consistently and turned into a half-edge mesh; only the corners the
  // triangles use count.
  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3>> polygons;
  std::vector<std::size_t> index(soup.points.size(), SIZE_MAX);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& t : soup.triangles) {
    std::array<std::size_t, 3> poly{};
    for (int c = 0; c < 3; ++c) {
      if (t[c] < 0 || std::size_t(t[c]) >= soup.points.size()) throw Error("malformed (a corner index out of range)");
      const glm::dvec3& p = soup.points[t[c]];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) throw Error("not finite (a corner is NaN or infinite)");
      if (index[t[c]] == SIZE_MAX) {
        index[t[c]] = points.size();
        points.emplace_back(p.x, p.y, p.z);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
      poly[c] = index[t[c]];
    }
    polygons.push_back(poly);
  }
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, impl_->whole);
  std::size_t open = 0;
  for (auto h : impl_->whole.halfedges())
    if (impl_->whole.is_border(h)) ++open;
  if (open) throw Error("not closed (" + std::to_string(open) + " open edges)");
  impl_->tree.insert(faces(impl_->whole).first, faces(impl_->whole).second, impl_->whole);
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
  CGAL::Polygon_mesh_processing::split_connected_components(impl_->whole, impl_->parts);
  for (const Mesh& part : impl_->parts) impl_->sides.push_back(std::make_unique<Side>(part));
  bounds_ = {lo, hi};
  triangles_ = soup.triangles.size();
  signedDistance(0.5 * (lo + hi));  // builds the trees CGAL builds lazily, before any threads query
}

ShellDistance::~ShellDistance() = default;

double ShellDistance::signedDistance(const glm::dvec3& p) const {
  const K::Point_3 q(p.x, p.y, p.z);
  const double d = std::sqrt(CGAL::to_double(impl_->tree.squared_distance(q)));
  for (const auto& side : impl_->sides)
    if ((*side)(q) != CGAL::ON_UNBOUNDED_SIDE) return -d;
  return d;
}

// Why half a cell diagonal bounds the interpolation error. The exact signed distance f is
// 1-Lipschitz (as any signed distance to a closed set's boundary). Trilinear interpolation in a
// cell of edges h (per axis) at a point p with local coordinates t ∈ [0, 1]³ is
// I(p) = Σ w_k f(v_k) with weights w_k = Π (t or 1 − t) ≥ 0 summing to 1, so
//   |I(p) − f(p)| ≤ Σ w_k |f(v_k) − f(p)| ≤ Σ w_k |v_k − p| ≤ √(Σ w_k |v_k − p|²)   (Jensen)
// and Σ w_k |v_k − p|² = Σ_axes h² ((1 − t)·t² + t·(1 − t)²) = Σ_axes h² t(1 − t) ≤ 3h²/4.
// Hence |I − f| ≤ (√3/2)·h, half the cell diagonal. Lowering every sample by that much makes the
// interpolant a lower bound of f, at most one diagonal below it.
MassField bakeMassField(const ShellDistance& shell, int resolution, Progress* progress) {
  if (resolution < 1 || resolution > kMaxMassResolution)
    throw Error("kifs.mass.resolution: must be in 1.." + std::to_string(kMaxMassResolution) + ", got " +
                std::to_string(resolution));
  const Aabb box = shell.bounds();
  const glm::dvec3 size = box.size();
  MassField f;
  f.shell = box;
  f.cell = std::max({size.x, size.y, size.z}) / resolution;
  if (!(f.cell > 0)) throw Error("flat (its box has no extent)");
  f.origin = box.lo - double(kMassFieldMargin) * f.cell;
  for (int a = 0; a < 3; ++a) f.count[a] = static_cast<int>(std::ceil(size[a] / f.cell)) + 2 * kMassFieldMargin + 1;
  f.lowered = 0.5 * std::sqrt(3.0) * f.cell;
  f.values.resize(std::size_t(f.count.x) * f.count.y * f.count.z);
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 16);
  std::atomic<int> nextLayer{0};
  std::atomic<bool> stop{false};
  auto work = [&] {
    while (!stop) {
      const int k = nextLayer++;
      if (k >= f.count.z) break;
      for (int j = 0; j < f.count.y; ++j)
        for (int i = 0; i < f.count.x; ++i) {
          const double v = shell.signedDistance(f.origin + f.cell * glm::dvec3(i, j, k)) - f.lowered;
          float s = static_cast<float>(v);
          if (double(s) > v) s = std::nextafter(s, -std::numeric_limits<float>::infinity());  // round down
          f.values[(std::size_t(k) * f.count.y + j) * f.count.x + i] = s;
        }
      if (progress && progress->cancelled()) stop = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (stop) throw Cancelled();
  if (progress) progress->report(1.0, "mass field");
  return f;
}

double MassField::distance(const glm::dvec3& p) const {
  const Aabb g = grid();
  const glm::dvec3 q = glm::clamp(p, g.lo, g.hi);
  const glm::dvec3 u = (q - origin) / cell;
  glm::ivec3 i;
  glm::dvec3 t;
  for (int a = 0; a < 3; ++a) {
    i[a] = std::clamp(static_cast<int>(std::floor(u[a])), 0, count[a] - 2);
    t[a] = std::clamp(u[a] - i[a], 0.0, 1.0);
  }
  auto lerp = [](double a, double b, double s) { return a + s * (b - a); };
  auto row = [&](int j, int k) { return lerp(at(i.x, j, k), at(i.x + 1, j, k), t.x); };
  const double inside = lerp(lerp(row(i.y, i.z), row(i.y + 1, i.z), t.y), lerp(row(i.y, i.z + 1), row(i.y + 1, i.z + 1), t.y), t.z);
  if (q == p) return inside;
  // Outside the grid: the field at the nearest grid point less the way there (f is 1-Lipschitz),
  // or the distance to the shell's box, whichever is larger; both are lower bounds.
  const glm::dvec3 out = glm::max(glm::max(shell.lo - p, p - shell.hi), 0.0);
  return std::max(inside - glm::length(p - q), glm::length(out));
}

}  // namespace corbel::kifs
