#pragma once
// Procedural seamless textures of the built-in materials (brick courses, roof tiles, slate,
// plaster, stone, concrete, timber boards, glass panes, metal seams, grass) and the UV of a
// point on a face from the face's plane, for the glb's baseColorTexture (docs/city.md).
#include "core/geometry.h"
#include "core/scene_properties.h"

#include <functional>
#include <string>
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
// The names materialTexture knows, in a fixed order (the renderer's texture layers).
const std::vector<std::string_view>& builtinTextureNames();

// A texture that faces show in textured output (the glb, the renderer's textured mode) in place
// of their material's: a built-in texture by name and the metres of one repeat (0: the
// texture's own tile). City styles give one per tag (`tag_textures`, docs/city.md).
struct SurfaceTexture {
  std::string name;
  double metres = 0;
  bool operator==(const SurfaceTexture&) const = default;
};
// The texture of an object's faces with a tag, or null for "by material". The Scene stores the
// tag of every face; what a tag shows comes with the export or render options (from the style).
using TagTextures = std::function<const SurfaceTexture*(ObjectId object, const std::string& tag)>;

// What a face shows when textured: its own texture (a style's tag texture; may be null) if that
// names a built-in one, else its material's built-in one; `metres` is one repeat on the building.
// `texture` is null when neither is built in (the face keeps its colour).
struct TextureUse {
  std::string_view name;
  const MaterialTexture* texture = nullptr;
  double metres = 1;
  bool own = false;  // the face's own texture, not its material's
};
TextureUse textureFor(const SurfaceTexture* own, std::string_view material);

// Coordinates in metres of point p on a plane of unit normal n: on a wall u runs along the
// wall (to the right seen from outside) and v up; on a sloped face u runs along the contour and
// v up the slope; on a horizontal face (|n.z| > 0.999) (u, v) = (x, y). Divide by
// MaterialTexture::metres for texture coordinates.
Vec2 planeUv(const Vec3& p, const Vec3& n);

// The texture coordinates of a face's corners `poly` (unit normal n) for a repeat of `metres`:
// planeUv / metres, shifted by whole repeats so that they stay small (float precision across a
// town) with the smallest u and the smallest (flipped) v in [0, 1), and v flipped (v runs down the image,
// as in glTF, and as a texture uploaded top row first samples), so the image's top is up on the
// building. The renderer's textured mode uses this; the glb shifts planeUv by whole repeats per
// patch of faces instead (docs/export.md), which looks the same.
void faceTextureCoordinates(const std::vector<Vec3>& poly, const Vec3& n, double metres, std::vector<Vec2>& out);

}  // namespace corbel
