#include "statics/ipm.h"

#include "statics/big_buffers.h"
#include "statics/block_ldlt.h"
#include "statics/parallel.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace corbel::statics {

std::string toString(SolveStatus s) {
  switch (s) {
    case SolveStatus::Optimal:
      return "optimal";
    case SolveStatus::IterationLimit:
      return "iteration limit";
    case SolveStatus::TimeLimit:
      return "time limit";
    case SolveStatus::ReducedAccuracy:
      return "reduced accuracy";
    case SolveStatus::NumericalFailure:
      return "numerical failure";
  }
  return "unknown";
}

namespace {

using Eigen::VectorXd;
using Mat4 = Eigen::Matrix4d;

// The average complementarity (loads are normalised) below which the Newton solves are
// refined on the unreduced system (IpmOptions::newtonRefinement).
constexpr double kRefineBelowMu = 1e-8;

// A best iterate this close is reported as `reduced accuracy` rather than a failure: a scaled
// primal residual ≤ 1e-9 (equilibrium holds), a dual residual ≤ 1e-7 and a gap ≤ 1e-3 of the
// objective (the objective is then within the gap of its optimum; the result reports it).
constexpr double kReducedPrimal = 1e-9;
constexpr double kReducedDual = 1e-7;
constexpr double kReducedGap = 1e-3;

// The polish (see solveBlockQP): rounds of active-set changes, proximal steps per round, and
// the proximal weight δ relative to the largest diagonal entry of Q.
constexpr int kPolishRounds = 4;
constexpr int kPolishSteps = 12;
constexpr double kPolishProximal = 1e-8;

double maxStep(const VectorXd& v, const VectorXd& dv) {
  double a = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (dv[i] < 0) a = std::min(a, -v[i] / dv[i]);
  return a;
}

bool allFinite(const VectorXd& v) { return v.allFinite(); }

// H⁻¹ of a block's Hessian (its leading size × size corner; zeros elsewhere) by a pivoted
// LDLᵀ of fixed size: the dynamic-size one spent most of its time in Eigen's generic
// triangular-solve and GEMM dispatch (about 8 % of a QP on the barrel vault).
// The solve is LDLT::solve's steps written out (Eigen sends a matrix right-hand side, even a
// fixed 4×4 one, through its generic blocked triangular solve).
template <int N>
Mat4 fixedInverse(const Mat4& H) {
  using M = Eigen::Matrix<double, N, N>;
  const Eigen::LDLT<M> f(H.topLeftCorner<N, N>());
  M X = f.transpositionsP() * M::Identity();
  const M& L = f.matrixLDLT();  // unit lower triangle below the diagonal
  const auto dv = f.vectorD();
  for (int i = 1; i < N; ++i)
    for (int k = 0; k < i; ++k) X.row(i) -= L(i, k) * X.row(k);
  constexpr double tiny = (std::numeric_limits<double>::min)();
  for (int i = 0; i < N; ++i) {
    if (std::abs(dv[i]) > tiny)
      X.row(i) /= dv[i];
    else
      X.row(i).setZero();
  }
  for (int i = N - 2; i >= 0; --i)
    for (int k = i + 1; k < N; ++k) X.row(i) -= L(k, i) * X.row(k);
  Mat4 inv = Mat4::Zero();
  inv.topLeftCorner<N, N>() = f.transpositionsP().transpose() * X;
  return inv;
}
Mat4 blockInverse(const Mat4& H, int size) {
  switch (size) {
    case 1:
      return fixedInverse<1>(H);
    case 2:
      return fixedInverse<2>(H);
    case 3:
      return fixedInverse<3>(H);
    default:
      return fixedInverse<4>(H);
  }
}

// min ‖E z − f‖ subject to z ≥ 0 for the polish's tiny systems (E: a block's ≤ 4 variables ×
// its active rows), by Lawson and Hanson's active-set method (Solving Least Squares Problems,
// 1974, ch. 23). Debian 12's Eigen 3.4.0 has no NNLS (it came to unsupported/ after 3.4), and
// these systems are at most 4 × 10, so the method is written out here.
Eigen::VectorXd smallNnls(const Eigen::MatrixXd& E, const Eigen::VectorXd& f) {
  const Eigen::Index p = E.cols();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(p);
  if (p == 0) return z;
  std::vector<char> passive(static_cast<std::size_t>(p), 0);
  const double tol = 1e-14 * (1 + f.cwiseAbs().maxCoeff()) * std::max(1.0, E.cwiseAbs().maxCoeff());
  // The least-squares solution on the passive columns, zero elsewhere.
  auto solvePassive = [&]() {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < p; ++i)
      if (passive[std::size_t(i)]) idx.push_back(i);
    Eigen::MatrixXd Ep(E.rows(), Eigen::Index(idx.size()));
    for (std::size_t k = 0; k < idx.size(); ++k) Ep.col(Eigen::Index(k)) = E.col(idx[k]);
    const Eigen::VectorXd sp = Ep.completeOrthogonalDecomposition().solve(f);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(p);
    for (std::size_t k = 0; k < idx.size(); ++k) s[idx[k]] = sp[Eigen::Index(k)];
    return s;
  };
  for (int outer = 0; outer < 3 * int(p) + 3; ++outer) {
    const Eigen::VectorXd wv = E.transpose() * (f - E * z);
    Eigen::Index t = -1;
    double wmax = tol;
    for (Eigen::Index i = 0; i < p; ++i)
      if (!passive[std::size_t(i)] && wv[i] > wmax) wmax = wv[i], t = i;
    if (t < 0) break;
    passive[std::size_t(t)] = 1;
    for (int inner = 0; inner < int(p) + 1; ++inner) {
      const Eigen::VectorXd s = solvePassive();
      double alpha = 1;
      bool clipped = false;
      for (Eigen::Index i = 0; i < p; ++i)
        if (passive[std::size_t(i)] && s[i] <= 0) {
          clipped = true;
          alpha = std::min(alpha, z[i] / (z[i] - s[i]));
        }
      if (!clipped) {
        z = s;
        break;
      }
      z += alpha * (s - z);
      for (Eigen::Index i = 0; i < p; ++i)
        if (passive[std::size_t(i)] && z[i] <= 0) passive[std::size_t(i)] = 0, z[i] = 0;
    }
  }
  return z;
}

// One interface to the factorisations of S (IpmOptions::schurSolver). S arrives as the lower
// triangle of a scalar sparse matrix; the block factorisation scatters it into 6×6 blocks
// through a map built once.
class SchurFactor {
 public:
  SchurFactor(SchurSolver kind, int rowGroup) : kind_(kind) {
    if (kind_ == SchurSolver::BlockLdlt && rowGroup != 6) kind_ = SchurSolver::EigenLdlt;
  }
  void analyze(const Eigen::SparseMatrix<double>& S) {
    if (kind_ == SchurSolver::BlockLdlt && S.rows() % 6 != 0) kind_ = SchurSolver::EigenLdlt;
    if (kind_ == SchurSolver::Cholmod) {
      cholmod_.analyzePattern(S);
    } else if (kind_ == SchurSolver::EigenLdlt) {
      ldlt_.analyzePattern(S);
    } else {
      std::vector<std::pair<int, int>> pairs;
      for (int c = 0; c < S.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(S, c); it; ++it)
          pairs.emplace_back(int(it.row()) / 6, c / 6);
      std::sort(pairs.begin(), pairs.end());
      pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
      blocks_.analyze(int(S.rows() / 6), pairs);
      // Each stored scalar of S goes to one or (off the diagonal of a diagonal block) two
      // places of the blocks: index = slot × 36 + column-major offset.
      scatter_.clear();
      for (int c = 0; c < S.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(S, c); it; ++it) {
          const int r = int(it.row()), gi = r / 6, gj = c / 6, oi = r % 6, oj = c % 6;
          const BlockLdlt::Slot sl = blocks_.slot(gi, gj);
          if (gi == gj) {
            scatter_.push_back({36 * sl.index + oi + 6 * oj, oi != oj ? 36 * sl.index + oj + 6 * oi : -1});
          } else {
            scatter_.push_back({sl.transposed ? 36 * sl.index + oj + 6 * oi : 36 * sl.index + oi + 6 * oj, -1});
          }
        }
    }
  }
  // False when S is not (numerically) positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& S) {
    if (kind_ == SchurSolver::Cholmod) {
      cholmod_.factorize(S);
      return cholmod_.info() == Eigen::Success;
    }
    if (kind_ == SchurSolver::BlockLdlt) {
      BlockLdlt::Values& v = blocks_.values();
      for (BlockLdlt::Block& b : v) b.setZero();
      double* out = v.empty() ? nullptr : v[0].data();
      const double* in = S.valuePtr();
      for (std::size_t k = 0; k < scatter_.size(); ++k) {
        out[scatter_[k][0]] += in[k];
        if (scatter_[k][1] >= 0) out[scatter_[k][1]] += in[k];
      }
      return blocks_.factorize();
    }
    ldlt_.factorize(S);
    if (ldlt_.info() != Eigen::Success) return false;
    const VectorXd D = ldlt_.vectorD();
    const double dmax = D.size() ? D.cwiseAbs().maxCoeff() : 1.0;
    for (Eigen::Index i = 0; i < D.size(); ++i)
      if (!(D[i] > 1e-15 * dmax)) return false;
    return true;
  }
  // The 6×6-block path without a scalar S: the caller sums its blocks into values() at the
  // slots it asked for, then calls factorizeBlocks().
  bool blockwise() const { return kind_ == SchurSolver::BlockLdlt; }
  void analyzeBlocks(int n, const std::vector<std::pair<int, int>>& pairs) { blocks_.analyze(n, pairs); }
  BlockLdlt& blocks() { return blocks_; }
  bool factorizeBlocks() { return blocks_.factorize(); }
  // x = S⁻¹ b (x not b; the block path allocates nothing).
  void solve(const VectorXd& b, VectorXd& x) {
    if (kind_ == SchurSolver::Cholmod)
      x = cholmod_.solve(b);
    else if (kind_ == SchurSolver::BlockLdlt)
      blocks_.solve(b, x);
    else
      x = ldlt_.solve(b);
  }

 private:
  SchurSolver kind_;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholmod_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  BlockLdlt blocks_;
  std::vector<std::array<int, 2>> scatter_;
};

}  // namespace

// Mehrotra predictor–corrector on the block-eliminated normal equations.
IpmResult solveBlockQP(const BlockQP& qp, const IpmOptions& options) {
  const int n = int(qp.A.cols());
  const int m = int(qp.A.rows());
  const int nb = int(qp.blocks.size());
  std::vector<int> rowStart(nb + 1, 0);
  for (int j = 0; j < nb; ++j) rowStart[j + 1] = rowStart[j] + int(qp.blocks[j].rows.size());
  const int mi = rowStart[nb];

  VectorXd x = VectorXd::Zero(n), y = VectorXd::Zero(m), s(mi), z(mi);
  // Infeasible start: x = 0 with unit slacks and multipliers (loads are normalised, so the
  // solution is O(1) or smaller). And the inequality rows flattened: row i acts on variables
  // offset[i] .. offset[i] + size[i] − 1 with coefficients coef[4i ..].
  std::vector<int> rowOffset(static_cast<std::size_t>(mi)), rowSize(static_cast<std::size_t>(mi));
  std::vector<double> coef(4 * std::size_t(mi));
  forEachIndex(nb, options.threads, [&](int j) {
    const VarBlock& blk = qp.blocks[j];
    for (std::size_t r = 0; r < blk.rows.size(); ++r) {
      const std::size_t i = std::size_t(rowStart[j]) + r;
      s[Eigen::Index(i)] = 1.0;
      z[Eigen::Index(i)] = 1.0;
      rowOffset[i] = blk.offset;
      rowSize[i] = blk.size;
      for (int k = 0; k < 4; ++k) coef[4 * i + std::size_t(k)] = k < blk.size ? blk.rows[r][k] : 0.0;
    }
  });
  // G v and Gᵀ w into `out` (sized by the caller; Gᵀ w's is overwritten).
  auto Gx = [&](const VectorXd& v, VectorXd& out) {
    for (std::size_t i = 0; i < std::size_t(mi); ++i) {
      const double* g = &coef[4 * i];
      const double* x0 = v.data() + rowOffset[i];
      double acc = 0;
      for (int k = 0; k < rowSize[i]; ++k) acc += g[k] * x0[k];
      out[Eigen::Index(i)] = acc;
    }
  };
  auto GTv = [&](const VectorXd& w, VectorXd& out) {
    out.setZero();
    for (std::size_t i = 0; i < std::size_t(mi); ++i) {
      const double* g = &coef[4 * i];
      double* o = out.data() + rowOffset[i];
      const double wi = w[Eigen::Index(i)];
      for (int k = 0; k < rowSize[i]; ++k) o[k] += g[k] * wi;
    }
  };
  VectorXd qdiag = VectorXd::Zero(n), c = VectorXd::Zero(n);
  for (const VarBlock& blk : qp.blocks)
    for (int k = 0; k < blk.size; ++k) {
      qdiag[blk.offset + k] = blk.hessian[k];
      c[blk.offset + k] = blk.cost[k];
    }
  const double bnorm = qp.b.size() ? qp.b.lpNorm<Eigen::Infinity>() : 0.0;
  const double cnorm = c.size() ? c.lpNorm<Eigen::Infinity>() : 0.0;

  // Per block: the rows of A it touches and the block of A there (dense, rows × size); only
  // the scalar path (below) needs them.
  struct BlockCols {
    std::vector<int> rows;
    Eigen::Matrix<double, Eigen::Dynamic, 4> vals;
  };
  std::vector<BlockCols> cols;
  auto buildCols = [&]() {
    cols.resize(std::size_t(nb));
    for (int j = 0; j < nb; ++j) {
      const VarBlock& blk = qp.blocks[j];
      std::vector<int>& rows = cols[j].rows;
      for (int k = 0; k < blk.size; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(qp.A, blk.offset + k); it; ++it)
          rows.push_back(int(it.row()));
      std::sort(rows.begin(), rows.end());
      rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
      cols[j].vals = Eigen::Matrix<double, Eigen::Dynamic, 4>::Zero(Eigen::Index(rows.size()), 4);
      for (int k = 0; k < blk.size; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(qp.A, blk.offset + k); it; ++it) {
          const auto pos = std::lower_bound(rows.begin(), rows.end(), int(it.row())) - rows.begin();
          cols[j].vals(pos, k) += it.value();
        }
    }
  };

  SchurFactor ldlt(options.schurSolver, qp.rowGroup);
  ldlt.blocks().setThreads(options.threads);
  bool analysed = false;
  BigVector<Mat4> hinv(nb), hess;  // hess only once the Newton refinement needs it (kRefineBelowMu)
  // The block path (BlockLdlt): every variable block touches at most two 6-row groups (a
  // contact vertex: the two blocks it joins; an artificial: one), so its A columns are a
  // fixed 12×4 matrix (zero-padded) and its contribution A_j H_j⁻¹ A_jᵀ is at most three
  // 6×6 blocks of S, summed straight into the factorisation's slots: no scalar S, no
  // triplets, no scatter, fixed-size kernels.
  // Constructed empty, each set by the (two-thread) loop that fills it: the first touch of a
  // 10,000-block QP's 50 MB of them is then shared between the threads too.
  struct BlockCols12 {
    BlockCols12() {}
    Eigen::Matrix<double, 12, 4> vals;
    int groups;                  // 0 (touches no equation), 1 or 2
    int row0, row1;              // the first equation row of groups g0 and g1
    int slot00, slot11, slot10;  // S blocks (g0, g0), (g1, g1), (g1, g0)
    bool transposed10;           // (g1, g0) stored as its transpose
  };
  BigVector<BlockCols12> cols12;
  std::vector<int> diagBlockSlot;
  bool blockwise = ldlt.blockwise() && m % 6 == 0 && m > 0;
  std::vector<std::array<int, 2>> blockGroups(std::size_t(nb), {-1, -1});
  if (blockwise) {
    std::atomic<bool> twoGroups{true};
    forEachIndex(nb, options.threads, [&](int j) {
      for (int k = 0; k < qp.blocks[j].size; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(qp.A, qp.blocks[j].offset + k); it; ++it) {
          const int g = int(it.row()) / 6;
          auto& gr = blockGroups[std::size_t(j)];
          if (gr[0] == g || gr[1] == g) continue;
          if (gr[0] < 0)
            gr[0] = g;
          else if (gr[1] < 0)
            gr[1] = g;
          else
            twoGroups.store(false, std::memory_order_relaxed);  // more than two groups: the scalar path
        }
    });
    blockwise = twoGroups.load();
  }
  if (!blockwise) buildCols();
  if (blockwise) {
    std::vector<std::pair<int, int>> pairs;
    for (int g = 0; g < m / 6; ++g) pairs.emplace_back(g, g);
    for (int j = 0; j < nb; ++j) {
      const auto& gr = blockGroups[std::size_t(j)];
      if (gr[1] >= 0) pairs.emplace_back(std::max(gr[0], gr[1]), std::min(gr[0], gr[1]));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    ldlt.analyzeBlocks(m / 6, pairs);
    const BlockLdlt& bl = ldlt.blocks();
    diagBlockSlot.resize(std::size_t(m / 6));
    for (int g = 0; g < m / 6; ++g) diagBlockSlot[std::size_t(g)] = bl.slot(g, g).index;
    cols12.resize(std::size_t(nb));
    forEachIndex(nb, options.threads, [&](int j) {
      BlockCols12& bc = cols12[std::size_t(j)];
      bc.vals.setZero();
      bc.groups = bc.row0 = bc.row1 = 0;
      bc.slot00 = bc.slot11 = bc.slot10 = -1;
      bc.transposed10 = false;
      auto gr = blockGroups[std::size_t(j)];
      if (gr[0] < 0) return;  // touches no equation
      if (gr[1] >= 0 && gr[1] < gr[0]) std::swap(gr[0], gr[1]);
      bc.groups = gr[1] >= 0 ? 2 : 1;
      bc.row0 = 6 * gr[0];
      bc.row1 = bc.groups == 2 ? 6 * gr[1] : 0;
      for (int k = 0; k < qp.blocks[j].size; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(qp.A, qp.blocks[j].offset + k); it; ++it) {
          const int r = int(it.row());
          bc.vals((r / 6 == gr[0] ? 0 : 6) + r % 6, k) = it.value();
        }
      bc.slot00 = bl.slot(gr[0], gr[0]).index;
      if (bc.groups == 2) {
        bc.slot11 = bl.slot(gr[1], gr[1]).index;
        const BlockLdlt::Slot sl = bl.slot(gr[1], gr[0]);
        bc.slot10 = sl.index;
        bc.transposed10 = sl.transposed;
      }
    });
    analysed = true;
  }
  // Sums A H⁻¹ Aᵀ + regularisation·I into the block factorisation and factors it.
  auto factorBlockwise = [&](double shift) {
    BlockLdlt::Values& v = ldlt.blocks().values();
    forEachIndex(int(v.size()), options.threads, [&](int k) { v[std::size_t(k)].setZero(); });
    for (int j = 0; j < nb; ++j) {
      const BlockCols12& bc = cols12[std::size_t(j)];
      if (bc.groups == 0) continue;
      const Eigen::Matrix<double, 12, 4> AH = bc.vals * hinv[std::size_t(j)];
      v[std::size_t(bc.slot00)].noalias() += AH.topRows<6>() * bc.vals.topRows<6>().transpose();
      if (bc.groups == 2) {
        v[std::size_t(bc.slot11)].noalias() += AH.bottomRows<6>() * bc.vals.bottomRows<6>().transpose();
        if (bc.transposed10)
          v[std::size_t(bc.slot10)].noalias() += (AH.bottomRows<6>() * bc.vals.topRows<6>().transpose()).transpose();
        else
          v[std::size_t(bc.slot10)].noalias() += AH.bottomRows<6>() * bc.vals.topRows<6>().transpose();
      }
    }
    // The diagonal blocks as the scalar path had them: exactly symmetric (the lower triangle
    // mirrored), plus the shift.
    for (const int sl : diagBlockSlot) {
      BlockLdlt::Block& b = v[std::size_t(sl)];
      b.triangularView<Eigen::StrictlyUpper>() = b.transpose();
      b.diagonal().array() += shift;
    }
    return ldlt.factorizeBlocks();
  };
  std::vector<Eigen::Triplet<double>> trips;
  Eigen::SparseMatrix<double> S;
  std::vector<int> diagSlot;
  std::vector<std::vector<int>> blockSlots;

  IpmResult best;
  VectorXd bestS, bestZ;  // the best iterate's slacks and inequality multipliers (for the polish)
  double bestMerit = std::numeric_limits<double>::infinity();
  IpmResult res;
  res.status = SolveStatus::IterationLimit;
  double regularisation = 0;
  auto record = [&](int iter, const VectorXd& rp, const VectorXd& rd, double gap) {
    const double pr = rp.size() ? rp.lpNorm<Eigen::Infinity>() / (1 + bnorm) : 0.0;
    const double dr = rd.size() ? rd.lpNorm<Eigen::Infinity>() / (1 + cnorm) : 0.0;
    const double obj = 0.5 * x.dot(qdiag.cwiseProduct(x)) + c.dot(x);
    const double merit = std::max({pr, dr, gap});
    if (merit < bestMerit) {
      bestMerit = merit;
      best.x = x;
      best.multipliers = y;
      best.objective = obj;
      best.primalResidual = pr;
      best.dualResidual = dr;
      best.gap = gap;
      best.iterations = iter;
      bestS = s;
      bestZ = z;
    }
    return pr <= options.residualTolerance && dr <= options.residualTolerance &&
           (gap <= options.gapTolerance || gap <= options.relativeGapTolerance * std::abs(obj));
  };

  // The early exit (IpmOptions::objectiveExitBelow): with c = 0 and Q ≥ 0 the objective is
  // ≥ 0 everywhere, so a primal-feasible x with objective φ(x) ≤ ε has optimum φ* ∈ [0, φ(x)]:
  // φ(x) is within φ(x) ≤ ε of it. Primal-feasible means A x = b to the residual tolerance
  // (the same sense as `optimal`) and G x ≥ 0 exactly (checked on every row, not via s).
  const bool objectiveNonNegative = options.objectiveExitBelow > 0 && (c.size() == 0 || c.cwiseAbs().maxCoeff() == 0) &&
                                    (n == 0 || qdiag.minCoeff() >= 0);
  // The iteration's vectors, allocated once: a fresh vector of 50,000 doubles costs its page
  // faults (the kernel zeroing new pages was 14 % of the 1,040-block wall's QP when every
  // step allocated its temporaries). Each is computed with the same operations in the same
  // order as the expressions they replace, so the iterates are bit for bit the same.
  VectorXd gx(mi), rd(n), rp(m), rg(mi), d(mi), rc(mi), tn(n), tm(m), tm2(m), ti(mi);
  VectorXd w(mi), rho(n), rhs(m), r1(n), r2(m), ddy(m), dx(n), dy(m), dz(mi), ds(mi), xt(n), gxt(mi), rpt(m);
  VectorXd sn1(n), sn2(n), xc(n);
  const VectorXd zeroN = VectorXd::Zero(n);
  // The projection of the early exit: every block with a null direction e moved along it by the
  // δ that minimises the block's objective ½Σq(x + δe)², clamped so that its rows g·x ≥ 0 hold.
  // One-sided (δ ≥ 0, rows taken as max(0, g·x)) for an interior iterate; two-sided for the
  // feasibility correction's point, whose rows may be negative before the move (then δ < 0 can
  // repair them: f_n⁺ and f_n⁻ both raised, the net force unchanged).
  auto project = [&](const VectorXd& xin, const VectorXd& gxin, VectorXd& out, bool twoSided) {
    out = xin;
    for (int j = 0; j < nb; ++j) {
      const VarBlock& blk = qp.blocks[std::size_t(j)];
      const auto& e = blk.nullDirection;
      double qe = 0, qxe = 0;
      for (int k = 0; k < blk.size; ++k) {
        qe += blk.hessian[k] * e[k] * e[k];
        qxe += blk.hessian[k] * xin[blk.offset + k] * e[k];
      }
      if (!(qe > 0)) continue;
      if (!twoSided) {
        if (!(qxe < 0)) continue;
        double delta = -qxe / qe;
        for (std::size_t r = 0; r < blk.rows.size(); ++r) {
          double ge = 0;
          for (int k = 0; k < blk.size; ++k) ge += blk.rows[r][k] * e[k];
          if (ge < 0) delta = std::min(delta, std::max(0.0, gxin[rowStart[j] + int(r)]) / -ge);
        }
        for (int k = 0; k < blk.size; ++k) out[blk.offset + k] += delta * e[k];
        continue;
      }
      double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
      for (std::size_t r = 0; r < blk.rows.size(); ++r) {
        double ge = 0;
        for (int k = 0; k < blk.size; ++k) ge += blk.rows[r][k] * e[k];
        const double gv = gxin[rowStart[j] + int(r)];
        if (ge < 0) hi = std::min(hi, gv / -ge);
        if (ge > 0) lo = std::max(lo, -gv / ge);
      }
      if (!(lo <= hi)) continue;  // no δ repairs this block: the certificate's check refuses the point
      const double delta = std::clamp(-qxe / qe, lo, hi);
      for (int k = 0; k < blk.size; ++k) out[blk.offset + k] += delta * e[k];
    }
  };
  // Blocks whose rows are negative (by rounding, after the correction's solve) moved along
  // their interior direction d by t = max over those rows of −g·x / g·d, a little more: the
  // rows are then ≥ 0 and A x moves by t A_j d (the certificate checks both again).
  auto repair = [&](VectorXd& v) {
    for (int j = 0; j < nb; ++j) {
      const VarBlock& blk = qp.blocks[std::size_t(j)];
      const auto& dir = blk.interiorDirection;
      // The margin covers the rounding of g·x (a few ulps of Σ|g_k x_k|) and of x + t d.
      constexpr double eps = std::numeric_limits<double>::epsilon();
      double t = 0, scale = 0;
      for (int k = 0; k < blk.size; ++k) scale = std::max(scale, std::abs(v[blk.offset + k]));
      for (const auto& g : blk.rows) {
        double gv = 0, gd = 0, ga = 0;
        for (int k = 0; k < blk.size; ++k) {
          gv += g[k] * v[blk.offset + k];
          gd += g[k] * dir[k];
          ga += std::abs(g[k]) * (std::abs(v[blk.offset + k]) + 4 * eps * scale);
        }
        if (gv < 0 && gd > 0) t = std::max(t, (-gv + 16 * eps * ga) / gd);
      }
      if (t > 0)
        for (int k = 0; k < blk.size; ++k) v[blk.offset + k] += t * dir[k];
    }
  };
  // The certificate (see "The early exit"): A x̃ = b to the residual tolerance and G x̃ ≥ 0 on
  // every row, both computed again here, with the objective φ(x̃) ≤ objectiveExitBelow.
  IpmResult early;
  auto certify = [&](const VectorXd& xtv, double obj, int iter, const VectorXd& rdv) {
    if (!(obj <= options.objectiveExitBelow)) return false;
    rpt.noalias() = qp.A * xtv;
    rpt -= qp.b;
    const double prt = rpt.size() ? rpt.lpNorm<Eigen::Infinity>() / (1 + bnorm) : 0.0;
    Gx(xtv, gxt);
    if (!(prt <= options.residualTolerance && (mi == 0 || gxt.minCoeff() >= 0))) return false;
    early.status = SolveStatus::Optimal;
    early.x = xtv;
    // With ½x̃ᵀQx̃ = 0 (so Q x̃ = 0) and c = 0, (x̃, 0, 0) satisfies the KKT conditions
    // exactly: the multipliers are 0. Otherwise the iterate's.
    early.multipliers = obj == 0 ? VectorXd::Zero(m) : y;
    early.objective = obj;
    early.primalResidual = prt;
    early.dualResidual = obj == 0 ? 0.0 : (rdv.size() ? rdv.lpNorm<Eigen::Infinity>() / (1 + cnorm) : 0.0);
    early.gap = obj;  // the certified bound on objective − optimum
    early.iterations = iter;
    early.regularisations = res.regularisations;
    early.corrections = res.corrections;
    return true;
  };
  auto factor = [&]() {
    if (blockwise) return factorBlockwise(regularisation);
    double* val = S.valuePtr();
    std::fill(val, val + S.nonZeros(), 0.0);
    for (int r = 0; r < m; ++r) val[diagSlot[std::size_t(r)]] += regularisation;
    for (int j = 0; j < nb; ++j) {
      const auto& bc = cols[j];
      const int sz = qp.blocks[j].size;
      // A vertex block touches the 12 rows of its two blocks: fixed-capacity, no allocation.
      using Cols = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 4>;
      using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
      if (bc.rows.size() <= 12) {
        const Cols AH = bc.vals.leftCols(sz).lazyProduct(hinv[j].topLeftCorner(sz, sz));
        const Square block = AH.lazyProduct(bc.vals.leftCols(sz).transpose());
        std::size_t k = 0;
        for (std::size_t p = 0; p < bc.rows.size(); ++p)
          for (std::size_t q = 0; q <= p; ++q)
            val[blockSlots[std::size_t(j)][k++]] += block(Eigen::Index(p), Eigen::Index(q));
        continue;
      }
      const Eigen::MatrixXd AH = bc.vals.leftCols(sz) * hinv[j].topLeftCorner(sz, sz);
      const Eigen::MatrixXd block = AH * bc.vals.leftCols(sz).transpose();
      std::size_t k = 0;
      for (std::size_t p = 0; p < bc.rows.size(); ++p)
        for (std::size_t q = 0; q <= p; ++q)
          val[blockSlots[std::size_t(j)][k++]] += block(Eigen::Index(p), Eigen::Index(q));
    }
    return ldlt.factorize(S);
  };
  // M v block by block, for M = H⁻¹ or H.
  auto applyBlocks = [&](const BigVector<Mat4>& M, const VectorXd& v, VectorXd& out) {
    for (int j = 0; j < nb; ++j) {
      const VarBlock& blk = qp.blocks[j];
      Eigen::Vector4d in = Eigen::Vector4d::Zero();
      for (int k = 0; k < blk.size; ++k) in[k] = v[blk.offset + k];
      const Eigen::Vector4d o = M[std::size_t(j)] * in;
      for (int k = 0; k < blk.size; ++k) out[blk.offset + k] = o[k];
    }
  };
  auto applyHinv = [&](const VectorXd& v, VectorXd& out) { applyBlocks(hinv, v, out); };
  auto applyH = [&](const VectorXd& v, VectorXd& out) { applyBlocks(hess, v, out); };
  // S dy = rhs with one step of iterative refinement against S applied as A H⁻¹ Aᵀ (near the
  // optimum S mixes entries of very different sizes, z/s → 0 or ∞).
  // On the block path, A H⁻¹ u, A H⁻¹ Aᵀ v and H⁻¹(u + Aᵀ v) in one pass over the blocks'
  // dense 12×4 columns each, instead of two or three sparse products with temporaries.
  using V12 = Eigen::Matrix<double, 12, 1>;
  auto gather = [&](const BlockCols12& bc, const VectorXd& v) {
    V12 g;
    g.head<6>() = v.segment<6>(bc.row0);
    if (bc.groups == 2)
      g.tail<6>() = v.segment<6>(bc.row1);
    else
      g.tail<6>().setZero();
    return g;
  };
  auto scatterAdd = [&](const BlockCols12& bc, const V12& o, VectorXd& out) {
    out.segment<6>(bc.row0) += o.head<6>();
    if (bc.groups == 2) out.segment<6>(bc.row1) += o.tail<6>();
  };
  auto blockIn = [&](int j, const VectorXd& u) {
    const VarBlock& blk = qp.blocks[std::size_t(j)];
    Eigen::Vector4d in = Eigen::Vector4d::Zero();
    for (int k = 0; k < blk.size; ++k) in[k] = u[blk.offset + k];
    return in;
  };
  // The three products write `out` (never one of their inputs); the scalar path uses sn1, sn2.
  auto applyAHinv = [&](const VectorXd& u, VectorXd& out) {
    if (!blockwise) {
      applyHinv(u, sn1);
      out.noalias() = qp.A * sn1;
      return;
    }
    out.setZero();
    for (int j = 0; j < nb; ++j) {
      const BlockCols12& bc = cols12[std::size_t(j)];
      if (bc.groups == 0) continue;
      scatterAdd(bc, bc.vals * (hinv[std::size_t(j)] * blockIn(j, u)), out);
    }
  };
  auto applySchur = [&](const VectorXd& v, VectorXd& out) {
    if (!blockwise) {
      sn1.noalias() = qp.A.transpose() * v;
      applyHinv(sn1, sn2);
      out.noalias() = qp.A * sn2;
      return;
    }
    out.setZero();
    for (int j = 0; j < nb; ++j) {
      const BlockCols12& bc = cols12[std::size_t(j)];
      if (bc.groups == 0) continue;
      scatterAdd(bc, bc.vals * (hinv[std::size_t(j)] * (bc.vals.transpose() * gather(bc, v))), out);
    }
  };
  auto hinvPlusAT = [&](const VectorXd& u, const VectorXd& v, VectorXd& out) {
    if (!blockwise) {
      sn1 = u;
      sn1.noalias() += qp.A.transpose() * v;
      applyHinv(sn1, out);
      return;
    }
    for (int j = 0; j < nb; ++j) {
      const BlockCols12& bc = cols12[std::size_t(j)];
      Eigen::Vector4d in = blockIn(j, u);
      if (bc.groups != 0) in.noalias() += bc.vals.transpose() * gather(bc, v);
      const Eigen::Vector4d o = hinv[std::size_t(j)] * in;
      const VarBlock& blk = qp.blocks[std::size_t(j)];
      for (int k = 0; k < blk.size; ++k) out[blk.offset + k] = o[k];
    }
  };
  // S out = rhs, refined once against S (uses tm, tm2).
  auto solveSchur = [&](const VectorXd& rhsv, VectorXd& out) {
    ldlt.solve(rhsv, out);
    applySchur(out, tm);
    tm2 = rhsv - tm - (regularisation)*out;
    ldlt.solve(tm2, tm);
    out += tm;
  };
  // The polish (docs/statics.md, "The polish"): where the iterations stop short, the best
  // iterate's slacks and multipliers name the rows that hold with equality (z > s); the QP
  // with those rows as equalities and the others dropped is an equality-constrained QP, solved
  // by proximal steps x⁺ = argmin ½xᵀQx + cᵀx + ½δ‖x − x⁻‖² on A x = b, G_act x = 0 with the
  // same block machinery (H_j⁻¹ replaced by N_j (N_jᵀQ_jN_j + δI)⁻¹ N_jᵀ, N_j an orthonormal
  // basis of the block's admissible directions). The point it ends at is optimal when it
  // satisfies the dropped rows and the active rows' multipliers, found per block by NNLS on
  // the stationarity residual, are ≥ 0 with the residual within the tolerance: those are the
  // QP's KKT conditions, sufficient for a convex QP. Rows that fail are moved between the two
  // sets and the polish tried again (kPolishRounds); a polish that never passes changes nothing.
  // The polish's vectors, sized only when it runs (a fresh vector costs its page faults on
  // every solve, and most solves never polish).
  VectorXd px, py, pxPrev, pgx, pz, pres, ptn, prhs, pddy, pcorr;
  std::vector<Mat4> polishProjector;  // N_j N_jᵀ
  auto polish = [&]() -> bool {
    if (best.x.size() != n || bestS.size() != mi || mi == 0) return false;
    for (VectorXd* v : {&px, &pxPrev, &pres, &ptn, &pcorr}) v->resize(n);
    for (VectorXd* v : {&py, &prhs, &pddy}) v->resize(m);
    for (VectorXd* v : {&pgx, &pz}) v->resize(mi);
    polishProjector.resize(static_cast<std::size_t>(nb));
    std::vector<char> active(static_cast<std::size_t>(mi));
    for (int i = 0; i < mi; ++i) active[std::size_t(i)] = bestZ[i] > bestS[i];
    const double delta = kPolishProximal * std::max(1.0, qdiag.size() ? qdiag.maxCoeff() : 0.0);
    for (int round = 0; round < kPolishRounds; ++round) {
      // The blocks' projected inverses, in hinv (the iteration's are not needed any more).
      for (int j = 0; j < nb; ++j) {
        const VarBlock& blk = qp.blocks[std::size_t(j)];
        const int k = blk.size;
        Eigen::MatrixXd GtG = Eigen::MatrixXd::Zero(k, k);
        for (std::size_t r = 0; r < blk.rows.size(); ++r) {
          if (!active[std::size_t(rowStart[j]) + r]) continue;
          const Eigen::Map<const Eigen::VectorXd> g(blk.rows[r].data(), k);
          GtG += g * g.transpose();
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(GtG);
        const double top = std::max(1.0, es.eigenvalues().cwiseAbs().maxCoeff());
        std::vector<Eigen::Index> free;
        for (Eigen::Index e = 0; e < k; ++e)
          if (es.eigenvalues()[e] <= 1e-12 * top) free.push_back(e);
        Mat4 P = Mat4::Zero();
        polishProjector[std::size_t(j)].setZero();
        if (!free.empty()) {
          Eigen::MatrixXd N(k, Eigen::Index(free.size()));
          for (std::size_t e = 0; e < free.size(); ++e) N.col(Eigen::Index(e)) = es.eigenvectors().col(free[e]);
          Eigen::MatrixXd M = N.transpose() * Eigen::Map<const Eigen::VectorXd>(blk.hessian.data(), k).asDiagonal() * N;
          M.diagonal().array() += delta;
          P.topLeftCorner(k, k) = N * M.ldlt().solve(N.transpose());
          polishProjector[std::size_t(j)].topLeftCorner(k, k) = N * N.transpose();
        }
        hinv[std::size_t(j)] = P;
      }
      regularisation = 0;
      bool ok = factor();
      for (int attempt = 0; !ok && attempt < 4; ++attempt) {
        regularisation = regularisation > 0 ? regularisation * 100 : 1e-12;
        ok = factor();
      }
      if (!ok) return false;
      // Proximal steps from the best iterate: x = P(Aᵀy + δx⁻ − c) with S y = b − A P(δx⁻ − c),
      // each followed by a correction that restores A x = b with the same factorisation.
      pxPrev = best.x;
      for (int step = 0; step < kPolishSteps; ++step) {
        ptn = delta * pxPrev - c;
        applyAHinv(ptn, tm);
        prhs = qp.b - tm;
        solveSchur(prhs, py);
        hinvPlusAT(ptn, py, px);
        for (int fix = 0; fix < 2; ++fix) {
          prhs = qp.b;
          prhs.noalias() -= qp.A * px;
          ldlt.solve(prhs, pddy);
          hinvPlusAT(zeroN, pddy, pcorr);
          px += pcorr;
          py += pddy;
        }
        const double change = (px - pxPrev).lpNorm<Eigen::Infinity>();
        pxPrev = px;
        if (!(delta * change > 1e-3 * options.residualTolerance)) break;
      }
      // P's entries reach 1/δ, so P v leaves the admissible directions by about 1e-16/δ of v's
      // part across them (Aᵀy's, which the active rows' multipliers balance): the active rows
      // were off by 1e-11 on the thin-buttressed vault. So x is projected onto them exactly
      // (N Nᵀ x: rounding of x itself) and A x = b restored by one more correction, whose
      // right-hand side is that small.
      for (int j = 0; j < nb; ++j) {
        const VarBlock& blk = qp.blocks[std::size_t(j)];
        const Eigen::Vector4d o = polishProjector[std::size_t(j)] * blockIn(j, px);
        for (int k = 0; k < blk.size; ++k) px[blk.offset + k] = o[k];
      }
      prhs = qp.b;
      prhs.noalias() -= qp.A * px;
      ldlt.solve(prhs, pddy);
      hinvPlusAT(zeroN, pddy, pcorr);
      px += pcorr;
      py += pddy;
      if (!allFinite(px) || !allFinite(py)) return false;
      // The KKT conditions at px: equilibrium, the dropped rows, the active rows' multipliers.
      rpt.noalias() = qp.A * px;
      rpt -= qp.b;
      const double pr = rpt.size() ? rpt.lpNorm<Eigen::Infinity>() / (1 + bnorm) : 0.0;
      Gx(px, pgx);
      pres = qdiag.cwiseProduct(px) + c;
      pres.noalias() -= qp.A.transpose() * py;
      const double xscale = std::max(1.0, px.lpNorm<Eigen::Infinity>());
      const double rowTol = options.residualTolerance * xscale;
      double dr = 0;
      bool changed = false;
      pz.setZero();
      for (int j = 0; j < nb; ++j) {
        const VarBlock& blk = qp.blocks[std::size_t(j)];
        const int k = blk.size;
        std::vector<std::size_t> act;
        for (std::size_t r = 0; r < blk.rows.size(); ++r)
          if (active[std::size_t(rowStart[j]) + r]) act.push_back(r);
        Eigen::MatrixXd E(k, Eigen::Index(act.size()));
        for (std::size_t a = 0; a < act.size(); ++a)
          for (int q = 0; q < k; ++q) E(q, Eigen::Index(a)) = blk.rows[act[a]][q];
        const Eigen::VectorXd g = pres.segment(blk.offset, k);
        const Eigen::VectorXd zj = smallNnls(E, g);
        const double r = (g - E * zj).lpNorm<Eigen::Infinity>() / (1 + cnorm);
        dr = std::max(dr, r);
        for (std::size_t a = 0; a < act.size(); ++a) pz[rowStart[j] + int(act[a])] = zj[Eigen::Index(a)];
        if (r > options.residualTolerance) {
          // Stationarity fails on this block: release the active rows that carry no multiplier.
          for (std::size_t a = 0; a < act.size(); ++a)
            if (zj[Eigen::Index(a)] <= 0) active[std::size_t(rowStart[j]) + act[a]] = 0, changed = true;
        }
        for (std::size_t r = 0; r < blk.rows.size(); ++r) {
          const std::size_t i = std::size_t(rowStart[j]) + r;
          if (!active[i] && pgx[Eigen::Index(i)] < -rowTol) active[i] = 1, changed = true;
        }
      }
      double gap = 0;
      for (int i = 0; i < mi; ++i) gap += pz[i] * std::abs(pgx[i]);
      const double obj = 0.5 * px.dot(qdiag.cwiseProduct(px)) + c.dot(px);
      const bool passes = !changed && pr <= options.residualTolerance && dr <= options.residualTolerance &&
                          (gap <= options.gapTolerance || gap <= options.relativeGapTolerance * std::abs(obj));
      if (passes) {
        // Rows short of 0 by rounding moved inside along the blocks' interior directions
        // (which leave A x unchanged for the penalty QP); the objective is taken after.
        repair(px);
        rpt.noalias() = qp.A * px;
        rpt -= qp.b;
        const double prRepaired = rpt.size() ? rpt.lpNorm<Eigen::Infinity>() / (1 + bnorm) : 0.0;
        if (!(prRepaired <= options.residualTolerance)) return false;
        best.x = px;
        best.multipliers = py;
        best.objective = 0.5 * px.dot(qdiag.cwiseProduct(px)) + c.dot(px);
        best.primalResidual = prRepaired;
        best.dualResidual = dr;
        best.gap = gap;
        best.polished = true;
        return true;
      }
      if (!changed) return false;
    }
    return false;
  };
  // Stopping short of the tolerances: the best iterate, called `reduced accuracy` when it is
  // within kReducedPrimal, kReducedDual and kReducedGap.
  auto stop = [&](SolveStatus why) {
    best.regularisations = res.regularisations;
    if (why != SolveStatus::TimeLimit && options.polish && polish()) {
      best.status = SolveStatus::Optimal;
      return best;
    }
    const bool close = best.x.size() == n && best.primalResidual <= kReducedPrimal &&
                       best.dualResidual <= kReducedDual &&
                       best.gap <= std::max(options.gapTolerance, kReducedGap * std::abs(best.objective));
    best.status = close && why != SolveStatus::TimeLimit ? SolveStatus::ReducedAccuracy : why;
    return best;
  };

  double lastProjected = std::numeric_limits<double>::infinity();
  const auto started = std::chrono::steady_clock::now();
  for (int iter = 0;; ++iter) {
    Gx(x, gx);
    rd = qdiag.cwiseProduct(x) + c;
    rd.noalias() -= qp.A.transpose() * y;
    GTv(z, tn);
    rd -= tn;
    rp.noalias() = qp.A * x;
    rp -= qp.b;
    rg = gx - s;
    const double gap = s.dot(z);
    if (record(iter, rp, rd, gap)) {
      best.status = SolveStatus::Optimal;
      best.regularisations = res.regularisations;
      return best;
    }
    const bool primalFeasible =
        (rp.size() ? rp.lpNorm<Eigen::Infinity>() / (1 + bnorm) : 0.0) <= options.residualTolerance;
    if (objectiveNonNegative) {
      project(x, gx, xt, false);
      lastProjected = 0.5 * xt.dot(qdiag.cwiseProduct(xt));
      if (primalFeasible && certify(xt, lastProjected, iter, rd)) return early;
    }
    if (iter >= options.maxIterations) break;
    if (options.maxSeconds > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() > options.maxSeconds) {
      return stop(SolveStatus::TimeLimit);
    }
    const double mu = mi ? gap / mi : 0.0;
    d = z.cwiseQuotient(s);

    // Block Hessians and their inverses; the Hessians kept only for the refinement's products.
    const bool keepHessians = mu < kRefineBelowMu && options.newtonRefinement > 0;
    if (keepHessians) hess.resize(std::size_t(nb));
    forEachIndex(nb, options.threads, [&](int j) {
      const VarBlock& blk = qp.blocks[j];
      Mat4 H = Mat4::Zero();
      for (int k = 0; k < blk.size; ++k) H(k, k) = blk.hessian[k];
      for (std::size_t r = 0; r < blk.rows.size(); ++r) {
        const Eigen::Vector4d g(blk.rows[r][0], blk.rows[r][1], blk.rows[r][2], blk.rows[r][3]);
        H += d[rowStart[j] + int(r)] * g * g.transpose();
      }
      hinv[j] = blockInverse(H, blk.size);
      if (keepHessians) hess[j] = H;
    });
    // Schur complement A H⁻¹ Aᵀ (lower triangle), with a diagonal entry on every row. The
    // pattern never changes: it is built once, then values are summed into fixed slots.
    if (!analysed) {
      trips.clear();
      for (int r = 0; r < m; ++r) trips.emplace_back(r, r, 1.0);
      for (int j = 0; j < nb; ++j) {
        const auto& rows = cols[j].rows;
        for (std::size_t p = 0; p < rows.size(); ++p)
          for (std::size_t q = 0; q <= p; ++q)
            trips.emplace_back(std::max(rows[p], rows[q]), std::min(rows[p], rows[q]), 1.0);
      }
      S.resize(m, m);
      S.setFromTriplets(trips.begin(), trips.end());
      S.makeCompressed();
      auto slot = [&](int r, int c) { return int(&S.coeffRef(r, c) - S.valuePtr()); };
      diagSlot.resize(std::size_t(m));
      for (int r = 0; r < m; ++r) diagSlot[std::size_t(r)] = slot(r, r);
      blockSlots.assign(std::size_t(nb), {});
      for (int j = 0; j < nb; ++j) {
        const auto& rows = cols[j].rows;
        for (std::size_t p = 0; p < rows.size(); ++p)
          for (std::size_t q = 0; q <= p; ++q)
            blockSlots[std::size_t(j)].push_back(slot(std::max(rows[p], rows[q]), std::min(rows[p], rows[q])));
      }
      ldlt.analyze(S);
      analysed = true;
    }
    bool ok = factor();
    for (int attempt = 0; !ok && attempt < 8; ++attempt) {
      regularisation = regularisation > 0 ? regularisation * 100 : 1e-12;
      ++res.regularisations;
      ok = factor();
    }
    if (!ok) {
      return stop(SolveStatus::NumericalFailure);
    }
    regularisation *= 0.1;  // relax again once things go well
    if (regularisation < 1e-14) regularisation = 0;

    // `refine`: false for the predictor, whose step only sets the centring σ and the
    // second-order term of the corrector (its errors perturb the centring, not the iterate):
    // one plain solve with the factorisation, no refinement. Writes dx, dy, dz, ds.
    auto newton = [&](const VectorXd& rcv, bool refine) {
      w = rcv.cwiseQuotient(s) + d.cwiseProduct(rg);
      GTv(w, tn);
      rho = -rd - tn;
      applyAHinv(rho, tm);
      rhs = -rp - tm;
      // Once the correction on the unreduced system below runs, it also corrects the Schur
      // solve's error: both solves are then plain (3 solves an iteration instead of 5; the
      // equilibrium residuals measured stay within 2× of the refined ones, 1e-16..5e-12).
      const bool unreduced = refine && mu < kRefineBelowMu && options.newtonRefinement > 0;
      if (refine && !unreduced)
        solveSchur(rhs, dy);
      else
        ldlt.solve(rhs, dy);
      hinvPlusAT(rho, dy, dx);
      // Refinement on the unreduced system H dx − Aᵀ dy = rho, A dx = −rp: forming the Schur
      // right-hand side cancels large terms (H⁻¹ reaches 1/μ), which leaves A dx + rp at
      // 1e-11..1e-10 near the optimum of strongly infeasible models; one correction solved
      // with the same factorisation brings it back to rounding. Only needed once μ is small.
      for (int step = 0; refine && mu < kRefineBelowMu && step < options.newtonRefinement; ++step) {
        r1 = rho;
        r1.noalias() += qp.A.transpose() * dy;
        applyH(dx, tn);
        r1 -= tn;
        r2 = -rp;
        r2.noalias() -= qp.A * dx;
        applyAHinv(r1, tm);
        tm2 = r2 - tm;
        ldlt.solve(tm2, ddy);
        hinvPlusAT(r1, ddy, tn);
        dx += tn;
        dy += ddy;
      }
      Gx(dx, ti);
      dz = -w - d.cwiseProduct(ti);
      ds = ti + rg;
      return allFinite(dx) && allFinite(dy) && allFinite(dz);
    };
    // The feasibility correction (IpmOptions::feasibilityCorrections): the projected point x̃
    // with its penalised variables set to 0 (the tension removed) misses equilibrium by r; the
    // least change in the metric of this iteration's H that restores it, H⁻¹Aᵀ S⁻¹ r, costs one
    // solve with the factorisation just made. Projected again (two-sided), the result either
    // passes the certificate — and the solve ends here, a few iterations before the iterate
    // itself would — or is dropped.
    if (objectiveNonNegative && options.feasibilityCorrections > 0 &&
        (iter == 0 || lastProjected <= options.correctBelow)) {
      xc = xt;
      for (int round = 0; round < options.feasibilityCorrections; ++round) {
        for (int j = 0; j < nb; ++j) {
          const VarBlock& blk = qp.blocks[std::size_t(j)];
          std::array<double, 4> v{};
          bool any = false;
          for (int k = 0; k < blk.size; ++k) {
            v[k] = xc[blk.offset + k];
            if (blk.hessian[k] > 0 && v[k] != 0) v[k] = 0, any = true;
          }
          if (!any) continue;
          bool ok = true;
          for (const auto& g : blk.rows) {
            double acc = 0;
            for (int k = 0; k < blk.size; ++k) acc += g[k] * v[k];
            ok = ok && acc >= 0;
          }
          if (ok)
            for (int k = 0; k < blk.size; ++k) xc[blk.offset + k] = v[k];
        }
        rpt.noalias() = qp.A * xc;
        tm2 = qp.b - rpt;
        ldlt.solve(tm2, ddy);
        hinvPlusAT(zeroN, ddy, tn);
        xc += tn;
        Gx(xc, gxt);
        project(xc, gxt, xt, true);
        repair(xt);
        const double obj = 0.5 * xt.dot(qdiag.cwiseProduct(xt));
        ++res.corrections;
        if (certify(xt, obj, iter, rd)) return early;
        xc = xt;
      }
    }
    rc = s.cwiseProduct(z);
    if (!newton(rc, false)) {
      return stop(SolveStatus::NumericalFailure);
    }
    const double aAff = std::min({1.0, maxStep(s, ds), maxStep(z, dz)});
    const double muAff = mi ? (s + aAff * ds).dot(z + aAff * dz) / mi : 0.0;
    const double sigma = mu > 0 ? std::pow(std::clamp(muAff / mu, 0.0, 1.0), 3) : 0.0;
    rc = s.cwiseProduct(z) + ds.cwiseProduct(dz) - VectorXd::Constant(mi, sigma * mu);
    if (!newton(rc, true)) {
      return stop(SolveStatus::NumericalFailure);
    }
    const double alpha = std::min(1.0, 0.995 * std::min(maxStep(s, ds), maxStep(z, dz)));
    x += alpha * dx;
    y += alpha * dy;
    z += alpha * dz;
    s += alpha * ds;
    res.iterations = iter + 1;
  }
  return stop(SolveStatus::IterationLimit);
}

}  // namespace corbel::statics
