#pragma once
// The equilibrium system A f + w = 0 of an assembly (Whiting et al. 2009, Sec. 3.1 and the
// appendix) and the penalty QP built on it (Sec. 3.2), as matrices. `analyse` solves them;
// the parameter search (Sec. 4) rebuilds them for nearby parameters to differentiate y.
#include "statics/analysis.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace corbel::statics {

// Geometry, contacts, the equilibrium rows and the loads of one assembly.
struct EquilibriumSystem {
  std::vector<BlockProperties> props;
  Contacts contacts;
  std::vector<int> rowOf;  // block → first of its six equilibrium rows, −1 for fixed blocks
  int rows = 0;
  double totalWeight = 0;  // W, N, of the free blocks
  Eigen::VectorXd w;       // loads / W, six per free block (force, then torque about the centroid)
  double alpha = 0.7;      // the friction coefficient in use (α or α/√2)
  int frictionSides = 4;   // of the pyramid, 4 or 8
  std::vector<std::string> warnings;
};

// Validates the assembly, finds its contacts and its loads. Throws corbel::Error for bad
// input and for blocks that float or are not connected to a fixed block, naming them.
EquilibriumSystem prepareEquilibrium(const Assembly& assembly, const AnalysisOptions& options);

// The penalty QP of Sec. 3.2 for loads / W: variables [f_n⁺, f_n⁻, f_t1, f_t2] per contact
// vertex, interfaces in the order of `system.contacts`, vertices in polygon order. A x = −w.
BlockQP penaltyQP(const EquilibriumSystem& system);

// λᵀ(A x + w) for the penalty QP's A (x laid out as `penaltyQP`'s variables, λ one per
// equilibrium row) without building A: the envelope gradient evaluates it at nearby
// parameters, where assembling the sparse matrix cost as much as the geometry.
double penaltyLagrangianTerm(const EquilibriumSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& lambda);

// Solves the penalty QP of a prepared system (what `analyse` does after preparing it).
AnalysisResult analyseSystem(const EquilibriumSystem& system, const AnalysisOptions& options);

// True when two systems have the same blocks, interfaces and vertex counts, so that one
// force vector x means the same forces in both (the layout of `penaltyQP`).
bool sameLayout(const EquilibriumSystem& a, const EquilibriumSystem& b);

}  // namespace corbel::statics
