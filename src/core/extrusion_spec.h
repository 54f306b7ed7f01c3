#pragma once
// The data of a procedural extrusion (Kelly & Wonka, Sec. 4.1), as the Document stores it.
// The kernel that turns it into a shell lives in src/extrude.
#include "core/geometry.h"

#include <string>
#include <vector>

namespace corbel {

// A profile: a vertically monotone polyline of (w, z) points starting at (0, 0); w grows
// towards the inside of the plan. Segment i goes from points[i] to points[i + 1] and sets the
// direction-plane angle θ_i (0 = vertical wall, > 0 leans inward, < 0 outward). The last
// segment must lean inward (θ > 0) so the roof closes.
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

// Ambiguity priority (Sec. 4.8) when colinear neighbouring edges meet.
enum class Priority { MaximiseVolume, MinimiseVolume };

struct ExtrusionSpec {
  std::vector<PlanLoop> loops;
  std::vector<Profile> profiles;  // the library the edges refer to
  Priority priority = Priority::MaximiseVolume;
  std::string material = "plaster";
  std::string roofMaterial;  // faces leaning inward; "" = material
  double baseZ = 0.0;
  bool operator==(const ExtrusionSpec&) const = default;
};

}  // namespace corbel
