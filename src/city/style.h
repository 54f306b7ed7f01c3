#pragma once
// Styles of a town (Kelly & Wonka Sec. 3.7): building types chosen by rule or by chance, each
// mapping edge labels to profiles with probabilities, plus anchored features. The file format
// is described in docs/city.md. Everything drawn at random is drawn from the seed and the
// building's id, so a building looks the same whatever order or thread builds it.
#include "city/import.h"
#include "city/labels.h"
#include "core/mesh_data.h"
#include "core/textures.h"
#include "extrude/spec.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace corbel::city {

// A condition on a footprint (all given parts must hold).
struct BuildingCondition {
  double minArea = 0, maxArea = INFINITY;                       // m²
  double minDepth = 0, maxDepth = INFINITY;                     // m, Building::depth
  std::map<std::string, std::vector<nlohmann::json>> property;  // key → accepted values
  // key → [min, max]: the property is a number, or a string of one (OSM's "12.5", "12.5 m"),
  // within the range (GIS heights, levels: "height": {"range": [14, 1000]}).
  std::map<std::string, std::pair<double, double>> propertyRange;
  bool matches(const Building& b) const;
};

// A condition on an edge's labels (all given parts must hold; empty lists accept any).
struct EdgeCondition {
  std::vector<Orientation> orientation;
  std::vector<LengthClass> length;
  double minAngle = -180, maxAngle = 180;  // degrees, on the disk
  bool matches(const EdgeLabel& e) const;
};

struct Weighted {
  int index = 0;  // into the style's profiles (edge rules) or types (assignments)
  double weight = 1;
};

struct EdgeRule {
  EdgeCondition when;
  std::vector<Weighted> profiles;
};

// Windows on the edges a condition picks: a grid from `margin` m after the edge's start to
// `margin` m before its end, `spacing` apart, one row per floor.
struct WindowRule {
  EdgeCondition when;
  double minLength = 3, margin = 1.5, spacing = 2.5, sill = 0.9, floorHeight = 3;
  int floors = 1;
  extrude::FeatureSize size{1.0, 1.3, 0.12};
};

// A row of natural steps (dormers) or one step (chimney) on edges a condition picks, at
// `height` above the base, drawn with `chance` per building.
struct StepRule {
  EdgeCondition when;
  double chance = 1, height = 0, width = 1.5, depth = 0.6, minLength = 6, margin = 2, spacing = 3;
  double along = 0.5;  // single steps: where on the edge (fraction)
  bool row = false;
  int frontProfile = 0, sideProfile = 0;
};

// A parapet (Fig. 17 d): at `height` an inward offset of `thickness` cuts the roof from a
// ring that rises by the inside profile.
struct ParapetRule {
  double height = 0, thickness = 0.3;
  int insideProfile = 0;
};

struct BuildingType {
  std::string name;
  BuildingCondition when;
  double weight = 1;
  std::string material = "plaster", roofMaterial;
  // Sec. 4.8's resolution of colinear edges for this type's buildings; manual ranks profile
  // segments tagged "high" over untagged ones over "low" ones (a chimney or dormer kept out of
  // the volume-maximising answer, Fig. 30 c).
  Priority priority = Priority::MaximiseVolume;
  std::vector<EdgeRule> edges;
  std::vector<WindowRule> windows;
  std::optional<extrude::FeatureSize> door;
  std::vector<StepRule> steps;
  std::optional<ParapetRule> parapet;
};

// Explicit assignment: the first rule whose condition holds picks one of its types.
struct AssignRule {
  BuildingCondition when;
  std::vector<Weighted> types;
};

// Wall heights from a footprint's attributes: the first of `walls` the building has (metres: a
// number, or OSM's "12.5", "12.5 m") is its wall height, else the first of `levels` times
// `storey`. A building given one gets walls that tall (each edge's profile's first vertical run
// from the ground, the roof above it kept as drawn and raised or lowered with it, the parapet and
// steps with it) and as many rows of windows as fit under the eaves. Values outside [2, 1000] m
// are ignored with a warning.
struct HeightRule {
  std::vector<std::string> walls, levels;
  double storey = 3;
};

struct Style {
  std::string name;
  LabelOptions labels;
  std::optional<HeightRule> heights;  // none: every building as its type draws it
  std::vector<extrude::Profile> profiles;
  std::vector<BuildingType> types;
  // Size rules, before any other assignment: the first whose condition holds (by footprint area
  // or depth) picks one of its types, so a style can give buildings past a size a roof that
  // stays low (flat inside a parapet) whatever else they would be.
  std::vector<AssignRule> bySize;
  std::vector<AssignRule> assign;  // empty: any type whose own condition holds, by weight
  // Faces with one of these tags take that material (chimneys of brick, copings of stone),
  // so the glb's materials follow the tags.
  std::map<std::string, std::string> tagMaterials;
  // Faces with one of these tags show that built-in texture (core/textures.h) in textured output
  // (the glb, the renderer's textured mode), whatever their material; metres 0 = the texture's
  // own tile. Independent of tagMaterials, which still gives such faces their material (colour).
  std::map<std::string, SurfaceTexture> tagTextures;
};

// Gives the faces of `mesh` whose tag the style names their material.
void applyTagMaterials(const Style& style, MeshData& mesh);
// The style's tag textures for ExportOptions and RenderSettings, for every object (the style
// must outlive it); empty when the style has none.
TagTextures tagTexturesOf(const Style& style);

// Parses a style; faults throw InputError naming the JSON path ("types[1].edges[0].profiles:
// no profile named \"x\""). `folder` resolves the paths in "use".
Style parseStyle(const std::string& text, const std::string& folder = {});
Style loadStyle(const std::string& path);

// The random stream of one building: splitmix64 of the seed and the id's FNV-1a hash.
class BuildingRandom {
 public:
  BuildingRandom(std::uint64_t seed, const std::string& id);
  double uniform();  // [0, 1)
  // Picks an entry by weight; returns its index in `choices`.
  std::size_t pick(const std::vector<Weighted>& choices);

 private:
  std::uint64_t state_;
};

// The type a building gets (index into style.types), or nullopt when none applies.
std::optional<std::size_t> assignType(const Style& style, const Building& b, BuildingRandom& random);

// A user's override of one building (core/town_spec.h, resolved against a style): its type
// (index into style.types), per edge orientation the profile (index into style.profiles), and
// per edge (loop, edge) the profile, which wins over its orientation's. The building's random
// draws are made as without it, so nothing else about it changes.
struct BuildingOverride {
  std::optional<std::size_t> type;
  std::map<Orientation, int> profiles;
  std::map<std::pair<int, int>, int> edges;
};

struct StyledBuilding {
  std::string type;  // "" when it could not be styled
  extrude::ExtrusionSpec spec;
  std::string problem;  // why not
  // What the styling changed to keep the building within the kernel's limits: overhangs taken
  // off the edges of corners past the mitre limit, rows of windows or dormers thinned to the
  // instance limits.
  std::vector<std::string> warnings;
};
// Styles one building. After the profiles are drawn, every convex corner whose edges' outward
// horizontal moves (overhangs) would push it out by more than kMitreLimit times the move (the
// kernel refuses such a spec: docs/extrude.md, "Mitre limit") has the overhangs taken off both its
// edges: they get a variant of their profile without outward moves ("NAME (no overhang)"), and
// a warning names the corner. Windows and doors stay within kMaxFeatureInstances per building
// and dormer rows within kMaxStepInstances (core/extrusion_spec.h): a row that would pass the
// limit is spread more thinly, with a warning.
StyledBuilding styleBuilding(const Style& style, const Building& b, const BuildingLabels& labels, std::uint64_t seed,
                             const BuildingOverride* override = nullptr);

// The kernel's mitre limit (extrude/recursive_extrusion.cpp, checkMitre): an overhang may push a corner out by
// at most this many times its own size.
inline constexpr double kMitreLimit = 20.0;
// How far an outward move of ka on the edge into a corner and kb on the edge out of it pushes the
// corner (m; the edges' directions da and db, inside on their left; moves negative outward), as
// the kernel works it out; 0 where the corner is reflex or not sharp (90° or more).
double cornerMove(const Vec2& da, const Vec2& db, double ka, double kb);
// The height of the profile's wall: the top of its first vertical run from (0, 0) (0 when its
// first segment leans).
double wallTop(const extrude::Profile& profile);
// The profile with its wall `height` tall: the wall's segments become one, and every point above
// them moves up or down by the difference, so the roof keeps its shape. A profile without a wall
// gets one (tagged "wall").
extrude::Profile withWallHeight(const extrude::Profile& profile, double height);
// The wall height a footprint's attributes give under the style's heights rule; nullopt when
// there is no rule or no such attribute. `warning` gets why a value was ignored.
std::optional<double> wallHeightOf(const Style& style, const Building& b, std::string* warning = nullptr);

// The profile without its outward horizontal moves: each height's net outward move is dropped
// and the points above it shifted back in by it, so the slopes stay as they were.
extrude::Profile withoutOverhang(const extrude::Profile& profile);

}  // namespace corbel::city
