#pragma once
// The site of a growth run (Ch. 3.1, Ch. 4): the envelope units must stay in, the storeys,
// the cores (full-height shafts), the circulation (stairs, corridors), and the seed units
// placed at exits along the circulation with their targets, behaviours and locked faces.
#include "core/extrusion_spec.h"
#include "growth/box.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace corbel::growth {

struct Seed {
  Vec2 at{0.0};                  // plan corner with the least x and y
  Vec2 size{3.0, 3.0};           // plan size, at least 3 m × 3 m
  int storey = 0;                // 0 = ground storey
  double targetArea = 0;         // floor area to reach (m²), or
  double targetVolume = 0;       // volume to reach (m³): exactly one of the two is positive
  std::array<bool, 6> locked{};  // by Side: faces of that orientation never advance
  std::string behaviour = "view";
};

// How unit tops are roofed (growth/finish.h): the exposed top of the units at one height, as one
// extrusion per connected region, with this profile.
enum class RoofProfile { Flat, Shed, Gable, Hip };
const char* roofProfileName(RoofProfile p);  // "flat", "shed", "gable", "hip"
struct RoofSettings {
  RoofProfile profile = RoofProfile::Flat;
  double pitch = 30;              // degrees from horizontal (shed, gable, hip)
  double parapet = 0.9;           // flat: the parapet's height above the roof surface (m)
  double parapetThickness = 0.25; // flat: the parapet's wall (m)
  double slab = 0.3;              // flat: the roof's build-up over the unit's ceiling (m)
  std::string material;           // roof faces; "" = concrete (flat) or roof_tile (pitched)
  std::string wallMaterial = "plaster";  // parapets and gable ends
};

// Doors and windows on the units' free faces (growth/finish.h): the extrusion kernel's feature
// meshes (extrude/features.h).
struct OpeningSettings {
  FeatureSize door{1.0, 2.1, 0.15};
  FeatureSize window{1.2, 1.4, 0.12};
  double sill = 0.9;     // window bottom above the storey's floor (m)
  double spacing = 3.0;  // one window per this many metres of facade with a view, per storey
};

// The growth behaviour's settings (docs/growth.md, "Growth settings"): the site file's "growth"
// object; GrowthOptions (growth/engine.h) carries them into a run.
struct GrowthSettings {
  double tau = 0.3;                 // view conflict: the share of its best view a unit lets others take
  double intrusionPenalty = 0.5;    // score lost per m² of view taken from other units
  double viewGoalRatio = 0.5;       // goal view = this × target floor area (Ch. 8: "about half")
  double aspectChance = 0.25;       // chance a step favours aspect ratio over view (Sec. 5.3)
  double doubleVolumeChance = 0.35; // chance a unit makes one part a double volume at half its target
  double maxAspect = 3.0;           // the view behaviour keeps each part's plan within 1 : maxAspect
  int patience = 5;                 // steps without a valid move before a unit is stuck
  int minSubUnits = 2, maxSubUnits = 3;  // a target is grown as this many sub-units (drawn evenly)
  bool operator==(const GrowthSettings&) const = default;
};

struct Site {
  // Envelope: an extruded simple polygon (plan, meters) from `base` up `storeys` storeys.
  // A box envelope is its rectangle.
  std::vector<Vec2> plan;
  double base = 0;
  double storeyHeight = 3.0;
  int storeys = 1;
  std::vector<Rect> cores;       // plan rectangles (u = x, v = y), full height
  std::vector<Box> circulation;  // staircases, corridors, landings
  std::vector<Seed> seeds;
  // Units already there (a growth object grown around the Document's unit objects, as after
  // Freeze): each a list of parts, with its name for messages. They never move; the seeds grow
  // around them as around each other, and roofs, doors and windows finish them with the rest.
  // In a run their unit ids follow the seeds' (seeds.size() + 1, ...). Not read from the site file.
  struct FixedUnit {
    std::string name;
    std::vector<Box> parts;
    bool operator==(const FixedUnit&) const = default;
  };
  std::vector<FixedUnit> fixed;
  double coreClearance = 1.0;         // least plan gap (L∞) between a unit and a core
  double circulationClearance = 0.0;  // ... and circulation (0: units may touch it)
  double cantilever = 4.0;            // the farthest a unit reaches beyond its supports
  double alpha = 0.3;                 // Face Advance distance α (Sec. 5.1)
  GrowthSettings growth;
  std::optional<RoofSettings> roof;          // none: bare unit tops
  std::optional<OpeningSettings> openings;   // none: no doors or windows

  double top() const { return base + storeys * storeyHeight; }
  Box coreBox(std::size_t i) const { return {{cores[i].u0, cores[i].v0, base}, {cores[i].u1, cores[i].v1, top()}}; }
  Box seedBox(std::size_t i) const;
  // The bounding box of the envelope.
  Box bounds() const;
  // Whether the plan rectangle lies inside the envelope polygon (boundary included).
  bool planContains(const Rect& r) const;
  // Whether the box lies inside the envelope.
  bool contains(const Box& b) const;
  // Site area: the envelope plan's area (Table 8.1).
  double area() const;
};

// A site from its rectangle: plan = [x0, x1] × [y0, y1].
std::vector<Vec2> rectanglePlan(double x0, double y0, double x1, double y1);

// Throws InputError naming the first bad field ("seeds[3].at: outside the site envelope",
// "cores[1]: overlaps cores[0]", "circulation[2]: overlaps cores[0]" (circulation may touch a
// core, as a landing at its lift door does, but not share its interior),
// "storey_height: must be positive", NaN anywhere).
void validateSite(const Site& site);

// Parses the site JSON of docs/growth.md and validates it. `warnings` gets unknown keys.
Site parseSite(const std::string& jsonText, std::vector<std::string>* warnings = nullptr);
Site loadSite(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace corbel::growth
