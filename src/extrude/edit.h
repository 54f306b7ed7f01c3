#pragma once
// Editing operations on an extrusion spec, as the editor's plan and profile panes perform them
// (Kelly & Wonka, Sec. 3). Each takes the spec, changes a copy and returns it, or throws
// InputError naming what is wrong; none leaves a half-made change. The same operations drive
// scripted editing (edit scripts: one JSON object per operation, see applyEdit), so a test can
// do exactly what a user does.
#include "core/document.h"
#include "extrude/spec.h"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace corbel::extrude::edit {

using EdgeRef = std::pair<int, int>;  // (loop, edge)

// Plan. Anchored things (steps, mesh anchors) belong to walls (core/extrusion_spec.h):
// - insertCorner splits an edge; both halves stay on its wall, so nothing anchored moves;
// - deleteCorner: the edge arriving at the corner runs on to the next one. Within one wall,
//   anchors keep their places along it. Where it joins two walls, an anchor whose point lies
//   on the joined wall keeps that point, one of the arriving edge's wall keeps its place along
//   the edge that turned, and one of the other wall is removed;
// - moveCorner keeps every anchor's fraction along its wall;
// - deleteLoop removes what is anchored on the loop.
// What is removed is named in `notes` ("removed feature \"door\": its wall went with ...").
ExtrusionSpec insertCorner(ExtrusionSpec s, int loop, int edge, const Vec2& at, std::vector<std::string>* notes = nullptr);
ExtrusionSpec deleteCorner(ExtrusionSpec s, int loop, int corner, std::vector<std::string>* notes = nullptr);
ExtrusionSpec moveCorner(ExtrusionSpec s, int loop, int corner, const Vec2& to);
// A new loop with every edge on `profile` and a wall of its own; drawn inside an odd number
// of loops it is a hole, so its orientation is set to match whichever way it was drawn.
ExtrusionSpec addLoop(ExtrusionSpec s, std::vector<Vec2> points, int profile);
ExtrusionSpec deleteLoop(ExtrusionSpec s, int loop, std::vector<std::string>* notes = nullptr);
ExtrusionSpec setEdgeProfile(ExtrusionSpec s, const std::vector<EdgeRef>& edges, int profile);

// Profiles. Point 0 stays at (0, 0); z never decreases along a profile (a dragged point is
// clamped between its neighbours' heights).
ExtrusionSpec insertProfilePoint(ExtrusionSpec s, int profile, int after, const Vec2& wz);
ExtrusionSpec deleteProfilePoint(ExtrusionSpec s, int profile, int point);
ExtrusionSpec moveProfilePoint(ExtrusionSpec s, int profile, int point, const Vec2& wz);
Vec2 clampProfilePoint(const Profile& p, int point, const Vec2& wz);
// "Add overhang" (Sec. 3.3): every profile that spans the absolute height (above the base)
// gets a horizontal segment there reaching `depth` metres outward, the rest of the profile
// moving out with it: one change to all. Main edges' profiles get it at `height`, a step's
// (which start at its anchor's height a; a grid's first row) at height − a, an offset
// event's at height less the event's; profiles that start at or above it get none. A profile
// used from several start heights is copied for each but the lowest (the users moved to it).
ExtrusionSpec addOverhang(ExtrusionSpec s, double height, double depth);
ExtrusionSpec setSegmentTag(ExtrusionSpec s, int profile, int segment, const std::string& tag);
// Adds a copy of a library profile under a free name; returns its index in `index`.
ExtrusionSpec addProfile(ExtrusionSpec s, Profile p, int* index = nullptr);

// Angle snapping of the plan pane (its Snap toggle): the edge being drawn or dragged turns to
// the nearest allowed direction and the point moves onto it. Allowed directions are parallel
// or perpendicular to a reference edge (a neighbour), preferred when one lies within half a
// step of the pointer's direction, else multiples of `stepDeg` from the plan's x axis. The
// snapped point is the pointer's orthogonal projection onto the snapped ray from `from`;
// `lengthStep` > 0 also rounds the edge's length to a multiple of it (at least one).
// A step outside (0, 90] degrees, or a pointer on `from`, leaves the point where it is.
enum class SnapKind { Axis, Parallel, Perpendicular };
struct SnapGuide {
  Vec2 from, direction;  // the guide line (direction is a unit vector)
  SnapKind kind = SnapKind::Axis;
};
struct AngleSnap {
  Vec2 point;
  std::vector<SnapGuide> guides;  // empty when nothing snapped
};
AngleSnap snapEdgeAngle(const Vec2& from, const Vec2& to, double stepDeg, const std::vector<Vec2>& references,
                        double lengthStep = 0);
// A corner between the fixed corners `prev` and `next` (dragged or inserted): both of its
// edges snap, each with its own references (the edge before `prev`, the edge after `next`),
// and the corner goes where the two snapped lines meet. When they are (nearly) parallel, meet
// behind either corner, or farther from the pointer than half the shorter edge, only the edge
// whose snap moves the pointer least is snapped.
AngleSnap snapCornerAngles(const Vec2& prev, const Vec2& next, const Vec2& to, double stepDeg,
                           const std::vector<Vec2>& prevReferences, const std::vector<Vec2>& nextReferences);

// Anchored features.
ExtrusionSpec addStep(ExtrusionSpec s, const PlanStep& step);
// A forced step (Sec. 3.5) from a polygon drawn on the plan in world coordinates, for input
// edge (loop, edge) at `height` above the base: its anchor is relative, at the point of the
// edge nearest the polygon (the middle of the stretch it covers when it reaches the edge), and
// its points are the polygon in that anchor's frame (u along the edge, v outward, as
// PlanStep::points). Refuses fewer than three corners, non-finite or repeated corners, a
// self-intersecting polygon and one enclosing no area, each with a reason.
struct ForcedStepFrame {
  Anchor anchor;
  std::vector<Vec2> points;
};
ForcedStepFrame forcedStepFrame(const ExtrusionSpec& s, int loop, int edge, const std::vector<Vec2>& world, double height);
ExtrusionSpec addForcedStep(ExtrusionSpec s, int loop, int edge, const std::vector<Vec2>& world, double height,
                            int frontProfile, const std::string& name = "forced step");
ExtrusionSpec moveAnchor(ExtrusionSpec s, int step, const Anchor& anchor);
ExtrusionSpec deleteStep(ExtrusionSpec s, int step);
// A row (or grid) of the same step (Sec. 3.6); RepeatKind::None removes it.
ExtrusionSpec setStepRepeat(ExtrusionSpec s, int step, const Repeat& repeat);

// Mesh anchors with their feature meshes (Sec. 3.4, Fig. 28). The anchor must name an edge of
// the plan, sizes must be positive, and a repeat must stay within the instance limit.
ExtrusionSpec addMeshAnchor(ExtrusionSpec s, const MeshAnchor& anchor);
ExtrusionSpec moveMeshAnchor(ExtrusionSpec s, int index, const Anchor& anchor);  // the repeat's last place stays
ExtrusionSpec deleteMeshAnchor(ExtrusionSpec s, int index);
ExtrusionSpec setFeatureSize(ExtrusionSpec s, int index, const FeatureSize& size);
ExtrusionSpec setFeatureRepeat(ExtrusionSpec s, int index, const Repeat& repeat);

// The library of Sec. 3 profiles the panes offer.
std::vector<Profile> profileLibrary();

// Applies one edit-script operation to a document, e.g.
//   {"op": "move_corner", "object": "House", "loop": 0, "corner": 2, "to": [10, 6]}
// Operations: new_extrusion {name, points, profile: library name}, insert_corner, delete_corner,
// move_corner, add_loop {points, profile}, delete_loop {loop}, set_edge_profile {edges: [[loop, edge]...], profile},
// add_profile {from: library name, as: name}, insert_profile_point {profile, after, at},
// move_profile_point {profile, point, to}, delete_profile_point, add_overhang {height, depth},
// set_tag {profile, segment, tag}, add_step {step: as in the project file}, add_forced_step
// {loop, edge, points: [[x, y]...] on the plan, height, profile, name (optional)}, move_anchor,
// delete_step, set_step_repeat {step, repeat}, add_feature {name, feature, anchor, size,
// repeat} (size and repeat optional), move_feature {index, anchor}, set_feature_size {index,
// size: [w, h, d]}, set_feature_repeat {index, repeat}, delete_feature {index}. A repeat is
// {kind: "row" | "grid" | "none", along, spacing, height, row_spacing} as in the project file.
// set_background {image, scale, origin, opacity} (the plan pane's tracing image; fields left
// out keep their value) and clear_background change the object, not its spec.
// Profiles are named; the label for undo is returned, and what an edit removed (anchored
// things whose wall went) is named in `notes`.
std::string applyEdit(Document& doc, const nlohmann::json& op, std::vector<std::string>* notes = nullptr);

}  // namespace corbel::extrude::edit
