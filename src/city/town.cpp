#include "city/town.h"

#include "extrude/batch.h"

#include <future>
#include <iterator>
#include <memory>
#include <numeric>

namespace corbel::city {

namespace {

// Drops points no face uses (merging coplanar faces leaves some): a Scene removes such points
// from the whole mesh after each insertion, which over a town would cost time quadratic in it.
void dropUnusedPoints(MeshData& m) {
  std::vector<int> remap(m.points.size(), -1);
  for (const auto& f : m.faces)
    for (int i : f) remap[i] = 0;
  std::size_t next = 0;
  for (std::size_t i = 0; i < remap.size(); ++i)
    if (remap[i] == 0) {
      m.points[next] = m.points[i];
      remap[i] = static_cast<int>(next++);
    }
  if (next == m.points.size()) return;
  m.points.resize(next);
  for (auto& f : m.faces)
    for (int& i : f) i = remap[i];
}

}  // namespace

TownSummary buildTown(const Town& town, const std::vector<BuildingLabels>& labels, const Style& style,
                      const TownOptions& options, const BuildingSink& sink, const std::vector<std::size_t>& orderIn,
                      const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<std::size_t> order = orderIn;
  if (order.empty()) {
    order.resize(town.buildings.size());
    std::iota(order.begin(), order.end(), 0);
  }
  TownSummary sum;
  sum.buildings = order.size();
  extrude::BatchOptions batch;
  batch.jobs = options.jobs;
  batch.keepMeshes = true;
  batch.mergeCoplanar = options.mergeCoplanar;
  batch.featuresApart = options.featuresApart;
  batch.timeLimitSeconds = options.timeLimitSeconds;
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  // One chunk: its buildings styled, ready to extrude, and their reports.
  struct Chunk {
    std::size_t from = 0, to = 0;
    std::vector<BuildingReport> reports;
    std::vector<extrude::BatchItem> items;
  };
  auto prepare = [&](std::size_t from) {
    auto c = std::make_unique<Chunk>();
    c->from = from;
    c->to = std::min(order.size(), from + chunk);
    c->reports.resize(c->to - from);
    c->items.resize(c->to - from);
    for (std::size_t k = from; k < c->to; ++k) {
      const Building& b = town.buildings[order[k]];
      BuildingReport& r = c->reports[k - from];
      r.index = order[k];
      r.id = b.id;
      r.notes = b.notes;
      extrude::BatchItem& item = c->items[k - from];
      item.id = b.id;
      if (!b.problem.empty()) {
        item.problem = b.problem;
        continue;
      }
      const BuildingOverride* over = nullptr;
      if (options.overrides)
        if (auto it = options.overrides->find(b.id); it != options.overrides->end()) over = &it->second;
      StyledBuilding s = styleBuilding(style, b, labels[order[k]], options.seed, over);
      r.type = s.type;
      r.warnings = std::move(s.warnings);
      item.spec = std::move(s.spec);
      if (options.detail != Detail::Full) item.spec.anchors.clear();
      if (options.detail == Detail::Massing) item.spec.steps.clear();
      item.problem = s.problem;
    }
    return c;
  };
  if (order.empty()) return sum;
  // The sink runs on this thread while the next chunk is extruded (styling a chunk and handing
  // its meshes on are serial; without the overlap one core idled through them). The chunks are
  // declared before the future, so that on an exception (a cancelled progress) the running
  // extrusion is waited for before the items it reads go.
  std::unique_ptr<Chunk> current = prepare(0), next;
  auto launch = [&](const Chunk* c) {
    return std::async(std::launch::async, [&batch, c] { return extrude::extrudeBatch(c->items, batch); });
  };
  std::future<std::vector<extrude::BatchResult>> running = launch(current.get());
  while (true) {
    std::vector<extrude::BatchResult> results = running.get();
    if (current->to < order.size()) {
      next = prepare(current->to);
      running = launch(next.get());
    }
    for (std::size_t k = 0; k < results.size(); ++k) {
      BuildingReport& r = current->reports[k];
      extrude::BatchResult& res = results[k];
      r.ok = res.ok;
      r.error = res.error;
      r.warnings.insert(r.warnings.end(), std::make_move_iterator(res.warnings.begin()),
                        std::make_move_iterator(res.warnings.end()));
      if (!current->items[k].problem.empty())
        ++sum.refused;
      else if (!res.ok)
        ++sum.failed;
      else {
        ++sum.ok;
        ++sum.types[r.type];
        sum.faces += res.mesh.faces.size();
        dropUnusedPoints(res.mesh);
        applyTagMaterials(style, res.mesh);
        r.features = std::move(res.features);
      }
      sink(r, res.ok ? &res.mesh : nullptr);
      res.mesh = MeshData();  // handed on: drop it now
    }
    if (progress) progress(current->to, order.size());
    if (current->to >= order.size()) break;
    current = std::move(next);
  }
  return sum;
}

}  // namespace corbel::city
