#include "extrude/batch.h"

#include "core/scene.h"
#include "extrude/features.h"

#include <atomic>
#include <chrono>
#include <thread>

namespace corbel::extrude {

namespace {

void runOne(const BatchItem& item, BatchResult& r, bool keepMesh, bool merge, double timeLimit) {
  r.id = item.id;
  if (!item.problem.empty()) {
    r.error = item.problem;
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const ExtrusionResult er = extrude(item.spec, nullptr, timeLimit);
    r.warnings = er.shell.warnings;
    r.anchors = er.anchors;
    r.measures = measure(er.shell);
    // A shell that is not closed fails here, before a mesh is built: inserting a badly broken
    // shell into a half-edge mesh can take seconds.
    if (const std::size_t open = unpairedEdges(er.shell)) {
      r.error = "the shell is not closed: " + std::to_string(open) + " edges without a partner";
      r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      return;
    }
    MeshData mesh = toMeshData(er.shell, item.spec, item.spec.material);
    appendFeatures(mesh, item.spec, er, r.warnings);
    Scene scene;
    scene.replaceObject(1, Kind::Shell, item.id, mesh);
    const ValidityReport v = scene.validate(1);
    r.meshFaces = v.faces;
    r.meshVertices = v.vertices;
    r.watertight = v.watertight();
    r.manifold = v.manifold();
    r.ok = v.closedManifold();
    if (!r.ok) {
      r.error = "the shell is not a closed 2-manifold:";
      for (const auto& p : v.problems()) r.error += " " + p + ";";
    }
    if (keepMesh && merge) {
      r.mesh = toMeshData(er.shell, item.spec, item.spec.material, true);
      std::vector<std::string> again;
      appendFeatures(r.mesh, item.spec, er, again);
    } else if (keepMesh) {
      r.mesh = std::move(mesh);
    }
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::vector<BatchResult> extrudeBatch(const std::vector<BatchItem>& items, const BatchOptions& options,
                                      Progress* progress) {
  std::vector<BatchResult> results(items.size());
  unsigned jobs = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::min<unsigned>(jobs, std::max<std::size_t>(1, items.size()));
  std::atomic<std::size_t> next{0}, done{0};
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < items.size();) {
      if (progress && progress->cancelled()) return;
      runOne(items[i], results[i], options.keepMeshes, options.mergeCoplanar, options.timeLimitSeconds);
      const std::size_t d = ++done;
      if (progress && (d % 64 == 0 || d == items.size()))
        progress->report(double(d) / items.size(), "extruding buildings");
    }
  };
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (progress && progress->cancelled()) throw Cancelled();
  return results;
}

}  // namespace corbel::extrude
