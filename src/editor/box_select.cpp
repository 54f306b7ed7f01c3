#include "editor/box_select.h"

#include <algorithm>
#include <set>

namespace corbel::editor {

std::optional<Vec2> projectToWindow(const Viewport& view, const Vec3& p) {
  const glm::dvec4 c = view.camera.projection(view.aspect()) * view.camera.view() * glm::dvec4(p[0], p[1], p[2], 1.0);
  if (c.w <= 1e-12) return std::nullopt;
  const double x = c.x / c.w, y = c.y / c.w;
  return Vec2(view.x() + (x + 1.0) * 0.5 * view.width(), view.y() + (1.0 - y) * 0.5 * view.height());
}

std::vector<ObjectId> objectsInBox(const Scene& scene, const Viewport& view, const Vec2& a, const Vec2& b,
                                   const std::function<bool(ObjectId)>& pickable,
                                   const std::vector<std::pair<ObjectId, BBox>>& extra) {
  const double x0 = std::min(a[0], b[0]), x1 = std::max(a[0], b[0]), y0 = std::min(a[1], b[1]),
               y1 = std::max(a[1], b[1]);
  auto inside = [&](const Vec3& p) {
    const auto w = projectToWindow(view, p);
    return w && (*w)[0] >= x0 && (*w)[0] <= x1 && (*w)[1] >= y0 && (*w)[1] <= y1;
  };
  std::set<ObjectId> out;
  const PolyMesh& mesh = scene.mesh();
  for (const auto& [id, faces] : scene.facesByObject()) {
    if (pickable && !pickable(id)) continue;
    bool hit = false;
    for (auto f = faces.begin(); f != faces.end() && !hit; ++f)
      for (auto v : mesh.fv_range(*f))
        if (inside(mesh.point(v))) {
          hit = true;
          break;
        }
    if (hit) out.insert(id);
  }
  for (const auto& [id, box] : extra) {
    if ((pickable && !pickable(id)) || box.empty()) continue;
    for (int corner = 0; corner < 8; ++corner)
      if (inside(Vec3(corner & 1 ? box.hi[0] : box.lo[0], corner & 2 ? box.hi[1] : box.lo[1],
                      corner & 4 ? box.hi[2] : box.lo[2]))) {
        out.insert(id);
        break;
      }
  }
  return {out.begin(), out.end()};
}

}  // namespace corbel::editor
