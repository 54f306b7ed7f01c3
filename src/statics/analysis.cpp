#include "statics/analysis.h"

#include "core/error.h"
#include "statics/equilibrium.h"
#include "statics/parallel.h"
#include "statics/tolerances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace corbel::statics {
namespace {

std::string blockName(const Assembly& as, int i) {
  const std::string& n = as.blocks[std::size_t(i)].name;
  return "block " + std::to_string(i) + (n.empty() ? "" : " \"" + n + "\"");
}

}  // namespace

EquilibriumSystem prepareEquilibrium(const Assembly& as, const AnalysisOptions& opt) {
  if (!std::isfinite(opt.friction) || opt.friction < 0) throw Error("statics: friction must be a number ≥ 0");
  if (!std::isfinite(opt.kernShrink) || opt.kernShrink < 0 || opt.kernShrink >= 1)
    throw Error("statics: kern shrink must be in [0, 1)");
  EquilibriumSystem p;
  BBox model;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices)
      if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) model.add(v);
  const double tol = lengthTolerance(model);
  p.props = validateAssembly(as, tol);
  if (!std::isfinite(opt.contactTolerance) || opt.contactTolerance < 0)
    throw Error("statics: the contact tolerance must be a number ≥ 0");
  p.contacts = findContacts(as, p.props, std::max(tol, opt.contactTolerance), opt.kernShrink);
  p.alpha = opt.conservativeFriction ? opt.friction / std::sqrt(2.0) : opt.friction;
  if (opt.frictionSides != 4 && opt.frictionSides != 8) throw Error("statics: the friction pyramid has 4 or 8 sides");
  p.frictionSides = opt.frictionSides;

  const int nb = int(as.blocks.size());
  p.rowOf.assign(std::size_t(nb), -1);
  for (int i = 0; i < nb; ++i)
    if (!as.blocks[std::size_t(i)].fixed) {
      p.rowOf[std::size_t(i)] = p.rows;
      p.rows += 6;
    }
  if (p.rows == 0) throw Error("statics: every block is fixed; there is nothing to analyse");

  // Every free block must reach a fixed one through contacts with area.
  std::vector<int> parent(static_cast<std::size_t>(nb));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
    return x;
  };
  for (const Interface& itf : p.contacts.interfaces) parent[std::size_t(find(itf.a))] = find(itf.b);
  std::vector<bool> grounded(std::size_t(nb), false);
  for (int i = 0; i < nb; ++i)
    if (as.blocks[std::size_t(i)].fixed) grounded[std::size_t(find(i))] = true;
  for (int i = 0; i < nb; ++i) {
    if (as.blocks[std::size_t(i)].fixed || grounded[std::size_t(find(i))]) continue;
    std::string why;
    for (const ZeroAreaContact& z : p.contacts.zeroArea)
      if (z.a == i || z.b == i)
        why = " (it touches " + blockName(as, z.a == i ? z.b : z.a) +
              " only along an edge or at a point: a zero-area contact)";
    bool touchesAny = false;
    for (const Interface& itf : p.contacts.interfaces) touchesAny = touchesAny || itf.a == i || itf.b == i;
    throw Error(
        "statics: " + blockName(as, i) +
        (touchesAny ? " is not connected to a fixed block through contacts" : " floats: it has no contact with area") +
        why);
  }
  for (const ZeroAreaContact& z : p.contacts.zeroArea)
    p.warnings.push_back(blockName(as, z.a) + " and " + blockName(as, z.b) +
                         " touch only along an edge or at a point; that contact carries no force");

  for (int i = 0; i < nb; ++i)
    if (!as.blocks[std::size_t(i)].fixed)
      p.totalWeight += as.blocks[std::size_t(i)].density * p.props[std::size_t(i)].volume * as.g;
  const Vec3 gdir = as.gravity / as.gravity.norm();
  p.w = Eigen::VectorXd::Zero(p.rows);
  for (int i = 0; i < nb; ++i) {
    const int r = p.rowOf[std::size_t(i)];
    if (r < 0) continue;
    const Block& b = as.blocks[std::size_t(i)];
    const Vec3 f = gdir * (b.density * p.props[std::size_t(i)].volume * as.g) + b.liveLoad;
    for (int k = 0; k < 3; ++k) p.w[r + k] = f[k] / p.totalWeight;  // loads act at the centroid: no torque
    // A point load adds its torque about the centroid.
    for (const PointLoad& l : b.pointLoads) {
      const Vec3 tq = cross(l.at - p.props[std::size_t(i)].centroid, l.force);
      for (int k = 0; k < 3; ++k) {
        p.w[r + k] += l.force[k] / p.totalWeight;
        p.w[r + 3 + k] += tq[k] / p.totalWeight;
      }
    }
  }
  return p;
}

namespace {

// The polygon's convex hull, counter-clockwise about its normal (Andrew's monotone chain in the
// interface frame); the polygon itself where it is convex.
std::vector<Vec3> convexHullOf(const Interface& itf) {
  const std::size_t n = itf.polygon.size();
  bool convex = true;
  for (std::size_t k = 0; k < n && convex; ++k) {
    const Vec3 a = itf.polygon[(k + n - 1) % n], b = itf.polygon[k], c = itf.polygon[(k + 1) % n];
    convex = dot(cross(b - a, c - b), itf.normal) >= 0;
  }
  if (convex) return itf.polygon;
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t(0));
  auto uv = [&](std::size_t i) {
    const Vec3 d = itf.polygon[i] - itf.centroid;
    return std::pair<double, double>(dot(d, itf.t1), dot(d, itf.t2));
  };
  std::sort(idx.begin(), idx.end(), [&](std::size_t x, std::size_t y) { return uv(x) < uv(y); });
  auto turn = [&](std::size_t o, std::size_t a, std::size_t b) {
    const auto [ox, oy] = uv(o);
    const auto [ax, ay] = uv(a);
    const auto [bx, by] = uv(b);
    return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox);
  };
  std::vector<std::size_t> h(2 * n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], idx[i]) <= 0) --k;
    h[k++] = idx[i];
  }
  for (std::size_t i = n - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], idx[i]) <= 0) --k;
    h[k++] = idx[i];
  }
  std::vector<Vec3> out;
  for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(itf.polygon[h[i]]);
  return out;
}

// The gauge of p about the polygon's area centroid c: max over the edges of its convex hull of
// how far p − c reaches towards the edge's line, in units of the centroid's distance to it (a
// non-convex contact's resultant can lie anywhere in its hull, so the hull is the bound).
double pressureGauge(const Interface& itf, const Vec3& p) {
  double g = 0;
  const std::vector<Vec3> hull = convexHullOf(itf);
  const std::size_t n = hull.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = hull[k], b = hull[(k + 1) % n];
    Vec3 out = cross(b - a, itf.normal);  // in-plane, away from the interior (counter-clockwise polygon)
    const double len = out.norm();
    if (len <= 0) continue;
    out /= len;
    const double reach = dot(a - itf.centroid, out);
    if (reach > 0) g = std::max(g, dot(p - itf.centroid, out) / reach);
  }
  return g;
}

}  // namespace

bool sameLayout(const EquilibriumSystem& x, const EquilibriumSystem& y) {
  if (x.rowOf != y.rowOf || x.contacts.interfaces.size() != y.contacts.interfaces.size()) return false;
  for (std::size_t i = 0; i < x.contacts.interfaces.size(); ++i) {
    const Interface &p = x.contacts.interfaces[i], &q = y.contacts.interfaces[i];
    if (p.a != q.a || p.b != q.b || p.faceA != q.faceA || p.faceB != q.faceB || p.points.size() != q.points.size())
      return false;
  }
  return true;
}

namespace {

// The friction pyramid's rows on a vertex's variables, the normal (compression) part at
// index `normal`, the tangential parts at `t`, `t + 1`: α f_n − (cos θ_k f_t1 + sin θ_k f_t2) ≥ 0
// for θ_k = 2πk/sides (for 4 sides: α f_n ± f_t1 ≥ 0, α f_n ± f_t2 ≥ 0).
void addFrictionRows(VarBlock& vb, const EquilibriumSystem& p, int normal, int t) {
  for (int k = 0; k < p.frictionSides; ++k) {
    std::array<double, 4> row{};
    row[std::size_t(normal)] = p.alpha;
    if (p.frictionSides == 4) {
      const double c[4] = {1, -1, 0, 0}, s[4] = {0, 0, 1, -1};
      row[std::size_t(t)] = -c[k];
      row[std::size_t(t + 1)] = -s[k];
    } else {
      const double th = 2 * std::numbers::pi * k / p.frictionSides;
      row[std::size_t(t)] = -std::cos(th);
      row[std::size_t(t + 1)] = -std::sin(th);
    }
    vb.rows.push_back(row);
  }
}

// Adds the column of a unit force `dir` acting on b (and −dir on a) at `point`.
void addForceColumn(const EquilibriumSystem& p, const Interface& itf, const Vec3& point, const Vec3& dir, int col,
                    std::vector<Eigen::Triplet<double>>& trips) {
  for (int side = 0; side < 2; ++side) {
    const int blk = side == 0 ? itf.b : itf.a;
    const int r = p.rowOf[std::size_t(blk)];
    if (r < 0) continue;
    const double sgn = side == 0 ? 1.0 : -1.0;
    const Vec3 arm = point - p.props[std::size_t(blk)].centroid;
    const Vec3 tq = cross(arm, dir);
    for (int k = 0; k < 3; ++k) {
      if (dir[k] != 0) trips.emplace_back(r + k, col, sgn * dir[k]);
      if (tq[k] != 0) trips.emplace_back(r + 3 + k, col, sgn * tq[k]);
    }
  }
}

// The nonzeros of the column of a unit force `dir` acting on b (and −dir on a) at `point`, as
// addForceColumn lays them out, sorted by row, written from `at` (counted only, without
// writing, when inner is null): each side's rows come in order (force r..r+2, torque r+3..r+5),
// so the side with the lower rows goes first. Returns the count.
int forceColumn(const EquilibriumSystem& p, const Interface& itf, const Vec3& point, const Vec3& dir, int* inner,
                double* value, int at) {
  const int start = at;
  const int rb = p.rowOf[std::size_t(itf.b)], ra = p.rowOf[std::size_t(itf.a)];
  const bool bFirst = ra < 0 || (rb >= 0 && rb < ra);
  for (int pass = 0; pass < 2; ++pass) {
    const int blk = (pass == 0) == bFirst ? itf.b : itf.a;
    const int r = p.rowOf[std::size_t(blk)];
    if (r < 0) continue;
    const double sgn = blk == itf.b ? 1.0 : -1.0;
    const Vec3 arm = point - p.props[std::size_t(blk)].centroid;
    const Vec3 tq = cross(arm, dir);
    for (int i = 0; i < 3; ++i)
      if (dir[i] != 0) {
        if (inner) inner[at] = r + i, value[at] = sgn * dir[i];
        ++at;
      }
    for (int i = 0; i < 3; ++i)
      if (tq[i] != 0) {
        if (inner) inner[at] = r + 3 + i, value[at] = sgn * tq[i];
        ++at;
      }
  }
  return at - start;
}

}  // namespace

BlockQP penaltyQP(const EquilibriumSystem& p) {
  // Variables per contact vertex: [f_n⁺, f_n⁻, f_t1, f_t2]. A's columns are written straight
  // into compressed storage (Eigen's setFromTriplets on the ~6 million triplets of a
  // 10,000-block wall sorts a copy of them): a first pass counts each vertex's nonzeros, a
  // second writes them where the counts put them. Both, and the blocks, on two threads for a
  // large model (parallel.h).
  BlockQP qp;
  std::vector<std::pair<const Interface*, const Vec3*>> vertex;
  for (const Interface& itf : p.contacts.interfaces)
    for (const Vec3& pt : itf.points) vertex.emplace_back(&itf, &pt);
  const int nv = int(vertex.size());
  auto dirs = [](const Interface& itf) { return std::array<Vec3, 4>{itf.normal, -itf.normal, itf.t1, itf.t2}; };
  std::vector<int> start(std::size_t(nv) + 1, 0);  // each vertex's first nonzero
  forEachIndex(nv, 0, [&](int v) {
    const auto& [itf, pt] = vertex[std::size_t(v)];
    int count = 0;
    for (const Vec3& d : dirs(*itf)) count += forceColumn(p, *itf, *pt, d, nullptr, nullptr, 0);
    start[std::size_t(v) + 1] = count;
  });
  for (int v = 0; v < nv; ++v) start[std::size_t(v) + 1] += start[std::size_t(v)];
  qp.A.resize(p.rows, 4 * nv);
  qp.A.resizeNonZeros(start.back());
  int* outer = qp.A.outerIndexPtr();
  int* inner = qp.A.innerIndexPtr();
  double* value = qp.A.valuePtr();
  outer[0] = 0;
  qp.blocks.resize(std::size_t(nv));
  forEachIndex(nv, 0, [&](int v) {
    const auto& [itf, pt] = vertex[std::size_t(v)];
    int at = start[std::size_t(v)];
    const std::array<Vec3, 4> d = dirs(*itf);
    for (int c = 0; c < 4; ++c) {
      at += forceColumn(p, *itf, *pt, d[std::size_t(c)], inner, value, at);
      outer[4 * v + c + 1] = at;
    }
    VarBlock& vb = qp.blocks[std::size_t(v)];
    vb.offset = 4 * v;
    vb.size = 4;
    vb.hessian = {0, 2, 0, 0};  // ½·2·(f_n⁻)²
    // The pyramid bounds friction by α·f_n⁺ (statics notes): f_n⁺ ≥ 0, f_n⁻ ≥ 0, α f_n⁺ ± f_t ≥ 0.
    vb.rows.reserve(std::size_t(2 + p.frictionSides));  // one allocation, not three
    vb.rows.push_back({1, 0, 0, 0});
    vb.rows.push_back({0, 1, 0, 0});
    addFrictionRows(vb, p, 0, 2);
    vb.nullDirection = {-1, -1, 0, 0};    // the columns of f_n⁺ and f_n⁻ are exact opposites
    vb.interiorDirection = {1, 1, 0, 0};  // more of both: every row grows (α > 0 on the pyramid's)
  });
  qp.b = -p.w;
  qp.rowGroup = 6;
  return qp;
}

double penaltyLagrangianTerm(const EquilibriumSystem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& lambda) {
  // Column by column as addForceColumn lays them out: λ_r·(A_rc x_c) summed.
  double acc = lambda.dot(p.w);
  int col = 0;
  for (const Interface& itf : p.contacts.interfaces)
    for (const Vec3& pt : itf.points) {
      const Vec3 dirs[4] = {itf.normal, -itf.normal, itf.t1, itf.t2};
      for (int side = 0; side < 2; ++side) {
        const int blk = side == 0 ? itf.b : itf.a;
        const int r = p.rowOf[std::size_t(blk)];
        if (r < 0) continue;
        const double sgn = side == 0 ? 1.0 : -1.0;
        const Vec3 arm = pt - p.props[std::size_t(blk)].centroid;
        for (int c = 0; c < 4; ++c) {
          const Vec3 tq = cross(arm, dirs[c]);
          const double xc = x[col + c];
          for (int k = 0; k < 3; ++k)
            acc += lambda[r + k] * (sgn * dirs[c][k]) * xc + lambda[r + 3 + k] * (sgn * tq[k]) * xc;
        }
      }
      col += 4;
    }
  return acc;
}

AnalysisResult analyse(const Assembly& as, const AnalysisOptions& opt) {
  return analyseSystem(prepareEquilibrium(as, opt), opt);
}

AnalysisResult analyseSystem(const EquilibriumSystem& p, const AnalysisOptions& opt) {
  const BlockQP qp = penaltyQP(p);
  const int col = int(qp.A.cols());
  const IpmResult sol = solveBlockQP(qp, opt.solver);

  AnalysisResult r;
  r.status = sol.status;
  r.iterations = sol.iterations;
  r.totalWeight = p.totalWeight;
  r.warnings = p.warnings;
  r.multipliers = sol.multipliers;
  r.solution = sol.x;
  r.gap = sol.gap;
  if (sol.x.size() != col) return r;
  double y = 0;
  for (int v = 0; v < col; v += 4) y += sol.x[v + 1] * sol.x[v + 1];
  r.yNormalised = y;
  r.y = y * p.totalWeight * p.totalWeight;
  r.equilibriumResidual = (qp.A * sol.x + p.w).norm() / p.w.norm();
  r.feasible = (sol.status == SolveStatus::Optimal || sol.status == SolveStatus::ReducedAccuracy) &&
               r.yNormalised <= kFeasibleMeasure;
  const double W = p.totalWeight;
  int v = 0;
  for (const Interface& itf : p.contacts.interfaces) {
    InterfaceForces f;
    f.a = itf.a;
    f.b = itf.b;
    f.normal = itf.normal;
    f.area = itf.area;
    Vec3 moment(0.0);
    for (const Vec3& pt : itf.points) {
      VertexForce vf;
      vf.point = pt;
      vf.compression = sol.x[v] * W;
      vf.tension = sol.x[v + 1] * W;
      vf.t1 = sol.x[v + 2] * W;
      vf.t2 = sol.x[v + 3] * W;
      f.resultant += itf.normal * vf.normal() + itf.t1 * vf.t1 + itf.t2 * vf.t2;
      f.normalForce += vf.normal();
      moment += pt * vf.normal();
      f.maxTension = std::max(f.maxTension, vf.tension);
      f.vertices.push_back(vf);
      v += 4;
    }
    f.tangentialForce = (f.resultant - itf.normal * f.normalForce).norm();
    f.centreOfPressure = f.normalForce > 0 ? moment / f.normalForce : itf.centroid;
    f.pressureGauge =
        f.normalForce > 0 ? pressureGauge(itf, f.centreOfPressure) : std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < f.vertices.size(); ++k)
      if (f.vertices[k].tension > kTensionSite * W)
        r.tensionSites.push_back({int(r.interfaces.size()), int(k), f.vertices[k].point, f.vertices[k].tension});
    r.interfaces.push_back(std::move(f));
  }
  std::stable_sort(r.tensionSites.begin(), r.tensionSites.end(),
                   [](const TensionSite& a, const TensionSite& b) { return a.tension > b.tension; });
  return r;
}

FeasibilityResult checkFeasibility(const Assembly& as, const AnalysisOptions& opt) {
  const EquilibriumSystem p = prepareEquilibrium(as, opt);
  // Variables per contact vertex: [f_n, f_t1, f_t2] with f_n ≥ 0 and |f_t| ≤ α f_n; then two
  // artificial variables (±) per equilibrium row, each costing 1.
  BlockQP qp;
  std::vector<Eigen::Triplet<double>> trips;
  int col = 0;
  for (const Interface& itf : p.contacts.interfaces)
    for (const Vec3& pt : itf.points) {
      addForceColumn(p, itf, pt, itf.normal, col, trips);
      addForceColumn(p, itf, pt, itf.t1, col + 1, trips);
      addForceColumn(p, itf, pt, itf.t2, col + 2, trips);
      VarBlock vb;
      vb.offset = col;
      vb.size = 3;
      vb.rows.reserve(std::size_t(1 + p.frictionSides));
      vb.rows.push_back({1, 0, 0, 0});
      addFrictionRows(vb, p, 0, 1);
      qp.blocks.push_back(vb);
      col += 3;
    }
  for (int r = 0; r < p.rows; ++r)
    for (double sgn : {1.0, -1.0}) {
      trips.emplace_back(r, col, sgn);
      VarBlock vb;
      vb.offset = col;
      vb.size = 1;
      vb.cost = {1, 0, 0, 0};
      vb.rows = {{1, 0, 0, 0}};
      qp.blocks.push_back(vb);
      ++col;
    }
  qp.A.resize(p.rows, col);
  qp.A.setFromTriplets(trips.begin(), trips.end());
  qp.b = -p.w;
  qp.rowGroup = 6;
  const IpmResult sol = solveBlockQP(qp, opt.solver);
  FeasibilityResult r;
  r.status = sol.status;
  r.iterations = sol.iterations;
  r.violation = sol.x.size() == col ? sol.objective : std::numeric_limits<double>::infinity();
  r.feasible = (sol.status == SolveStatus::Optimal || sol.status == SolveStatus::ReducedAccuracy) &&
               r.violation <= kFeasibleViolation;
  return r;
}

}  // namespace corbel::statics
