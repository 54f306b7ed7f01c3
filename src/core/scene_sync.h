#pragma once
// Keeps a Scene in step with a Document: re-runs the kernel of each object whose spec changed,
// places each object's geometry by its placement (core/placement.h; a change of placement alone
// moves the last build without running the kernel) and removes objects that are gone. The application's one path from inputs to geometry.
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
  // The mesh is already where it stands (world space) and the object's placement does not apply
  // to it: a KIFS building meshed on the object it follows (kifs/follow.h).
  bool worldSpace = false;
};
// Spec → geometry; throws (InputError or Error) with a message a user can act on, or
// Cancelled when the progress (may be null) is cancelled. A pure function of the object: it
// may run on any thread.
using Builder = std::function<BuildResult(const DocObject&, Progress*)>;
// Other objects of the Document a build reads (a growth site grown around the Document's unit
// objects): chosen when a job is planned and handed to the builder as copies, so the build stays
// a pure function of what it was given; the object is rebuilt whenever they change.
using Inputs = std::function<std::vector<DocObject>(const Document&, const DocObject&)>;
using InputBuilder = std::function<BuildResult(const DocObject&, const std::vector<DocObject>& inputs, Progress*)>;

class SceneSync {
 public:
  SceneSync();  // the box kernel is built in
  // Builders may hold this object's address (buildPlaced), so it stays where it was made.
  SceneSync(const SceneSync&) = delete;
  SceneSync& operator=(const SceneSync&) = delete;
  // Registers the builder of the spec alternative with index `specIndex` in Spec.
  void setBuilder(std::size_t specIndex, Builder builder);
  template <class SpecT>
  void setBuilder(Builder builder) {
    setBuilder(indexOf<SpecT>(), std::move(builder));
  }
  // A builder that also reads other objects, which `inputs` picks from the Document.
  void setBuilder(std::size_t specIndex, Inputs inputs, InputBuilder builder);
  template <class SpecT>
  void setBuilder(Inputs inputs, InputBuilder builder) {
    setBuilder(indexOf<SpecT>(), std::move(inputs), std::move(builder));
  }

  // The other objects of `doc` that `o`'s builder reads (empty: none, or a builder that reads
  // its object only).
  std::vector<DocObject> inputsOf(const Document& doc, const DocObject& o) const;
  // Runs `o`'s builder on `inputs` (inputsOf) and places the result as the Scene would hold it
  // (world space), for a builder that stands on another object's shell (a KIFS building meshed
  // on the object it follows). Throws what the builder throws. Safe on any thread.
  MeshData buildPlaced(const DocObject& o, const std::vector<DocObject>& inputs, Progress* progress) const;

  // Returns the number of objects rebuilt. Cancelling leaves the Scene consistent with the
  // objects already processed; a later call finishes the work.
  std::size_t update(const Document& doc, Scene& scene, Progress* progress = nullptr);

  // The same update in three steps, so that the kernels can run off the UI thread (see
  // LiveSync): plan() and apply() touch the Scene and this object's records, run() only
  // calls the builders. A job's results are applied even when the document has moved on
  // since it was planned; the next plan() then picks up what changed after it.
  struct Job {
    std::vector<DocObject> build;  // objects to (re)build, as the document had them
    std::vector<std::vector<DocObject>> inputs;  // per build entry: the other objects it reads
    std::vector<ObjectId> gone;    // objects to remove from the Scene
    std::vector<std::pair<ObjectId, std::string>> renamed;
    // Objects whose placement alone changed: their last build is placed again, no kernel runs.
    std::vector<std::pair<ObjectId, Placement>> moved;
    struct Outcome {
      bool ran = false;  // false: not reached (cancelled before it)
      BuildResult result;
      std::string error;  // the builder failed with this
    };
    std::vector<Outcome> outcomes;  // run() fills one per build entry
    bool empty() const { return build.empty() && gone.empty() && renamed.empty() && moved.empty(); }
  };
  Job plan(const Document& doc, const Scene& scene) const;
  void run(Job& job, Progress* progress = nullptr) const;  // safe on any thread
  std::size_t apply(Job& job, Scene& scene);               // returns the objects rebuilt
  void invalidate() { built_.clear(); }
  // The next plan() rebuilds this object even though its spec did not change (its builder
  // reads a setting outside the Document that changed: the editor's view maps).
  void invalidate(ObjectId id) { built_.erase(id); }

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
  std::vector<Inputs> inputs_;  // by spec index; empty: the builder reads its object only
  std::vector<InputBuilder> builders_;
  std::map<ObjectId, DocObject> built_;  // what each object was last built (or tried) from
  std::map<ObjectId, std::vector<DocObject>> builtInputs_;  // ... and the other objects it read
  // Each object's last good build in its own frame, before its placement, with its kind.
  struct Unplaced {
    Kind kind = Kind::Mass;
    MeshData mesh;
    bool worldSpace = false;  // BuildResult::worldSpace: the placement does not apply
  };
  std::map<ObjectId, Unplaced> unplaced_;
  std::map<ObjectId, Status> status_;
};

}  // namespace corbel
