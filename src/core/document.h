#pragma once
// Document: the user's inputs, one entry per object. Kernels turn specs into geometry; the
// Scene is derived from the Document and can always be rebuilt (see scene_sync.h).
#include "core/extrusion_spec.h"
#include "core/growth_spec.h"
#include "core/kifs_spec.h"
#include "core/masonry_spec.h"
#include "core/placement.h"
#include "core/geometry.h"
#include "core/scene_properties.h"
#include "core/town_spec.h"
#include "core/unit_spec.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace corbel {

// A simple mass model: a box standing on z = origin.z, centred on (origin.x, origin.y),
// rotated about Z, optionally repeated on a grid in its own frame (a row of houses).
struct BoxSpec {
  Vec3 origin{0.0, 0.0, 0.0};
  Vec3 size{10.0, 6.0, 4.0};
  double rotation_deg = 0.0;
  std::string material = "plaster";
  int repeat_x = 1;
  int repeat_y = 1;
  double spacing_x = 0.0;  // distance between neighbouring copies' centres along local x
  double spacing_y = 0.0;
  bool operator==(const BoxSpec&) const = default;
};

// One spec type per kernel; extrude, statics, growth and kifs add theirs.
using Spec = std::variant<BoxSpec, ExtrusionSpec, MasonrySpec, KifsSpec, GrowthSpec, UnitSpec, TownSpec>;

// An image laid under an object's plan in the plan pane, to trace a drawing or a map from.
// It belongs to the object but no kernel sees it, so changing it never rebuilds geometry.
struct PlanBackground {
  std::string image;     // the file; in memory as chosen or resolved, in a project file
                         // relative to that file where possible (core/project_io.h)
  double scale = 0.05;   // metres per pixel
  Vec2 origin{0.0, 0.0}; // where the image's lower-left corner lies on the plan, m
  double opacity = 0.5;  // 0 (invisible) .. 1
  bool operator==(const PlanBackground&) const = default;
};

// A key of a project file that this build does not know (written by a newer corbel, or by
// hand), kept as read so that saving writes it back where it was (core/project_io.h).
struct KeptKey {
  std::string pointer;  // JSON pointer (RFC 6901) from the object, or from the file's root
  std::string json;     // the value, as JSON text
  bool operator==(const KeptKey&) const = default;
};

struct DocObject {
  ObjectId id = 0;
  std::string name;
  bool visible = true;
  Spec spec;
  std::optional<PlanBackground> background;
  std::vector<KeptKey> kept;  // unknown keys of its entry in the file
  Placement placement;        // where the kernel's geometry stands in the scene (core/placement.h)
  bool locked = false;        // a locked object cannot be picked in the 3D view or moved
  bool operator==(const DocObject&) const = default;
};

struct Document {
  std::string name = "untitled";
  std::vector<DocObject> objects;
  std::vector<KeptKey> kept;  // unknown keys at the file's top level

  DocObject* find(ObjectId id);
  const DocObject* find(ObjectId id) const;
  const DocObject* findByName(const std::string& name) const;
  ObjectId nextId() const;  // one past the largest id in use
  // Adds an object with a fresh id and a unique name derived from `base`.
  ObjectId add(const std::string& base, Spec spec);
  bool remove(ObjectId id);
  std::string uniqueName(const std::string& base) const;
  bool operator==(const Document&) const = default;
};

// Whether a kind's placement may scale it: boxes, extrusions and units. Masonry is analysed at
// its real size, growth sites grow on a metre grid, KIFS buildings are ray-marched at theirs and
// towns keep their georeference, so those only move and turn.
bool scalable(const Spec& spec);

// Limits on what a Document may hold, checked by the loader and the editor.
namespace limits {
inline constexpr std::size_t kMaxObjects = 100000;
inline constexpr long kMaxRepeat = 10000;       // boxes per repeated spec
inline constexpr double kMaxCoordinate = 1e7;   // meters from the origin
inline constexpr double kMinSize = 1e-4;        // meters
inline constexpr std::size_t kMaxNameLength = 256;
inline constexpr std::size_t kMaxLoops = 10000;        // plan loops per extrusion
inline constexpr std::size_t kMaxLoopPoints = 100000;  // plan corners per extrusion
inline constexpr std::size_t kMaxProfiles = 1000;
inline constexpr std::size_t kMaxSteps = 1000;     // plan steps and mesh anchors per extrusion
inline constexpr std::size_t kMaxProfilePoints = 1000;
inline constexpr std::size_t kMaxPathLength = 4096;  // a background image's file path
inline constexpr double kMinBackgroundScale = 1e-6, kMaxBackgroundScale = 1e4;  // metres per pixel
}  // namespace limits

// Checks a spec's values (the loader and the editor share it). Returns an error text with
// the offending field, relative to the spec, or nullopt.
std::optional<std::string> checkBoxSpec(const BoxSpec& spec);
// The same for a plan background ("scale: ...", "opacity: ...").
std::optional<std::string> checkPlanBackground(const PlanBackground& background);

}  // namespace corbel
