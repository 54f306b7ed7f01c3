#pragma once
// What the growth panel shows of a grown model without changing it (Ng, Ch. 8): the statistics
// of Table 8.1, the four view maps as false-colour images (the exact CPU mapper the object's
// build grows on, growth/kernel.h), and the model sliced at a height (Fig. 8.3), a view
// setting that replaces the object's faces in the shown Scene only.
#include "core/growth_spec.h"
#include "core/mesh_data.h"
#include "core/progress.h"
#include "core/scene.h"
#include "growth/kernel.h"
#include "growth/statistics.h"
#include "growth/view_map.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace corbel::editor {

// A grown model with its view maps and statistics.
struct GrowthInspection {
  growth::GrowthInput of;
  std::string maps;  // which view maps ("exact", or the GL mapper's name), as the request said
  growth::GrownModel grown;
  growth::ViewMaps views;
  growth::Statistics stats;
};

// What the engine renders its view maps of: every unit part (id = unit id), then the cores and
// the circulation (kObstacleId).
std::vector<growth::ViewBox> viewBoxesOf(const growth::Site& site, const std::vector<growth::Unit>& units);
// Grows `spec` as its build does (growth::grow) on `mapper` (null: the exact CPU mapper) and
// measures the result on the same mapper; `maps` names it in the result.
// Throws InputError for a bad site, Cancelled when `progress` is cancelled.
GrowthInspection inspectGrowth(const growth::GrowthInput& input, Progress* progress = nullptr,
                               growth::ViewMapper* mapper = nullptr, const std::string& maps = "exact");

// Table 8.1 as (row, value) text, in the paper's order.
std::vector<std::pair<std::string, std::string>> statisticsRows(const growth::Statistics& s);

// One view map as an RGBA image (top row first, v = height up), each pixel the colour of what
// the map holds at the pixel's centre: `width` pixels across the map's u range, as many rows as
// keep pixels square (at least 1). Seen from outside, looking against the faces' normal:
// mirrored (u decreasing to the right) for -x and +y, so the picture is what a viewer standing
// on that side sees. `depthRgba` is the same pixels' depth in grey: the nearest face seen in the
// map white, the farthest dark grey (kFarthestGrey), linear between; nothing the empty colour.
struct ViewMapImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba, depthRgba;
  std::uint32_t idAt(int x, int y) const { return ids[std::size_t(y) * width + x]; }
  double depthAt(int x, int y) const { return depths[std::size_t(y) * width + x]; }
  std::vector<std::uint32_t> ids;  // per pixel, the id sampled
  std::vector<double> depths;      // and its depth (growth::frontDepth: larger is nearer)
};
inline constexpr int kFarthestGrey = 60;
ViewMapImage viewMapImage(const growth::ViewMap& map, growth::ViewDirection d, int width);
// False colour of an id: nothing (0) is near black, a core or circulation (kObstacleId) grey,
// a unit a bright hue that neighbouring ids do not share.
std::array<std::uint8_t, 3> idColour(std::uint32_t id);
const char* viewDirectionName(growth::ViewDirection d);  // "+x", "-x", "+y", "-y"

// An object's faces in the Scene as a polygon soup (materials and tags kept).
MeshData objectMesh(const Scene& scene, ObjectId id);
// The part of `mesh` below the height `z`: every face clipped to z' ≤ z, and dropped where
// nothing of positive area is left (so faces lying in the plane z, the ceilings at the cut, go:
// the plans under them are seen from above). Faces wholly above go, so a unit whose floor is at
// or above z disappears.
MeshData sliceBelow(const MeshData& mesh, double z);
// The indices of the units a slice at z leaves shown (those whose lowest floor is below z).
std::vector<std::size_t> unitsBelow(const std::vector<growth::Unit>& units, double z);

}  // namespace corbel::editor
