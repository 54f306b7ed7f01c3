#pragma once
// Forward statics of a rigid-block assembly (Whiting et al. 2009, Sec. 3): the penalty QP
// y = min Σ (f_n⁻)² (Sec. 3.2) and a strict LP feasibility test for exact thresholds.
#include "statics/interfaces.h"
#include "statics/ipm.h"
#include "statics/model.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace corbel::statics {

struct AnalysisOptions {
  double friction = 0.7;              // α, the coefficient of static friction
  bool conservativeFriction = false;  // use α/√2, so the cone circumscribes the pyramid (Sec. 3.1)
  // Sides of the friction pyramid (Sec. 3.1): 4 (|f_t1|, |f_t2| ≤ α f_n⁺, the paper's) or 8
  // (the octagon whose sides touch the friction circle: it exceeds the cone by at most
  // 1/cos(π/8) − 1 = 8 % in its corners, the square by √2 − 1 = 41 %; twice the rows).
  int frictionSides = 4;
  double kernShrink = 0.0;            // in [0, 1): geometric factor of safety (Sec. 3.4)
  // Faces of different blocks closer than this (m) and opposite count as touching: 0 keeps the
  // kernel's own tolerance (1e-9 of the model's size). Placed objects rarely touch to that, so
  // masonry objects analysed together (statics/composite.h) use a joint the artist sets.
  double contactTolerance = 0.0;
  IpmOptions solver;
};

// The force at one contact vertex, in the interface frame, in newtons. The force on block b
// is (compression − tension)·n + t1·t̂1 + t2·t̂2; block a receives its opposite.
struct VertexForce {
  Vec3 point{0.0};
  double compression = 0, tension = 0, t1 = 0, t2 = 0;
  double normal() const { return compression - tension; }
};

struct InterfaceForces {
  int a = -1, b = -1;
  Vec3 normal{0.0};
  double area = 0;
  std::vector<VertexForce> vertices;
  Vec3 resultant{0.0};        // net force on b, N
  double normalForce = 0;     // net normal force (positive: compression), N
  double tangentialForce = 0; // magnitude of the net in-plane force, N
  // Where the net normal force acts (the centre of pressure); meaningful when normalForce > 0.
  Vec3 centreOfPressure{0.0};
  // The centre of pressure relative to the contact polygon, as the factor by which the polygon
  // must be scaled about its area centroid to reach it (Sec. 3.4, Fig. 7): 0 at the centroid,
  // 1 on the boundary, above 1 outside (only tension can put it there). The kern shrink s
  // keeps it within 1 − s; a rectangle's middle third along an axis is 1/3. Infinite when the
  // net normal force is not compressive.
  double pressureGauge = 0;
  double maxTension = 0;      // the largest f_n⁻ at a vertex, N
};

// A contact vertex carrying tension (f_n⁻ > kTensionSite·W): where the structure would need
// glue (Sec. 3.2, Fig. 6).
struct TensionSite {
  int interface = -1;  // index into AnalysisResult::interfaces
  int vertex = -1;     // index into that interface's vertices
  Vec3 point{0.0};
  double tension = 0;  // N
};

struct AnalysisResult {
  SolveStatus status = SolveStatus::NumericalFailure;
  int iterations = 0;
  double totalWeight = 0;          // W, N
  double y = 0;                    // Σ (f_n⁻)², N²
  double yNormalised = 0;          // y / W²
  bool feasible = false;           // optimal and y/W² ≤ kFeasibleMeasure
  double equilibriumResidual = 0;  // ‖A f + w‖ / ‖w‖
  double gap = 0;                  // the solver's duality gap in units of y/W²: y/W² is within it of the optimum
  std::vector<InterfaceForces> interfaces;
  std::vector<TensionSite> tensionSites;  // largest tension first
  std::vector<std::string> warnings;
  Eigen::VectorXd multipliers;  // of the equilibrium rows, for loads normalised by W
  Eigen::VectorXd solution;     // the QP's x: [f_n⁺, f_n⁻, f_t1, f_t2] per vertex, in units of W
};

// Solves the penalty QP. Throws corbel::Error for bad input or degenerate geometry (a block
// that floats, one touching others only along an edge), naming the block.
AnalysisResult analyse(const Assembly& assembly, const AnalysisOptions& options = {});

struct FeasibilityResult {
  bool feasible = false;
  double violation = 0;  // least Σ |equilibrium violation| with f_n ≥ 0 and friction, in units of W
  SolveStatus status = SolveStatus::NumericalFailure;
  int iterations = 0;
};

// LP phase-1: is there a compression-only force field (f_n ≥ 0, friction pyramid on f_n,
// no tension variables) in equilibrium? Artificial variables on every equilibrium row
// measure the least violation, which grows linearly past a threshold.
FeasibilityResult checkFeasibility(const Assembly& assembly, const AnalysisOptions& options = {});

}  // namespace corbel::statics
