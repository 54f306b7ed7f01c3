#pragma once
// Push/pull on a built extrusion (the 3D view's Push/Pull tool): which spec entry a face of the
// shell comes from, and the edits a drag on it makes. A wall face (the first profile segment of
// a plan edge) moves its plan edge along the edge's outward normal; a face of a later segment
// turns that profile segment about its lower end; a step's or a feature's face slides the
// step's or feature's anchor along its wall. No GL, no UI: the editor's drag (editor/push_pull.h)
// turns the pointer into the numbers these take.
#include "extrude/extrude.h"
#include "extrude/spec.h"

#include <optional>
#include <utility>
#include <vector>

namespace corbel::extrude::pushpull {

enum class Kind { None, Wall, Roof, Step, Feature };

// What a ray meets first on the shell and its features, and what dragging it changes.
struct Target {
  Kind kind = Kind::None;
  int loop = -1, edge = -1;        // Wall, Roof: the plan edge that traced the face
  int profile = -1, segment = -1;  // Roof (and Wall): the profile segment of the face
  int step = -1;                   // Step: index into spec.steps
  int feature = -1;                // Feature: index into spec.anchors
  Vec3 hit{0, 0, 0};               // where the ray meets the face
  Vec3 normal{0, 0, 1};            // the face's outward normal
  std::vector<Vec3> outline;       // the face's outer boundary (for drawing)
  double t = 0;                    // along the ray, in units of its direction's length
};

// The face the ray origin + t·direction (t > 0, the extrusion's own frame) meets first: shell
// faces by their provenance (ShellFace), feature meshes by their anchor. Base faces and the
// horizontal faces a plan change makes are no target (Kind::None, with the hit).
Target pick(const ExtrusionSpec& spec, const ExtrusionResult& built, const Vec3& origin, const Vec3& direction);

// The plan edge's outward unit normal (to the right of its direction: loops keep the building
// on their left) and its length.
Vec2 edgeNormal(const ExtrusionSpec& spec, int loop, int edge);
double edgeLength(const ExtrusionSpec& spec, int loop, int edge);

// Moves plan edge (loop, edge) `distance` metres along its outward normal (negative: inward).
// Each of its corners slides along the neighbouring edge's line, so the neighbours keep their
// directions and only change length; where a neighbour is (nearly) parallel to the edge the
// corner moves straight along the normal. Anchors keep their fractions (as edit::moveCorner).
ExtrusionSpec pushEdge(ExtrusionSpec s, int loop, int edge, double distance);

// A profile segment's pitch in degrees above the horizontal, measured towards the inside: 90 a
// vertical wall, 45 a roof leaning in, 0 a ledge, 180 an overhang's soffit.
double segmentPitch(const Profile& profile, int segment);
// Turns segment `segment` of profile `profile` about its lower end to `pitchDeg`, keeping its
// length; the points above it move with its upper end. The pitch must keep z from decreasing
// ([0, 180]) and the last segment from leaning outward ((0, 90]).
ExtrusionSpec turnSegment(ExtrusionSpec s, int profile, int segment, double pitchDeg);
// The pitches turnSegment accepts for that segment.
std::pair<double, double> pitchRange(const Profile& profile, int segment);
// How many plan edges use the profile (main edges only).
int profileUsers(const ExtrusionSpec& s, int profile);
// Gives plan edge (loop, edge) a copy of its profile of its own, named after it ("hip 2");
// `index` receives the copy's index.
ExtrusionSpec ownProfile(ExtrusionSpec s, int loop, int edge, int* index);

// An anchor moved `metres` along its wall (Anchor, core/extrusion_spec.h): a relative anchor's
// fraction by metres over the wall's length, an absolute one's distance by metres; both stay on
// the wall (clamped to its ends).
Anchor slideAnchor(const ExtrusionSpec& s, Anchor anchor, double metres);
// A repeated row or grid (Sec. 3.6) slides as a whole: its first and last places move by the
// same metres, stopping where either end reaches an end of the wall, so the spacing and the
// count stay. Without a repeat it is slideAnchor.
std::pair<Anchor, Repeat> slideRow(const ExtrusionSpec& s, Anchor anchor, Repeat repeat, double metres);
ExtrusionSpec slideStep(ExtrusionSpec s, int step, double metres);
ExtrusionSpec slideFeature(ExtrusionSpec s, int feature, double metres);

}  // namespace corbel::extrude::pushpull
