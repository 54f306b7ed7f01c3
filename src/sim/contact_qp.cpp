#include "sim/contact_qp.h"

#include "statics/ipm.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace corbel::sim {
namespace {

// One contact point of the step: which bodies (index into the QP's bodies, −1 for a fixed one),
// where on each, its frame and gap.
struct ContactPoint {
  int a = -1, b = -1;
  btVector3 onA, onB;   // world points on A and B
  btVector3 n, t1, t2;  // n from B towards A; the impulse p on A is p_n n + p_t1 t1 + p_t2 t2
  double gap = 0;       // m, negative in overlap
  double slip = 0;      // m/s, |w·t1| + |w·t2| of the relative velocity w at the step's start
};

// The friction axes of a manifold: along an edge of its contact polygon (its points in order
// about their centre), as the statics kernel takes a joint's first edge, so a rectangular joint
// gets the same pyramid in both; any pair of axes for a single point.
void frictionAxes(const btPersistentManifold& m, const btVector3& n, btVector3& t1, btVector3& t2) {
  btPlaneSpace1(n, t1, t2);
  const int k = m.getNumContacts();
  if (k < 2) return;
  btVector3 c(0, 0, 0);
  for (int i = 0; i < k; ++i) c += m.getContactPoint(i).getPositionWorldOnB();
  c /= btScalar(k);
  const btVector3 u = t1, w = t2;
  int first = 0, second = -1;
  double a0 = 10, a1 = 10;  // the two smallest angles about n
  std::vector<double> angle(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) {
    const btVector3 d = m.getContactPoint(i).getPositionWorldOnB() - c;
    angle[std::size_t(i)] = std::atan2(double(d.dot(w)), double(d.dot(u)));
  }
  for (int i = 0; i < k; ++i)
    if (angle[std::size_t(i)] < a0) {
      a0 = angle[std::size_t(i)];
      first = i;
    }
  for (int i = 0; i < k; ++i)
    if (i != first && angle[std::size_t(i)] < a1) {
      a1 = angle[std::size_t(i)];
      second = i;
    }
  btVector3 e = m.getContactPoint(second).getPositionWorldOnB() - m.getContactPoint(first).getPositionWorldOnB();
  e -= n * e.dot(n);
  if (e.length() < 1e-9) return;
  t1 = e.normalized();
  t2 = n.cross(t1);
}

}  // namespace

ContactQpSolver::ContactQpSolver(double friction, double touching) : friction_(friction), touching_(touching) {}

btScalar ContactQpSolver::solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
                                     int numManifolds, btTypedConstraint** constraints, int numConstraints,
                                     const btContactSolverInfo& info, btIDebugDraw* debugDrawer,
                                     btDispatcher* dispatcher) {
  const double h = info.m_timeStep;
  // The moving bodies and their velocities after the step's external forces.
  std::vector<btRigidBody*> moving;
  std::unordered_map<const btCollisionObject*, int> index;
  for (int i = 0; i < numBodies; ++i) {
    btRigidBody* b = btRigidBody::upcast(bodies[i]);
    if (!b || b->getInvMass() == 0) continue;
    index.emplace(b, int(moving.size()));
    moving.push_back(b);
  }
  const int nb = int(moving.size());
  std::vector<btVector3> vStar(static_cast<std::size_t>(nb)), wStar(static_cast<std::size_t>(nb));
  for (int j = 0; j < nb; ++j) {
    const btRigidBody& b = *moving[std::size_t(j)];
    vStar[std::size_t(j)] = b.getLinearVelocity() + b.getTotalForce() * b.getInvMass() * h;
    wStar[std::size_t(j)] = b.getAngularVelocity() + b.getInvInertiaTensorWorld() * b.getTotalTorque() * h;
  }

  std::vector<ContactPoint> contacts;
  for (int m = 0; m < numManifolds; ++m) {
    const btPersistentManifold& man = *manifolds[m];
    if (man.getNumContacts() == 0) continue;
    const auto ia = index.find(man.getBody0()), ib = index.find(man.getBody1());
    const int a = ia == index.end() ? -1 : ia->second, b = ib == index.end() ? -1 : ib->second;
    if (a < 0 && b < 0) continue;
    btVector3 t1, t2;
    const btVector3 n = man.getContactPoint(0).m_normalWorldOnB;
    frictionAxes(man, n, t1, t2);
    for (int k = 0; k < man.getNumContacts(); ++k) {
      const btManifoldPoint& p = man.getContactPoint(k);
      ContactPoint c;
      c.a = a;
      c.b = b;
      c.onA = p.getPositionWorldOnA();
      c.onB = p.getPositionWorldOnB();
      c.n = p.m_normalWorldOnB;
      c.t1 = t1 - c.n * t1.dot(c.n);
      c.t1.normalize();
      c.t2 = c.n.cross(c.t1);
      // Faces within the touching distance touch (the statics kernel's tolerance).
      c.gap = std::abs(double(p.getDistance())) <= touching_ ? 0.0 : double(p.getDistance());
      btVector3 w(0, 0, 0);
      if (a >= 0)
        w += moving[std::size_t(a)]->getVelocityInLocalPoint(c.onA - moving[std::size_t(a)]->getCenterOfMassPosition());
      if (b >= 0)
        w -= moving[std::size_t(b)]->getVelocityInLocalPoint(c.onB - moving[std::size_t(b)]->getCenterOfMassPosition());
      c.slip = std::abs(double(w.dot(c.t1))) + std::abs(double(w.dot(c.t2)));
      contacts.push_back(c);
    }
  }
  if (contacts.empty()) {
    for (int j = 0; j < nb; ++j) {
      moving[std::size_t(j)]->setLinearVelocity(vStar[std::size_t(j)]);
      moving[std::size_t(j)]->setAngularVelocity(wStar[std::size_t(j)]);
    }
    return 0;
  }

  // Scales, so the QP's numbers are O(1) whatever the model's size: mass m0 (the mean body),
  // length L0 (the mean radius of gyration), speed u (the fastest point, at least the speed
  // gravity adds in one step).
  double m0 = 0, l0 = 0, u = 9.81 * h;
  for (int j = 0; j < nb; ++j) {
    const btRigidBody& b = *moving[std::size_t(j)];
    const double mass = 1.0 / b.getInvMass();
    const btVector3 inertia = b.getLocalInertia();
    m0 += mass;
    l0 += std::sqrt((inertia.x() + inertia.y() + inertia.z()) / (3 * mass));
  }
  m0 /= nb;
  l0 /= nb;
  for (int j = 0; j < nb; ++j)
    u = std::max({u, double(vStar[std::size_t(j)].length()), double(wStar[std::size_t(j)].length()) * l0});

  // Variables: per body its velocity (3, world axes) and angular velocity (3, the body's
  // principal axes, so M is diagonal); per contact point (p_n, p_t1, p_t2), or p_n alone without
  // friction. Equations: per body M v − Jᵀ p = M v*, 6 rows.
  const bool rubs = friction_ > 0;
  const int perContact = rubs ? 3 : 1;
  statics::BlockQP qp;
  qp.rowGroup = 6;
  const int nv = 6 * nb + perContact * int(contacts.size());
  qp.b = Eigen::VectorXd::Zero(6 * nb);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(6 * nb) + contacts.size() * std::size_t(perContact) * 12);
  std::vector<btMatrix3x3> basis(static_cast<std::size_t>(nb));
  for (int j = 0; j < nb; ++j) {
    const btRigidBody& b = *moving[std::size_t(j)];
    basis[std::size_t(j)] = b.getCenterOfMassTransform().getBasis();
    const double mass = 1.0 / b.getInvMass() / m0;
    const btVector3 inertia = b.getLocalInertia() / (m0 * l0 * l0);
    const btVector3 wBody = basis[std::size_t(j)].transpose() * wStar[std::size_t(j)] * (l0 / u);
    statics::VarBlock lin, ang;
    lin.offset = 6 * j;
    ang.offset = 6 * j + 3;
    lin.size = ang.size = 3;
    for (int k = 0; k < 3; ++k) {
      lin.hessian[std::size_t(k)] = mass;
      ang.hessian[std::size_t(k)] = inertia[k];
      entries.emplace_back(6 * j + k, 6 * j + k, mass);
      entries.emplace_back(6 * j + 3 + k, 6 * j + 3 + k, inertia[k]);
      qp.b[6 * j + k] = mass * vStar[std::size_t(j)][k] / u;
      qp.b[6 * j + 3 + k] = inertia[k] * wBody[k];
    }
    qp.blocks.push_back(lin);
    qp.blocks.push_back(ang);
  }
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const ContactPoint& cp = contacts[c];
    const int offset = 6 * nb + perContact * int(c);
    statics::VarBlock blk;
    blk.offset = offset;
    blk.size = perContact;
    const double phi = cp.gap >= 0 ? cp.gap : kOverlapRecovery * cp.gap;
    // The relaxation lets a sliding contact part at α times its slip speed (the dual cone asks
    // v_n + φ/h ≥ α(|v_t1| + |v_t2|)); the slip it had at the step's start is added back, so a
    // block sliding at a steady speed keeps its contact instead of lifting off by α·|v_t|·h a
    // step. A contact at rest has no slip, and its law is untouched.
    blk.cost[0] = (phi / h + (rubs ? friction_ * cp.slip : 0.0)) / u;
    blk.interiorDirection[0] = 1;
    if (rubs) {
      blk.rows = {{friction_, -1, 0, 0}, {friction_, 1, 0, 0}, {friction_, 0, -1, 0}, {friction_, 0, 1, 0}};
    } else {
      blk.rows = {{1, 0, 0, 0}};
    }
    qp.blocks.push_back(blk);
    const btVector3 dirs[3] = {cp.n, cp.t1, cp.t2};
    auto couple = [&](int body, const btVector3& at, double side) {
      if (body < 0) return;
      const btRigidBody& b = *moving[std::size_t(body)];
      const btVector3 r = (at - b.getCenterOfMassPosition()) / l0;
      for (int d = 0; d < perContact; ++d) {
        const btVector3 torque = basis[std::size_t(body)].transpose() * r.cross(dirs[d]);
        for (int k = 0; k < 3; ++k) {
          if (dirs[d][k] != 0) entries.emplace_back(6 * body + k, offset + d, -side * dirs[d][k]);
          if (torque[k] != 0) entries.emplace_back(6 * body + 3 + k, offset + d, -side * torque[k]);
        }
      }
    };
    couple(cp.a, cp.onA, 1.0);
    couple(cp.b, cp.onB, -1.0);
  }
  qp.A.resize(6 * nb, nv);
  qp.A.setFromTriplets(entries.begin(), entries.end());

  statics::IpmOptions options;
  options.objectiveExitBelow = 0;      // the objective is not the statics penalty's
  options.feasibilityCorrections = 0;  // nor are its blocks tension and compression
  const statics::IpmResult r = statics::solveBlockQP(qp, options);
  iterations_ += r.iterations;
  // Where the method stops short of its tolerances (its factorisation fails near the optimum),
  // its best iterate is taken when the momentum equations hold and the optimality gap is small:
  // at rest to 1e-7 (in units of the step's kinetic energy at speed u), and while bodies move
  // faster than ten steps of gravity to 1e-6 of the objective, with a dual residual of 1e-3 (the
  // velocities then err by at most √(2 gap) in the mass-weighted norm: about a hundredth of u in
  // a collapse, where the steps that need this come). Fewer steps fall back to Bullet's solver:
  // 3 instead of 59 of the 144 after the paper's shake on the barrel vault.
  const bool fast = u > 10 * 9.81 * h;
  const bool nearlyOptimal =
      r.primalResidual <= 1e-9 && (fast ? r.dualResidual <= 1e-3 && r.gap <= 1e-6 * std::max(1.0, std::abs(r.objective))
                                        : r.dualResidual <= 1e-7 && r.gap <= 1e-7);
  const bool solved = r.x.allFinite() && (r.status == statics::SolveStatus::Optimal ||
                                          r.status == statics::SolveStatus::ReducedAccuracy || nearlyOptimal);
  if (!solved) {
    ++failures_;
    return fallback_.solveGroup(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info,
                                debugDrawer, dispatcher);
  }
  for (int j = 0; j < nb; ++j) {
    btRigidBody& b = *moving[std::size_t(j)];
    const btVector3 v(r.x[6 * j], r.x[6 * j + 1], r.x[6 * j + 2]);
    const btVector3 w(r.x[6 * j + 3], r.x[6 * j + 4], r.x[6 * j + 5]);
    b.setLinearVelocity(v * u);
    b.setAngularVelocity(basis[std::size_t(j)] * w * (u / l0));
  }
  return 0;
}

}  // namespace corbel::sim
