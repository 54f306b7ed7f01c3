#include "editor/kifs_followers.h"

#include "core/error.h"
#include "kifs/kernel.h"

namespace corbel::editor {

namespace {

bool sameMass(const DocObject& a, const DocObject& b) {
  return a.id == b.id && a.name == b.name && a.spec == b.spec && a.placement == b.placement;
}

bool isFollower(const DocObject& o) {
  const auto* k = std::get_if<KifsSpec>(&o.spec);
  return k && k->meshResolution == 0 && k->mass.footprint == "object";
}

}  // namespace

bool KifsFollowers::update(const Document& doc, const Scene& scene, bool sceneCurrent,
                           const std::function<bool(ObjectId)>& visible,
                           const std::function<void(const std::string&, bool)>& log, bool wait,
                           const kifs::TownBuildings& buildings) {
  bool arrived = false;
  // Followers that are gone, or follow no more, are dropped (their jobs cancelled and joined).
  for (auto it = entries_.begin(); it != entries_.end();) {
    const DocObject* o = doc.find(it->first);
    it = o && isFollower(*o) ? std::next(it) : entries_.erase(it);
  }
  for (const DocObject& o : doc.objects) {
    if (!isFollower(o) || (visible && !visible(o.id))) continue;
    Entry& e = entries_[o.id];
    auto report = [&](const std::string& error) {
      if (error != e.error && !error.empty() && log) log("KIFS building " + o.name + ": " + error, true);
      e.error = error;
    };
    auto collect = [&] {
      if (!e.job || !(wait || e.job->finished())) return;
      e.job->wait();
      try {
        e.job->rethrow();
        if (!e.job->progress().cancelled()) {
          e.done = *e.running;
          arrived = true;
          report("");
        }
      } catch (const Cancelled&) {
      } catch (const std::exception& ex) {
        report(ex.what());
      }
      e.job.reset();
    };
    collect();
    const DocObject* mass = nullptr;
    int resolution = 0;
    const KifsSpec& spec = std::get<KifsSpec>(o.spec);
    try {
      mass = &kifs::followedObject(doc, o);
      resolution = kifs::paramsOf(spec).mass.resolution;
    } catch (const std::exception& ex) {
      report(ex.what());
      continue;
    }
    auto matches = [&](const Bake& b) {
      return sameMass(b.mass, *mass) && b.building == spec.mass.building && b.resolution == resolution;
    };
    if (e.done && matches(*e.done)) continue;
    if (e.job && matches(*e.running)) continue;
    if (!sceneCurrent) continue;  // the Scene still shows the mass as it was
    if (e.job) e.job.reset();     // cancels and joins the bake of an older mass
    kifs::TriangleSoup triangles;
    try {
      triangles = kifs::massTriangles(*mass, spec, scene, buildings);
    } catch (const std::exception& ex) {
      report(ex.what());
      continue;
    }
    auto bake = std::make_shared<Bake>();
    bake->mass = *mass;
    bake->building = spec.mass.building;
    bake->resolution = resolution;
    e.running = bake;
    const kifs::KifsParams params = kifs::paramsOf(spec);
    e.job = std::make_unique<BackgroundJob>(
        "Baking the mass of " + o.name, [bake, params, triangles = std::move(triangles)](Progress& progress) {
          bake->field = kifs::bakeFollowedMass(bake->mass, triangles, params, &progress);
        });
    collect();  // scripted runs wait for it
  }
  return arrived;
}

std::vector<KifsFollowers::Shown> KifsFollowers::shown(const Document& doc,
                                                       const std::function<bool(ObjectId)>& visible) const {
  std::vector<Shown> out;
  for (const DocObject& o : doc.objects) {
    if (!isFollower(o) || (visible && !visible(o.id))) continue;
    const auto it = entries_.find(o.id);
    if (it == entries_.end() || !it->second.done) continue;
    try {
      out.push_back({o.id, kifs::paramsOf(std::get<KifsSpec>(o.spec)), it->second.done->field});
    } catch (const std::exception&) {
      // a spec the kernel refuses: its build error says why
    }
  }
  return out;
}

bool KifsFollowers::baking() const {
  for (const auto& [id, e] : entries_)
    if (e.job) return true;
  return false;
}

}  // namespace corbel::editor
