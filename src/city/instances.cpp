#include "city/instances.h"

#include <cstdio>

namespace corbel::city {

void FeatureInstances::add(const std::vector<extrude::FeaturePlacement>& features,
                           const std::function<void(std::size_t, const RigidPlacement&)>& place) {
  for (const extrude::FeaturePlacement& f : features) {
    const Shape shape{static_cast<int>(f.kind), f.size.width, f.size.height, f.size.depth, f.sink};
    auto [it, fresh] = index_.try_emplace(shape, meshes_.size());
    if (fresh) {
      InstancedMesh m;
      char size[96];
      std::snprintf(size, sizeof size, " %gx%gx%g", f.size.width, f.size.height, f.size.depth);
      m.name = extrude::featureTag(f.kind) + size;
      if (f.kind == FeatureKind::ChimneyPot) {
        std::snprintf(size, sizeof size, " sink %g", f.sink);
        m.name += size;
      }
      const int tag = m.mesh.addTag(extrude::featureTag(f.kind));
      for (const extrude::FeaturePart& part : extrude::featureParts(f, true)) {
        const int base = static_cast<int>(m.mesh.points.size());
        const int material = m.mesh.addMaterial(part.material);
        for (const Vec3& q : part.points) m.mesh.addPoint(q);
        for (std::vector<int> loop : part.faces) {
          for (int& v : loop) v += base;
          m.mesh.addFace(std::move(loop), tag, material);
        }
      }
      applyTagMaterials(style_, m.mesh);
      meshes_.push_back(std::move(m));
    }
    const RigidPlacement p{f.origin, f.ex, f.ey, f.ez};
    if (place)
      place(it->second, p);
    else
      meshes_[it->second].placements.push_back(p);
  }
}

std::size_t FeatureInstances::placements() const {
  std::size_t n = 0;
  for (const InstancedMesh& m : meshes_) n += m.placements.size();
  return n;
}

void FeatureInstances::clear() {
  index_.clear();
  meshes_.clear();
}

}  // namespace corbel::city
