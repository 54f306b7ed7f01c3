// The block LDLᵀ of the statics QP's Schur complement (src/statics/block_ldlt.h) and the big
// buffers it lives in (src/statics/big_buffers.h): a factor shared between two threads is the
// one-thread factor bit for bit, it solves the matrix it factored (the residual computed from
// the matrix's own blocks), and a released buffer is kept for the next solve within a bound.
#include "statics/block_ldlt.h"
#include "statics/big_buffers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <utility>
#include <vector>

namespace {

using corbel::statics::BlockLdlt;
using Block = BlockLdlt::Block;

// A symmetric positive definite matrix of 6×6 blocks on a g × g grid, each block joined to its
// eight neighbours (a running-bond wall's pattern is of this kind): random off-diagonal
// blocks, diagonal blocks symmetric and dominant.
struct GridMatrix {
  int n = 0;
  std::vector<std::pair<int, int>> pairs;  // (i, j), i ≥ j, the diagonal included
  std::vector<Block> blocks;               // block (i, j) of each pair
};

GridMatrix grid(int g, unsigned seed) {
  GridMatrix M;
  M.n = g * g;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> rowSum(std::size_t(M.n) * 6, 0.0);
  for (int y = 0; y < g; ++y)
    for (int x = 0; x < g; ++x) {
      const int i = y * g + x;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy, j = yy * g + xx;
          if (xx < 0 || yy < 0 || xx >= g || yy >= g || j >= i) continue;
          Block B;
          for (int k = 0; k < 36; ++k) B.data()[k] = u(rng);
          M.pairs.emplace_back(i, j);
          M.blocks.push_back(B);
          for (int r = 0; r < 6; ++r) {
            rowSum[std::size_t(i) * 6 + r] += B.row(r).cwiseAbs().sum();
            rowSum[std::size_t(j) * 6 + r] += B.col(r).cwiseAbs().sum();
          }
        }
    }
  for (int i = 0; i < M.n; ++i) {
    Block D;
    for (int k = 0; k < 36; ++k) D.data()[k] = u(rng);
    D = (D + D.transpose()).eval();
    for (int r = 0; r < 6; ++r) D(r, r) = rowSum[std::size_t(i) * 6 + r] + D.row(r).cwiseAbs().sum() + 1.0;
    M.pairs.emplace_back(i, i);
    M.blocks.push_back(D);
  }
  return M;
}

void load(BlockLdlt& f, const GridMatrix& M) {
  for (Block& b : f.values()) b.setZero();
  for (std::size_t k = 0; k < M.pairs.size(); ++k) {
    const BlockLdlt::Slot s = f.slot(M.pairs[k].first, M.pairs[k].second);
    f.values()[std::size_t(s.index)] += s.transposed ? Block(M.blocks[k].transpose()) : M.blocks[k];
  }
}

TEST(BlockLdlt, TwoThreadsFactorBitForBitAsOneAndSolveTheMatrix) {
  const GridMatrix M = grid(48, 7);  // 2,304 blocks: its separators' columns are shared
  BlockLdlt one, two;
  one.setThreads(1);
  two.setThreads(2);
  one.analyze(M.n, M.pairs);
  two.analyze(M.n, M.pairs);
  ASSERT_TRUE(two.sharesWork()) << "the grid is too small to take the second thread";
  load(one, M);
  load(two, M);
  ASSERT_TRUE(one.factorize());
  ASSERT_TRUE(two.factorize());
  ASSERT_EQ(one.values().size(), two.values().size());
  EXPECT_EQ(0, std::memcmp(one.values().data(), two.values().data(), one.values().size() * sizeof(Block)))
      << "the shared factorisation changed a sum";

  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd b(6 * M.n);
  for (Eigen::Index k = 0; k < b.size(); ++k) b[k] = u(rng);
  const Eigen::VectorXd x = two.solve(b);
  // S x from the matrix's own blocks, S_ij and S_ji = S_ijᵀ.
  Eigen::VectorXd Sx = Eigen::VectorXd::Zero(b.size());
  for (std::size_t k = 0; k < M.pairs.size(); ++k) {
    const auto [i, j] = M.pairs[k];
    Sx.segment<6>(6 * i) += M.blocks[k] * x.segment<6>(6 * j);
    if (i != j) Sx.segment<6>(6 * j) += M.blocks[k].transpose() * x.segment<6>(6 * i);
  }
  // Diagonally dominant, so well conditioned: rounding leaves the residual near 1e-15.
  EXPECT_LT((Sx - b).lpNorm<Eigen::Infinity>(), 1e-12 * b.lpNorm<Eigen::Infinity>());
}

TEST(BigBuffers, AReleasedBufferIsKeptForTheNextWithinTheBound) {
  namespace bb = corbel::statics::bigbuffers;
  if (!bb::kMapped) GTEST_SKIP() << "buffers go through operator new here (AddressSanitizer)";
  const std::size_t size = std::size_t(24) << 20;
  const std::size_t before = bb::cachedBytes();
  void* p = bb::allocate(size);
  std::memset(p, 1, size);
  bb::release(p, size);
  EXPECT_GE(bb::cachedBytes(), before + size);
  void* q = bb::allocate(size);
  EXPECT_EQ(p, q) << "the released mapping was not reused";
  bb::release(q, size);
  // More released than the bound: the oldest are given back, the kept bytes stay within it.
  std::vector<void*> many;
  for (std::size_t k = 0; k < bb::kCacheBytes / size + 3; ++k) many.push_back(bb::allocate(size));
  for (void* m : many) bb::release(m, size);
  EXPECT_LE(bb::cachedBytes(), bb::kCacheBytes);
  EXPECT_GE(bb::cachedBytes(), bb::kCacheBytes - size);
}

}  // namespace
