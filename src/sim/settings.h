#pragma once
// The collapse simulation's settings and every constant it depends on, with the reason for
// each (Whiting et al. 2009, Sec. 5 "Dynamic simulations"). docs/sim.md has the measurements
// behind the choices.
#include <cstdint>

namespace corbel::sim {

// The fixed step, s: four steps per 1/60 s frame of the paper's shake, so the shake lasts
// exactly four steps. A box resting on the ground settles by 0.02 mm at this step; the creep
// of a standing arch grows with the step (docs/sim.md).
inline constexpr double kTimeStep = 1.0 / 240.0;

// Sequential-impulse iterations per step (Solver::SequentialImpulse). That solver never fully
// converges on a statically indeterminate structure, and what it leaves each step becomes
// creep: an 8-voussoir arch at
// 1.5 times its middle-third thickness moves 1.9 mm in 5 s with 100 iterations and 0.25 mm
// with 200 (with exact contacts 0.73, 0.11 and, at 400, 0.013 mm). Time per step grows about
// linearly with the iterations.
inline constexpr int kSolverIterations = 200;

// Bullet's collision margin, m. Its GJK test rounds every hull by the margin, which would
// lift each stacked block by twice the margin; here the contact points between blocks come
// from clipping the hulls' faces against each other (Bullet's polyhedral clipping, or
// hull_contact.h with SimSettings::exactContacts), which ignores the margin: a box rests
// within 0.03 mm of where it was built (to 1 µm with exact contacts). The margin then pads the
// broad phase's boxes and rounds the blocks against the floor plane, and is kept small for
// thin blocks.
inline constexpr double kCollisionMargin = 0.001;

// The paper's shake: a lateral change of the ground's velocity of 4 m/s within 1/60 s, on a
// model about 10 m wide (Sec. 5).
inline constexpr double kPaperShakeVelocity = 4.0;         // m/s
inline constexpr double kPaperShakeDuration = 1.0 / 60.0;  // s
inline constexpr double kPaperModelWidth = 10.0;           // m

// A block has fallen when its centroid ends farther than this fraction of the block's least
// width (its thinnest extent across any of its faces) from where it was built: half a
// voussoir's thickness out of place, a drum half off its seat.
inline constexpr double kFallenFraction = 0.5;

// How the contact impulses of a step are found.
enum class Solver {
  // A convex QP per step solved to optimality by the statics kernel's interior-point method
  // (contact_qp.h): an assembly the statics analysis calls standing stays still.
  ContactQp,
  // Bullet's sequential-impulse solver, `solverIterations` Gauss–Seidel sweeps a step: faster
  // per step, but on indeterminate vaults what it leaves becomes creep (docs/sim.md).
  SequentialImpulse,
};

struct SimSettings {
  Solver solver = Solver::ContactQp;
  double timeStep = kTimeStep;
  int solverIterations = kSolverIterations;
  // α, the friction coefficient of the statics analysis (MasonrySpec::friction). Bullet
  // multiplies the two bodies' coefficients of a contact, so each body gets √α.
  double friction = 0.7;
  double restitution = 0.0;  // the paper's value (Bullet's default)
  // Bullet's sequential-impulse solver visits constraints in a random order from this seed
  // when `randomOrder` is on; a fixed seed and step give bitwise-equal runs either way.
  std::uint32_t seed = 1;
  bool randomOrder = false;
  // With Bullet's solver: contacts between blocks from the blocks' own faces, clipped whether
  // they overlap or just touch (hull_contact.h), instead of Bullet's: its faces rounded to
  // 1/10216 of each block's extent, clipped only once GJK finds the blocks overlapping. They let
  // a box rest to 1 µm and halve an arch's creep, but on the shipped examples they are no
  // uniform gain for that solver (docs/sim.md), so they are off for it. The contact QP always
  // clips the blocks' own faces (useFaceContacts).
  bool exactContacts = false;
  // An endless floor level with the bottom of the model's fixed blocks (under its ground slab),
  // so a block thrown past the slab's edge lands instead of falling for ever.
  bool floor = true;
  // Density of dropped loads, kg/m³ (stone).
  double loadDensity = 2400.0;
};

}  // namespace corbel::sim
