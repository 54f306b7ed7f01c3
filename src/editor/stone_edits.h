#pragma once
// An extrusion built in stone from the editor (core/stone_walls.h, compose/stone_extrusion.h):
// the masonry section switched on and off, its settings edited by the stone model's parameter
// names, the walls analysed as coursed blocks carrying the roof (Whiting et al. 2009 on a Kelly
// & Wonka extrusion), and Make It Stand's walls written back into the section, so the result
// stays the extrusion the artist keeps editing. Each is a Document change the caller commits as
// one undo step. No GL, no ImGui.
#include "core/document.h"
#include "core/progress.h"
#include "editor/masonry_view.h"
#include "statics/search.h"

#include <optional>
#include <string>

namespace corbel::editor {

// The extrusion `id` with its masonry section on (the defaults of core/stone_walls.h, or what
// it had) or off. Throws InputError when `id` is not an extrusion.
Document setStone(const Document& doc, ObjectId id, bool on);

// One setting of the section by the stone model's parameter name (thickness, courseHeight,
// blockLength, coveringWeight, density, ties, windPressure, windDirection; buttressDepth sizes
// the buttress steps, or adds them: statics::stoneSpecAt). Throws InputError
// naming the setting when the extrusion cannot be built in stone, the name is none of those, or
// the value is outside the model's range (a wall thicker than a third of the shortest wall).
Document setStoneSetting(const Document& doc, ObjectId id, const std::string& name, double value);

// What spans the opening of door or window anchor `anchor` (every instance of a repeat): a
// lintel (the default, kept out of the section's list), a flat or a semicircular arch. Throws
// InputError naming the anchor when the extrusion has no door or window anchor of that name or
// is not built in stone.
Document setOpeningHead(const Document& doc, ObjectId id, const std::string& anchor, OpeningHead head);

// The stone model of the extrusion analysed at its section's values (default friction, no kern
// margin, as `corbel-cli statics --object`): a view with `error` set when it cannot be built.
MasonryView analyseStone(const ExtrusionSpec& spec, Progress* progress = nullptr);

// Make It Stand on the stone model: `free` (by default its suggested free parameters: the wall
// thickness, and the buttresses' depth where it has buttress steps) searched from the section's
// values. Free buttressDepth (from above kMinButtressDepth) to let it add buttresses.
statics::SearchResult searchStone(const ExtrusionSpec& spec, Progress* progress = nullptr, int maxEvaluations = 200,
                                  const std::vector<statics::FreeParameter>* free = nullptr);

// What Make It Stand frees: the model's suggested free parameters and, when `addButtresses`,
// buttressDepth from 0.1 m to the wall height too (on an extrusion without buttresses, so the
// search may add them). Throws InputError when the extrusion cannot be built in stone.
std::vector<statics::FreeParameter> stoneSearchFree(const ExtrusionSpec& spec, bool addButtresses);

// The deepest buttress step's depth (the stone model's buttressDepth), 0 when there is none.
double buttressDepthOf(const ExtrusionSpec& spec);

// The search's result written into extrusion `id` of `doc` (statics::stoneSpecAt: the section
// and the buttress steps), or nullopt
// with the reason: cancelled, nothing standing found, or the extrusion was edited meanwhile
// (its spec is no longer `started`).
std::optional<Document> applyStoneSearch(const Document& doc, ObjectId id, const ExtrusionSpec& started,
                                         const statics::SearchResult& result, std::string* why);

}  // namespace corbel::editor
