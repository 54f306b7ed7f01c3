#include "sim/mass_properties.h"

#include "core/error.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::sim {

MassProperties massProperties(const statics::Block& block) {
  if (block.vertices.empty() || block.faces.empty()) throw Error("block \"" + block.name + "\" has no faces");
  // Every face, fanned into triangles, makes a tetrahedron with the reference point; their signed
  // volumes, first and second moments add up to the solid's. For a tetrahedron with corners
  // 0, a, b, c (relative to the reference), ∫ x xᵀ dV = V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a + b + c.
  const Eigen::Vector3d ref(block.vertices[0][0], block.vertices[0][1], block.vertices[0][2]);
  auto at = [&](int i) -> Eigen::Vector3d {
    return Eigen::Vector3d(block.vertices[i][0], block.vertices[i][1], block.vertices[i][2]) - ref;
  };
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& f : block.faces) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d a = at(f[0]), b = at(f[k]), c = at(f[k + 1]);
      const double v = a.dot(b.cross(c)) / 6.0;
      const Eigen::Vector3d s = a + b + c;
      volume += v;
      first += v * s / 4.0;
      second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  if (!(volume > 0) || !std::isfinite(volume))
    throw Error("block \"" + block.name + "\" encloses no positive volume (open or inward-facing faces)");
  const Eigen::Vector3d mean = first / volume;
  const Eigen::Matrix3d central = second - volume * mean * mean.transpose();
  // Inertia about the centroid: I = tr(C) 1 − C, C the central second moment.
  const Eigen::Matrix3d inertia = central.trace() * Eigen::Matrix3d::Identity() - central;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
  Eigen::Matrix3d axes = eigen.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);

  MassProperties m;
  m.volume = volume;
  const Eigen::Vector3d c = ref + mean;
  m.centroid = Vec3(c[0], c[1], c[2]);
  for (int i = 0; i < 3; ++i) {
    m.principalMoments[i] = std::max(eigen.eigenvalues()[i], 0.0);
    m.principalAxes[i] = Vec3(axes(0, i), axes(1, i), axes(2, i));
  }
  m.leastWidth = std::numeric_limits<double>::infinity();
  for (const auto& f : block.faces) {
    std::vector<Vec3> loop;
    for (int i : f) loop.push_back(block.vertices[i]);
    Vec3 n = newellNormal(loop);
    if (!(n.norm() > 0)) continue;
    n /= n.norm();
    double depth = 0;
    for (const Vec3& v : block.vertices) depth = std::max(depth, dot(n, loop[0] - v));
    m.leastWidth = std::min(m.leastWidth, depth);
  }
  return m;
}

}  // namespace corbel::sim
