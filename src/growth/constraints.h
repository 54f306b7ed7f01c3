#pragma once
// The constraint enforcer (Ch. 4.1): only moves it passes are committed.
//
// Constraints on every unit, after every committed move:
// - site: inside the envelope, on storey levels;
// - structural: a plan gap of at least the site's clearance from cores and circulation
//   (measured L∞ in plan, where the vertical extents overlap);
// - no overlap with other units (nor between a unit's own parts);
// - shape: parts at least 3 m × 3 m, one or two storeys high, a unit spanning at most two
//   storeys (double volume, Sec. 5.3), at most kMaxParts parts;
// - physical plausibility: every point of the unit's plan lies within the site's cantilever
//   limit (L∞) of its supports. Supports are the ground, the tops of other units' parts and
//   of circulation under a part's floor, and the sides of cores and circulation the unit is
//   fixed to (a part at most its clearance away from one, over a shared storey).
//
// Advances that would run into an obstacle are trimmed to stop at it (when at least
// kMinAdvance remains): the collide behaviour of Sec. 5.3 in its straightforward form.
// A stair base (Fig. 5.4, Move::StairBase) is the whole top of a staircase or nothing: the
// part of growth/collide.h's stairBasePart, refused when anything stands on any of it.
#include "growth/collide.h"
#include "growth/plan_grid.h"
#include "growth/site.h"
#include "growth/unit.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::growth {

// The cores and the circulation grown by their clearances: where no unit may be.
std::vector<Box> clearanceZones(const Site& site);

struct Verdict {
  bool ok = false;
  Move move;           // the move to commit (an advance may be trimmed)
  std::string reason;  // why not, when !ok
};

class ConstraintEnforcer {
 public:
  explicit ConstraintEnforcer(const Site& site);

  Verdict check(const std::vector<Unit>& units, std::size_t unit, const Move& m) const;
  // Look-ahead clearance query (Sec. 5.3): how far side s of the part can advance, up to
  // `limit`, before it meets the envelope, a clearance zone, or any unit.
  double freeDistance(const std::vector<Unit>& units, std::size_t unit, int part, Side s, double limit) const;
  // Look-ahead with the conservative estimate of Sec. 5.3: the free distance if every other
  // unit marked in `growing` had already advanced every side of its parts by `reach` in plan
  // (what it can take within reach / α steps).
  double lookAhead(const std::vector<Unit>& units, std::size_t unit, int part, Side s, double limit, double reach,
                   const std::vector<bool>& growing) const;
  // The look-ahead of a face that is not yet a part's: side s of box `from` (the face of a part
  // about to be added to units[unit]; every part of the unit counts as an obstacle).
  double lookAheadFrom(const std::vector<Unit>& units, std::size_t unit, const Box& from, Side s, double limit,
                       double reach, const std::vector<bool>& growing) const;
  // Collide (Sec. 5.3): side s of the part in its plane (u along the face, v = z) and the
  // footprints on that plane of every obstacle (envelope excluded: clearance zones and parts)
  // that lies in front of it closer than `distance` (growth/collide.h).
  FaceObstacles obstaclesAhead(const std::vector<Unit>& units, std::size_t unit, int part, Side s,
                               double distance) const;
  // Physical plausibility of one unit among the others.
  bool plausible(const std::vector<Unit>& units, std::size_t unit) const;
  // Every constraint above over a whole configuration; one sentence per violation.
  std::vector<std::string> violations(const std::vector<Unit>& units) const;

  const Site& site() const { return site_; }

  // The circulation boxes (indices, ascending) whose plans may meet r: all that do, maybe more.
  void circulationNear(const Rect& r, std::vector<std::size_t>& out) const;

  // Answers the queries on `units` from a plan grid instead of a scan of every part (the same
  // answers, in the same order: growth/plan_grid.h). `units` is the caller's own vector, which
  // must outlive the enforcer or be released by index of another; after changing units[i] the
  // caller calls reindex(i). Queries on any other vector scan it as before.
  void index(const std::vector<Unit>& units);
  void reindex(std::size_t unit);

 private:
  bool indexed(const std::vector<Unit>& units) const { return indexed_.units == &units; }
  // Keys of the parts (unit << 8 | part, ascending) and of the zones whose plans may meet r.
  void nearParts(const Rect& r, std::vector<std::uint64_t>& out) const { parts_.query(r, out); }
  void nearZones(const Rect& r, std::vector<std::uint64_t>& out) const { zoneGrid_.query(r, out); }
  // Plausibility of `u` standing in for units[unit].
  bool plausibleAs(const std::vector<Unit>& units, std::size_t unit, const Unit& u) const;
  // From side s of box b, skipping part `skip` of units[unit] (−1: none).
  double distanceAhead(const std::vector<Unit>& units, std::size_t unit, const Box& b, int skip, Side s, double limit,
                       double reach, const std::vector<bool>* growing) const;
  Verdict checkStairBase(const std::vector<Unit>& units, std::size_t unit, const Move& m) const;
  const Site& site_;
  std::vector<Box> zones_;  // cores and circulation grown by their clearances
  PlanGrid zoneGrid_;       // zones_ by index
  // The vector the grid mirrors; a copy of the enforcer does not inherit it (the copy's grid
  // would fall behind as the original's owner moves units), so a copy scans.
  struct IndexedUnits {
    const std::vector<Unit>* units = nullptr;
    IndexedUnits() = default;
    IndexedUnits(const IndexedUnits&) {}
    IndexedUnits& operator=(const IndexedUnits&) {
      units = nullptr;
      return *this;
    }
  };
  IndexedUnits indexed_;
  PlanGrid parts_;                  // the parts of *indexed_
  std::vector<int> indexedParts_;  // per unit, how many of its parts parts_ holds
};

}  // namespace corbel::growth
