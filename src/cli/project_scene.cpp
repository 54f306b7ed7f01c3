#include "cli/project_scene.h"

#include "core/error.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "extrude/kernel.h"
#include "growth/kernel.h"
#include "kifs/kernel.h"
#include "statics/kernel.h"

#include <iostream>

namespace corbel::cli {

LoadedScene loadScene(const std::string& path) {
  LoadedScene l;
  LoadedProject p = loadProject(path);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << path << ": " << w << "\n";
  l.doc = std::move(p.document);
  SceneSync sync;
  extrude::registerKernel(sync);
  statics::registerKernel(sync);
  kifs::registerKernel(sync);
  growth::registerKernel(sync);
  l.towns = city::registerKernel(sync);
  sync.update(l.doc, l.scene);
  for (const auto& [id, st] : sync.status()) {
    const DocObject* o = l.doc.find(id);
    const std::string name = o ? o->name : std::to_string(id);
    for (const auto& w : st.warnings) std::cerr << "corbel-cli: warning: " << name << ": " << w << "\n";
    if (!st.error.empty()) throw Error(path + ": object \"" + name + "\": " + st.error);
  }
  return l;
}

}  // namespace corbel::cli
