#pragma once
// Roofs over grown units, by the extrusion kernel (Kelly & Wonka, src/extrude). The exposed top
// at one height (the tops of the units' parts there, less whatever stands on them) falls into
// connected regions; each becomes one extrusion with the site's roof profile (growth/site.h's
// RoofSettings), so neighbouring units of equal height share one roof.
#include "core/extrusion_spec.h"
#include "core/mesh_data.h"
#include "growth/site.h"
#include "growth/unit.h"

#include <string>
#include <vector>

namespace corbel::growth {

// One connected region of exposed top at height z: loops[0] the outer loop (counter-clockwise),
// then its holes (clockwise), without collinear corners.
struct RoofRegion {
  double z = 0;
  std::vector<std::vector<Vec2>> loops;
  double area() const;  // outer less holes
};

// The exposed tops: per height, the union of the tops of the parts ending there less the
// footprints of the boxes (units' parts, cores, circulation) standing on or passing that
// height, by CGAL's Boolean set operations on exact coordinates (snapped to the micrometre, so
// tops that meet within the growth tolerance join). A region whose boundary touches itself at a
// corner (lobes, or a hole and the outside, meeting at a point) is cut along x through that
// corner into regions with simple loops. Ordered by height, then by position.
std::vector<RoofRegion> exposedTops(const Site& site, const std::vector<Unit>& units);

// The extrusion of a region with the roof settings, based at the region's height:
//  flat: walls rise slab + parapet; at the slab's height a profile offset event (Fig. 17 d) cuts
//        all but a ring parapetThickness wide, so the roof surface lies `slab` above the unit's
//        ceiling and the parapet stands `parapet` above it.
//  hip: every edge leans in at the pitch.
//  gable: the edges along the region's longer side (of its bounding box) lean in at the pitch,
//        the others stay vertical (gable ends); a rectangle's ridge is half its short side ×
//        tan(pitch) above its base.
//  shed: as gable, but only the edges facing −(the shorter axis) lean in: one slope rising
//        across the short side.
// Faces: roof faces in the roof material, parapets and gable ends in the wall material.
ExtrusionSpec roofSpec(const RoofRegion& region, const RoofSettings& settings);

struct Roofs {
  std::vector<RoofRegion> regions;  // every exposed region
  std::vector<MeshData> shells;     // per region: its roof, a closed shell (empty: not built)
  MeshData mesh;                    // every roof built
  std::vector<std::string> warnings;  // a region the kernel could not roof, and why
};
// The roofs of a grown model.
Roofs buildRoofs(const Site& site, const std::vector<Unit>& units, const RoofSettings& settings);

}  // namespace corbel::growth
