#pragma once
// The 3D view's navigation beyond orbit and pan: zoom towards the pointer, whether a box is in
// view, and the axis widget in the view's corner (where each axis points on screen, which one
// a click hits, and the side view it turns to). Pure functions of the camera: no GL, no ImGui.
#include "core/geometry.h"
#include "render/camera.h"

#include <array>
#include <optional>

namespace corbel::editor {

// Zooms by `steps` wheel steps (the camera's factor 0.88 a step) keeping the point under the
// pointer where it is: the point of the plane through the target, facing the camera, at
// normalised device coordinates (ndcX, ndcY) ∈ [−1, 1]² (y up) stays at those coordinates.
void zoomTowards(render::OrbitCamera& camera, double ndcX, double ndcY, double aspect, double steps);

// Whether every corner of `box` projects inside the view (and in front of the near plane for a
// perspective camera). An empty box is in view.
bool boxInView(const render::OrbitCamera& camera, double aspect, const BBox& box);

// The axis widget: a circle of radius kAxisWidgetRadius whose centre lies kAxisWidgetInset
// pixels left of the view's right edge and below its top.
inline constexpr float kAxisWidgetRadius = 42.0f;
inline constexpr float kAxisWidgetInset = 56.0f;
inline constexpr float kAxisKnobRadius = 9.0f;  // the clickable end of each axis

// The six axis ends, in the order +X, +Y, +Z, −X, −Y, −Z.
struct AxisEnd {
  int axis = 0;       // 0, 1, 2 for X, Y, Z
  bool positive = true;
  float dx = 0, dy = 0;  // screen offset from the widget's centre (pixels, y down)
  double depth = 0;      // towards the viewer: the larger, the nearer (drawn last)
};
std::array<AxisEnd, 6> axisEnds(const render::OrbitCamera& camera, float radius = kAxisWidgetRadius);

// The axis end a click at offset (dx, dy) from the widget's centre hits (the nearest to the
// viewer when knobs overlap), or none.
std::optional<AxisEnd> axisEndAt(const render::OrbitCamera& camera, float dx, float dy);

// The side view an axis end turns to: the camera looks from that end towards the target
// (+X: Right, −X: Left, +Y: Back, −Y: Front, +Z: Top, −Z: Bottom).
render::CameraPreset presetOfAxis(const AxisEnd& end);

}  // namespace corbel::editor
