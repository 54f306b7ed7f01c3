#pragma once
// The data of a procedural extrusion (Kelly & Wonka, Sec. 4.1), as the Document stores it.
// The kernel that turns it into a shell lives in src/extrude.
#include "core/geometry.h"

#include <string>
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
  std::vector<Vec2> points;  // corners; outer loops counter-clockwise, holes clockwise
  std::vector<int> profile;  // per edge i (points[i] → points[i+1]): index into profiles
  bool operator==(const PlanLoop&) const = default;
};

// Ambiguity priority (Sec. 4.8) when colinear neighbouring edges meet. Manual: a profile
// segment tagged "high" beats an untagged one, which beats one tagged "low"; ties fall back to
// volume maximising.
enum class Priority { MaximiseVolume, MinimiseVolume, Manual };

// Where a feature sits on the shell (Sec. 3.4): on the active-plan edge that descends from an
// input plan edge, at a profile height above the base.
struct Anchor {
  int loop = 0, edge = 0;  // the input plan edge
  bool absolute = false;   // false: `along` is a fraction of the active edge; true: metres
                           // along the input edge's line from its start (a plane across it)
  double along = 0.5;
  double height = 0.0;     // above the extrusion's base
  bool operator==(const Anchor&) const = default;
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

// A named place on the shell (doors, windows): the kernel reports its position and frame.
struct MeshAnchor {
  std::string name;
  Anchor anchor;
  bool operator==(const MeshAnchor&) const = default;
};

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
  bool operator==(const ExtrusionSpec&) const = default;
};

}  // namespace corbel
