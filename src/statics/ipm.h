#pragma once
// A primal-dual interior-point method for the block-structured convex QPs of the statics
// kernel: min ½ xᵀQx + cᵀx  s.t.  A x = b,  G x ≥ 0, where x splits into small variable
// blocks (at most 4 variables: one contact vertex, or one artificial), Q is diagonal and
// every inequality row involves one block only. Each Newton step eliminates the blocks'
// Hessians H_j = Q_j + G_jᵀ D_j G_j (dense, ≤ 4×4) and factors the Schur complement
// A H⁻¹ Aᵀ (one row per equilibrium equation) with a sparse LDLᵀ after an AMD ordering.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace corbel::statics {

struct VarBlock {
  int offset = 0;                   // first variable of the block in x
  int size = 0;                     // 1..4
  std::array<double, 4> hessian{};  // diagonal of Q on the block
  std::array<double, 4> cost{};     // c on the block
  // Inequality rows g·x_block ≥ 0, coefficients on the block's variables.
  std::vector<std::array<double, 4>> rows;
  // Optional: a direction e on the block's variables with A_j e = 0 exactly (the penalty QP:
  // f_n⁺ and f_n⁻ have opposite columns, e = (−1, −1, 0, 0) trades tension for less
  // compression). The early exit moves an iterate along it to lower the objective, keeping
  // every row ≥ 0; all zeros for none.
  std::array<double, 4> nullDirection{};
  // Optional: a direction d with g·d > 0 for every row of the block (strictly inside its cone).
  // The feasibility correction moves a point whose rows are negative by rounding along it, by
  // just enough to make them ≥ 0; all zeros for none.
  std::array<double, 4> interiorDirection{};
};

struct BlockQP {
  std::vector<VarBlock> blocks;
  Eigen::SparseMatrix<double> A;  // equations × variables
  Eigen::VectorXd b;
  // Equations come in groups of this many consecutive rows (6: force and torque of a block);
  // SchurSolver::BlockLdlt needs 6, other values fall back to Eigen's SimplicialLDLT.
  int rowGroup = 1;
};

enum class SolveStatus {
  Optimal,          // residuals and duality gap within tolerance, or the objective certified
                    // within IpmOptions::objectiveExitBelow of its optimum (then gap = that bound)
  IterationLimit,   // the iteration cap was reached; the best iterate is returned
  TimeLimit,        // the time cap was reached; the best iterate is returned
  ReducedAccuracy,  // stopped short of the tolerances (iteration cap or a failed factorisation)
                    // at a best iterate in equilibrium (residual ≤ 1e-9), dual residual ≤ 1e-7,
                    // gap ≤ 1e-3 of the objective: the objective is within the gap of its optimum
  NumericalFailure  // the Newton system could not be factored even with regularisation
};

std::string toString(SolveStatus s);

// The factorisation of the Schur complement A H⁻¹ Aᵀ in every Newton step.
enum class SchurSolver {
  BlockLdlt,  // ours (block_ldlt.h): LDLᵀ on 6×6 blocks, AMD on the graph of blocks; needs rowGroup 6
  Cholmod,    // CHOLMOD's supernodal LLᵀ (SuiteSparse), AMD/METIS ordering chosen by CHOLMOD
  EigenLdlt   // Eigen's SimplicialLDLT with AMD ordering
};

struct IpmOptions {
  SchurSolver schurSolver = SchurSolver::BlockLdlt;
  int maxIterations = 80;
  double maxSeconds = 0;  // wall-clock cap on one solve, 0 for none
  // Threads for the block factorisation (BlockLdlt::setThreads): 0 takes two on a large Schur
  // complement where the machine has them, 1 keeps the solve on the calling thread. The
  // answer is the same bit for bit.
  int threads = 0;
  int newtonRefinement = 1;             // correction steps on the unreduced Newton system (see ipm.cpp)
  double residualTolerance = 1e-11;     // on ‖Ax − b‖∞/(1 + ‖b‖∞) and the dual residual
  double gapTolerance = 1e-13;          // absolute, on sᵀz (loads are normalised, so O(1))
  double relativeGapTolerance = 1e-10;  // or relative to |objective|
  // Early exit on a certified small objective (docs/statics.md, "The early exit"): when c = 0
  // and Q ≥ 0 (the objective is ≥ 0, as in the penalty QP), a point x̃ with A x̃ = b to
  // residualTolerance, G x̃ ≥ 0 and ½x̃ᵀQx̃ ≤ this bound is optimal to within the bound. x̃ is
  // the iterate moved along the blocks' nullDirection; the solve stops there as `optimal`
  // with `gap` = ½x̃ᵀQx̃ (the certified bound). 0 turns it off.
  double objectiveExitBelow = 1e-12;
  // The feasibility correction ("the least-squares start", docs/statics.md): after the first
  // factorisation, and at later iterates whose projected objective is already at most
  // correctBelow, this many rounds of "remove the tension, restore equilibrium with one solve
  // of this iteration's factorisation, project" are tried against the early exit's
  // certificate; a point that fails it is dropped. 0 turns it off.
  int feasibilityCorrections = 1;
  double correctBelow = 1e-8;
  // Where the iterations stop short of the tolerances (a failed factorisation or the iteration
  // cap, not the time cap), the best iterate's active rows are taken as equalities and the
  // equality-constrained QP solved ("the polish", docs/statics.md); its point is returned as
  // `optimal` when it passes the KKT conditions to the tolerances, else nothing changes.
  bool polish = true;
};

struct IpmResult {
  SolveStatus status = SolveStatus::NumericalFailure;
  Eigen::VectorXd x, multipliers;  // multipliers of A x = b
  double objective = 0;
  double primalResidual = 0, dualResidual = 0, gap = 0;
  int iterations = 0;
  int regularisations = 0;  // factorisations that needed a diagonal shift
  int corrections = 0;      // feasibility-correction rounds tried
  bool polished = false;    // the point is the polish's (IpmOptions::polish), not an iterate
};

IpmResult solveBlockQP(const BlockQP& qp, const IpmOptions& options = {});

}  // namespace corbel::statics
