#pragma once
// What a ray meets first in a Scene: the 3D view's click selection. Every face of the visible
// objects is tried (triangulated as the renderer draws it); a box test per object skips the
// ones the ray misses, so a click on a town costs one pass over the objects it crosses.
#include "core/scene.h"

#include <functional>
#include <optional>

namespace corbel {

struct ScenePick {
  ObjectId object = 0;
  PolyMesh::FaceHandle face;
  double t = 0;  // along the ray, in units of `direction`'s length
};

// The nearest face of an object `visible` accepts (null: every object) that the ray
// origin + t·direction, t > 0, meets; nullopt when it meets none.
std::optional<ScenePick> pickScene(const Scene& scene, const Vec3& origin, const Vec3& direction,
                                   const std::function<bool(ObjectId)>& visible = nullptr);

}  // namespace corbel
