#pragma once
// Dimensions in the plan and profile panes (SketchUp's measurements box): the length of a plan
// edge, the length and pitch of a profile segment, and the spec changes that give one a typed
// length exactly. GL-free; the panes draw the labels and take the typed value
// (editor/typed_value.h).
#include "core/extrusion_spec.h"

namespace corbel::editor {

// The length of edge `edge` of loop `loop` (from its corner `edge` to the next).
double planEdgeLength(const ExtrusionSpec& spec, int loop, int edge);

// The edge given `length` by moving its end corner (edge + 1) along the edge; its start and
// every other corner stay. A dragged corner takes a typed length so for the edge arriving at
// it, along where the drag has it. Throws InputError where the length is not positive and finite or
// the edge has no length (no direction to keep).
ExtrusionSpec setPlanEdgeLength(const ExtrusionSpec& spec, int loop, int edge, double length);

// Profile segment `segment` (points segment → segment + 1) of profile `profile`: its length,
// and its pitch in degrees from the ground (90 for a wall, 0 for a flat overhang, towards
// inside positive).
double profileSegmentLength(const ExtrusionSpec& spec, int profile, int segment);
double profileSegmentPitch(const ExtrusionSpec& spec, int profile, int segment);

// The segment given `length` along its own direction; the points above it move with its upper
// end, so the rest of the profile keeps its shape. Throws InputError as setPlanEdgeLength does.
ExtrusionSpec setProfileSegmentLength(const ExtrusionSpec& spec, int profile, int segment, double length);

}  // namespace corbel::editor
