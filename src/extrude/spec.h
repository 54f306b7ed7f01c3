#pragma once
// The input of a procedural extrusion (Sec. 4.1): a plan of oriented loops and, per edge, a
// profile. Stored in the project file; turned into geometry by extrude().
#include "core/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::extrude {

// A profile: a vertically monotone polyline of (w, z) points starting at (0, 0); w grows
// towards the inside of the plan. Segment i goes from points[i] to points[i + 1] and sets the
// direction-plane angle θ_i (0 = vertical wall, > 0 leans inward, < 0 outward, ±π/2
// horizontal). The last segment must lean inward (θ > 0) so the roof closes.
struct Profile {
  std::string name;
  std::vector<Vec2> points;          // (w, z)
  std::vector<std::string> tags;     // per segment ("" = none); may be shorter
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
  std::vector<Profile> profiles;
  Priority priority = Priority::MaximiseVolume;
  bool operator==(const ExtrusionSpec&) const = default;
};

// One direction plane angle change along a profile: from height z on, angle θ (radians).
struct AngleStep {
  double z;
  double angle;
  int segment;  // profile segment index (provenance)
};

// Profile → the angle steps of Sec. 4.5. Horizontal segments become a step with angle ±π/2
// and the horizontal run in `run` (Sec. 4.5.2 handles them).
struct ProfileSteps {
  std::vector<AngleStep> steps;
};

// Standard profiles used by the CLI and tests.
Profile hipProfile(double pitchRadians);                             // one inward segment
Profile wallAndRoofProfile(double wallHeight, double pitchRadians);  // wall, then roof

// Checks a spec and returns the first fault as "loops[1].points[3]: ...", or nullopt.
std::optional<std::string> checkSpec(const ExtrusionSpec& spec);

}  // namespace corbel::extrude
