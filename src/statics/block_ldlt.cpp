#include "statics/block_ldlt.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::statics {
namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define CORBEL_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define CORBEL_CLONES
#endif

// X ← D⁺ X for a pivot block D = Pᵀ L diag(d) Lᵀ P, X with 6 rows of C entries (row i at
// X + C·i): the steps of Eigen's LDLT::solve (permutation, unit-triangular substitutions, zero
// for pivots ≤ the smallest normal double, permutation back), written as row operations on
// contiguous rows so they vectorise.
template <int C>
inline void pivotApply(const BlockLdlt::Pivot& pv, double* X) {
  for (int i = 0; i < 6; ++i) {
    const int t = pv.transpositions[i];
    if (t != i)
      for (int c = 0; c < C; ++c) std::swap(X[C * i + c], X[C * t + c]);
  }
  for (int i = 1; i < 6; ++i)
    for (int k = 0; k < i; ++k) {
      const double l = pv.L[i + 6 * k];
      for (int c = 0; c < C; ++c) X[C * i + c] -= l * X[C * k + c];
    }
  constexpr double tiny = (std::numeric_limits<double>::min)();
  for (int i = 0; i < 6; ++i) {
    if (std::abs(pv.d[i]) > tiny) {
      const double inv = 1.0 / pv.d[i];
      for (int c = 0; c < C; ++c) X[C * i + c] *= inv;
    } else {
      for (int c = 0; c < C; ++c) X[C * i + c] = 0.0;
    }
  }
  for (int i = 4; i >= 0; --i)
    for (int k = i + 1; k < 6; ++k) {
      const double l = pv.L[k + 6 * i];
      for (int c = 0; c < C; ++c) X[C * i + c] -= l * X[C * k + c];
    }
  for (int i = 5; i >= 0; --i) {
    const int t = pv.transpositions[i];
    if (t != i)
      for (int c = 0; c < C; ++c) std::swap(X[C * i + c], X[C * t + c]);
  }
}

// L_a = S_a D⁺ for the m off-diagonal blocks of a column (S column-major, m blocks in a row).
// (S_a D⁺)ᵀ = D⁺ S_aᵀ, and S_aᵀ read row by row is S_a's column-major storage, so the result's
// storage is D⁺ applied to the rows of a copy of S_a.
CORBEL_CLONES
void pivotColumn(int m, const BlockLdlt::Pivot& pv, const double* __restrict S, double* __restrict L) {
  for (int a = 0; a < m; ++a) {
    double* X = L + 36 * a;
    for (int k = 0; k < 36; ++k) X[k] = S[36 * a + k];
    pivotApply<6>(pv, X);
  }
}

// L D Lᵀ y = b in place, y by position (6 a block row).
CORBEL_CLONES
void blockSubstitute(int n, const int* __restrict colStart, const int* __restrict rows, const double* __restrict values,
                     const BlockLdlt::Pivot* __restrict pivots, double* __restrict y) {
  for (int p = 0; p < n; ++p) {
    const double* yp = y + 6 * p;
    for (int s = colStart[p] + 1; s < colStart[p + 1]; ++s) {
      const double* V = values + 36 * std::size_t(s);
      double* yr = y + 6 * rows[s];
      for (int k = 0; k < 6; ++k)
        for (int i = 0; i < 6; ++i) yr[i] -= V[i + 6 * k] * yp[k];
    }
  }
  for (int p = 0; p < n; ++p) pivotApply<1>(pivots[p], y + 6 * p);
  for (int p = n - 1; p >= 0; --p) {
    double* yp = y + 6 * p;
    for (int s = colStart[p] + 1; s < colStart[p + 1]; ++s) {
      const double* V = values + 36 * std::size_t(s);
      const double* yr = y + 6 * rows[s];
      for (int k = 0; k < 6; ++k) {
        double acc = 0;
        for (int i = 0; i < 6; ++i) acc += V[i + 6 * k] * yr[i];
        yp[k] -= acc;
      }
    }
  }
}

// The right-looking update of one column: C_t −= L_a S_bᵀ for every pair of the column's rows
// a ≥ b, t the pair's target slot. This is most of the factorisation's arithmetic (6×6 times
// 6×6, 432 flops a pair), written as plain loops so the compiler vectorises them for the
// machine: `target_clones` builds an AVX2/FMA version beside the baseline x86-64 one and picks
// one when the program loads (GCC's ifunc). Eigen's own kernels are fixed at compile time to
// SSE2 here, since the build targets baseline x86-64. No aliasing: L is a scratch copy, the
// S_b are the column's own slots and every target lies in a later column.
CORBEL_CLONES
void updateColumn(int m, const double* __restrict L, const double* __restrict S, const int* __restrict targets,
                  double* __restrict values) {
  for (int a = 0; a < m; ++a) {
    const double* La = L + 36 * a;
    for (int b = 0; b <= a; ++b) {
      const double* Sb = S + 36 * b;
      double* C = values + 36 * std::size_t(*targets++);
      for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 6; ++k) {
          const double sjk = Sb[j + 6 * k];
          for (int i = 0; i < 6; ++i) C[i + 6 * j] -= La[i + 6 * k] * sjk;
        }
    }
  }
}

}  // namespace

void BlockLdlt::analyze(int n, const std::vector<std::pair<int, int>>& pairs) {
  n_ = n;
  // AMD on the graph of blocks.
  std::vector<Eigen::Triplet<double>> trips;
  for (int i = 0; i < n; ++i) trips.emplace_back(i, i, 1.0);
  for (const auto& [i, j] : pairs)
    if (i != j) {
      trips.emplace_back(i, j, 1.0);
      trips.emplace_back(j, i, 1.0);
    }
  Eigen::SparseMatrix<double> G(n, n);
  G.setFromTriplets(trips.begin(), trips.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  Eigen::AMDOrdering<int> amd;
  amd(G, P);
  // Eigen's orderings return the inverse permutation: entry p is the old index placed at p.
  pos_.assign(std::size_t(n), 0);
  perm_.assign(std::size_t(n), 0);
  for (int p = 0; p < n; ++p) {
    perm_[std::size_t(p)] = P.indices()[p];
    pos_[std::size_t(P.indices()[p])] = p;
  }
  // Symbolic factorisation: the rows of column p are its later neighbours and its
  // elimination-tree children's rows (all after p).
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(n));
  for (const auto& [i, j] : pairs) {
    if (i == j) continue;
    const int pi = pos_[std::size_t(i)], pj = pos_[std::size_t(j)];
    adj[std::size_t(std::min(pi, pj))].push_back(std::max(pi, pj));
  }
  std::vector<std::vector<int>> col(static_cast<std::size_t>(n));
  std::vector<std::vector<int>> children(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) {
    std::vector<int>& c = col[std::size_t(p)];
    c = adj[std::size_t(p)];
    for (int ch : children[std::size_t(p)])
      for (int q : col[std::size_t(ch)])
        if (q > p) c.push_back(q);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    if (!c.empty()) children[std::size_t(c.front())].push_back(p);
  }
  colStart_.assign(std::size_t(n) + 1, 0);
  rows_.clear();
  for (int p = 0; p < n; ++p) {
    colStart_[std::size_t(p)] = int(rows_.size());
    rows_.push_back(p);  // the diagonal slot
    for (int q : col[std::size_t(p)]) rows_.push_back(q);
  }
  colStart_[std::size_t(n)] = int(rows_.size());
  // Not zeroed here: the caller zeroes the blocks before it sums the matrix in (values()).
  values_.clear();
  values_.resize(rows_.size());
  // Copies of a factorised LDLT: Eigen 3.4 leaves a default-constructed one's status
  // uninitialised, and copying that is undefined behaviour (UBSan reports it).
  dfac_.assign(std::size_t(n), Eigen::LDLT<Block>(Block::Identity()));
  pivots_.assign(std::size_t(n), Pivot{});
}

BlockLdlt::Slot BlockLdlt::slot(int i, int j) const {
  const int pi = pos_[std::size_t(i)], pj = pos_[std::size_t(j)];
  const int row = std::max(pi, pj), column = std::min(pi, pj);
  const auto b = rows_.begin() + colStart_[std::size_t(column)], e = rows_.begin() + colStart_[std::size_t(column) + 1];
  Slot s;
  s.index = int(std::lower_bound(b, e, row) - rows_.begin());
  s.transposed = pi < pj;  // stored as (row, column) = (j, i)
  return s;
}

bool BlockLdlt::factorize(double minPivot) {
  std::vector<Block>& L = scratchL_;
  for (int p = 0; p < n_; ++p) {
    const int start = colStart_[std::size_t(p)], end = colStart_[std::size_t(p) + 1];
    // D_p by a dense LDLᵀ with symmetric pivoting (scaling-invariant, unlike an explicit
    // inverse); zero pivots give zero components (Eigen's LDLT solve).
    Eigen::LDLT<Block>& f = dfac_[std::size_t(p)];
    f.compute(values_[std::size_t(start)]);
    if (f.info() != Eigen::Success) return false;
    const auto dv = f.vectorD();
    const double top = std::max(dv.cwiseAbs().maxCoeff(), 1e-300);
    if (!(dv.minCoeff() > minPivot * top)) return false;
    // L_qp = S_qp D_p⁺, then S_ab −= L_ap S_bpᵀ for the column's rows a ≥ b.
    const int m = end - start - 1;
    Pivot& pv = pivots_[std::size_t(p)];
    for (int i = 0; i < 6; ++i) {
      pv.transpositions[i] = f.transpositionsP().indices()[i];
      pv.d[i] = dv[i];
    }
    Eigen::Map<Block>(pv.L) = f.matrixLDLT();
    L.resize(std::size_t(m));
    if (m > 0) pivotColumn(m, pv, values_[std::size_t(start + 1)].data(), L[0].data());
    if (m > 0) {
      // The slots updated, for the rows a ≥ b of this column (a·(a+1)/2 + b): block (c_a, c_b)
      // lies in column c_b, whose rows include every c_a > c_b (the symbolic factorisation
      // closes each column over its children), so one forward walk of column c_b finds them.
      const int* c = rows_.data() + start + 1;
      std::vector<int>& targets = scratchTargets_;
      targets.resize(std::size_t(m) * std::size_t(m + 1) / 2);
      for (int b = 0; b < m; ++b) {
        const int q = c[b];
        int s = colStart_[std::size_t(q)];
        targets[std::size_t(b) * std::size_t(b + 1) / 2 + std::size_t(b)] = s;  // the diagonal block
        for (int a = b + 1; a < m; ++a) {
          do ++s;
          while (rows_[std::size_t(s)] != c[a]);
          targets[std::size_t(a) * std::size_t(a + 1) / 2 + std::size_t(b)] = s;
        }
      }
      updateColumn(m, L[0].data(), values_[std::size_t(start + 1)].data(), targets.data(), values_[0].data());
    }
    for (int a = 0; a < m; ++a) values_[std::size_t(start + 1 + a)] = L[std::size_t(a)];
  }
  return true;
}

Eigen::VectorXd BlockLdlt::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x;
  solve(b, x);
  return x;
}

void BlockLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  Eigen::VectorXd& y = scratchY_;
  y.resize(b.size());
  for (int p = 0; p < n_; ++p) y.segment<6>(6 * p) = b.segment<6>(6 * perm_[std::size_t(p)]);
  if (n_ > 0) blockSubstitute(n_, colStart_.data(), rows_.data(), values_[0].data(), pivots_.data(), y.data());
  x.resize(b.size());
  for (int p = 0; p < n_; ++p) x.segment<6>(6 * perm_[std::size_t(p)]) = y.segment<6>(6 * p);
}

}  // namespace corbel::statics
