#pragma once
// Box select in the 3D view (Blender's B, or Ctrl+left drag): the objects with any part inside
// a rectangle of the window. No GL.
#include "core/scene.h"
#include "editor/viewport.h"

#include <functional>
#include <optional>
#include <vector>

namespace corbel::editor {

// Where a point of the scene appears in the window (pixels, top-left origin), or nullopt when
// it lies behind the camera.
std::optional<Vec2> projectToWindow(const Viewport& view, const Vec3& p);

// The objects `pickable` accepts (null: all) that have a vertex (or, for `extra` objects
// without faces such as ray-marched KIFS buildings, a corner of their bounds) projecting into
// the rectangle between the window points a and b, in id order.
std::vector<ObjectId> objectsInBox(const Scene& scene, const Viewport& view, const Vec2& a, const Vec2& b,
                                   const std::function<bool(ObjectId)>& pickable,
                                   const std::vector<std::pair<ObjectId, BBox>>& extra = {});

}  // namespace corbel::editor
