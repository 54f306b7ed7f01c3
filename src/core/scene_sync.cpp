#include "core/scene_sync.h"

#include "core/error.h"
#include "core/massing.h"

#include <ranges>
#include <vector>

namespace corbel {

SceneSync::SceneSync() : builders_(std::variant_size_v<Spec>) {
  setBuilder<BoxSpec>([](const DocObject& o) {
    BuildResult r;
    r.kind = Kind::Mass;
    r.mesh = buildBoxes(std::get<BoxSpec>(o.spec));
    return r;
  });
}

void SceneSync::setBuilder(std::size_t specIndex, Builder builder) {
  if (specIndex < builders_.size()) builders_[specIndex] = std::move(builder);
  built_.clear();
}

std::size_t SceneSync::update(const Document& doc, Scene& scene, Progress* progress) {
  std::vector<ObjectId> gone;
  for (const auto& [id, _] : built_)
    if (!doc.find(id)) gone.push_back(id);
  for (ObjectId id : scene.objects() | std::views::keys)
    if (!doc.find(id) && !built_.count(id)) gone.push_back(id);
  for (ObjectId id : gone) {
    scene.removeObject(id);
    built_.erase(id);
    status_.erase(id);
  }
  std::size_t rebuilt = 0, done = 0;
  for (const DocObject& o : doc.objects) {
    if (progress && progress->cancelled()) break;
    auto it = built_.find(o.id);
    const bool failedBefore = status_.count(o.id) && !status_[o.id].error.empty();
    const bool stale = it == built_.end() || !(it->second.spec == o.spec) || (!scene.hasObject(o.id) && !failedBefore);
    if (stale) {
      built_[o.id] = o;
      Status& st = status_[o.id];
      const Builder& b = builders_[o.spec.index()];
      try {
        if (!b) throw Error("this build of corbel has no kernel for this kind of object");
        BuildResult r = b(o);
        scene.replaceObject(o.id, r.kind, o.name, r.mesh);
        st.error.clear();
        st.warnings = std::move(r.warnings);
        ++rebuilt;
      } catch (const Cancelled&) {
        built_.erase(o.id);
        throw;
      } catch (const std::exception& e) {
        st.error = e.what();  // the last good geometry (if any) stays in the Scene
      }
    } else if (it->second.name != o.name) {
      scene.setObjectName(o.id, o.name);
      it->second.name = o.name;
    }
    if (progress) progress->report(static_cast<double>(++done) / doc.objects.size(), "building objects");
  }
  return rebuilt;
}

}  // namespace corbel
