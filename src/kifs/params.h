#pragma once
// The parameters of a KIFS building (McGraw, Sec. 3-4): one struct that the CPU distance
// function reads and that render/kifs_pass writes into the shader's uniforms, so both twins
// see the same numbers. Building coordinates follow the paper (y up); the world is Z up, and
// the distance function swaps the two (an isometry) on entry. Definitions: docs/kifs.md.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace corbel::kifs {

// Rotation about the x, then y, then z axis of building coordinates, in degrees
// (R = Rz · Ry · Rx). The paper uses R_y(θ) for R2 and R1 = I (Sec. 4).
struct Rotation {
  double xDeg = 0.0, yDeg = 0.0, zDeg = 0.0;
};

// Footprints of the mass model (Sec. 3, Fig. 8): unions of boxes, Eq. 1-3; or Object, the
// shell of another object of the Document (kifs/mass_field.h, kifs/follow.h), in world space.
enum class Footprint { Box, T, H, Object };

struct MassModel {
  Footprint footprint = Footprint::Box;
  double halfWidth = 6.0;  // h_x of the whole footprint (building units)
  double halfDepth = 6.0;  // h_z of the whole footprint
  double height = 24.0;    // the building stands on y = 0 and ends at y = height
  double wing = 2.5;       // half-width of the bars of T and H footprints
  double shell = 1.2;      // the inner shell is the outer one inset by this much (walls, windows)
  int resolution = 64;     // Object: cells of the baked distance along the longest side of its box
};

// Algorithm 2 (facade fold) and the id-dependent transform of Sec. 3, step 4, with the
// simplifications of Sec. 4: one period w and one r for the x- and z-faces, and
// s = a1·id + a2, t = b1·id + b2.
struct Facade {
  double period = 6.0;                    // w_x = w_z (building units)
  glm::dvec3 r{0.25, 0.125, 0.4};         // r_x = r_z
  double a1 = 0.0, a2 = 1.0, b1 = 0.0, b2 = 0.0;
};

// Eq. 4: y_f = s_y · mod(y − y0, h) / h.
struct Floors {
  double height = 3.0;  // h, one storey (building units)
  double y0 = 0.0;
  double sy = 1.0;
};

// Eq. 5-6: x' = s_θ (atan2(z − z0, x) + c_θ), z' = s_r (√(x² + (z − z0)²) + c_r). The paper's
// Eq. 5 writes atan2(z, x); we measure the angle about the same axis as the radius.
struct Curvilinear {
  bool enabled = false;
  double sTheta = 10.0;  // building units per radian
  double cTheta = 0.0;   // radians
  double sR = 1.0;
  double cR = -14.0;     // building units
  double z0 = 0.0;
};

// How the two tracers (CPU and shader) march rays; also uniforms.
struct Trace {
  int maxSteps = 300;
  double lipschitz = 0.9;        // k ≤ 1: steps are k·d, d a distance bound
  double overRelax = 1.4;        // ω ≥ 1 of Keinert et al. with fallback to plain steps
  double hitFactor = 1.0;        // a hit when d < hitFactor · pixel angle · t
  double pixelAngle = 1e-3;      // radians per pixel; set from the camera by the renderer
};

struct KifsParams {
  // Algorithm 1.
  int iterations = 6;                       // M: folds for i = 0..M (M + 1 in all)
  double scale = 3.0;                       // s
  glm::dvec3 centre{0.93, 0.93, 0.33};      // (x_c, y_c, z_c), Fig. 1b
  Rotation r1, r2;
  double bailout = 1000.0;                  // on r = |p|²; at least ρ², docs/kifs.md
  MassModel mass;
  Facade facade;
  Floors floors;
  Curvilinear curvilinear;
  Trace trace;
};

// Limits of the parameters; validate() refuses values outside them.
inline constexpr int kMaxIterations = 30;
inline constexpr double kMaxScale = 10.0;
inline constexpr int kMaxMassResolution = 512;  // mass.resolution: cells along the longest side

// ρ = max(2, |c|): the radius beyond which orbits escape and the bound's sphere (docs/kifs.md).
double escapeRadius(const KifsParams& p);
// Throws corbel::Error naming the first bad field ("kifs.scale: must be > 1, got 0.5").
void validate(const KifsParams& p);

// Named presets reproducing the looks of the paper's figures (docs/kifs.md lists them): the
// files assets/kifs/NAME.json (core/assets.h finds assets/), each a KIFS spec in the project
// file's format (core/kifs_json.h), read at every call.
std::string presetDir();
// The stems of the folder's .json files, sorted.
std::vector<std::string> presetNames();
// Throws corbel::Error listing the names when `name` is unknown.
KifsParams preset(const std::string& name);
// Reads one preset file: its values validated (kifs::paramsOf), unknown keys refused. Throws
// corbel::Error beginning with the file's path and naming the JSON path of the fault
// ("…/box.json: kifs.mass.shell: must be …").
KifsParams loadPreset(const std::string& file);

}  // namespace corbel::kifs
