// The penalty QP of Sec. 3.2, y = min Σ (f_n⁻)² subject to A f + w = 0 and the friction
// pyramid, solved a second time by Ipopt (coinor-libipopt-dev, its C interface, exact
// Hessian) and compared with corbel's interior-point solver (src/statics/ipm.cpp).
//
// The oracle shares only the geometry with corbel: the contacts (polygons, force points,
// frames), the blocks' centroids and the loads / W from `prepareEquilibrium`. Its equilibrium
// matrix is assembled here from those, independently of `penaltyQP`, and corbel's forces are
// checked against it too, so a wrong A in either would show as a residual.
#include "statics/arch.h"
#include "statics/builder.h"
#include "statics/equilibrium.h"
#include "statics/examples.h"
#include "statics/tolerances.h"
#include "statics/wall.h"

#include <gtest/gtest.h>

#include <IpStdCInterface.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using namespace corbel::statics;
using corbel::Vec3;

// The QP in the variables [f_n⁺, f_n⁻, f_t1, f_t2] per contact vertex (interfaces in the order
// of the contacts, points in polygon order), all forces in units of W.
struct OracleQP {
  int n = 0;                                     // variables
  Eigen::SparseMatrix<double> A;                 // equilibrium rows × variables
  Eigen::VectorXd w;                             // loads / W
  double alpha = 0.7;                            // friction coefficient
  std::vector<Eigen::Triplet<double>> friction;  // rows α f_n⁺ ± f_t ≥ 0 (row, variable, coefficient)
  int frictionRows = 0;
  int iterations = 0;  // Ipopt's, set by its intermediate callback
};

OracleQP buildOracle(const EquilibriumSystem& sys) {
  OracleQP q;
  q.alpha = sys.alpha;
  q.w = sys.w;
  std::vector<Eigen::Triplet<double>> trips;
  int v = 0;
  for (const Interface& itf : sys.contacts.interfaces)
    for (const Vec3& p : itf.points) {
      // Unit force directions of the four variables, as forces on b (a gets the opposite).
      const Vec3 dir[4] = {itf.normal, -itf.normal, itf.t1, itf.t2};
      for (int blockSide = 0; blockSide < 2; ++blockSide) {
        const int blk = blockSide == 0 ? itf.b : itf.a;
        const int row = sys.rowOf[std::size_t(blk)];
        if (row < 0) continue;  // the ground: no equations
        const double sign = blockSide == 0 ? 1.0 : -1.0;
        const Vec3 arm = p - sys.props[std::size_t(blk)].centroid;
        for (int c = 0; c < 4; ++c) {
          const Vec3 f = dir[c] * sign;
          const Vec3 m = cross(arm, f);
          for (int k = 0; k < 3; ++k) {
            trips.emplace_back(row + k, v + c, f[k]);
            trips.emplace_back(row + 3 + k, v + c, m[k]);
          }
        }
      }
      for (int t = 0; t < 2; ++t)
        for (double s : {1.0, -1.0}) {
          q.friction.emplace_back(q.frictionRows, v, q.alpha);
          q.friction.emplace_back(q.frictionRows, v + 2 + t, s);
          ++q.frictionRows;
        }
      v += 4;
    }
  q.n = v;
  q.A.resize(sys.rows, v);
  q.A.setFromTriplets(trips.begin(), trips.end());  // duplicates (none expected) would be summed
  q.A.prune(0.0);
  q.A.makeCompressed();
  return q;
}

double objective(const Eigen::VectorXd& x) {
  double y = 0;
  for (Eigen::Index k = 1; k < x.size(); k += 4) y += x[k] * x[k];
  return y;
}

// Ipopt's callbacks: constraints g = [A x (= −w); friction rows (≥ 0)].
Bool evalF(Index n, Number* x, Bool, Number* f, UserDataPtr) {
  double y = 0;
  for (Index k = 1; k < n; k += 4) y += x[k] * x[k];
  *f = y;
  return TRUE;
}
Bool evalGradF(Index n, Number* x, Bool, Number* g, UserDataPtr) {
  for (Index k = 0; k < n; ++k) g[k] = k % 4 == 1 ? 2 * x[k] : 0.0;
  return TRUE;
}
Bool evalG(Index n, Number* x, Bool, Index m, Number* g, UserDataPtr data) {
  const OracleQP& q = *static_cast<const OracleQP*>(data);
  const Eigen::Map<const Eigen::VectorXd> xv(x, n);
  Eigen::Map<Eigen::VectorXd> gv(g, m);
  gv.head(q.A.rows()) = q.A * xv;
  gv.tail(q.frictionRows).setZero();
  for (const auto& t : q.friction) g[q.A.rows() + t.row()] += t.value() * x[t.col()];
  return TRUE;
}
Bool evalJacG(Index, Number*, Bool, Index, Index, Index* iRow, Index* jCol, Number* values, UserDataPtr data) {
  const OracleQP& q = *static_cast<const OracleQP*>(data);
  Index k = 0;
  for (int c = 0; c < q.A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(q.A, c); it; ++it, ++k) {
      if (values) {
        values[k] = it.value();
      } else {
        iRow[k] = Index(it.row());
        jCol[k] = c;
      }
    }
  for (const auto& t : q.friction) {
    if (values) {
      values[k] = t.value();
    } else {
      iRow[k] = Index(q.A.rows() + t.row());
      jCol[k] = t.col();
    }
    ++k;
  }
  return TRUE;
}
// The exact Hessian of the Lagrangian: the constraints are linear, so only the objective's
// 2 on every f_n⁻.
Bool evalH(Index n, Number*, Bool, Number objFactor, Index, Number*, Bool, Index, Index* iRow, Index* jCol,
           Number* values, UserDataPtr) {
  Index k = 0;
  for (Index v = 1; v < n; v += 4, ++k) {
    if (values) {
      values[k] = 2 * objFactor;
    } else {
      iRow[k] = v;
      jCol[k] = v;
    }
  }
  return TRUE;
}

struct OracleResult {
  int status = -100;  // Ipopt's ApplicationReturnStatus
  double y = 0;       // Σ (f_n⁻)², units of W²
  Eigen::VectorXd x;
  int iterations = 0;
};

Bool countIterations(Index, Index iter, Number, Number, Number, Number, Number, Number, Number, Number, Index,
                     UserDataPtr data) {
  static_cast<OracleQP*>(data)->iterations = iter;
  return TRUE;
}

OracleResult solveWithIpopt(OracleQP& q) {
  const Index n = q.n, m = Index(q.A.rows()) + q.frictionRows;
  std::vector<Number> xL(std::size_t(n), -2e19), xU(std::size_t(n), 2e19);
  for (Index v = 0; v < n; v += 4) xL[std::size_t(v)] = xL[std::size_t(v) + 1] = 0.0;  // f_n⁺, f_n⁻ ≥ 0
  std::vector<Number> gL(std::size_t(m), 0.0), gU(std::size_t(m), 2e19);
  for (Eigen::Index r = 0; r < q.A.rows(); ++r) gL[std::size_t(r)] = gU[std::size_t(r)] = -q.w[r];
  const Index nJac = Index(q.A.nonZeros() + Eigen::Index(q.friction.size()));
  IpoptProblem p = CreateIpoptProblem(n, xL.data(), xU.data(), m, gL.data(), gU.data(), nJac, n / 4, 0, &evalF, &evalG,
                                      &evalGradF, &evalJacG, &evalH);
  EXPECT_NE(p, nullptr);
  OracleResult r;
  if (!p) return r;
  AddIpoptIntOption(p, const_cast<char*>("print_level"), 0);
  AddIpoptStrOption(p, const_cast<char*>("sb"), const_cast<char*>("yes"));
  // Tight and unmodified: no bound relaxation (Ipopt relaxes f_n⁻ ≥ 0 by 1e-8 by default, which
  // would let it pay less than the true y), no automatic scaling (loads are already / W).
  AddIpoptNumOption(p, const_cast<char*>("tol"), 1e-14);
  AddIpoptNumOption(p, const_cast<char*>("constr_viol_tol"), 1e-12);
  AddIpoptNumOption(p, const_cast<char*>("bound_relax_factor"), 0.0);
  AddIpoptStrOption(p, const_cast<char*>("nlp_scaling_method"), const_cast<char*>("none"));
  AddIpoptStrOption(p, const_cast<char*>("mu_strategy"), const_cast<char*>("adaptive"));
  AddIpoptStrOption(p, const_cast<char*>("hessian_constant"), const_cast<char*>("yes"));
  AddIpoptStrOption(p, const_cast<char*>("jac_c_constant"), const_cast<char*>("yes"));
  AddIpoptStrOption(p, const_cast<char*>("jac_d_constant"), const_cast<char*>("yes"));
  AddIpoptIntOption(p, const_cast<char*>("max_iter"), 3000);
  r.x = Eigen::VectorXd::Zero(n);
  for (Index v = 0; v < n; v += 4) r.x[v] = 1.0;  // a start inside the pyramid
  std::vector<Number> g(static_cast<std::size_t>(m));
  Number obj = 0;
  SetIntermediateCallback(p, &countIterations);
  r.status = IpoptSolve(p, r.x.data(), g.data(), &obj, nullptr, nullptr, nullptr, &q);
  FreeIpoptProblem(p);
  r.y = objective(r.x);
  r.iterations = q.iterations;
  return r;
}

double residual(const OracleQP& q, const Eigen::VectorXd& x) { return (q.A * x + q.w).norm() / q.w.norm(); }

// The least of f_n⁺, f_n⁻ and the friction rows at x (≥ 0 up to rounding when x is admissible).
double leastSlack(const OracleQP& q, const Eigen::VectorXd& x) {
  double least = 0;
  for (Eigen::Index v = 0; v < x.size(); v += 4) least = std::min({least, x[v], x[v + 1]});
  std::vector<double> rows(std::size_t(q.frictionRows), 0.0);
  for (const auto& t : q.friction) rows[std::size_t(t.row())] += t.value() * x[t.col()];
  for (double r : rows) least = std::min(least, r);
  return least;
}

// Solves the model both ways and compares. corbel must end `optimal` (where its iterations stop
// short, the polish's point: docs/statics.md), y within 1e-8 relative (the largest difference
// measured on these models is 5.8e-9, the thin-buttressed vault's), with an absolute floor of
// kFeasibleMeasure (1e-10 in y/W², the resolution at which "stands" is decided: both solvers
// stop at complementarity of that order, so y ≈ 0 cannot be compared relatively). Returns
// Ipopt's y/W².
double compareWithIpopt(const Assembly& as, const AnalysisOptions& opt = {}) {
  const EquilibriumSystem sys = prepareEquilibrium(as, opt);
  OracleQP q = buildOracle(sys);
  const AnalysisResult ours = analyseSystem(sys, opt);
  const OracleResult ip = solveWithIpopt(q);
  // Solve_Succeeded (0) or Solved_To_Acceptable_Level (1).
  EXPECT_TRUE(ip.status == 0 || ip.status == 1) << "Ipopt status " << ip.status;
  EXPECT_EQ(ours.status, SolveStatus::Optimal) << toString(ours.status);
  EXPECT_EQ(ours.solution.size(), q.n);
  if (ours.solution.size() != q.n) return ip.y;

  const double tol = std::max(1e-8 * ip.y, kFeasibleMeasure);
  std::printf(
      "  %d blocks, %d variables: corbel y/W² %.10g (%s, %d iterations, gap %.2g), Ipopt %.10g (%d iterations), "
      "difference %.2g (%.2g relative); residuals %.1e, %.1e\n",
      int(as.blocks.size()), q.n, ours.yNormalised, toString(ours.status).c_str(), ours.iterations, ours.gap, ip.y,
      ip.iterations, ours.yNormalised - ip.y, ip.y > 0 ? (ours.yNormalised - ip.y) / ip.y : 0.0,
      ours.equilibriumResidual, residual(q, ip.x));
  EXPECT_NEAR(ours.yNormalised, ip.y, tol)
      << "corbel " << ours.yNormalised << " (gap " << ours.gap << ", " << toString(ours.status) << ", "
      << ours.iterations << " iterations), Ipopt " << ip.y;
  EXPECT_NEAR(objective(ours.solution), ours.yNormalised, 1e-15 + 1e-12 * ours.yNormalised);
  // Both force fields balance every block in the oracle's own A, and are admissible.
  EXPECT_LE(residual(q, ip.x), 1e-8);
  EXPECT_LE(residual(q, ours.solution), 1e-8);
  EXPECT_NEAR(residual(q, ours.solution), ours.equilibriumResidual, 1e-10);
  EXPECT_GE(leastSlack(q, ip.x), -1e-9);
  EXPECT_GE(leastSlack(q, ours.solution), -1e-9);
  return ip.y;
}

Assembly arch(int blocks, double thickness, double tiltDeg = 0) {
  ArchSpec s;
  s.blocks = blocks;
  s.thickness = thickness;
  s.tiltDeg = tiltDeg;
  return semicircularArch(s);
}

TEST(IpoptOracle, StandingArch) {
  const double y = compareWithIpopt(arch(40, 0.2));
  EXPECT_LE(y, kFeasibleMeasure);
}

TEST(IpoptOracle, ArchTooThinToStand) {
  // The statics notes' y = 1.0837e-4 (cvxopt, Ipopt and Clp agreed) for this arch, in their units.
  const double y = compareWithIpopt(arch(100, 0.10));
  EXPECT_GT(y, 1e-4);
}

TEST(IpoptOracle, ArchOnTiltedGround) {
  // Past Ochsendorf's 15.84° for t/R = 0.2: a tipping mechanism needs tension.
  EXPECT_GT(compareWithIpopt(arch(40, 0.2, 18.0)), 1e-8);
  // Below it the arch still stands.
  EXPECT_LE(compareWithIpopt(arch(40, 0.2, 14.0)), kFeasibleMeasure);
}

Assembly wallWithWindows(double push) {
  WallSpec w;
  w.length = 4.0;
  w.courses = 8;
  w.height = 4.0;
  w.windows = {{0.75, 1.0, 2, 6}, {2.5, 1.0, 0, 5}};  // a window and a door
  std::vector<Block> blocks = wallBlocks(w);
  // A horizontal push across the wall's thickness on the top course (push × the wall's
  // weight in all): vertical interfaces then carry friction and the bed joints tension.
  double weight = 0, topZ = 0;
  for (const Block& b : blocks)
    for (const Vec3& v : b.vertices) topZ = std::max(topZ, v[2]);
  std::vector<int> top;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    double zmax = 0;
    for (const Vec3& v : blocks[i].vertices) zmax = std::max(zmax, v[2]);
    if (zmax > topZ - 1e-9) top.push_back(int(i));
  }
  weight = 9.81 * 2400.0 * w.length * w.thickness * w.height;  // the order of it; exact value immaterial
  for (int i : top) blocks[std::size_t(i)].liveLoad = Vec3(0, push * weight / double(top.size()), 0);
  StructureBuilder b;
  b.add("wall", std::move(blocks));
  b.groundUnder(1.0);
  return b.build();
}

TEST(IpoptOracle, WallWithWindows) {
  EXPECT_LE(compareWithIpopt(wallWithWindows(0.0)), kFeasibleMeasure);
  EXPECT_GT(compareWithIpopt(wallWithWindows(0.05)), 1e-8);
}

TEST(IpoptOracle, BarrelVault) {
  // Fig. 13's vault (140 blocks) at the search's start, thin buttresses that fail: one of the
  // models where corbel's iterations stop short and the polish finds the optimum
  // (docs/statics.md).
  const ParametricModel m = barrelVaultExample();
  EXPECT_GT(compareWithIpopt(m.build(m.parameters)), 1e-6);
  // Buttresses wide enough to stand.
  ParameterSet wide = m.parameters;
  wide.set("buttressWidth", 1.0);
  EXPECT_LE(compareWithIpopt(m.build(wide)), kFeasibleMeasure);
}

TEST(IpoptOracle, LeaningTower) {
  // Fig. 11's tower at the search's start (every level 0.12 m over the one below, 96 blocks):
  // the other model where the iterations stop short.
  const ParametricModel m = towerExample();
  EXPECT_GT(compareWithIpopt(m.build(m.parameters)), 1e-3);
}

Assembly twoCubes(double offset) {
  Assembly as;
  as.blocks.push_back(boxBlock("ground", Vec3(-3, -3, -1), Vec3(3, 3, 0), 1.0, true));
  as.blocks.push_back(boxBlock("bottom", Vec3(0, 0, 0), Vec3(1, 1, 1)));
  as.blocks.push_back(boxBlock("top", Vec3(offset, 0, 1), Vec3(offset + 1, 1, 2)));
  return as;
}

TEST(IpoptOracle, StackPastTipping) {
  // Offset 0.7 > 1/2: the top cube's weight (half of W) at 0.2 past the edge. The least tension
  // is 2/3 of the top cube's weight split over the two far corners: y/W² = 2 (1/6)² = 1/18.
  // Within Ipopt's own stopping tolerance (tol 1e-14 on the scaled KKT error) with room for
  // rounding in y = Σ x²: measured 8e-12 relative.
  EXPECT_NEAR(compareWithIpopt(twoCubes(0.7)), 1.0 / 18.0, 1e-10);
  EXPECT_LE(compareWithIpopt(twoCubes(0.4)), kFeasibleMeasure);
}

}  // namespace
