#pragma once
// Keeps a Scene in step with a Document: re-runs the kernel of each object whose spec changed
// and removes objects that are gone. The application's one path from inputs to geometry.
#include "core/document.h"
#include "core/progress.h"
#include "core/scene.h"

#include <map>

namespace corbel {

class SceneSync {
 public:
  // Returns the number of objects rebuilt. Cancelling leaves the Scene consistent with the
  // objects already processed; a later call finishes the work.
  std::size_t update(const Document& doc, Scene& scene, Progress* progress = nullptr);
  void invalidate() { built_.clear(); }

 private:
  std::map<ObjectId, DocObject> built_;  // what each Scene object was built from
};

// Runs the object's kernel (pure: spec → geometry).
MeshData buildObject(const DocObject& object, Kind* kind);

}  // namespace corbel
