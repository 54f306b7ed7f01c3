#pragma once
// Export of the Scene: OBJ (+ .mtl), PLY, OFF and binary glTF 2.0, chosen by extension
// (docs/export.md). Meters; OBJ is Y up by default (the convention of the programs that read
// it), PLY and OFF keep corbel's Z up, glTF is Y up as its spec requires.
#include "core/instances.h"
#include "core/placement.h"
#include "core/scene.h"
#include "core/textures.h"

#include <functional>
#include <map>
#include <string>

namespace corbel {

enum class UpAxis { Default, Y, Z };

struct ExportOptions {
  // Which objects to write (all when empty).
  std::function<bool(ObjectId)> include;
  // OBJ, PLY and OFF: the axis that points up in the file. Default: Y for OBJ, Z for PLY and
  // OFF. glb is always Y up.
  UpAxis up = UpAxis::Default;
  // glb only: a procedural texture (core/textures.h) per built-in material, embedded as PNG,
  // with TEXCOORD_0 from each face's plane in its material's primitives.
  bool textures = false;
  // glb only: which objects are textured, in place of `textures` (null: `textures` for all).
  std::function<bool(ObjectId)> textured;
  // With textures: the texture an object's tagged faces show in place of their material's (a
  // city style's tag_textures); none when empty or null.
  TagTextures tagTextures;
  // glb only: where the scene's origin lies on the Earth, written to the scene's extras as
  // "georeference": {crs, proj, origin: [lon, lat, height], axes}; none when `proj` is empty.
  // `proj` is the PROJ definition of the metric frame the scene is in (x east, y north, z up:
  // glTF's +X, −Z and +Y); `crs` names the CRS the data came in.
  struct Georeference {
    std::string crs, proj;
    double lon = 0, lat = 0, height = 0;  // degrees (WGS 84), metres
  } georeference;
  // glb only: the asset's copyright, e.g. the ODbL attribution of OpenStreetMap data.
  std::string copyright;
  // glb only: the placement (core/placement.h) each object's vertices were moved by. The
  // vertices stay placed; the node's extras record it as "corbel_placement" so a reader can
  // take a town back to its georeferenced frame (docs/export.md).
  std::map<ObjectId, Placement> placements;
  // glb only: meshes written once each and placed many times (EXT_mesh_gpu_instancing), beside
  // the scene's objects; none when null. Other formats refuse them.
  const std::vector<InstancedMesh>* instances = nullptr;
  // glb only: the geometry's buffer views compressed by meshoptimizer (EXT_meshopt_compression,
  // then required). Other formats refuse it.
  bool compress = false;
};

enum class ExportFormat { Obj, Ply, Off, Glb };
// From the file extension; throws corbel::Error for an unknown one.
ExportFormat exportFormatFor(const std::string& path);

// Writes atomically (a temporary sibling renamed over the target). Throws corbel::Error.
void exportScene(const Scene& scene, const std::string& path, const ExportOptions& options = {});

// A name as one token for OBJ's `o` and `usemtl`: letters, digits, '-', '_' and '.' are kept,
// anything else (spaces, ':', '#', other bytes) becomes '_'; an empty name becomes "_".
std::string objToken(const std::string& name);

}  // namespace corbel
