#pragma once
// Feature meshes at mesh anchors (Kelly & Wonka, Sec. 3.4 and Fig. 28): a door, a window, a
// roof window and a chimney pot, each a few closed, outward-oriented polyhedra built in the
// anchor's frame. Their control points are the corners of the outer outline (width × height
// from the anchor) and the corners inset from them by fixed thicknesses, so resizing a
// feature stretches its panes and keeps its frame, sill and step as thick as before.
#include "core/mesh_data.h"
#include "extrude/extrude.h"

#include <string>
#include <vector>

namespace corbel::extrude {

// The fixed thicknesses (m) between the control points. A thickness larger than a quarter of
// the feature's width or height is reduced to that quarter, so a small feature still has a pane.
struct FeatureDimensions {
  double doorFrame = 0.08;       // jambs, head and threshold of a door
  double doorStepHeight = 0.15;  // the step under a door
  double doorStepDepth = 0.3;    // how far the step reaches out of the wall
  double doorStepOverhang = 0.1; // how far the step reaches past the frame on each side
  double windowFrame = 0.06;
  double sillHeight = 0.06;      // a window's sill, under the frame
  double sillOverhang = 0.05;    // past the frame on each side and in front of it
  double roofWindowFrame = 0.07;
  double potRim = 0.04;          // a chimney pot's rim: how far it stands out
  double potRimHeight = 0.08;
  int potSides = 8;
};
const FeatureDimensions& featureDimensions();

// One closed polyhedron: points in world coordinates, faces counter-clockwise from outside.
struct FeaturePart {
  std::string name;      // "frame", "leaf", "step", "pane", "sill", "pot", "rim"
  std::string material;  // a built-in material
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

// The parts of a feature of `kind` and `size` placed at `frame`:
//  door: bottom centre at the anchor, its back on the face; a step (the full width plus the
//        overhang, doorStepHeight high), on it a frame ring `depth` deep, and a leaf filling
//        the frame's opening, half as deep (set back by depth / 2).
//  window: bottom centre of the frame at the anchor; the frame ring `depth` deep, a pane in
//        its opening depth / 2 deep, a sill under it.
//  roof window: as a window without a sill, in the plane of the face (up the slope).
//  chimney pot: stands straight up (world z) centred on the anchor; an n-sided prism whose
//        footprint has width (along the edge) and depth (across) as diameters, reaching down
//        below the anchor far enough to meet a sloped face under its whole footprint, with a
//        rim round its top.
// Nothing for FeatureKind::None.
std::vector<FeaturePart> featureParts(FeatureKind kind, const FeatureSize& size, const AnchorFrame& frame);

// Where a feature stands and what fixes its shape: the parts are built in the frame (origin,
// ex, ey, ez; orthonormal, right-handed) from the kind, the size and, for a chimney pot, how far
// it reaches below its anchor (`sink`, rounded up to the millimetre). Features equal in kind,
// size and sink have equal parts in their own frames: a town writes them once (docs/export.md).
struct FeaturePlacement {
  FeatureKind kind = FeatureKind::None;
  FeatureSize size;
  double sink = 0;
  Vec3 origin{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
};
FeaturePlacement featurePlacement(FeatureKind kind, const FeatureSize& size, const AnchorFrame& frame);
// The parts where the placement puts them, or with `own`, in the feature's own frame (the
// placement's origin at 0 and its axes as x, y, z).
std::vector<FeaturePart> featureParts(const FeaturePlacement& placement, bool own = false);

// Tag of a feature's faces ("door", "window", "roof_window", "chimney_pot").
std::string featureTag(FeatureKind kind);

// Appends a feature's parts to `mesh`: their own vertices, the kind's tag, each part's material.
void appendParts(MeshData& mesh, FeatureKind kind, const std::vector<FeaturePart>& parts);

// Appends every instanced feature of the extrusion to `mesh` (its own vertices, tag and
// materials), or with `apart`, its placement there in place of its parts; an instance whose
// anchor was not placed adds a warning naming the feature.
void appendFeatures(MeshData& mesh, const ExtrusionSpec& spec, const ExtrusionResult& result,
                    std::vector<std::string>& warnings, std::vector<FeaturePlacement>* apart = nullptr);

// A feature of an extrusion where its anchor put it, with its parts there (world coordinates).
struct PlacedFeature {
  FeaturePlacement placement;
  std::vector<FeaturePart> parts;
};
// Every instanced feature of the extrusion, in the order appendFeatures adds them, with the
// same warnings for instances whose anchors were not placed.
std::vector<PlacedFeature> placeFeatures(const ExtrusionSpec& spec, const ExtrusionResult& result,
                                         std::vector<std::string>& warnings);
// Appends the parts of `features` to `mesh` as appendFeatures does (their own vertices, the
// feature's tag, each part's material).
void appendFeatures(MeshData& mesh, const std::vector<PlacedFeature>& features);

}  // namespace corbel::extrude
