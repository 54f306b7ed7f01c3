#include "editor/shape_gallery.h"

#include "extrude/edit.h"

namespace corbel::editor {

GalleryInfo galleryInfo(GalleryShape shape) {
  switch (shape) {
    case GalleryShape::Rectangle: return {"rectangle", "Rectangle", "A 12 × 8 m rectangle."};
    case GalleryShape::L: return {"l", "L", "An L: 12 × 10 m without its 6 × 5 m upper right quarter."};
    case GalleryShape::T: return {"t", "T", "A T: a 14 × 5 m bar on a 6 × 7 m stem."};
    case GalleryShape::U: return {"u", "U", "A U: 14 × 10 m with a 6 × 6 m notch from the top."};
    case GalleryShape::Courtyard:
      return {"courtyard", "Courtyard", "A 16 × 16 m block round an 8 × 8 m courtyard (a loop with a hole)."};
  }
  return {"", "", ""};
}

std::vector<std::vector<Vec2>> galleryLoops(GalleryShape shape, Vec2 at) {
  auto loop = [&](std::initializer_list<std::pair<double, double>> pts) {
    std::vector<Vec2> l;
    for (const auto& [x, y] : pts) l.push_back(at + Vec2(x, y));
    return l;
  };
  switch (shape) {
    case GalleryShape::Rectangle: return {loop({{0, 0}, {12, 0}, {12, 8}, {0, 8}})};
    case GalleryShape::L: return {loop({{0, 0}, {12, 0}, {12, 5}, {6, 5}, {6, 10}, {0, 10}})};
    case GalleryShape::T: return {loop({{4, 0}, {10, 0}, {10, 7}, {14, 7}, {14, 12}, {0, 12}, {0, 7}, {4, 7}})};
    case GalleryShape::U: return {loop({{0, 0}, {14, 0}, {14, 10}, {10, 10}, {10, 4}, {4, 4}, {4, 10}, {0, 10}})};
    case GalleryShape::Courtyard:
      return {loop({{0, 0}, {16, 0}, {16, 16}, {0, 16}}), loop({{4, 4}, {4, 12}, {12, 12}, {12, 4}})};
  }
  return {};
}

ExtrusionSpec galleryExtrusion(GalleryShape shape, Vec2 at) {
  ExtrusionSpec e;
  e.profiles.push_back(extrude::edit::profileLibrary()[1]);  // hip
  e.roofMaterial = "roof_tile";
  for (std::vector<Vec2>& points : galleryLoops(shape, at)) {
    const std::size_t n = points.size();
    e.loops.push_back({std::move(points), std::vector<int>(n, 0)});
  }
  return e;
}

}  // namespace corbel::editor
