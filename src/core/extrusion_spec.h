#pragma once
// The data of a procedural extrusion (Kelly & Wonka, Sec. 4.1), as the Document stores it.
// The kernel that turns it into a shell lives in src/extrude.
#include "core/geometry.h"
#include "core/stone_walls.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace corbel {

// A profile: a vertically monotone polyline of (w, z) points starting at (0, 0); w grows
// towards the inside of the plan. Segment i goes from points[i] to points[i + 1] and sets the
// direction-plane angle θ_i (0 = vertical wall, > 0 leans inward, < 0 outward). A horizontal
// segment (same z) moves the edge sideways at that height by its Δw (a ledge when inward, an
// overhang's soffit when outward: Sec. 4.5.2). The last segment must not lean outward, and
// some edge of every loop must end leaning inward so the roof closes.
struct Profile {
  std::string name;
  std::vector<Vec2> points;       // (w, z)
  std::vector<std::string> tags;  // per segment ("" = none); may be shorter
  bool operator==(const Profile&) const = default;
};

struct PlanLoop {
  PlanLoop() = default;
  PlanLoop(std::vector<Vec2> corners, std::vector<int> profiles, std::vector<int> wallIds = {})
      : points(std::move(corners)), profile(std::move(profiles)), walls(std::move(wallIds)) {}
  std::vector<Vec2> points;  // corners; outer loops counter-clockwise, holes clockwise
  std::vector<int> profile;  // per edge i (points[i] → points[i+1]): index into profiles
  // The wall of each edge: an id (≥ 1, unique to this loop within the spec) that edits keep.
  // Splitting an edge gives both halves its wall; deleting a corner between two walls merges
  // them. Empty: every edge is a wall of its own (as specs made by program are).
  std::vector<int> walls;
  bool operator==(const PlanLoop&) const = default;
};

// Ambiguity priority (Sec. 4.8) when colinear neighbouring edges meet. Manual: a profile
// segment tagged "high" beats an untagged one, which beats one tagged "low"; ties fall back to
// volume maximising.
enum class Priority { MaximiseVolume, MinimiseVolume, Manual };

// Where a feature sits on the shell (Sec. 3.4): on the wall of an input plan edge, at a
// profile height above the base. A wall is the run of consecutive edges that share the edge's
// wall id (PlanLoop::walls): one edge until an edit splits it. `along` measures the whole run,
// so splitting an edge moves nothing.
struct Anchor {
  int loop = 0, edge = 0;  // an input plan edge of the wall
  bool absolute = false;   // false: `along` is a fraction of the wall's active edge; true:
                           // metres along the wall's run of input edges from its start
  double along = 0.5;
  double height = 0.0;     // above the extrusion's base
  bool operator==(const Anchor&) const = default;
};

// Repeating an anchored thing (Sec. 3.6): the anchor marks the first element and `along` (and,
// for a grid, `height`) the last one, on the same input edge. Between them go as many columns
// as fit with at least `spacing` metres between neighbours (rows: `rowSpacing`), spread evenly
// so both ends are used. `along` is in the anchor's own units (a fraction of the active edge
// for a relative anchor, metres along the input edge for an absolute one), so with relative
// anchors the columns follow a resized facade. The number of columns of a relative repeat is
// fixed by the input edge's length.
enum class RepeatKind { None, Row, Grid };
struct Repeat {
  RepeatKind kind = RepeatKind::None;
  double along = 0.5;       // the last column's place on the edge
  double height = 0.0;      // grid: the last row's height above the base
  double spacing = 2.0;     // least distance between columns, m
  double rowSpacing = 3.0;  // grid: least distance between rows, m
  bool operator==(const Repeat&) const = default;
};

// A natural step (Sec. 3.5, 4.7): a small protrusion inserted into the active plan at the
// anchor and grown by a recursive extrusion to its size, so it never self-intersects.
// Rectangle (dormers, chimneys, buttresses): `width` along the edge, `depth` out. Bay: an
// opening `width` wide in the edge, a front `depth` out and `cant` narrower on each side.
// Forced (Sec. 3.5): `points`, a simple polygon in the anchor's frame (u along the edge,
// v outward, metres), unioned with the active plan; its new edges follow frontProfile.
enum class StepShape { Rectangle, Bay, Forced };
struct PlanStep {
  std::string name;
  Anchor anchor;
  StepShape shape = StepShape::Rectangle;
  double width = 1.0;  // along the edge, m
  double depth = 0.5;  // outward from the active edge, m (negative: a recess into the plan)
  double cant = 0.0;   // bay: how much narrower the front is on each side, m
  int frontProfile = 0, sideProfile = 0;
  std::vector<Vec2> points;  // forced steps only
  Repeat repeat;             // a row (or grid) of the same step, e.g. dormers along a roof
  bool operator==(const PlanStep&) const = default;
};

// A profile offset event (Sec. 3.3, 4.6, Fig. 17): at `height` above the base, an offset
// region bounded by two offsets of the active plan is inserted into it (offsets outward) or
// cut from it (offsets inward). Each active edge whose profile is listed takes part: its inside
// and outside boundaries lie `inside` and `outside` metres out from it (negative: in), and the
// new edges on them follow insideProfile and outsideProfile. Edges whose profile is not listed
// are disabled (no offset region along them). Edges where the region ends follow sideProfile.
struct OffsetEdge {
  int profile = 0;
  double inside = 0.0, outside = 0.5;
  int insideProfile = 0, outsideProfile = 0;
  bool operator==(const OffsetEdge&) const = default;
};
struct OffsetEvent {
  double height = 0.0;
  std::vector<OffsetEdge> edges;
  int sideProfile = 0;
  bool operator==(const OffsetEvent&) const = default;
};

// A feature mesh instanced at a mesh anchor (Fig. 28), built in the anchor's frame by
// extrude/features.h.
enum class FeatureKind { None, Door, Window, RoofWindow, ChimneyPot };
struct FeatureSize {
  double width = 1.0;   // along the edge, m
  double height = 1.5;  // up the face (a chimney pot: straight up), m
  double depth = 0.15;  // out of the face (a chimney pot: its size across), m
  bool operator==(const FeatureSize&) const = default;
};

// A named place on the shell (doors, windows): the kernel reports its position and frame and,
// when a feature is attached, instances its mesh there (repeated as `repeat` says).
struct MeshAnchor {
  MeshAnchor() = default;
  MeshAnchor(std::string n, Anchor a, FeatureKind f = FeatureKind::None, FeatureSize s = {}, Repeat r = {})
      : name(std::move(n)), anchor(a), feature(f), size(s), repeat(r) {}
  std::string name;
  Anchor anchor;
  FeatureKind feature = FeatureKind::None;
  FeatureSize size;
  Repeat repeat;
  bool operator==(const MeshAnchor&) const = default;
};

// Feature names as the project file writes them ("door", "window", "roof_window",
// "chimney_pot"; "none").
const char* featureName(FeatureKind kind);
std::optional<FeatureKind> featureFromName(std::string_view name);
// A size that suits the kind (used when a file or a script names a feature without a size).
FeatureSize defaultFeatureSize(FeatureKind kind);

struct ExtrusionSpec {
  std::vector<PlanLoop> loops;
  std::vector<Profile> profiles;  // the library the edges refer to
  Priority priority = Priority::MaximiseVolume;
  std::string material = "plaster";
  std::string roofMaterial;  // faces leaning inward; "" = material
  double baseZ = 0.0;
  std::vector<PlanStep> steps;
  std::vector<OffsetEvent> offsets;
  std::vector<MeshAnchor> anchors;
  std::optional<StoneWalls> masonry;  // built in stone for the statics kernel (off when absent)
  bool operator==(const ExtrusionSpec&) const = default;
};

// Walls (PlanLoop::walls). The wall id of an edge (its own when the loop has none), the run
// of consecutive edges with that id (in order, from the run's first edge; a loop that is one
// wall runs from edge 0), and where an anchor lies on the plan along its run.
int wallOf(const PlanLoop& loop, int edge);
struct WallRun {
  int loop = -1;
  std::vector<int> edges;  // empty when the anchor's loop or edge does not exist
  double length = 0;       // of the input edges, m
};
WallRun wallRun(const ExtrusionSpec& spec, int loop, int edge);
// The point of the plan at `along` on the wall (a fraction of the run's length, or metres for
// an absolute anchor), clamped to the run; nullopt when the anchor names no edge.
std::optional<Vec2> anchorPoint(const ExtrusionSpec& spec, const Anchor& anchor);
// The run's direction at that point (the direction of the edge holding it).
std::optional<Vec2> anchorDirection(const ExtrusionSpec& spec, const Anchor& anchor);
// How far along its wall's run (m) a point `metres` into input edge (loop, edge) lies.
double alongWall(const ExtrusionSpec& spec, int loop, int edge, double metres);
// The point of a run nearest `p`, and how far along the run it lies (m).
struct WallPoint {
  Vec2 point{0.0, 0.0};
  double along = 0.0;
};
WallPoint nearestOnWall(const ExtrusionSpec& spec, const WallRun& run, const Vec2& p);
// Gives every loop without wall ids fresh ones (one per edge, unique in the spec), so edits
// can keep them; loops that have them keep them.
void assignWalls(ExtrusionSpec& spec);
// Whether every wall is one edge (as when no loop has ids). Specs keep that case as empty
// `walls` (canonicalWalls), so a split undone by deleting the corner is the spec it was.
bool wallsAreEdges(const ExtrusionSpec& spec);
void canonicalWalls(ExtrusionSpec& spec);
// The ids renumbered 1, 2, ... in order of first use (as the project file writes them).
std::vector<std::vector<int>> numberedWalls(const ExtrusionSpec& spec);
int nextWallId(const ExtrusionSpec& spec);

// Columns and rows of a repeat at an anchor (1 × 1 when it does not repeat). Columns of a
// relative anchor count on its wall's length (0 when the edge does not exist). Counts
// are capped at 1e9 each so absurd spacings stay representable for the limit checks.
struct RepeatGrid {
  std::size_t columns = 1, rows = 1;
  std::size_t count() const { return columns * rows; }
};
RepeatGrid repeatGrid(const ExtrusionSpec& spec, const Anchor& anchor, const Repeat& repeat);
// The anchors of every element of a repeat, first row first, each row from the first column
// to the last: the anchor itself when it does not repeat.
std::vector<Anchor> repeatAnchors(const ExtrusionSpec& spec, const Anchor& anchor, const Repeat& repeat);

// Limits on the expansion (per extrusion): mesh-anchor instances and step instances.
inline constexpr std::size_t kMaxFeatureInstances = 10000;
inline constexpr std::size_t kMaxStepInstances = 1000;

// The spec with every repeat expanded into single instances (Sec. 3.6), before the sweep: a
// repeated step or anchor becomes one entry per element, named "name (i of n)", without a
// repeat. `stepSource` and `anchorSource` give each entry's index in the original spec.
struct ExpandedSpec {
  ExtrusionSpec spec;
  std::vector<int> stepSource, anchorSource;
};
ExpandedSpec expandRepeats(const ExtrusionSpec& spec);

// Value checks shared by the loader, the kernel and the editing operations. Each returns the
// first fault naming its field relative to the checked value ("spacing: ..."), or nullopt.
std::optional<std::string> checkRepeat(const Anchor& anchor, const Repeat& repeat);
std::optional<std::string> checkFeatureSize(const FeatureSize& size);
// The expanded instance counts against the limits, e.g. "anchors[2].repeat: ...".
std::optional<std::string> checkInstanceCounts(const ExtrusionSpec& spec);

}  // namespace corbel
