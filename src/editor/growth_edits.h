#pragma once
// The growth panel's changes to a growth object (core/growth_spec.h): pure functions the panel
// commits, so Step and Run are undoable and a scripted run replays them exactly; and the site
// editor's changes to the site's hand-placed cores, circulation and seeds, each checked as the
// kernel will check it (growth/site.h's validator, then the engine's own refusals) before the
// panel commits it.
#include "core/document.h"
#include "core/growth_spec.h"
#include "growth/kernel.h"
#include "growth/seeding.h"
#include "growth/site.h"

#include <optional>
#include <string>

namespace corbel::editor {

// One step more than `spec` grows, or nullopt when there is none to take: it already grows
// until every unit stops (steps = -1), or its last build said every unit stopped after
// `stoppedAfter` ≤ spec.steps steps (-1: it did not say so).
std::optional<GrowthSpec> nextStep(const GrowthSpec& spec, int stoppedAfter);

// What the site editor edits: entries of the site file's "cores", "circulation" and "seeds"
// lists. Generated seeds (generate_seeds) come after the hand-placed ones in the parsed site
// and are not in the file's list, so they are not editable by hand.
enum class SiteItem { Core, Circulation, Seed };

// The hand-placed entries of a site, as the site file has them (the parsed site's first
// entries of each list: growth/site_json.cpp appends generated seeds after them).
struct HandPlaced {
  std::vector<growth::Rect> cores;
  std::vector<growth::Box> circulation;
  std::vector<growth::Seed> seeds;
};
// How many entries of one kind (SiteItem) the site has by hand.
int itemCount(const HandPlaced& h, SiteItem item);
// Throws InputError for site text that is not a site file (the kernel names the fault).
HandPlaced handPlaced(const std::string& siteText);

// Either the edited spec or why not: the message names the field by its path in the project
// file, as the object's build error would ("growth.site.cores[1]: overlaps cores[0]").
struct SiteEditResult {
  std::optional<GrowthSpec> spec;
  std::string error;
};

// The site's error as its build would report it, or "" when it parses, validates, and the
// engine accepts every seed (a known behaviour, something holding it up).
std::string checkSite(const std::string& siteText);

// `spec` with entry `index` of the list replaced (index = the list's size appends one), its
// other keys ("name") kept; refused, with the validator's message, when the site would be
// invalid. An index past the end is refused too ("cores[7]: no such entry").
SiteEditResult setCore(const GrowthSpec& spec, int index, const growth::Rect& core);
SiteEditResult setCirculation(const GrowthSpec& spec, int index, const growth::Box& box);
// A seed is written with exactly its positive target, its locked sides and its behaviour.
SiteEditResult setSeed(const GrowthSpec& spec, int index, const growth::Seed& seed);
// `spec` without entry `index` of the list.
SiteEditResult removeItem(const GrowthSpec& spec, SiteItem item, int index);

// The site's frame as the Site tab shows it: the envelope's plan (a box is its rectangle, in
// the order growth::rectanglePlan gives), whether the file writes it as a box (origin and size)
// or a polygon, the storeys and their height, and the generate_seeds controls (nullopt: none).
// valid = false when the site does not parse (the build names the fault).
struct SiteFrame {
  bool valid = false;
  std::vector<Vec2> plan;
  bool box = true;
  int storeys = 1;
  double storeyHeight = 3.0;
  std::optional<growth::SeedControls> controls;
  growth::GrowthSettings growth;  // the view behaviour's settings ("growth"), defaults where unset
};
SiteFrame siteFrame(const std::string& siteText);

// The envelope as a box [origin, origin + size] ("envelope": {"origin", "size"}), or as the
// extruded polygon of these corners ("envelope": {"polygon"}); each replaces the other form.
// Refused as setCore is: a non-finite or non-positive value names its field, and a site whose
// cores, circulation or seeds no longer fit gets the validator's message
// ("growth.site.cores[0]: lies outside the site envelope").
SiteEditResult setEnvelopeBox(const GrowthSpec& spec, Vec2 origin, Vec2 size);
SiteEditResult setEnvelopePolygon(const GrowthSpec& spec, const std::vector<Vec2>& corners);
// The envelope's corners edited one at a time (a box becomes the polygon of its four corners,
// in growth::rectanglePlan's order, first): a corner inserted at the middle of edge `edge`
// (from corner edge to edge + 1), corner `corner` removed (a plan keeps 3), corner `corner`
// moved to `to`. Refused as setEnvelopePolygon is, with "envelope.polygon[7]: no such corner"
// for an index out of range and the validator's message for a plan that crosses itself.
SiteEditResult insertEnvelopeCorner(const GrowthSpec& spec, int edge);
SiteEditResult removeEnvelopeCorner(const GrowthSpec& spec, int corner);
SiteEditResult moveEnvelopeCorner(const GrowthSpec& spec, int corner, Vec2 to);
// The plan view's drag of an envelope corner: corner `corner` of `from` (the plan when the drag
// started) moved by (dx, dy) rounded to 0.5 m steps; nullopt when that leaves it where `now`
// has it. The corner nearest (x, y) within `radius`, nullopt for none.
std::optional<SiteEditResult> dragEnvelopeCorner(const GrowthSpec& spec, const std::vector<Vec2>& from,
                                                 const std::vector<Vec2>& now, int corner, double dx, double dy);
std::optional<int> pickEnvelopeCorner(const std::vector<Vec2>& plan, double x, double y, double radius);
// "storeys" (1..1000) and "storey_height" (> 0 m) together.
SiteEditResult setStoreys(const GrowthSpec& spec, int storeys, double storeyHeight);
// "generate_seeds" written with every control (storeys only when some are chosen), or removed
// for nullopt (the site then keeps an empty "seeds" list if it had none); bad controls get
// growth/seeding.h's message ("growth.site.generate_seeds.count: ...").
SiteEditResult setSeedControls(const GrowthSpec& spec, const std::optional<growth::SeedControls>& controls);
// The growth behaviour's settings ("growth": τ, the intrusion penalty, the chances, the
// aspect limit, patience, sub-units; docs/growth.md): the keys that differ from the defaults are
// written, and "growth" is removed when none does. Out-of-range values get the site reader's
// message ("growth.site.growth.tau: ...").
SiteEditResult setGrowthSettings(const GrowthSpec& spec, const growth::GrowthSettings& settings);

// The plan view's drag: entry `index` as `from` has it (the entry when the drag started) moved by
// (dx, dy) rounded to 0.5 m steps, in plan only (circulation and seeds keep their height and
// storey). nullopt when the rounded move is nil or leaves `from`'s entry where `now` has it
// (nothing to commit); else the edit, refused as setCore/setCirculation/setSeed refuse.
std::optional<SiteEditResult> dragItem(const GrowthSpec& spec, const HandPlaced& from, const HandPlaced& now,
                                       SiteItem item, int index, double dx, double dy);
// What a click at (x, y) on the plan of `storey` picks: a seed on that storey, else circulation
// spanning part of it, else a core (the first of each list that holds the point, boundary
// included); nullopt for none.
std::optional<std::pair<SiteItem, int>> pickItem(const HandPlaced& h, const growth::Site& site, int storey, double x,
                                                 double y);

// What a press in the 3D view grabs, for a drag in plan on the horizontal plane at height z
// through the grabbed point `at`: the hand-placed core (its full height), circulation box or
// seed box (on its storey) that the ray (origin, unit dir) enters first, or an envelope corner
// (item nullopt, index the corner) when the ray passes within max(0.3 m, 1.5 % of its distance)
// of the corner's vertical edge before it enters any of those. nullopt for nothing.
struct SiteGrab {
  std::optional<SiteItem> item;  // nullopt: the envelope corner `index`
  int index = -1;
  double z = 0;
  Vec2 at;
};
std::optional<SiteGrab> grabInView(const HandPlaced& h, const growth::Site& site, const Vec3& origin, const Vec3& dir);
// Where the ray meets the plane at height z (in front of the origin), or nullopt (parallel, or
// behind it, or farther than 1e4 m: a grazing ray would throw an entry across the site).
std::optional<Vec2> rayOnPlane(const Vec3& origin, const Vec3& dir, double z);

// Where Add puts a new core of `size` or a new seed: the first place on a 1 m grid over the
// envelope's bounds (rows from the least y, each from the least x; seeds on `storey`) at which
// the site stays valid, or nullopt if there is none.
std::optional<growth::Rect> freeCoreSpot(const growth::Site& site, Vec2 size);
std::optional<growth::Seed> freeSeedSpot(const growth::Site& site, const growth::Seed& like);

// Freeze (the grown units taken over by hand): `doc` with the growth object's grown units (those
// of `grown` grown from its seeds, not the fixed ones) as unit objects, named "<object> unit
// <id>", each with the growth object's placement and its parts in the site's frame, so each
// stands where it grew. The site's seeds become an empty list and generate_seeds goes (they are
// spent), and the growth object grows around unit objects from then on (aroundUnits): it still
// roofs and opens them, and new seeds grow around them. One edit: one undo step. `added` gets
// the new objects' ids. Throws InputError when `id` is no growth object or grew no unit.
Document freezeGrowth(const Document& doc, ObjectId id, const growth::GrownModel& grown,
                      std::vector<ObjectId>* added = nullptr);

}  // namespace corbel::editor
