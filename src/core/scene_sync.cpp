#include "core/scene_sync.h"

#include "core/massing.h"

#include <ranges>
#include <vector>

namespace corbel {

MeshData buildObject(const DocObject& object, Kind* kind) {
  return std::visit(
      [&](const auto& spec) -> MeshData {
        using T = std::decay_t<decltype(spec)>;
        if constexpr (std::is_same_v<T, BoxSpec>) {
          *kind = Kind::Mass;
          return buildBoxes(spec);
        }
      },
      object.spec);
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
  }
  std::size_t rebuilt = 0, done = 0;
  for (const DocObject& o : doc.objects) {
    if (progress && progress->cancelled()) break;
    auto it = built_.find(o.id);
    if (it == built_.end() || !(it->second.spec == o.spec) || !scene.hasObject(o.id)) {
      Kind kind = Kind::Mass;
      MeshData mesh = buildObject(o, &kind);
      scene.replaceObject(o.id, kind, o.name, mesh);
      built_[o.id] = o;
      ++rebuilt;
    } else if (it->second.name != o.name) {
      scene.setObjectName(o.id, o.name);
      it->second.name = o.name;
    }
    if (progress) progress->report(static_cast<double>(++done) / doc.objects.size(), "building objects");
  }
  return rebuilt;
}

}  // namespace corbel
