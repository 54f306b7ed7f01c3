#pragma once
// The masses the editor's KIFS followers stand on (footprint "object", kifs/follow.h), baked on
// worker threads: a follower's field is baked again when the object it follows is edited (its
// spec, its placement) or its resolution changes, and the view keeps the last field until the
// new one is in, so editing a house under a fractal facade never stalls a frame. No GL.
#include "core/document.h"
#include "core/progress.h"
#include "core/scene.h"
#include "kifs/follow.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace corbel::editor {

class KifsFollowers {
 public:
  // A follower the view can draw: its parameters and the baked mass (world space).
  struct Shown {
    ObjectId id = 0;
    kifs::KifsParams params;
    std::shared_ptr<const kifs::MassField> mass;
  };

  // Once per frame. `sceneCurrent`: the Scene is built from `doc` (bakes start only then, from
  // the mass object's triangles as the Scene holds them). Collects finished bakes (true when a
  // new field arrived), starts a bake for each visible follower whose mass changed, and logs a
  // follower's error once when it first appears (`log(text, isError)`). `wait` (scripted runs)
  // waits for the bakes it starts. `buildings` gives a town's building to a follower that
  // names one (kifs.mass.building).
  bool update(const Document& doc, const Scene& scene, bool sceneCurrent, const std::function<bool(ObjectId)>& visible,
              const std::function<void(const std::string&, bool)>& log, bool wait,
              const kifs::TownBuildings& buildings = {});
  // The visible followers that have a field, in the Document's order.
  std::vector<Shown> shown(const Document& doc, const std::function<bool(ObjectId)>& visible) const;
  bool baking() const;

 private:
  struct Bake {
    DocObject mass;  // the followed object as the bake saw it
    std::string building;  // the town's building it follows ("" = the whole object)
    int resolution = 0;
    std::shared_ptr<const kifs::MassField> field;
  };
  struct Entry {
    std::optional<Bake> done;                   // the field shown
    std::shared_ptr<Bake> running;              // what the job bakes
    std::unique_ptr<BackgroundJob> job;
    std::string error;                          // the last error logged
  };
  std::map<ObjectId, Entry> entries_;
};

}  // namespace corbel::editor
