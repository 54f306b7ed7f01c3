#pragma once
// Shared by the kernels' tests: one object of a Document built into a Scene by a SceneSync
// with the kernels the test registers.
#include "core/document.h"
#include "core/scene.h"
#include "core/scene_sync.h"

#include <functional>

namespace corbel::test {

struct OneObject {
  Document doc;
  Scene scene;
  SceneSync sync;
  ObjectId id = 0;
  OneObject(Spec spec, const std::function<void(SceneSync&)>& registerKernels) {
    id = doc.add("object", std::move(spec));
    registerKernels(sync);
    sync.update(doc, scene);
  }
  const SceneSync::Status& status() const { return sync.status().at(id); }
  const std::string& error() const { return status().error; }
};

}  // namespace corbel::test
