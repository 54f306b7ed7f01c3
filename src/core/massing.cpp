#include "core/massing.h"

#include <cmath>
#include <numbers>

namespace corbel {

MeshData buildBoxes(const BoxSpec& s) {
  MeshData out;
  const int wall = out.addTag("wall"), roof = out.addTag("roof"), base = out.addTag("base");
  const int mat = out.addMaterial(s.material);
  const double a = s.rotation_deg * std::numbers::pi / 180.0;
  const double c = std::cos(a), sn = std::sin(a);
  const double hx = 0.5 * s.size[0], hy = 0.5 * s.size[1];
  for (int j = 0; j < s.repeat_y; ++j) {
    for (int i = 0; i < s.repeat_x; ++i) {
      // Copy centre in the box's own frame, the grid centred on the origin.
      const double cx = (i - 0.5 * (s.repeat_x - 1)) * s.spacing_x;
      const double cy = (j - 0.5 * (s.repeat_y - 1)) * s.spacing_y;
      int v[8];
      for (int k = 0; k < 8; ++k) {
        const double lx = cx + ((k & 1) ? hx : -hx);
        const double ly = cy + ((k & 2) ? hy : -hy);
        const double z = s.origin[2] + ((k & 4) ? s.size[2] : 0.0);
        v[k] = out.addPoint(Vec3(s.origin[0] + c * lx - sn * ly, s.origin[1] + sn * lx + c * ly, z));
      }
      out.addFace({v[0], v[2], v[3], v[1]}, base, mat);  // z-, normal down
      out.addFace({v[4], v[5], v[7], v[6]}, roof, mat);  // z+, normal up
      out.addFace({v[0], v[1], v[5], v[4]}, wall, mat);  // y-
      out.addFace({v[1], v[3], v[7], v[5]}, wall, mat);  // x+
      out.addFace({v[3], v[2], v[6], v[7]}, wall, mat);  // y+
      out.addFace({v[2], v[0], v[4], v[6]}, wall, mat);  // x-
    }
  }
  return out;
}

}  // namespace corbel
