#include "core/scene_sync.h"

#include "core/error.h"
#include "core/massing.h"

#include <ranges>
#include <vector>

namespace corbel {

SceneSync::SceneSync() : inputs_(std::variant_size_v<Spec>), builders_(std::variant_size_v<Spec>) {
  setBuilder<BoxSpec>([](const DocObject& o, Progress*) {
    BuildResult r;
    r.kind = Kind::Mass;
    r.mesh = buildBoxes(std::get<BoxSpec>(o.spec));
    return r;
  });
}

void SceneSync::setBuilder(std::size_t specIndex, Builder builder) {
  InputBuilder b;
  if (builder) b = [builder = std::move(builder)](const DocObject& o, const std::vector<DocObject>&, Progress* p) { return builder(o, p); };
  setBuilder(specIndex, nullptr, std::move(b));
}

void SceneSync::setBuilder(std::size_t specIndex, Inputs inputs, InputBuilder builder) {
  if (specIndex < builders_.size()) {
    inputs_[specIndex] = std::move(inputs);
    builders_[specIndex] = std::move(builder);
  }
  built_.clear();
  builtInputs_.clear();
  unplaced_.clear();
}

std::vector<DocObject> SceneSync::inputsOf(const Document& doc, const DocObject& o) const {
  const Inputs& pick = inputs_[o.spec.index()];
  return pick ? pick(doc, o) : std::vector<DocObject>{};
}

MeshData SceneSync::buildPlaced(const DocObject& o, const std::vector<DocObject>& inputs, Progress* progress) const {
  const InputBuilder& b = builders_[o.spec.index()];
  if (!b) throw Error("this build of corbel has no kernel for this kind of object");
  BuildResult r = b(o, inputs, progress);
  if (!r.worldSpace) applyPlacement(r.mesh, o.placement);
  return std::move(r.mesh);
}

SceneSync::Job SceneSync::plan(const Document& doc, const Scene& scene) const {
  Job job;
  for (const auto& [id, _] : built_)
    if (!doc.find(id)) job.gone.push_back(id);
  for (ObjectId id : scene.objects() | std::views::keys)
    if (!doc.find(id) && !built_.count(id)) job.gone.push_back(id);
  for (const DocObject& o : doc.objects) {
    auto it = built_.find(o.id);
    const auto st = status_.find(o.id);
    const bool failedBefore = st != status_.end() && !st->second.error.empty();
    std::vector<DocObject> inputs = inputsOf(doc, o);
    bool stale = it == built_.end() || !(it->second.spec == o.spec) || (!scene.hasObject(o.id) && !failedBefore);
    if (!stale && inputs_[o.spec.index()]) {
      const auto was = builtInputs_.find(o.id);
      stale = was == builtInputs_.end() ? !inputs.empty() : was->second != inputs;
    }
    if (stale) {
      job.build.push_back(o);
      job.inputs.push_back(std::move(inputs));
      continue;
    }
    if (it->second.name != o.name) job.renamed.emplace_back(o.id, o.name);
    if (!(it->second.placement == o.placement)) job.moved.emplace_back(o.id, o.placement);
  }
  return job;
}

void SceneSync::run(Job& job, Progress* progress) const {
  job.outcomes.assign(job.build.size(), {});
  for (std::size_t i = 0; i < job.build.size(); ++i) {
    if (progress && progress->cancelled()) return;
    const DocObject& o = job.build[i];
    Job::Outcome& out = job.outcomes[i];
    try {
      const InputBuilder& b = builders_[o.spec.index()];
      if (!b) throw Error("this build of corbel has no kernel for this kind of object");
      static const std::vector<DocObject> none;
      out.result = b(o, i < job.inputs.size() ? job.inputs[i] : none, progress);
      out.ran = true;
    } catch (const Cancelled&) {
      return;  // this object and the rest stay as they were; a later job rebuilds them
    } catch (const std::exception& e) {
      out.error = e.what();  // the last good geometry (if any) stays in the Scene
      out.ran = true;
    }
    if (progress) progress->report(static_cast<double>(i + 1) / job.build.size(), "building objects");
  }
}

std::size_t SceneSync::apply(Job& job, Scene& scene) {
  for (ObjectId id : job.gone) {
    scene.removeObject(id);
    built_.erase(id);
    builtInputs_.erase(id);
    unplaced_.erase(id);
    status_.erase(id);
  }
  for (const auto& [id, name] : job.renamed) {
    if (!scene.hasObject(id)) continue;
    scene.setObjectName(id, name);
    if (auto it = built_.find(id); it != built_.end()) it->second.name = name;
  }
  std::size_t rebuilt = 0;
  for (const auto& [id, placement] : job.moved) {
    auto b = built_.find(id);
    if (b == built_.end()) continue;
    b->second.placement = placement;
    const auto u = unplaced_.find(id);
    if (u == unplaced_.end() || u->second.worldSpace || !scene.hasObject(id)) continue;
    MeshData placed = u->second.mesh;
    applyPlacement(placed, placement);
    scene.replaceObject(id, u->second.kind, b->second.name, placed);
    ++rebuilt;
  }
  for (std::size_t i = 0; i < job.build.size() && i < job.outcomes.size(); ++i) {
    Job::Outcome& out = job.outcomes[i];
    if (!out.ran) continue;
    const DocObject& o = job.build[i];
    built_[o.id] = o;
    if (i < job.inputs.size() && inputs_[o.spec.index()]) builtInputs_[o.id] = job.inputs[i];
    else builtInputs_.erase(o.id);
    Status& st = status_[o.id];
    if (!out.error.empty()) {
      st.error = out.error;
      // The last good geometry stays, placed where the object now is.
      if (const auto u = unplaced_.find(o.id); u != unplaced_.end() && scene.hasObject(o.id)) {
        MeshData placed = u->second.mesh;
        if (!u->second.worldSpace) applyPlacement(placed, o.placement);
        scene.replaceObject(o.id, u->second.kind, o.name, placed);
      }
      continue;
    }
    MeshData placed = out.result.mesh;
    if (!out.result.worldSpace) applyPlacement(placed, o.placement);
    unplaced_[o.id] = {out.result.kind, std::move(out.result.mesh), out.result.worldSpace};
    scene.replaceObject(o.id, out.result.kind, o.name, placed);
    st.error.clear();
    st.warnings = std::move(out.result.warnings);
    ++rebuilt;
  }
  return rebuilt;
}

std::size_t SceneSync::update(const Document& doc, Scene& scene, Progress* progress) {
  Job job = plan(doc, scene);
  run(job, progress);
  return apply(job, scene);
}

}  // namespace corbel
