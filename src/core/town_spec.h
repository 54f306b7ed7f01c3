#pragma once
// A town in the Document (Kelly & Wonka Sec. 3.7, Fig. 2): GIS footprints, a style that turns
// each into an extrusion (docs/city.md), the seed every building draws from, and the user's
// per-building overrides of the type or of the profiles, keyed by footprint id. The city
// kernel owns the meaning of the footprints and the style: it reads and checks them when it
// builds the object and names a bad override by its path ("town.overrides[\"w12\"].type").
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace corbel {

// What the user changed on one building: its type (a type name of the style, "" = as the style
// assigns it) and, per edge orientation ("street", "side", "back"), the profile its edges take.
struct TownOverride {
  std::string type;
  std::map<std::string, std::string> profiles;
  bool empty() const { return type.empty() && profiles.empty(); }
  bool operator==(const TownOverride&) const = default;
};

struct TownSpec {
  // The footprints: a GeoJSON file (in memory as chosen or resolved, in a project file relative
  // to that file where possible), or, when that is empty, the GeoJSON text held in the project.
  std::string footprints;
  std::string footprintsJson;
  // The style: a style file (as footprints) or, when that is empty, the style's JSON text.
  std::string style;
  std::string styleJson;
  std::uint64_t seed = 1;
  std::string detail = "full";  // "massing", "steps" or "full" (city::Detail)
  std::map<std::string, TownOverride> overrides;  // by footprint id
  bool operator==(const TownSpec&) const = default;
};

namespace limits {
inline constexpr std::size_t kMaxTownOverrides = 100000;
inline constexpr std::size_t kMaxEmbeddedBytes = 32u << 20;  // embedded footprints or style text
}  // namespace limits

// "detail: ...", "overrides[\"id\"].profiles: ..." and the like for a bad spec; nullopt when fine.
std::optional<std::string> checkTownSpec(const TownSpec& spec);

}  // namespace corbel
