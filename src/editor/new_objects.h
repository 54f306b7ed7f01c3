#pragma once
// What Object > Add makes, besides the shape gallery (shape_gallery.h): where a new object goes
// beside the scene, a starter growth site, and a masonry object from one of the statics
// kernel's templates. Pure: the App commits them. No GL.
#include "core/geometry.h"
#include "core/growth_spec.h"
#include "core/masonry_spec.h"

#include <string>
#include <vector>

namespace corbel::editor {

// The lower left corner of a plan `depth` deep placed 4 m right of `scene` and centred on it in
// y; the origin for an empty scene.
Vec2 besideScene(const BBox& scene, double depth);

// A 30 × 20 m site of 3 storeys round one 4 × 4 m core with a landing north and south of it on
// every storey and 8 seeds generated at their exits, its envelope's lower left corner at `at`;
// grown until every unit stops.
GrowthSpec starterGrowthSite(Vec2 at);

// The statics kernel's templates as Add offers them: model name and a label in words.
struct MasonryTemplate {
  std::string model;  // statics::exampleByName's name
  std::string label;  // "Arch on columns (Fig. 8)"
  bool example = false;  // a composed example (under Masonry > Examples), not a template alone
};
std::vector<MasonryTemplate> masonryTemplates();
MasonrySpec masonryObject(const std::string& model);
// The bounds of a masonry object's blocks, ground included, in its own frame. Throws
// corbel::Error when the model refuses the spec.
BBox masonryBounds(const MasonrySpec& spec);

}  // namespace corbel::editor
