#pragma once
// Procedural seamless textures of the built-in materials (brick courses, roof tiles, slate,
// plaster, stone, concrete, timber boards, glass panes, metal seams, grass) and the UV of a
// point on a face from the face's plane, for the glb's baseColorTexture (docs/city.md).
#include "core/geometry.h"

#include <string_view>
#include <vector>

namespace corbel {

struct MaterialTexture {
  int size = 0;                    // pixels per side; square, RGB, rows from the top
  std::vector<unsigned char> rgb;  // size * size * 3
  double metres = 1;               // the side of one tile on the building, in metres
};

// The texture of a built-in material, generated once (thread-safe); nullptr for any other name.
const MaterialTexture* materialTexture(std::string_view name);

// Coordinates in metres of point p on a plane of unit normal n: on a wall u runs along the
// wall (to the right seen from outside) and v up; on a sloped face u runs along the contour and
// v up the slope; on a horizontal face (|n.z| > 0.999) (u, v) = (x, y). Divide by
// MaterialTexture::metres for texture coordinates.
Vec2 planeUv(const Vec3& p, const Vec3& n);

}  // namespace corbel
