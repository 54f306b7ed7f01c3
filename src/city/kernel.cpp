#include "city/kernel.h"

#include "city/street.h"

#include "core/error.h"
#include "core/placement.h"
#include "core/project_io.h"
#include "extrude/kernel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>

namespace corbel::city {

namespace {

std::uint64_t fnv1a(const std::string& text, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// A building's inputs as one hash: its styled extrusion spec (footprint, labels, type,
// profiles, features) written as the project format writes specs, and the detail.
std::uint64_t inputHash(const extrude::ExtrusionSpec& spec, const std::string& type, Detail detail) {
  Document d;
  d.objects.push_back({1, "b", true, spec, std::nullopt, {}, {}, false});
  return fnv1a(serializeProject(d) + type + std::to_string(static_cast<int>(detail)));
}

std::string fileStamp(const std::string& path) {
  std::error_code ec;
  const auto t = std::filesystem::last_write_time(path, ec);
  const auto size = std::filesystem::file_size(path, ec);
  return path + "@" + std::to_string(t.time_since_epoch().count()) + ":" + std::to_string(size);
}

// Rethrows a fault of the footprints or the style under the spec's key.
template <class F>
auto under(const std::string& key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(key, e.what());
  } catch (const Error& e) {
    throw InputError(key, e.what());
  }
}

}  // namespace

Detail detailFromName(const std::string& name) {
  if (name == "massing") return Detail::Massing;
  if (name == "steps") return Detail::Steps;
  if (name == "full") return Detail::Full;
  throw InputError("town.detail", "expected \"massing\", \"steps\" or \"full\", found \"" + name + "\"");
}

TownInputs readTownInputs(const TownSpec& spec) {
  if (auto problem = checkTownSpec(spec)) {
    const auto colon = problem->find(": ");
    throw InputError("town." + problem->substr(0, colon), problem->substr(colon + 2));
  }
  TownInputs in;
  in.style = under("town.style", [&] { return spec.style.empty() ? parseStyle(spec.styleJson) : loadStyle(spec.style); });
  ReadOptions read;
  read.crs = spec.crs;
  read.layer = spec.layer;
  read.where = spec.where;
  in.town = under("town.footprints", [&] {
    return spec.footprints.empty() ? readTown(spec.footprintsJson, read) : readTownFile(spec.footprints, read);
  });
  try {
    addStreets(in.town, spec.streets);
  } catch (const InputError& e) {
    throw InputError("town." + e.where, e.reason);
  }
  in.labels = labelTown(in.town, in.style.labels);
  return in;
}

std::map<std::string, BuildingOverride> resolveOverrides(const Style& style, const TownSpec& spec) {
  std::map<std::string, BuildingOverride> out;
  for (const auto& [id, o] : spec.overrides) {
    const std::string at = "town.overrides[\"" + id + "\"]";
    BuildingOverride r;
    // The style's profile of that name; a missing one throws at `where`.
    const auto profileIndex = [&style](const std::string& name, const std::string& where) {
      for (std::size_t i = 0; i < style.profiles.size(); ++i)
        if (style.profiles[i].name == name) return static_cast<int>(i);
      throw InputError(where, "the style \"" + style.name + "\" has no profile named \"" + name + "\"");
    };
    if (!o.type.empty()) {
      for (std::size_t i = 0; i < style.types.size(); ++i)
        if (style.types[i].name == o.type) r.type = i;
      if (!r.type) throw InputError(at + ".type", "the style \"" + style.name + "\" has no type named \"" + o.type + "\"");
    }
    for (const auto& [side, name] : o.profiles) {
      const auto orientation = orientationFromName(side);
      if (!orientation) throw InputError(at + ".profiles", "expected \"street\", \"side\" or \"back\", found \"" + side + "\"");
      r.profiles[*orientation] = profileIndex(name, at + ".profiles." + side);
    }
    for (const auto& [key, name] : o.edges) {
      const auto edge = parseTownEdgeKey(key);
      if (!edge) throw InputError(at + ".edges", "expected an edge \"LOOP:EDGE\" (as \"0:3\"), found \"" + key + "\"");
      r.edges[*edge] = profileIndex(name, at + ".edges[\"" + key + "\"]");
    }
    out[id] = std::move(r);
  }
  return out;
}

std::shared_ptr<const TownInputs> TownCache::inputsFor(ObjectId object, const TownSpec& spec) {
  std::string key = (spec.footprints.empty() ? spec.footprintsJson : fileStamp(spec.footprints)) + "\n" + spec.crs +
                    "\n" + spec.layer + "\n" + spec.where + "\n" +
                    (spec.style.empty() ? spec.styleJson : fileStamp(spec.style));
  // The streets make plots and change labels: they are inputs too (every number, exactly).
  char number[32];
  for (const TownStreet& st : spec.streets) {
    key += "\nstreet";
    for (const auto& p : st.points)
      for (double v : p) std::snprintf(number, sizeof number, " %a", v), key += number;
    for (double v : {st.width, st.setback, st.depth, st.plotWidth})
      std::snprintf(number, sizeof number, " %a", v), key += number;
    key += st.bothSides ? " both" : " left";
    key += st.skeletonPlots ? " skeleton" : " normals";
  }
  {
    std::lock_guard lock(mutex_);
    auto it = inputs_.find(object);
    if (it != inputs_.end() && it->second.key == key) return it->second.inputs;
  }
  auto inputs = std::make_shared<const TownInputs>(readTownInputs(spec));
  std::lock_guard lock(mutex_);
  inputs_[object] = {key, inputs};
  return inputs;
}

BuildResult TownCache::build(const DocObject& object, Progress* progress, std::size_t chunk) {
  const TownSpec& spec = std::get<TownSpec>(object.spec);
  if (progress) progress->report(0, "reading footprints");
  const std::shared_ptr<const TownInputs> in = inputsFor(object.id, spec);
  const Detail detail = detailFromName(spec.detail);
  const std::map<std::string, BuildingOverride> overrides = resolveOverrides(in->style, spec);
  for (const auto& [id, o] : spec.overrides) {
    const Building* found = nullptr;
    for (const Building& b : in->town.buildings)
      if (b.id == id) found = &b;
    if (!found) throw InputError("town.overrides[\"" + id + "\"]", "no footprint has this id");
    // An edge override must name an edge of the cleaned footprint.
    for (const auto& [key, name] : o.edges) {
      const auto [loop, edge] = *parseTownEdgeKey(key);
      const std::string at = "town.overrides[\"" + id + "\"].edges[\"" + key + "\"]";
      if (found->loops.empty()) throw InputError(at, "the footprint has no plan to override: " + found->problem);
      if (loop >= static_cast<int>(found->loops.size()))
        throw InputError(at, "the footprint has " + std::to_string(found->loops.size()) + " loop(s) (0 to " +
                                 std::to_string(found->loops.size() - 1) + ")");
      if (edge >= static_cast<int>(found->loops[loop].size()))
        throw InputError(at, "loop " + std::to_string(loop) + " of the footprint has " +
                                 std::to_string(found->loops[loop].size()) + " edges (0 to " +
                                 std::to_string(found->loops[loop].size() - 1) + ")");
    }
  }

  // Style every building (cheap) to learn its inputs' hash; extrude only the ones not cached.
  const std::size_t n = in->town.buildings.size();
  std::vector<std::uint64_t> hashes(n, 0);
  std::vector<std::size_t> misses;
  std::vector<char> extruded(n, 0);  // styled without a problem: the batch extrudes it
  std::vector<std::vector<std::string>> adapted(n);  // what the styling changed to build it
  {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < n; ++i) {
      const Building& b = in->town.buildings[i];
      std::string problem = b.problem, type;
      if (problem.empty()) {
        auto it = overrides.find(b.id);
        StyledBuilding s = styleBuilding(in->style, b, in->labels[i], spec.seed, it == overrides.end() ? nullptr : &it->second);
        type = s.type;
        problem = s.problem;
        adapted[i] = std::move(s.warnings);
        if (problem.empty()) hashes[i] = inputHash(s.spec, s.type, detail), extruded[i] = 1;
      }
      if (!problem.empty()) hashes[i] = fnv1a(problem + type);
      auto e = entries_.find({object.id, b.id});
      if (e == entries_.end() || e->second.hash != hashes[i]) misses.push_back(i);
    }
  }
  TownOptions options;
  options.detail = detail;
  options.seed = spec.seed;
  options.chunk = chunk;
  options.overrides = &overrides;
  options.timeLimitSeconds = extrude::kEditTimeLimitSeconds;
  if (!misses.empty()) {
    const auto sink = [&](const BuildingReport& r, MeshData* mesh) {
      Entry e;
      e.hash = hashes[r.index];
      e.ok = mesh != nullptr;
      e.type = r.type;
      e.error = r.error;
      if (mesh) e.mesh = std::move(*mesh);
      if (extruded[r.index]) ++extrusions_;
      std::lock_guard lock(mutex_);
      entries_[{object.id, r.id}] = std::move(e);
    };
    const auto onChunk = [&](std::size_t done, std::size_t total) {
      if (progress) {
        progress->report(double(done) / double(total),
                         "extruded " + std::to_string(done) + " of " + std::to_string(total) + " buildings");
        if (progress->cancelled()) throw Cancelled();
      }
    };
    if (progress && progress->cancelled()) throw Cancelled();
    buildTown(in->town, in->labels, in->style, options, sink, misses, onChunk);
  }

  // The object's mesh: every built building in footprint order.
  BuildResult out;
  out.kind = Kind::Shell;
  std::vector<BuiltBuilding> list;
  std::lock_guard lock(mutex_);
  for (std::size_t i = 0; i < n; ++i) {
    const Building& b = in->town.buildings[i];
    const Entry& e = entries_.at({object.id, b.id});
    BuiltBuilding bb;
    bb.id = b.id;
    bb.type = e.type;
    bb.hash = e.hash;
    bb.error = e.ok ? std::string() : (e.error.empty() ? b.problem : e.error);
    if (e.ok) {
      bb.firstFace = out.mesh.faces.size();
      bb.faceCount = e.mesh.faces.size();
      for (const Vec3& p : e.mesh.points) bb.bounds.add(p);
      out.mesh.append(e.mesh);
      for (const std::string& w : adapted[i]) out.warnings.push_back("building " + b.id + ": " + w);
    } else {
      out.warnings.push_back("building " + b.id + ": " + bb.error);
    }
    list.push_back(std::move(bb));
  }
  last_[object.id] = std::move(list);
  return out;
}

std::vector<BuiltBuilding> TownCache::buildings(ObjectId object) const {
  std::lock_guard lock(mutex_);
  auto it = last_.find(object);
  return it == last_.end() ? std::vector<BuiltBuilding>{} : it->second;
}

MeshData TownCache::mesh(ObjectId object, const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto it = entries_.find({object, id});
  return it == entries_.end() ? MeshData{} : it->second.mesh;
}

MeshData buildingMesh(const TownCache& cache, const DocObject& town, const std::string& id) {
  const std::vector<BuiltBuilding> built = cache.buildings(town.id);
  if (built.empty()) throw Error("is not built yet");
  const auto it = std::find_if(built.begin(), built.end(), [&](const BuiltBuilding& b) { return b.id == id; });
  if (it == built.end()) throw Error("has no building \"" + id + "\"");
  if (!it->error.empty()) throw Error("building \"" + id + "\" was not built: " + it->error);
  MeshData mesh = cache.mesh(town.id, id);
  applyPlacement(mesh, town.placement);
  return mesh;
}

std::function<MeshData(const DocObject&, const std::string&)> buildingMeshes(std::shared_ptr<const TownCache> cache) {
  return [cache = std::move(cache)](const DocObject& town, const std::string& id) {
    return buildingMesh(*cache, town, id);
  };
}

std::shared_ptr<const TownInputs> TownCache::inputs(ObjectId object) const {
  std::lock_guard lock(mutex_);
  auto it = inputs_.find(object);
  return it == inputs_.end() ? nullptr : it->second.inputs;
}

TagTextures TownCache::tagTextures() const {
  auto styles = std::make_shared<std::map<ObjectId, std::shared_ptr<const TownInputs>>>();
  {
    std::lock_guard lock(mutex_);
    for (const auto& [id, e] : inputs_)
      if (e.inputs && !e.inputs->style.tagTextures.empty()) (*styles)[id] = e.inputs;
  }
  if (styles->empty()) return {};
  return [styles](ObjectId object, const std::string& tag) -> const SurfaceTexture* {
    const auto s = styles->find(object);
    if (s == styles->end()) return nullptr;
    const auto& table = s->second->style.tagTextures;
    const auto it = table.find(tag);
    return it == table.end() ? nullptr : &it->second;
  };
}

std::shared_ptr<TownCache> registerKernel(SceneSync& sync, std::shared_ptr<TownCache> cache) {
  if (!cache) cache = std::make_shared<TownCache>();
  sync.setBuilder<TownSpec>([cache](const DocObject& o, Progress* p) { return cache->build(o, p); });
  return cache;
}

}  // namespace corbel::city
