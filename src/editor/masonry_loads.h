#pragma once
// Placing loads on a masonry object by clicking its blocks in the 3D view (Whiting et al.
// 2009, Sec. 3.4's point loads: a bell, a statue, people; wind as a pressure on a face). What a
// click makes, as pure functions of the analysed view, so the tests replay exactly what the
// statics panel does; the panel commits the load with addMasonryLoad (masonry_edits.h).
#include "core/masonry_spec.h"
#include "editor/masonry_view.h"

#include <optional>

namespace corbel::editor {

// The first face of a block a ray meets: the block and face (indices as the view and the
// model have them), the point and its distance along the ray (direction need not be unit:
// distance is in its lengths).
struct BlockHit {
  int block = -1;
  int face = -1;
  Vec3 point{0.0};
  double distance = 0;
};
// Fixed blocks (the ground) are skipped when `fixedToo` is false: loads go on what they load.
std::optional<BlockHit> firstBlockHit(const MasonryView& view, const Vec3& origin, const Vec3& direction,
                                      bool fixedToo = false);

enum class LoadKind { Weight, Pressure };

inline constexpr double kGravity = 9.81;             // m/s², as the statics kernel's
inline constexpr double kDefaultLoadMass = 1000.0;   // kg: a tonne, a small bell or a dozen people
// Pa: the dynamic pressure ½ρv² of a 31 m/s gale (ρ = 1.225 kg/m³), about what codes take for a
// low building's facade.
inline constexpr double kDefaultWindPressure = 600.0;

// The load a click at `hit` places: a weight of `amount` kg acting at the clicked point (its
// offset from the block's centre, so it moves with the block), or a pressure of `amount` Pa
// on the clicked face. Unnamed: addMasonryLoad names it.
MasonryLoad loadAt(const MasonryView& view, const BlockHit& hit, LoadKind kind, double amount);

// The mass a vertical point load stands for, kg (its downward force over g); 0 for a pressure.
double loadMass(const MasonryLoad& load);

}  // namespace corbel::editor
