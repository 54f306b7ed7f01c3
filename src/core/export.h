#pragma once
// Export of the Scene: OBJ (+ .mtl), PLY, OFF and binary glTF 2.0, chosen by extension.
// OBJ, PLY and OFF keep corbel's frame (meters, Z up); glTF is Y up as its spec requires.
#include "core/scene.h"
#include "core/textures.h"

#include <functional>
#include <string>

namespace corbel {

struct ExportOptions {
  // Which objects to write (all when empty).
  std::function<bool(ObjectId)> include;
  // glb only: a procedural texture (core/textures.h) per built-in material, embedded as PNG,
  // with TEXCOORD_0 from each face's plane in its material's primitives.
  bool textures = false;
  // With textures: the texture an object's tagged faces show in place of their material's (a
  // city style's tag_textures); none when empty or null.
  TagTextures tagTextures;
};

enum class ExportFormat { Obj, Ply, Off, Glb };
// From the file extension; throws corbel::Error for an unknown one.
ExportFormat exportFormatFor(const std::string& path);

// Writes atomically (a temporary sibling renamed over the target). Throws corbel::Error.
void exportScene(const Scene& scene, const std::string& path, const ExportOptions& options = {});

}  // namespace corbel
