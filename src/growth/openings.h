#pragma once
// Doors and windows on grown units: the extrusion kernel's feature meshes (extrude/features.h,
// Kelly & Wonka Fig. 28) placed on the units' faces.
//  - A door at each unit's entrance: where a part on the unit's lowest storey meets circulation
//    (a landing, a corridor) along at least the door's width; the door stands in the middle of
//    the longest such contact, at the storey's floor, facing the circulation.
//  - Windows on the free stretches of the faces that have a view: per part side and storey, the
//    stretches of the side that nothing (another part of any unit, a core, circulation) touches
//    over the whole storey; a stretch whose seen area in the view maps (cells showing the unit at
//    the stretch's depth) is positive gets floor(length / spacing) windows, evenly spread
//    (centred in equal shares of the stretch), their sills `sill` above the storey's floor.
#include "core/extrusion_spec.h"
#include "core/mesh_data.h"
#include "growth/site.h"
#include "growth/unit.h"
#include "growth/view_map.h"

#include <vector>

namespace corbel::growth {

struct Opening {
  FeatureKind kind = FeatureKind::None;  // Door or Window
  int unit = 0;                          // Unit::id
  Side side = Side::PosX;                // the face's outward normal
  Vec3 position{0.0};                    // bottom centre on the face
  FeatureSize size;
};

// Openings of a grown model on the given view maps (those the model grew on, or any mapper's).
std::vector<Opening> placeOpenings(const Site& site, const std::vector<Unit>& units, const ViewMaps& views,
                                   const OpeningSettings& settings);
// The same on exact view maps of the model (growth/view_map.h's ExactViewMapper).
std::vector<Opening> placeOpenings(const Site& site, const std::vector<Unit>& units, const OpeningSettings& settings);

// The view (m²) of a stretch of a face: side `side` of a box at coordinate `at`, over plan range
// [u0, u1] along the other horizontal axis and heights [z0, z1]: the cells of the view map
// facing that way that show unit `id` at that depth.
double stretchView(const ViewMaps& views, std::uint32_t id, Side side, double at, double u0, double u1, double z0,
                   double z1);

// The feature meshes of the openings (tags "door" and "window", the features' own materials).
MeshData openingsMesh(const std::vector<Opening>& openings);

}  // namespace corbel::growth
