#pragma once
// Keeps a Scene in step with a Document: re-runs the kernel of each object whose spec changed
// and removes objects that are gone. The application's one path from inputs to geometry.
//
// Kernels live in their own libraries and register a Builder for their spec type; core only
// knows the mass-model box. An object whose kernel fails keeps its last good geometry and the
// failure is reported (problems()).
#include "core/document.h"
#include "core/progress.h"
#include "core/scene.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace corbel {

struct BuildResult {
  MeshData mesh;
  Kind kind = Kind::Mass;
  std::vector<std::string> warnings;
};
// Spec → geometry; throws (InputError or Error) with a message a user can act on.
using Builder = std::function<BuildResult(const DocObject&)>;

class SceneSync {
 public:
  SceneSync();  // the box kernel is built in
  // Registers the builder of the spec alternative with index `specIndex` in Spec.
  void setBuilder(std::size_t specIndex, Builder builder);
  template <class SpecT>
  void setBuilder(Builder builder) {
    setBuilder(indexOf<SpecT>(), std::move(builder));
  }

  // Returns the number of objects rebuilt. Cancelling leaves the Scene consistent with the
  // objects already processed; a later call finishes the work.
  std::size_t update(const Document& doc, Scene& scene, Progress* progress = nullptr);
  void invalidate() { built_.clear(); }

  struct Status {
    std::string error;                  // the last build failed with this ("" = fine)
    std::vector<std::string> warnings;  // from the last successful build
  };
  // Per object: what the last build said.
  const std::map<ObjectId, Status>& status() const { return status_; }

 private:
  template <class SpecT, std::size_t I = 0>
  static constexpr std::size_t indexOf() {
    if constexpr (std::is_same_v<std::variant_alternative_t<I, Spec>, SpecT>) return I;
    else return indexOf<SpecT, I + 1>();
  }
  std::vector<Builder> builders_;
  std::map<ObjectId, DocObject> built_;  // what each object was last built (or tried) from
  std::map<ObjectId, Status> status_;
};

}  // namespace corbel
