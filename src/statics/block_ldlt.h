#pragma once
// A sparse LDLᵀ factorisation of a symmetric positive semidefinite matrix made of 6×6 blocks
// (the Schur complement A H⁻¹ Aᵀ of the statics QPs has one 6×6 block row per free block:
// force and torque). Working on whole blocks gives dense fixed-size kernels the compiler
// vectorises, instead of one scalar column at a time; the ordering (AMD) and the symbolic
// factorisation are done once, on the graph of blocks.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "statics/big_buffers.h"

#include <utility>
#include <vector>

namespace corbel::statics {

class BlockLdlt {
 public:
  using Block = Eigen::Matrix<double, 6, 6>;
  // Block storage in mappings kept for the next factorisation (big_buffers.h).
  using Values = BigVector<Block>;

  // `pairs`: the block positions (i, j) of the matrix's nonzero blocks, either triangle, the
  // diagonal included; n block rows.
  void analyze(int n, const std::vector<std::pair<int, int>>& pairs);

  // Where block (i, j) of the matrix (any (i, j) among `pairs` or its transpose) lives in
  // `values()`, and whether it is stored transposed.
  struct Slot {
    int index = -1;
    bool transposed = false;
  };
  Slot slot(int i, int j) const;

  // The matrix's blocks by slot (fill positions included): set them to zero, add the matrix,
  // then factorize. The factorisation overwrites them.
  Values& values() { return values_; }

  // S = L D Lᵀ with unit block-lower L and dense 6×6 blocks D_j, each factored by a dense
  // LDLᵀ with pivoting. Returns false (the caller regularises) when a pivot is not above
  // `minPivot` × the largest pivot of its block.
  bool factorize(double minPivot = 1e-15);

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The same into x (sized here; not b), without allocating once x has its size.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

  long factorNonZeroBlocks() const { return long(values_.size()); }

  // Threads for factorize: 0 (the default) takes two where the machine has them and the
  // factorisation is large enough to gain (block_ldlt.cpp); 1 keeps it on the calling thread.
  // The factor is the same bit for bit either way.
  void setThreads(int threads) { threads_ = threads; }
  // Whether the analysed pattern is large enough for factorize to take a second thread.
  bool sharesWork() const;

 private:
  int n_ = 0;
  std::vector<int> perm_;      // position → block row
  std::vector<int> pos_;       // block row → position
  std::vector<int> colStart_;  // position → first slot of its column (the diagonal), then its rows
  std::vector<int> rows_;      // per off-diagonal slot: the position of its row (> column)
  Values values_;
  std::vector<Eigen::LDLT<Block>> dfac_;  // per position: D's factorisation
  std::vector<Block> scratchL_;           // factorize's L of one column
  double largePairs_ = 0;                 // block pairs in the columns a helper thread shares
  int threads_ = 0;
  mutable Eigen::VectorXd scratchY_;  // solve's permuted vector
 public:
  // D_p's factorisation D = Pᵀ L diag(d) Lᵀ P as plain arrays, for the vectorised kernels.
  struct Pivot {
    int transpositions[6];
    double L[36];  // column-major; the unit lower triangle below the diagonal
    double d[6];
  };

 private:
  std::vector<Pivot> pivots_;
};

}  // namespace corbel::statics
