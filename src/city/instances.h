#pragma once
// A town's features (windows, sills, doors, roof windows, chimney pots) gathered for instanced
// export: each placement is filed under the mesh of its shape (kind, size and a pot's reach
// down, extrude::FeaturePlacement), built once in its own frame with the style's tag materials
// (docs/export.md, "Instances").
#include "city/style.h"
#include "core/instances.h"
#include "extrude/features.h"

#include <functional>
#include <map>
#include <tuple>
#include <vector>

namespace corbel::city {

class FeatureInstances {
 public:
  explicit FeatureInstances(const Style& style) : style_(style) {}

  // Files each feature under its shape's mesh (made the first time the shape is met). With
  // `place`, a feature's placement is handed to place(mesh number, placement) rather than kept in
  // the mesh's placements (a glb writer's GlbWriter::place, which holds them on disk).
  void add(const std::vector<extrude::FeaturePlacement>& features,
           const std::function<void(std::size_t, const RigidPlacement&)>& place = nullptr);
  const std::vector<InstancedMesh>& meshes() const { return meshes_; }
  std::size_t placements() const;
  void clear();

 private:
  using Shape = std::tuple<int, double, double, double, double>;  // kind, width, height, depth, sink
  const Style& style_;
  std::map<Shape, std::size_t> index_;
  std::vector<InstancedMesh> meshes_;
};

}  // namespace corbel::city
