#pragma once
// The distance to a mass object's shell (an extrusion, a box, a unit), for KIFS buildings that
// follow it (footprint "object", docs/kifs.md): the exact signed distance to a closed triangle
// shell (CGAL), and that distance baked into a regular grid and read back trilinearly as a
// lower bound, which the sphere tracers (CPU and shader) can step by. No GL.
#include "core/mesh_data.h"
#include "kifs/distance.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <vector>

namespace corbel {
class Progress;
}

namespace corbel::kifs {

// Triangles over shared corners: corners are shared by index, as the kernels' soups and the
// Scene share them, never by equal coordinates (a feature mesh touching a wall is a part of its
// own, not glued to the wall).
struct TriangleSoup {
  std::vector<glm::dvec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::array<glm::dvec3, 3> corners(std::size_t t) const {
    return {points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]]};
  }
};

// The faces of a kernel's soup cut into triangles (core's ear clipping; a closed soup stays
// closed: the cuts add only diagonals inside faces).
TriangleSoup trianglesOf(const MeshData& mesh);

// The exact signed distance (negative inside) to the solid a closed triangle shell bounds:
// CGAL's AABB tree for the distance to the nearest triangle, Side_of_triangle_mesh for the
// side. The shell may have several closed components (a house and its chimney); a point is
// inside when it is inside one of them. Where components overlap, a face of one buried in
// another still counts as surface, so deep inside such an overlap |distance| can be smaller
// than the true one (outside the solid the distance is exact).
class ShellDistance {
 public:
  // Throws corbel::Error, its text a predicate of the shell: "not closed (N open edges)",
  // "empty (no triangles)", "not finite (...)".
  explicit ShellDistance(const TriangleSoup& soup);
  ~ShellDistance();
  ShellDistance(const ShellDistance&) = delete;
  ShellDistance& operator=(const ShellDistance&) = delete;

  double signedDistance(const glm::dvec3& p) const;  // safe on any number of threads
  Aabb bounds() const { return bounds_; }
  std::size_t triangles() const { return triangles_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Aabb bounds_;
  std::size_t triangles_ = 0;
};

// A wall of a mass in plan (kifs/facings.h): its extent in the frame's x and y, and its facing.
struct PlanWall {
  glm::dvec2 a{0.0}, b{0.0};
  int facing = 0;
};

// The signed distance sampled at the vertices of a grid of cubic cells over the shell's box
// (plus a margin of kMassFieldMargin cells each way), each sample lowered by the trilinear
// interpolation's error bound (mass_field.cpp) and rounded down to float: the values the shader
// samples from its 3D texture. distance() interpolates them trilinearly, so it is a lower bound
// of the exact signed distance everywhere, and within one cell diagonal of it inside the grid.
struct MassField {
  glm::dvec3 origin{0.0};       // the grid's vertex (0, 0, 0), world
  double cell = 1.0;            // the edge of a cell
  glm::ivec3 count{0};          // vertices per axis
  std::vector<float> values;    // x fastest, then y, then z
  Aabb shell;                   // the shell's box (the field outside the grid: the distance to it)
  double lowered = 0.0;         // what each sample was lowered by: half a cell diagonal
  // The followed object's own frame: its placement's move and turn about z (not its scale).
  // The building folds facades and storeys in it, so they follow the object moved and turned.
  glm::dvec3 frameOrigin{0.0};
  glm::dvec2 frameAxis{1.0, 0.0};  // (cos, sin) of the turn
  glm::dvec3 toFrame(const glm::dvec3& world) const {
    const glm::dvec3 d = world - frameOrigin;
    return {frameAxis.x * d.x + frameAxis.y * d.y, -frameAxis.y * d.x + frameAxis.x * d.y, d.z};
  }
  // With walls that face more than one way (kifs/facings.h; the frame above is then turned to
  // the longest walls): the walls in the frame's plan, each with its facing, and each facing's
  // axis (cos, sin of the frame's turn and the facing's together: one rotation from world, as
  // frameAxis is). Empty with one facing.
  std::vector<PlanWall> walls;
  std::vector<glm::dvec2> facings;
  // The facing of the wall nearest to a point of the frame's plan; `other`, the facing whose
  // nearest wall comes next, and `gap`, half of how much nearer the first wall is than that one:
  // the point is at least `gap` from every point that takes `other` (distances to walls are
  // 1-Lipschitz), and at least `beyond` from every point that takes any third facing.
  struct FacingAt {
    int facing = 0, other = 0;
    double gap = 0, beyond = 0;
  };
  FacingAt facingAt(const glm::dvec2& plan) const;

  Aabb grid() const { return {origin, origin + cell * glm::dvec3(count - 1)}; }
  float at(int i, int j, int k) const { return values[(std::size_t(k) * count.y + j) * count.x + i]; }
  // ≤ the exact signed distance to the shell at any point; inside the grid, ≥ it less one cell
  // diagonal (plus float rounding).
  double distance(const glm::dvec3& p) const;
};

inline constexpr int kMassFieldMargin = 2;     // cells of grid beyond the shell's box

// Bakes `shell` with `resolution` cells along the longest side of its box (1..kMaxMassResolution,
// else corbel::Error naming kifs.mass.resolution). Uses every core; a cancelled progress stops
// it (throws Cancelled).
MassField bakeMassField(const ShellDistance& shell, int resolution, Progress* progress = nullptr);

}  // namespace corbel::kifs
