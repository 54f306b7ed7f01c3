#pragma once
// A project file loaded and built into a Scene by every kernel, for the commands that work on
// the built geometry (render, export, check, statics --scene).
#include "city/kernel.h"
#include "core/document.h"
#include "core/scene.h"

#include <memory>
#include <string>

namespace corbel::cli {

struct LoadedScene {
  Document doc;
  Scene scene;
  std::shared_ptr<city::TownCache> towns;  // their styles' tag textures
};

// Loads `path`, prints its warnings and the kernels' warnings to stderr, and throws Error
// naming the object whose build failed.
LoadedScene loadScene(const std::string& path);

}  // namespace corbel::cli
