#include "sim/session.h"

#include "core/error.h"
#include "sim/contact_qp.h"
#include "sim/hull_contact.h"
#include "sim/split.h"
#include "statics/tolerances.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace corbel::sim {
namespace {

btVector3 bt(const Vec3& v) { return btVector3(v[0], v[1], v[2]); }
Vec3 vec(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

// The principal frame of a block: origin at its centroid, axes its principal axes.
btTransform principalFrame(const MassProperties& m) {
  const auto& a = m.principalAxes;
  const btMatrix3x3 basis(a[0][0], a[1][0], a[2][0], a[0][1], a[1][1], a[2][1], a[0][2], a[1][2], a[2][2]);
  return btTransform(basis, bt(m.centroid));
}

void checkSettings(const SimSettings& s) {
  if (!(s.timeStep > 0) || !(s.timeStep <= 0.1)) throw Error("simulation: the time step must be in (0, 0.1] s");
  if (s.solverIterations < 1 || s.solverIterations > 10000)
    throw Error("simulation: solver iterations must be in 1..10000");
  if (!(s.friction >= 0) || !std::isfinite(s.friction)) throw Error("simulation: friction must be a finite number ≥ 0");
  if (!(s.restitution >= 0 && s.restitution <= 1)) throw Error("simulation: restitution must be in [0, 1]");
  if (!(s.loadDensity > 0) || !std::isfinite(s.loadDensity))
    throw Error("simulation: the load density must be positive");
}

}  // namespace

Vec3 Pose::apply(const Vec3& p) const {
  const auto& r = rotation;
  return Vec3(r[0] * p[0] + r[1] * p[1] + r[2] * p[2], r[3] * p[0] + r[4] * p[1] + r[5] * p[2],
              r[6] * p[0] + r[7] * p[1] + r[8] * p[2]) +
         translation;
}

BBox movingBounds(const statics::Assembly& design) {
  BBox box;
  for (const statics::Block& b : design.blocks)
    if (!b.fixed)
      for (const Vec3& v : b.vertices) box.add(v);
  return box;
}

ShakeSpec paperShake(const statics::Assembly& design) {
  const BBox box = movingBounds(design);
  const double scale = std::sqrt(std::max(box.size()[0], box.size()[1]) / kPaperModelWidth);
  return {kPaperShakeVelocity * scale, kPaperShakeDuration * scale};
}

// One Bullet world. Rebuilt from scratch by reset(), so no cached contact, warm-start impulse
// or broad-phase pair order survives into a new run.
struct Session::World {
  World(const SimSettings& s, double touching)
      : qp(s.solver == Solver::ContactQp ? std::make_unique<ContactQpSolver>(s.friction, touching) : nullptr),
        solver(qp ? &qp->fallback() : &impulses),
        world(&dispatcher, &broadphase, qp ? static_cast<btConstraintSolver*>(qp.get()) : &impulses, &config) {}
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver impulses;
  std::unique_ptr<ContactQpSolver> qp;          // the solver with Solver::ContactQp
  btSequentialImpulseConstraintSolver* solver;  // Bullet's: the solver, or the QP's fallback
  std::unique_ptr<btCollisionAlgorithmCreateFunc> faceContacts;  // with Solver::ContactQp
  btDiscreteDynamicsWorld world;
  std::vector<std::unique_ptr<btConvexHullShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // per design block, then per load
  std::vector<btTransform> designFrames;             // each body's principal frame as built
  std::vector<Vec3> baseGravity;                     // per body: gravity plus its live load / mass
  std::unique_ptr<btStaticPlaneShape> floorShape;
  std::unique_ptr<btRigidBody> floor;

  ~World() {
    for (auto& b : bodies)
      if (b && b->isInWorld()) world.removeRigidBody(b.get());
    if (floor) world.removeRigidBody(floor.get());
  }

  // A body for a closed convex block: its hull in the principal frame, mass from its volume.
  // `motion` places it: the identity for a block where it was built.
  btRigidBody* add(const statics::Block& block, const MassProperties& m, double density, bool fixed,
                   const SimSettings& s, const btTransform& motion = btTransform::getIdentity()) {
    const btTransform frame = principalFrame(m);
    const btTransform toLocal = frame.inverse();
    auto shape = std::make_unique<btConvexHullShape>();
    std::vector<btVector3> local;
    for (const Vec3& v : block.vertices) local.push_back(toLocal(bt(v)));
    for (const btVector3& v : local) shape->addPoint(v, false);
    shape->recalcLocalAabb();
    shape->setMargin(kCollisionMargin);
    // The faces contact clipping uses: the block's own, or Bullet's rounded rebuild of them.
    if (s.exactContacts || s.solver == Solver::ContactQp)
      setExactFaces(*shape, local, block.faces);
    else
      shape->initializePolyhedralFeatures();
    const double mass = fixed ? 0.0 : density * m.volume;
    const btVector3 inertia = fixed ? btVector3(0, 0, 0) : bt(m.principalMoments * density);
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
    info.m_startWorldTransform = motion * frame;
    info.m_friction = std::sqrt(s.friction);  // Bullet multiplies the two coefficients
    info.m_restitution = s.restitution;
    info.m_linearDamping = info.m_angularDamping = 0;
    auto body = std::make_unique<btRigidBody>(info);
    if (!fixed) {
      body->setFlags(body->getFlags() | BT_DISABLE_WORLD_GRAVITY);
      // Never put to sleep: Bullet's sleeping thresholds (0.8 m/s, 1 rad/s held for 2 s) would
      // freeze a slow collapse, and smaller ones (1 cm/s) never trigger on a standing arch,
      // whose blocks jitter faster than they creep.
      body->setActivationState(DISABLE_DEACTIVATION);
    }
    world.addRigidBody(body.get());
    shapes.push_back(std::move(shape));
    bodies.push_back(std::move(body));
    designFrames.push_back(frame);
    return bodies.back().get();
  }
};

Session::Session(statics::Assembly design, SimSettings settings) : design_(std::move(design)), settings_(settings) {
  checkSettings(settings_);
  BBox box;
  for (const statics::Block& b : design_.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  const auto props = statics::validateAssembly(design_, statics::lengthTolerance(box));
  // Bullet's bodies here are convex hulls: a non-convex block would be simulated as something
  // else, so refuse it. Point loads act where they are (applyPointLoads).
  for (std::size_t i = 0; i < design_.blocks.size(); ++i) {
    const statics::Block& b = design_.blocks[i];
    const std::string who = "block " + std::to_string(i) + (b.name.empty() ? "" : " \"" + b.name + "\"");
    if (!props[i].convex) throw Error("simulate: " + who + " is not convex; the simulation takes convex blocks only");
  }
  for (const statics::Block& b : design_.blocks) mass_.push_back(sim::massProperties(b));
  reset();
}

Session::~Session() = default;

void Session::reset() {
  world_.reset();
  steps_ = 0;
  pendingWall_ = 0;
  shakeUntil_ = 0;
  shakeAcceleration_ = Vec3(0.0);
  loads_.clear();
  loadPoses_.clear();
  pieces_.clear();
  piecePoses_.clear();
  extras_.clear();
  const std::size_t n = design_.blocks.size();
  poses_.assign(n, Pose{});
  displacement_.assign(n, 0.0);
  maxDisplacement_.assign(n, 0.0);
  removed_.assign(n, false);
  build();
}

void Session::build() {
  BBox box;
  for (const statics::Block& b : design_.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  world_ = std::make_unique<World>(settings_, statics::lengthTolerance(box));
  World& w = *world_;
  if (settings_.solver == Solver::ContactQp)
    w.faceContacts = useFaceContacts(w.dispatcher, w.qp->touching());
  else if (settings_.exactContacts)
    useClippedHullContacts(w.dispatcher);
  w.world.getDispatchInfo().m_deterministicOverlappingPairs = true;
  btContactSolverInfo& info = w.world.getSolverInfo();
  info.m_numIterations = settings_.solverIterations;
  // Two friction directions per contact, fixed by the contact normal rather than by the
  // sliding velocity: Bullet's default gives one, along the velocity, so a contact at rest
  // resists sliding in one arbitrary direction only and an arch's feet creep outwards.
  info.m_solverMode = SOLVER_USE_WARMSTARTING | SOLVER_SIMD | SOLVER_USE_2_FRICTION_DIRECTIONS |
                      SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION;
  if (settings_.randomOrder) info.m_solverMode |= SOLVER_RANDMIZE_ORDER;
  w.solver->setRandSeed(settings_.seed);
  const Vec3 g = design_.gravity * design_.g;
  for (std::size_t i = 0; i < design_.blocks.size(); ++i) {
    const statics::Block& b = design_.blocks[i];
    w.add(b, mass_[i], b.density, b.fixed, settings_);
    w.baseGravity.push_back(b.fixed ? Vec3(0.0) : g + b.liveLoad / (b.density * mass_[i].volume));
  }
  if (settings_.floor) {
    // An endless plane across gravity, level with the bottom of the fixed blocks (the model's
    // ground slab, which then stands on it like a plinth; the bottom of everything when nothing
    // is fixed), so what is thrown off the slab comes to rest. Not level with the slab's top:
    // a block on the slab would then touch both, and Bullet's friction from two coincident
    // supports exceeds what one gives (a shaken box slid 4 % short).
    const Vec3 up = -design_.gravity / design_.gravity.norm();
    bool anyFixed = false;
    for (const statics::Block& b : design_.blocks) anyFixed = anyFixed || b.fixed;
    double level = std::numeric_limits<double>::infinity();
    for (const statics::Block& b : design_.blocks)
      if (b.fixed || !anyFixed)
        for (const Vec3& v : b.vertices) level = std::min(level, dot(v, up));
    // Convex-against-plane contacts, unlike hull-against-hull ones, keep the hull's margin: the
    // plane lies a margin lower, so a block on it rests at the floor's level.
    w.floorShape = std::make_unique<btStaticPlaneShape>(bt(up), level - kCollisionMargin);
    btRigidBody::btRigidBodyConstructionInfo floorInfo(0.0, nullptr, w.floorShape.get());
    floorInfo.m_friction = std::sqrt(settings_.friction);
    floorInfo.m_restitution = settings_.restitution;
    w.floor = std::make_unique<btRigidBody>(floorInfo);
    w.world.addRigidBody(w.floor.get());
  }
  applyGravity();
}

long Session::qpFailures() const { return world_->qp ? world_->qp->failures() : 0; }
long Session::qpIterations() const { return world_->qp ? world_->qp->iterations() : 0; }

void Session::applyGravity() {
  const bool shaking = steps_ < shakeUntil_;
  for (std::size_t i = 0; i < world_->bodies.size(); ++i) {
    btRigidBody* b = world_->bodies[i].get();
    if (b->isStaticObject()) continue;
    b->setGravity(bt(world_->baseGravity[i] + (shaking ? shakeAcceleration_ : Vec3(0.0))));
  }
}

void Session::applyPointLoads() {
  // A point load is a fixed force in the world at a point of the block: the point moves with the
  // block, the force keeps its direction (a roof's weight and thrust). Its force is applied
  // before every step (Bullet clears applied forces after each), its torque about the centroid
  // goes straight into the angular velocity (semi-implicit Euler, as Bullet integrates an applied
  // torque): Bullet's friction rows leave out the velocity an applied torque adds within the
  // step, so a cube held by friction under a steady torque slid against the push, at a speed
  // proportional to the step (27.6 mm/s at 1/240 s for a unit cube pushed at 0.9 of its
  // tipping force; docs/sim.md).
  for (std::size_t i = 0; i < design_.blocks.size(); ++i) {
    const statics::Block& b = design_.blocks[i];
    if (b.fixed || removed_[i] || b.pointLoads.empty()) continue;
    btRigidBody* body = world_->bodies[i].get();
    const btTransform motion = body->getWorldTransform() * world_->designFrames[i].inverse();
    btVector3 torque(0, 0, 0);
    for (const statics::PointLoad& l : b.pointLoads) {
      body->applyCentralForce(bt(l.force));
      torque += (motion * bt(l.at) - body->getCenterOfMassPosition()).cross(bt(l.force));
    }
    // The contact QP takes the torque with the step's other loads (its friction sees it), and
    // the velocity a step starts with must be the last step's: it is the slip it compensates.
    if (settings_.solver == Solver::ContactQp)
      body->applyTorque(torque);
    else
      body->setAngularVelocity(body->getAngularVelocity() +
                               body->getInvInertiaTensorWorld() * torque * settings_.timeStep);
  }
}

void Session::step(int steps) {
  for (int k = 0; k < steps; ++k) {
    applyGravity();
    applyPointLoads();
    // maxSubSteps = 0: exactly one internal step of the given length, no interpolation.
    world_->world.stepSimulation(settings_.timeStep, 0, settings_.timeStep);
    ++steps_;
    readPoses();
  }
}

void Session::runUntil(double seconds) {
  if (!std::isfinite(seconds)) throw Error("simulation: the end time must be finite");
  const long target = long(std::ceil(seconds / settings_.timeStep - 1e-9));
  if (target > steps_) step(int(target - steps_));
}

int Session::advance(double wallSeconds, int maxSteps) {
  if (!playing_ || !(wallSeconds > 0)) return 0;
  pendingWall_ += wallSeconds;
  int n = int(std::floor(pendingWall_ / settings_.timeStep));
  if (n > maxSteps) {
    n = maxSteps;
    pendingWall_ = 0;  // drop the backlog rather than catch up
  } else {
    pendingWall_ -= n * settings_.timeStep;
  }
  step(n);
  return n;
}

void Session::readPoses() {
  auto poseOf = [](const btRigidBody& body, const btTransform& designFrame) {
    // current = T_now · T_design⁻¹ applied to a design point.
    const btTransform motion = body.getWorldTransform() * designFrame.inverse();
    Pose p;
    const btMatrix3x3& r = motion.getBasis();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) p.rotation[3 * i + j] = r[i][j];
    p.translation = vec(motion.getOrigin());
    return p;
  };
  for (std::size_t i = 0; i < design_.blocks.size(); ++i) {
    if (removed_[i] || design_.blocks[i].fixed) continue;
    poses_[i] = poseOf(*world_->bodies[i], world_->designFrames[i]);
    double d = 0;
    for (const Vec3& v : design_.blocks[i].vertices) d = std::max(d, (poses_[i].apply(v) - v).norm());
    displacement_[i] = d;
    maxDisplacement_[i] = std::max(maxDisplacement_[i], d);
  }
  for (std::size_t k = 0; k < extras_.size(); ++k) {
    const std::size_t body = design_.blocks.size() + k;
    (extras_[k].load ? loadPoses_ : piecePoses_)[extras_[k].index] =
        poseOf(*world_->bodies[body], world_->designFrames[body]);
  }
}

void Session::shake(const Vec3& velocityChange, double duration) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(velocityChange[i])) throw Error("shake: the velocity change must be finite");
  if (!(duration > 0) || !std::isfinite(duration)) throw Error("shake: the duration must be positive");
  const long n = std::max(1L, std::lround(duration / settings_.timeStep));
  // The ground gains velocityChange over n steps; in its frame every body is pushed the other way.
  shakeAcceleration_ = -velocityChange / (double(n) * settings_.timeStep);
  shakeUntil_ = steps_ + n;
}

void Session::removeBlock(int block) { takeOut(block, "remove"); }

void Session::takeOut(int block, const char* what) {
  const std::string w = what;
  if (block < 0 || block >= int(design_.blocks.size())) throw Error(w + ": no block " + std::to_string(block));
  const statics::Block& b = design_.blocks[block];
  if (b.fixed) throw Error(w + ": block \"" + b.name + "\" is fixed (ground or abutment) and stays");
  if (removed_[block]) throw Error(w + ": block \"" + b.name + "\" was already removed or broken");
  world_->world.removeRigidBody(world_->bodies[block].get());
  removed_[block] = true;
}

int Session::breakBlock(int block) {
  if (block >= 0 && block < int(design_.blocks.size()) && !design_.blocks[block].fixed && !removed_[block]) {
    const statics::Block& b = design_.blocks[block];
    const std::array<statics::Block, 2> parts = splitBlock(b, mass_[block].centroid, shearCrackNormal(b));
    const btRigidBody& whole = *world_->bodies[block];
    const btTransform motion = whole.getWorldTransform() * world_->designFrames[block].inverse();
    const btVector3 v = whole.getLinearVelocity(), w = whole.getAngularVelocity();
    takeOut(block, "break");
    const int first = int(pieces_.size());
    for (const statics::Block& p : parts) {
      const MassProperties m = sim::massProperties(p);
      btRigidBody* body = world_->add(p, m, p.density, false, settings_, motion);
      // Each part keeps the velocity its material had: v + ω × (its centroid − the block's).
      body->setLinearVelocity(v + w.cross(body->getCenterOfMassPosition() - whole.getCenterOfMassPosition()));
      body->setAngularVelocity(w);
      world_->baseGravity.push_back(world_->baseGravity[block]);
      extras_.push_back({false, int(pieces_.size())});
      pieces_.push_back({block, p});
      piecePoses_.push_back(poses_[block]);
    }
    applyGravity();
    return first;
  }
  takeOut(block, "break");  // says what is wrong
  return -1;
}

bool Session::broken(int block) const {
  for (const Piece& p : pieces_)
    if (p.block == block) return true;
  return false;
}

int Session::dropLoad(int block, double mass, double height) {
  if (block < 0 || block >= int(design_.blocks.size())) throw Error("drop: no block " + std::to_string(block));
  const statics::Block& target = design_.blocks[block];
  if (removed_[block]) throw Error("drop: block \"" + target.name + "\" was removed");
  if (!(mass > 0) || !std::isfinite(mass)) throw Error("drop: the load's mass must be a positive number of kg");
  if (!(height >= 0) || !std::isfinite(height)) throw Error("drop: the drop height must be a finite number ≥ 0 m");
  // "Above" is against gravity; the cube's base is `height` over the block's highest point now.
  const Vec3 up = -design_.gravity / design_.gravity.norm();
  const Pose& now = poses_[block];
  const Vec3 centre = now.apply(mass_[block].centroid);
  double top = 0;
  for (const Vec3& v : target.vertices) top = std::max(top, dot(now.apply(v) - centre, up));
  const double side = std::cbrt(mass / settings_.loadDensity);
  const Vec3 at = centre + up * (top + height + side / 2);
  DroppedLoad load;
  load.block = block;
  load.mass = mass;
  load.height = height;
  load.cube = statics::boxBlock("load " + std::to_string(loads_.size() + 1), at - Vec3(side / 2), at + Vec3(side / 2),
                                settings_.loadDensity);
  const MassProperties m = sim::massProperties(load.cube);
  world_->add(load.cube, m, settings_.loadDensity, false, settings_);
  world_->baseGravity.push_back(design_.gravity * design_.g);
  applyGravity();
  extras_.push_back({true, int(loads_.size())});
  loads_.push_back(std::move(load));
  loadPoses_.push_back(Pose{});
  return int(loads_.size()) - 1;
}

int Session::blockIndex(const std::string& name) const {
  for (std::size_t i = 0; i < design_.blocks.size(); ++i)
    if (design_.blocks[i].name == name) return int(i);
  std::string some;
  const std::size_t shown = std::min<std::size_t>(design_.blocks.size(), 5);
  for (std::size_t i = 0; i < shown; ++i) some += (i ? ", \"" : "\"") + design_.blocks[i].name + "\"";
  throw Error("no block named \"" + name + "\" (blocks: " + some +
              (design_.blocks.size() > shown ? ", … " + std::to_string(design_.blocks.size()) + " in all" : "") + ")");
}

bool Session::fallen(int block) const {
  if (removed_[block] || design_.blocks[block].fixed) return false;
  const Vec3& c = mass_[block].centroid;
  return (poses_[block].apply(c) - c).norm() > kFallenFraction * mass_[block].leastWidth;
}

std::vector<int> Session::fallenBlocks() const {
  std::vector<int> out;
  for (int i = 0; i < int(design_.blocks.size()); ++i)
    if (fallen(i)) out.push_back(i);
  return out;
}

}  // namespace corbel::sim
