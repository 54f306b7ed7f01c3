#pragma once
// The KIFS building's distance function (McGraw, Sec. 3): Algorithm 1 on coordinates folded by
// Algorithm 2 and Eq. 4 (optionally after Eq. 5-6), cut by the mass model's shells. The shader
// shaders/kifs.frag.glsl is its twin, line for line. Definitions and proofs: docs/kifs.md.
#include "kifs/params.h"

#include <glm/glm.hpp>

#include <cmath>
#include <memory>

namespace corbel::kifs {

// One evaluation at a world point (Z up).
struct Sample {
  double bound = 0;    // ≤ the distance to the building everywhere (world units): safe steps
  double surface = 0;  // the building's estimate without the cell-boundary caps: hit tests, normals
  int idX = 0, idZ = 0;  // facade ids of Algorithm 2 (x- and z-faces)
  int floor = 0;         // storey index, floor((y − y0) / h)
};

struct Aabb {
  glm::dvec3 lo, hi;
  glm::dvec3 size() const { return hi - lo; }
};

struct MassField;  // kifs/mass_field.h

class Building {
 public:
  // Throws corbel::Error naming the bad field (validate()). A building whose footprint is
  // Object follows `mass`, the baked distance to that object's shell in world space (its outer
  // shell; the inner one is that shell offset inward by mass.shell); the others ignore it.
  explicit Building(const KifsParams& params, std::shared_ptr<const MassField> mass = nullptr);

  Sample evaluate(const glm::dvec3& world) const;
  // Algorithm 1 in fractal coordinates: negative inside, ≤ the distance to its solid.
  double kifs(glm::dvec3 q) const;
  // The world box holding the outer shell (the ray-bounds test).
  Aabb worldBounds() const { return bounds_; }

  const KifsParams& params() const { return p_; }
  const std::shared_ptr<const MassField>& mass() const { return mass_; }
  // Derived values the shader receives too (render/kifs_pass.cpp).
  const glm::dmat3& r1() const { return r1_; }
  const glm::dmat3& r2() const { return r2_; }
  bool r1Identity() const { return r1Identity_; }
  bool r2Identity() const { return r2Identity_; }
  double rho() const { return rho_; }                  // ρ of the bound
  double fractalStretch() const { return stretch_; }   // Lipschitz constant of building → fractal coordinates
  bool idsCut() const { return idsCut_; }              // ids change the transform (a1 or b1 ≠ 0)
  double ringInner() const { return ringInner_; }      // curvilinear: the annulus holding the building
  double ringOuter() const { return ringOuter_; }
  bool closedRing() const { return closedRing_; }      // curvilinear: no seam where the angle jumps

 private:
  KifsParams p_;
  std::shared_ptr<const MassField> mass_;
  glm::dmat3 r1_{1.0}, r2_{1.0};
  bool r1Identity_ = true, r2Identity_ = true;
  double rho_ = 2, stretch_ = 1;
  bool idsCut_ = false;
  double ringInner_ = 0, ringOuter_ = 0;
  bool closedRing_ = false;
  Aabb bounds_;
};

// Algorithm 2 for one coordinate: the fold value, the facade id, and `gap`, the least |value|
// at the id tests in fold units (the fold is 2/w-Lipschitz, so the id cannot change within
// gap·w/2 of x). The triangle wave is |2 mod(x, w)/w − 1| (docs/kifs.md: the paper's "− 1/2"
// is not periodic).
struct FacadeFold {
  double f;
  int id;
  double gap;
};
FacadeFold facadeFold(double x, const Facade& facade);

// Eq. 1-3: the distance to a union of boxes of the footprint, standing on y = 0, each box
// shrunk by `inset` sideways and at the top (inset 0: the outer shell; shell: the inner one).
double massModelDistance(const MassModel& m, const glm::dvec3& building, double inset);

// GLSL's mod (x − y·floor(x / y)), which the facade and floor folds use.
inline double glslMod(double x, double y) { return x - y * std::floor(x / y); }

}  // namespace corbel::kifs
