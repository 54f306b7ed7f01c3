#pragma once
// A KIFS building (McGraw): the numbers of kifs::KifsParams as plain data, so the Document and
// the project file can hold them. The kifs library owns what they mean: kifs::paramsOf turns
// a spec into its KifsParams and kifs::validate checks the values, naming the field by the
// same path the project file uses ("kifs.mass.shell"). The names and defaults here mirror
// kifs/params.h field by field (a test holds the two to each other).
#include "core/geometry.h"

#include <string>

namespace corbel {

struct KifsSpec {
  std::string preset;  // the preset it started from ("" = none); informational
  // Algorithm 1.
  int iterations = 6;
  double scale = 3.0;
  Vec3 centre{0.93, 0.93, 0.33};
  Vec3 r1{0.0, 0.0, 0.0};  // rotations about x, y, z, degrees (R = Rz · Ry · Rx)
  Vec3 r2{0.0, 0.0, 0.0};
  double bailout = 1000.0;
  struct Mass {
    std::string footprint = "box";  // "box", "T", "H" or "object"
    double halfWidth = 6.0, halfDepth = 6.0, height = 24.0, wing = 2.5, shell = 1.2;
    std::string object;   // footprint "object": the name of the Document's object it follows
    std::string building; // when that object is a town: the footprint id of the one building it follows
    int resolution = 64;  // footprint "object": cells of the baked distance along the longest side
    bool operator==(const Mass&) const = default;
  } mass;
  struct Facade {
    double period = 6.0;
    Vec3 r{0.25, 0.125, 0.4};
    double a1 = 0.0, a2 = 1.0, b1 = 0.0, b2 = 0.0;
    bool operator==(const Facade&) const = default;
  } facade;
  struct Floors {
    double height = 3.0, y0 = 0.0, sy = 1.0;
    bool operator==(const Floors&) const = default;
  } floors;
  struct Curvilinear {
    bool enabled = false;
    double sTheta = 10.0, cTheta = 0.0, sR = 1.0, cR = -14.0, z0 = 0.0;
    bool operator==(const Curvilinear&) const = default;
  } curvilinear;
  struct Trace {
    int maxSteps = 300;
    double lipschitz = 0.9, overRelax = 1.4, hitFactor = 1.0;
    bool operator==(const Trace&) const = default;
  } trace;
  // Cells along the building's longest side when it is meshed into the Scene ("Mesh to
  // Scene"); 0: it is only ray-marched and has no faces in the Scene.
  int meshResolution = 0;
  std::string material = "stone";  // of the meshed faces
  bool operator==(const KifsSpec&) const = default;
};

namespace limits {
// Whole numbers of a KIFS spec (iterations, trace.maxSteps) the file may hold; the kifs kernel
// has its own, tighter limits and names the field when one is exceeded.
inline constexpr long kMaxKifsCount = 1000000;
inline constexpr long kMaxKifsMeshResolution = 1024;  // kifs::kMaxMeshResolution
}  // namespace limits

}  // namespace corbel
