#include "statics/block_ldlt.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

namespace corbel::statics {
namespace {

// (Not under ThreadSanitizer: a clone's resolver runs while the program loads, before the
// sanitizer's runtime is ready, and crashes there.)
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_THREAD__)
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

// The right-looking update of one column's rows b in [b0, b1): C_t −= L_a S_bᵀ for every a ≥ b
// of the column's m rows c, t the slot of block (c_a, c_b). That block lies in column c_b, whose
// rows include every c_a > c_b (the symbolic factorisation closes each column over its
// children), so one forward walk of column c_b finds the targets as the updates go. This is
// most of the factorisation's arithmetic (6×6 times 6×6, 432 flops a pair). No aliasing: L is a
// scratch copy, the S_b are the column's own slots and every target lies in a later column.
// Every target takes one update from a column, so splitting the b between threads changes no
// sum: the factor is the same bit for bit.
//
// Two kernels for a pair, with the same operations in the same order (C's entry less one
// product at a time, k = 0..5, each a fused multiply-add where the machine has them): plain
// loops, which the compiler vectorises for the baseline x86-64 (SSE2; Eigen's own kernels are
// fixed to it at compile time too), and AVX2/FMA intrinsics chosen when the program runs on a
// machine that has them. There L_a's six columns stay in registers (6 × 4 + 6 × 2 doubles) and
// each column of C takes six broadcasts of S_b: 1.6 to 2 times the compiler's own AVX2 code on
// the plain loops, which reloaded L_a for every column of C.
template <typename Pair>
inline void walkColumn(int b0, int b1, int m, const int* __restrict c, const double* __restrict L,
                       const double* __restrict S, const int* __restrict colStart, const int* __restrict rows,
                       double* __restrict values, Pair pair) {
  for (int b = b0; b < b1; ++b) {
    const double* Sb = S + 36 * b;
    int s = colStart[c[b]];  // the diagonal block (c_b, c_b)
    for (int a = b; a < m; ++a) {
      if (a > b) do
          ++s;
        while (rows[s] != c[a]);
      pair(L + 36 * a, Sb, values + 36 * std::size_t(s));
    }
  }
}

void updateColumnPlain(int b0, int b1, int m, const int* c, const double* L, const double* S, const int* colStart,
                       const int* rows, double* values) {
  walkColumn(b0, b1, m, c, L, S, colStart, rows, values,
             [](const double* __restrict La, const double* __restrict Sb, double* __restrict C) {
               for (int j = 0; j < 6; ++j)
                 for (int k = 0; k < 6; ++k) {
                   const double sjk = Sb[j + 6 * k];
                   for (int i = 0; i < 6; ++i) C[i + 6 * j] -= La[i + 6 * k] * sjk;
                 }
             });
}

#if defined(__GNUC__) && defined(__x86_64__)
#define CORBEL_AVX2_KERNEL 1
__attribute__((target("avx2,fma"))) void updateColumnAvx2(int b0, int b1, int m, const int* c, const double* L,
                                                          const double* S, const int* colStart, const int* rows,
                                                          double* values) {
  walkColumn(
      b0, b1, m, c, L, S, colStart, rows, values,
      [](const double* __restrict La, const double* __restrict Sb, double* __restrict C)
          __attribute__((target("avx2,fma"))) {
            __m256d lo[6];
            __m128d hi[6];
            for (int k = 0; k < 6; ++k) {
              lo[k] = _mm256_loadu_pd(La + 6 * k);
              hi[k] = _mm_loadu_pd(La + 6 * k + 4);
            }
            for (int j = 0; j < 6; ++j) {
              __m256d cl = _mm256_loadu_pd(C + 6 * j);
              __m128d ch = _mm_loadu_pd(C + 6 * j + 4);
              for (int k = 0; k < 6; ++k) {
                const __m256d x = _mm256_broadcast_sd(Sb + j + 6 * k);
                cl = _mm256_fnmadd_pd(lo[k], x, cl);
                ch = _mm_fnmadd_pd(hi[k], _mm256_castpd256_pd128(x), ch);
              }
              _mm256_storeu_pd(C + 6 * j, cl);
              _mm_storeu_pd(C + 6 * j + 4, ch);
            }
          });
}
#endif

void updateColumn(int b0, int b1, int m, const int* c, const double* L, const double* S, const int* colStart,
                  const int* rows, double* values) {
#if defined(CORBEL_AVX2_KERNEL)
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (avx2) return updateColumnAvx2(b0, b1, m, c, L, S, colStart, rows, values);
#endif
  updateColumnPlain(b0, b1, m, c, L, S, colStart, rows, values);
}

// A CPU hint that this thread is spinning (x86 PAUSE): the core slows the loop down and leaves
// its resources to the other thread on it.
inline void spinPause() {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_ia32_pause();
#endif
}

// A second thread for the factorisation's large columns: `run(f)` calls f(0) here and f(1) on
// the helper and returns when both are done. Between calls the helper spins (a large column
// follows the last within microseconds while the factorisation is in its large columns), then
// sleeps on the counter (C++20 atomic wait) once none has come for about a tenth of a
// millisecond.
class HelperThread {
 public:
  HelperThread() : thread_([this] { loop(); }) {}
  ~HelperThread() {
    task_ = nullptr;
    go_.fetch_add(1, std::memory_order_release);
    go_.notify_one();
    thread_.join();
  }
  template <typename F>
  void run(F& f) {
    context_ = &f;
    task_ = [](void* c, int half) { (*static_cast<F*>(c))(half); };
    const unsigned ticket = go_.fetch_add(1, std::memory_order_release) + 1;
    go_.notify_one();
    f(0);
    for (int spin = 0; done_.load(std::memory_order_acquire) != ticket; ++spin)
      if (spin < kSpins)
        spinPause();
      else
        std::this_thread::yield();
  }

 private:
  static constexpr int kSpins = 4096;
  void loop() {
    unsigned seen = 0;
    for (;;) {
      unsigned now;
      for (int spin = 0; (now = go_.load(std::memory_order_acquire)) == seen; ++spin)
        if (spin < kSpins)
          spinPause();
        else
          go_.wait(seen, std::memory_order_acquire);
      seen = now;
      if (!task_) return;
      task_(context_, 1);
      done_.store(seen, std::memory_order_release);
    }
  }
  std::atomic<unsigned> go_{0}, done_{0};
  void (*task_)(void*, int) = nullptr;
  void* context_ = nullptr;
  std::thread thread_;
};

// Columns with at least this many off-diagonal blocks are shared with the helper (two
// handshakes a column), and the helper is started only when such columns hold at least
// kParallelPairs pairs (about 0.1 GFlop, tens of milliseconds on one core).
constexpr int kParallelColumn = 32;
constexpr double kParallelPairs = 2e5;

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
  largePairs_ = 0;
  for (int p = 0; p < n; ++p) {
    const double m = colStart_[std::size_t(p) + 1] - colStart_[std::size_t(p)] - 1;
    if (m >= kParallelColumn) largePairs_ += m * (m + 1) / 2;
  }
  // Not zeroed here: the caller zeroes the blocks before it sums the matrix in (values()).
  values_.clear();
  values_.resize(rows_.size());
  // Copies of a factorised LDLT: Eigen 3.4 leaves a default-constructed one's status
  // uninitialised, and copying that is undefined behaviour (UBSan reports it).
  dfac_.assign(std::size_t(n), Eigen::LDLT<Block>(Block::Identity()));
  pivots_.assign(std::size_t(n), Pivot{});
}

bool BlockLdlt::sharesWork() const { return largePairs_ >= kParallelPairs; }

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
  const unsigned cores = threads_ > 0 ? unsigned(threads_) : std::max(1u, std::thread::hardware_concurrency());
  std::optional<HelperThread> helper;
  if (cores >= 2 && sharesWork()) helper.emplace();
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
    if (m == 0) continue;
    L.resize(std::size_t(m));
    const double* S = values_[std::size_t(start + 1)].data();
    const int* c = rows_.data() + start + 1;
    if (helper && m >= kParallelColumn) {
      // Rows of L split in two halves; then the b split where the pairs (m − b for each b) halve.
      const int half = m / 2;
      auto pivots = [&](int t) {
        const int a0 = t == 0 ? 0 : half, a1 = t == 0 ? half : m;
        pivotColumn(a1 - a0, pv, S + 36 * a0, L[std::size_t(a0)].data());
      };
      helper->run(pivots);
      const double total = double(m) * (m + 1) / 2;
      int split = 0;
      for (double acc = 0; split < m && acc + (m - split) <= total / 2; ++split) acc += m - split;
      // Each thread reads S_b only for its own b, so it stores L over them once it is done.
      auto updates = [&](int t) {
        const int b0 = t == 0 ? 0 : split, b1 = t == 0 ? split : m;
        updateColumn(b0, b1, m, c, L[0].data(), S, colStart_.data(), rows_.data(), values_[0].data());
        std::copy(L.begin() + b0, L.begin() + b1, values_.begin() + start + 1 + b0);
      };
      helper->run(updates);
    } else {
      pivotColumn(m, pv, S, L[0].data());
      updateColumn(0, m, m, c, L[0].data(), S, colStart_.data(), rows_.data(), values_[0].data());
      std::copy(L.begin(), L.begin() + m, values_.begin() + start + 1);
    }
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
