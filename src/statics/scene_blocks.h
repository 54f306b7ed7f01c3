#pragma once
// Blocks read from the Scene (Whiting et al. 2009, Sec. 3.1, "rigid blocks"): every connected
// piece of an object's surface one block, convex or not, with the density of its material;
// pieces tagged "ground" fixed; nonstructural shapes carried as loads by the blocks they rest
// on, with no contacts of their own. See docs/statics.md, "Blocks from the Scene".
#include "core/scene.h"
#include "statics/model.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace corbel::statics {

// Density in kg/m³ of a material name (core/materials.h), `overrides` first. "" is stone.
// Throws corbel::Error naming the material when neither knows it.
double materialDensity(std::string_view material, const std::map<std::string, double>& overrides = {});

struct SceneBlockOptions {
  // The objects whose pieces are blocks, whatever their kind; empty: every object of kind Block.
  std::vector<ObjectId> objects;
  // Objects whose pieces are carried as loads (also every piece with a face tagged
  // "nonstructural" in the objects above).
  std::vector<ObjectId> nonstructural;
  std::map<std::string, double> densities;  // kg/m³ by material name, before the built-in table
  // When no piece is tagged "ground": a fixed slab whose top is the plane through the lowest
  // point of the blocks (so what stands on the ground plane stands on it).
  bool groundPlane = true;
};

// Where one block of the assembly came from.
struct SceneBlockOrigin {
  ObjectId object = 0;  // 0 for the ground plane's slab
  int piece = -1;       // index of the connected piece within the object's faces
  std::string material;
};

struct SceneAssembly {
  Assembly assembly;
  std::vector<SceneBlockOrigin> origins;  // one per block of `assembly`
  int nonstructuralPieces = 0;            // carried as point loads
  double nonstructuralWeight = 0;         // their weight, N
  bool groundPlaneAdded = false;
};

// Throws corbel::Error naming the object and piece for a piece that is not a closed block, a
// material without a density, a nonstructural piece resting on no block, or no block at all.
SceneAssembly assemblyFromScene(const Scene& scene, const SceneBlockOptions& options = {});

}  // namespace corbel::statics
