#pragma once
// Collapse simulation (Whiting et al. 2009, Sec. 5, Fig. 14): the blocks of a masonry assembly
// as rigid bodies in a Bullet world, stepped at a fixed rate, shaken, robbed of a block or hit
// by a dropped load. A Session owns a copy of the design; nothing it does reaches the
// Document or the statics model it came from, and reset() returns to the design state.
#include "sim/mass_properties.h"
#include "sim/settings.h"
#include "statics/model.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace corbel::sim {

// A rigid motion taking a block from where it was built to where it is now: p ↦ R p + t.
struct Pose {
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // R, row-major
  Vec3 translation{0.0};
  Vec3 apply(const Vec3& p) const;
  bool operator==(const Pose&) const = default;
};

// A load dropped on a block: a stone cube of `mass` released at rest, centred over the
// block's centroid with its base `height` above the block's highest point.
struct DroppedLoad {
  int block = -1;
  double mass = 0;      // kg
  double height = 0;    // m
  statics::Block cube;  // as released, in model coordinates
};

// The paper's shake (4 m/s within 1/60 s on a model about 10 m wide) scaled to `design` by
// Froude similarity: under gravity, velocities and times scale with the square root of the
// size, here the larger horizontal extent w of the blocks that are not fixed, so the velocity
// is 4 m/s · √(w / 10 m) and the duration 1/60 s · √(w / 10 m).
struct ShakeSpec {
  double velocity = 0;  // m/s, along x
  double duration = 0;  // s
};
ShakeSpec paperShake(const statics::Assembly& design);

// The bounding box of the blocks that are not fixed.
BBox movingBounds(const statics::Assembly& design);

class Session {
 public:
  // Checks the assembly (statics::validateAssembly) and builds the world. Throws corbel::Error
  // naming the fault: a bad block, non-positive step, negative friction.
  explicit Session(statics::Assembly design, SimSettings settings = {});
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // The design state: time 0, every block where it was built, at rest, no perturbation. The
  // world is rebuilt from scratch, so a run after reset() equals a run in a new Session.
  void reset();

  // Advances by `steps` fixed steps (settings().timeStep each).
  void step(int steps = 1);
  // Advances by whole steps to the first step boundary at or after `seconds` of simulated time.
  void runUntil(double seconds);

  // Play state for a UI: advance() is what a frame calls with the wall time since the last one;
  // while playing it takes the steps that time covers (at most `maxSteps`, so a slow frame
  // slows the simulation rather than stalling the window) and returns how many it took.
  void play() { playing_ = true; }
  void pause() { playing_ = false; }
  bool playing() const { return playing_; }
  int advance(double wallSeconds, int maxSteps = 32);

  // Perturbations, from the current time on.
  // A ground shake: the ground's velocity changes by `velocityChange` (m/s) uniformly over
  // `duration` (rounded to whole steps, at least one). Simulated in the ground's frame: every
  // body feels the inertial acceleration −velocityChange/duration while the ground
  // accelerates, which is exact for a rigid ground, and positions stay relative to it.
  void shake(const Vec3& velocityChange, double duration = kPaperShakeDuration);
  // Takes a block out of the world (Fig. 14b). Throws for a fixed block, a bad index or a block
  // already removed.
  void removeBlock(int block);
  // Breaks a block (Fig. 14b): the block leaves the world and its two parts either side of a
  // shear crack (split.h: shearCrackNormal, through its centroid) take its place, moving as it
  // moved. Returns the index of the first part in pieces(). Throws like removeBlock.
  int breakBlock(int block);
  // Drops a stone cube of `mass` kg from `height` m above `block` (see DroppedLoad). Returns
  // its index in loads(). Throws for a bad block, non-positive mass or negative height.
  int dropLoad(int block, double mass, double height);

  // The index of the block named `name`; throws corbel::Error naming it and a few known names.
  int blockIndex(const std::string& name) const;

  const statics::Assembly& design() const { return design_; }
  const SimSettings& settings() const { return settings_; }
  // With Solver::ContactQp: the steps since reset whose QP was left to Bullet's solver (see
  // ContactQpSolver::failures) and the interior-point iterations taken; 0 otherwise.
  long qpFailures() const;
  long qpIterations() const;
  const MassProperties& massProperties(int block) const { return mass_[block]; }
  double time() const { return steps_ * settings_.timeStep; }
  long steps() const { return steps_; }

  // Per design block, updated every step: where it is, how far its farthest vertex has moved
  // (now and the most since reset), and whether it was removed or has fallen (its centroid
  // more than kFallenFraction of its least width from where it was built).
  const std::vector<Pose>& poses() const { return poses_; }
  const std::vector<double>& displacement() const { return displacement_; }
  const std::vector<double>& maxDisplacement() const { return maxDisplacement_; }
  bool removed(int block) const { return removed_[block]; }
  bool fallen(int block) const;
  std::vector<int> fallenBlocks() const;

  // The parts of broken blocks, in the block's design coordinates (so a part's pose maps it
  // like its block's), and where they are now.
  struct Piece {
    int block = -1;
    statics::Block shape;
  };
  const std::vector<Piece>& pieces() const { return pieces_; }
  const std::vector<Pose>& piecePoses() const { return piecePoses_; }
  bool broken(int block) const;

  const std::vector<DroppedLoad>& loads() const { return loads_; }
  const std::vector<Pose>& loadPoses() const { return loadPoses_; }

 private:
  struct World;
  void build();
  void applyGravity();
  void applyPointLoads();
  void readPoses();
  void takeOut(int block, const char* what);

  statics::Assembly design_;
  SimSettings settings_;
  std::vector<MassProperties> mass_;
  std::unique_ptr<World> world_;
  long steps_ = 0;
  bool playing_ = false;
  double pendingWall_ = 0;  // wall time advance() has not yet turned into steps
  long shakeUntil_ = 0;     // the shake acts on steps before this one
  Vec3 shakeAcceleration_{0.0};
  std::vector<Pose> poses_, loadPoses_;
  std::vector<double> displacement_, maxDisplacement_;
  std::vector<bool> removed_;
  std::vector<DroppedLoad> loads_;
  std::vector<Piece> pieces_;
  std::vector<Pose> piecePoses_;
  // Extra bodies in world order after the design's: each a load (index into loads_) or a piece.
  struct Extra {
    bool load = true;
    int index = 0;
  };
  std::vector<Extra> extras_;
};

}  // namespace corbel::sim
