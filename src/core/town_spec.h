#pragma once
// A town in the Document (Kelly & Wonka Sec. 3.7, Fig. 2): GIS footprints, a style that turns
// each into an extrusion (docs/city.md), the seed every building draws from, and the user's
// per-building overrides of the type or of the profiles, keyed by footprint id. The city
// kernel owns the meaning of the footprints and the style: it reads and checks them when it
// builds the object and names a bad override by its path ("town.overrides[\"w12\"].type").
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace corbel {

// What the user changed on one building: its type (a type name of the style, "" = as the style
// assigns it), per edge orientation ("street", "side", "back") the profile its edges take, and
// per single edge the profile that edge takes (it wins over its orientation's). An edge is
// named "L:E": edge E (from corner E to corner E + 1) of loop L of the cleaned footprint, the
// numbering the Town panel's plan view shows.
struct TownOverride {
  std::string type;
  std::map<std::string, std::string> profiles;
  std::map<std::string, std::string> edges;
  bool empty() const { return type.empty() && profiles.empty() && edges.empty(); }
  bool operator==(const TownOverride&) const = default;
};

// A street of the town (Fig. 26): a spline through a few control points in the town's metric
// frame, and the plots cut along it on one or both sides, which the style builds as town
// houses facing it. Reshaping it re-cuts its plots; footprints within reach orient to it too.
struct TownStreet {
  std::vector<std::array<double, 2>> points;  // control points, metres
  double width = 10;      // kerb to kerb
  double setback = 2;     // kerb to the plots' fronts
  double depth = 12;      // plot depth, front to back
  double plotWidth = 7;   // wanted frontage of one plot (the frontage is cut evenly)
  bool bothSides = true;
  bool skeletonPlots = false;  // plots grown from seeds by the skeleton (Fig. 26), else cut along normals
  bool operator==(const TownStreet&) const = default;
};

struct TownSpec {
  // The footprints: a GeoJSON file (in memory as chosen or resolved, in a project file relative
  // to that file where possible), or, when that is empty, the GeoJSON text held in the project.
  std::string footprints;
  std::string footprintsJson;
  // How the footprints are read (city/import.h, ReadOptions): their CRS when the file names none
  // (EPSG:32632, a WKT, a PROJ string or "local"), the layer of a source with several, an OGR SQL
  // attribute filter; "" = the file's own, the only layer, every feature.
  std::string crs, layer, where;
  // The style: a style file (as footprints) or, when that is empty, the style's JSON text.
  std::string style;
  std::string styleJson;
  std::uint64_t seed = 1;
  std::string detail = "full";  // "massing", "steps" or "full" (city::Detail)
  std::map<std::string, TownOverride> overrides;  // by footprint id (street plots: "street K/left/I")
  std::vector<TownStreet> streets;
  bool operator==(const TownSpec&) const = default;
};

namespace limits {
inline constexpr std::size_t kMaxTownOverrides = 100000;
inline constexpr std::size_t kMaxEmbeddedBytes = 32u << 20;  // embedded footprints or style text
inline constexpr std::size_t kMaxTownStreets = 256;
inline constexpr std::size_t kMaxStreetPoints = 64;
}  // namespace limits

// Reads an edge key "L:E" of TownOverride::edges (two decimal numbers, each below 10⁶);
// nullopt when it is not one.
std::optional<std::pair<int, int>> parseTownEdgeKey(const std::string& key);
std::string townEdgeKey(int loop, int edge);

// "detail: ...", "overrides[\"id\"].profiles: ..." and the like for a bad spec; nullopt when fine.
std::optional<std::string> checkTownSpec(const TownSpec& spec);

}  // namespace corbel
