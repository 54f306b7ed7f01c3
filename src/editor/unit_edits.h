#pragma once
// Unit objects edited by hand (core/unit_spec.h; Ng Sec. 5.1 and 5.3, Fig. 8.4): a wall pushed
// or pulled with collide-and-extrude (growth/collide.h) against what stands around it, a unit
// split in two by a plane, two touching units merged. Pure functions on the Document, so each is
// one undo step and a script replays it exactly; each throws InputError saying why it cannot be
// done, and then nothing changes.
#include "core/document.h"
#include "core/geometry.h"
#include "growth/box.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::editor {

// A unit's rooms are at least this wide (Sec. 5.3: usable sub-units of at least 3 m × 3 m).
inline constexpr double kUnitLeast = 3.0;

// The boxes around unit `id` that a push meets, in its own frame: every other unit object's
// parts and every growth site's cores and circulation. An object turned against the unit by
// other than a quarter turn, or scaled differently, is left out.
std::vector<growth::Box> obstaclesAround(const Document& doc, ObjectId id);

// `doc` with side `side` of part `part` of unit `id` pushed out by `distance` (m; negative pulls
// it in) past what it meets (growth::collideAndExtrude with obstaclesAround). A floor or ceiling
// moves by the whole storeys nearest `distance` (growth::moveFloorOrCeiling): the storeys and
// ground of the Document's growth site (one with around_units first), else the unit's lowest
// part's height over z = 0.
Document pushUnitFace(const Document& doc, ObjectId id, int part, growth::Side side, double distance);

// `doc` with unit `id` cut by the plane `axis` = `at` (axis 0: x, 1: y, in its frame): it keeps
// the parts below the plane, and a new unit object "<name> (split)" with its placement and
// material gets those above. Refused when the plane leaves either side empty.
Document splitUnit(const Document& doc, ObjectId id, int axis, double at, ObjectId* added = nullptr);

// `doc` with unit `b`'s parts added to unit `a` (in a's frame) and `b` removed. Refused unless
// they touch over a face (a shared area, not an edge) and share no volume.
Document mergeUnits(const Document& doc, ObjectId a, ObjectId b);

// The exposed side of a unit's part that a ray (in the unit's frame) meets first: the part, the
// side, the point, and the side's rectangle as four corners (counter-clockwise seen from outside).
struct UnitFace {
  int part = -1;
  growth::Side side = growth::Side::PosX;
  Vec3 hit{0.0};
  double t = 0;
  std::vector<Vec3> outline;
};
std::optional<UnitFace> pickUnitFace(const UnitSpec& unit, const Vec3& origin, const Vec3& direction);

}  // namespace corbel::editor
