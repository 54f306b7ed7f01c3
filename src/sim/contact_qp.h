#pragma once
// The contact impulses of one time step as a convex QP, solved to optimality (Anitescu 2006,
// "Optimization-based simulation of nonsmooth rigid multibody dynamics", Math. Program. 105:
// the cone complementarity relaxation of the Stewart–Trinkle time step).
//
// Each step finds the bodies' new velocities v and the contact impulses p from
//
//   min ½ vᵀ M v + Σ_c p_c,n φ_c / h   s.t.  M v − Jᵀ p = M v*,  p_c in its friction pyramid,
//
// with v* the velocities after the external forces (gravity, loads) of the step, J the
// contacts' Jacobians, φ_c a contact's gap (negative in overlap) and h the step. Its optimality
// conditions are the relaxed contact law: a contact's velocity plus φ/h lies in the pyramid's
// dual cone, and only there may it push. The pyramid is the statics kernel's (Whiting et al.
// 2009, Sec. 3.1: |p_t1|, |p_t2| ≤ α p_n along the joint's edges), and the QP has the shape of
// the statics equilibrium QP (6 equations a body, a small block of variables a contact
// vertex), so the statics kernel's interior-point method (statics/ipm.h) solves it. At rest the
// QP's optimum is v = 0 exactly when the contact impulses can hold the weight, i.e. when the
// statics analysis calls the assembly standing: where the QP is solved, what stands stays
// still, with no creep.
//
// Bullet's sequential-impulse solver, the simulation's default, stops after a fixed number of
// Gauss–Seidel sweeps; on statically indeterminate vaults what it leaves every step becomes
// creep (docs/sim.md, "Step and solver" and "The contact QP").
#include <BulletDynamics/ConstraintSolver/btConstraintSolver.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

namespace corbel::sim {

class ContactQpSolver : public btConstraintSolver {
 public:
  // α, the coefficient of friction of every contact (the statics kernel's); `touching`, the
  // distance (m) within which faces touch (statics::lengthTolerance of the model: blocks built
  // to touch may overlap or stand apart by that much).
  ContactQpSolver(double friction, double touching);

  btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
                      btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
                      btIDebugDraw* debugDrawer, btDispatcher* dispatcher) override;
  void reset() override {}
  btConstraintSolverType getSolverType() const override { return BT_SEQUENTIAL_IMPULSE_SOLVER; }

  // Steps whose QP the interior-point method could not solve; each was left to Bullet's
  // sequential-impulse solver (`fallback`) instead (the mosque's flyers, an arch with no kern
  // margin: docs/sim.md).
  long failures() const { return failures_; }
  // Interior-point iterations over all steps so far (for the benchmarks and the docs).
  long iterations() const { return iterations_; }
  // A contact may close its gap φ in one step; an overlap is pushed apart by this fraction of
  // itself a step (Baumgarte stabilisation, as Bullet's ERP).
  static constexpr double kOverlapRecovery = 0.2;

  btSequentialImpulseConstraintSolver& fallback() { return fallback_; }
  double touching() const { return touching_; }

 private:
  double friction_, touching_;
  long failures_ = 0, iterations_ = 0;
  btSequentialImpulseConstraintSolver fallback_;
};

}  // namespace corbel::sim
