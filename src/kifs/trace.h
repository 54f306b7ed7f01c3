#pragma once
// CPU sphere tracing of a KIFS building (Hart et al.; McGraw Sec. 3), the twin of the
// shader's march: steps of k·bound with over-relaxation ω and fallback (Keinert et al. 2014),
// only inside the outer shell's box, a hit when the estimate falls below a threshold
// proportional to the distance travelled (one pixel's footprint times trace.hitFactor).
#include "kifs/distance.h"

#include <glm/glm.hpp>

#include <limits>

namespace corbel::kifs {

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 dir;  // unit length
};

struct Hit {
  bool hit = false;
  double t = 0;    // along the ray, world units
  int steps = 0;   // distance evaluations
  // The least estimate / threshold at the samples where it stopped falling and rose again (the
  // ray passed something by): how near the ray came to stopping earlier. Close to 1, a tiny
  // change of the march could stop it there (a graze).
  double closest = std::numeric_limits<double>::infinity();
  // How far, in hit thresholds (at the sample's t), the march's closest decision was from
  // going the other way: the box test (the chord inside the bounds, or the gap to them), each
  // over-relaxation fallback test, each hit test and the exit test. A march run in float (the
  // shader) whose rounding stays below this takes every decision the same way, so it stops at
  // the same sample (the twin test compares only such rays).
  double margin = std::numeric_limits<double>::infinity();
  // With trace's probe > 0 (tests): the largest change, in hit thresholds, of a sample's
  // estimate or bound over six points `probe` away along the axes. Small where both are smooth
  // (about probe / threshold); large where the sample lies within probe of a place where they
  // jump (a storey or facade-id plane, Algorithm 1's bailout), which float rounding can cross.
  double wobble = 0;
  Sample sample;   // at the hit
};

// The ray through the centre of pixel (px, py) of a width × height viewport, py counted from the
// bottom row as gl_FragCoord does, from `eye` through the far plane of `inverseViewProj`.
Ray pixelRay(const glm::dmat4& inverseViewProj, const glm::dvec3& eye, int px, int py, int width, int height);
// Radians per pixel of a vertical field of view spread over `height` pixels (at the centre).
double pixelAngle(double fovDeg, int height);

// Slab test: the interval [t0, t1] of the ray inside the box, false when it misses.
bool rayBox(const Ray& ray, const Aabb& box, double& t0, double& t1);

Hit trace(const Building& building, const Ray& ray, double probe = 0);

// The estimate's gradient by central differences on a tetrahedron of offsets h (normalised).
glm::dvec3 normalAt(const Building& building, const glm::dvec3& p, double h);

}  // namespace corbel::kifs
