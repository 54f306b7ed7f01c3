#pragma once
// The shape gallery of Object > Add > Extrusion: plans an artist starts a building from, each
// on the profile library's hip roof. Outer loops counter-clockwise, holes clockwise, as the
// extrusion kernel wants them (core/extrusion_spec.h); sizes in metres, the plan's lower left
// corner at `at`. No GL.
#include "core/extrusion_spec.h"
#include "core/geometry.h"

#include <string>
#include <vector>

namespace corbel::editor {

enum class GalleryShape { Rectangle, L, T, U, Courtyard };

inline constexpr GalleryShape kGalleryShapes[] = {GalleryShape::Rectangle, GalleryShape::L, GalleryShape::T,
                                                  GalleryShape::U, GalleryShape::Courtyard};

struct GalleryInfo {
  const char* id;     // "rectangle": the action is object.add_extrusion_<id>
  const char* label;  // "Rectangle"
  const char* help;   // its size in words
};
GalleryInfo galleryInfo(GalleryShape shape);

// The shape's loops with its lower left corner at `at`:
//   Rectangle 12 × 8; L 12 × 10 without its 6 × 5 upper right quarter; T a 14 × 5 bar on a
//   6 × 7 stem; U 14 × 10 without a 6 × 6 notch from the top middle; Courtyard 16 × 16 round
//   an 8 × 8 hole in its middle.
std::vector<std::vector<Vec2>> galleryLoops(GalleryShape shape, Vec2 at = Vec2(0, 0));

// The shape as a procedural extrusion: every edge on the hip profile, roof tiles on plaster.
ExtrusionSpec galleryExtrusion(GalleryShape shape, Vec2 at = Vec2(0, 0));

}  // namespace corbel::editor
