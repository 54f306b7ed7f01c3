#pragma once
// What an export writes of a built project (docs/export.md): the Scene as built, with every
// KIFS building the view ray-marches meshed into it, and each town split into one object per
// building named by its footprint's id, as `corbel-cli city` writes them. Nothing the view
// shows is left out of the file.
#include "city/kernel.h"
#include "core/document.h"
#include "core/export.h"
#include "core/scene.h"
#include "core/textures.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace corbel::compose {

// Cells along a ray-marched KIFS building's longest side when it is meshed for an export.
inline constexpr int kExportKifsResolution = 96;

struct ExportableScene {
  Scene scene;                     // the objects to write, and only those
  std::vector<std::string> notes;  // what was meshed or split for the file
  // The towns' buildings, textured as the city command writes them, with their styles' tag
  // textures (ExportOptions::textured, ::tagTextures).
  std::function<bool(ObjectId)> textured;
  TagTextures tagTextures;
  // Where the first exported town with georeferenced footprints lies, and its data's
  // attribution (ExportOptions::georeference, ::copyright; docs/city.md).
  ExportOptions::Georeference georeference;
  std::string copyright;
  // The placement of each written object that has one (a town's buildings take the town's):
  // its vertices are written placed, and the glb says how (ExportOptions::placements).
  std::map<ObjectId, Placement> placements;
};

// `include` picks the document's objects (null: the visible ones); `kifsResolution` is used
// for ray-marched KIFS buildings (0: kExportKifsResolution). `towns` is the cache the Scene's
// towns were built with (null when none).
ExportableScene exportableScene(const Document& doc, const Scene& built, const city::TownCache* towns,
                                const std::function<bool(ObjectId)>& include, int kifsResolution = 0);

}  // namespace corbel::compose
