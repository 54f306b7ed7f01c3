#include "extrude/batch.h"

#include "core/error.h"
#include "core/scene.h"
#include "extrude/features.h"
#include "extrude/part_validity.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace corbel::extrude {

namespace {

// One build of one building at one tolerance factor, validated as a closed 2-manifold whose
// faces are simple polygons in their planes.
struct Attempt {
  bool ok = false;
  bool retryable = false;  // failed in a way wider tolerances may mend (not bad input, not time)
  std::string error;
  std::vector<std::string> warnings;
  ShellMeasures measures;
  std::size_t meshFaces = 0, meshVertices = 0;
  bool watertight = false, manifold = false;
  std::vector<AnchorFrame> anchors;
  MeshData mesh;
  std::vector<FeaturePlacement> features;
};

Attempt attempt(const BatchItem& item, double factor, bool keepMesh, bool merge, bool apart, double timeLimit,
                bool windingRule) {
  Attempt a;
  try {
    const ExtrusionResult er = extrude(item.spec, nullptr, ExtrudeOptions{timeLimit, factor, windingRule});
    a.warnings = er.shell.warnings;
    a.anchors = er.anchors;
    a.measures = measure(er.shell);
    a.retryable = true;
    // A shell that is not closed fails here, before a mesh is built: inserting a badly broken
    // shell into a half-edge mesh can take seconds.
    if (const std::size_t open = unpairedEdges(er.shell)) {
      a.error = "the shell is not closed: " + std::to_string(open) + " edges without a partner";
      return a;
    }
    MeshData mesh = toMeshData(er.shell, item.spec, item.spec.material);
    std::vector<PlacedFeature> features = placeFeatures(item.spec, er, a.warnings);
    // The shell with its features, checked in parts (their faces outnumber the shell's).
    const ValidityReport v = validateWithFeatures(mesh, features, item.id);
    a.meshFaces = v.faces;
    a.meshVertices = v.vertices;
    a.watertight = v.watertight();
    a.manifold = v.manifold();
    a.ok = v.closedManifold();
    if (!a.ok) {
      a.error = "the shell is not a closed 2-manifold:";
      for (const auto& p : v.problems()) a.error += " " + p + ";";
    } else if (const std::string crossed = crossedFace(er.shell); !crossed.empty()) {
      a.ok = false;
      a.error = "the shell is not valid: " + crossed;
    }
    if (keepMesh) {
      a.mesh = merge ? toMeshData(er.shell, item.spec, item.spec.material, true) : std::move(mesh);
      if (apart)
        for (PlacedFeature& f : features) a.features.push_back(f.placement);
      else
        appendFeatures(a.mesh, features);
    }
  } catch (const InputError& e) {
    a.error = e.what();  // bad input: the same with any tolerance
  } catch (const std::exception& e) {
    a.error = e.what();
    // A sweep that ran out of time would only run out again, for each factor.
    a.retryable = std::string(e.what()).find("time limit") == std::string::npos;
  }
  return a;
}

double relativeDifference(double a, double b) {
  const double m = std::max(std::abs(a), std::abs(b));
  return m > 0 ? std::abs(a - b) / m : 0.0;
}

std::string times(double factor) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g×", factor);
  return buf;
}

void finish(BatchResult& r, Attempt& a, std::chrono::steady_clock::time_point t0) {
  r.ok = a.ok;
  r.error = a.error;
  r.warnings = std::move(a.warnings);
  r.measures = a.measures;
  r.meshFaces = a.meshFaces;
  r.meshVertices = a.meshVertices;
  r.watertight = a.watertight;
  r.manifold = a.manifold;
  r.anchors = std::move(a.anchors);
  r.mesh = std::move(a.mesh);
  r.features = std::move(a.features);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void runOne(const BatchItem& item, BatchResult& r, const BatchOptions& o) {
  r.id = item.id;
  if (!item.problem.empty()) {
    r.error = item.problem;
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  Attempt first = attempt(item, 1.0, o.keepMeshes, o.mergeCoplanar, o.featuresApart, o.timeLimitSeconds, o.windingRule);
  r.builds = 1;
  if (!first.ok && first.retryable && !o.retryFactors.empty()) {
    // Rebuild with a window of consecutive factors, stopping at the first rebuild that fails
    // or disagrees with the window's first; keep that first only if all passed and agreed.
    // Where the window's first rebuild fails outright (it says nothing about the answer, unlike
    // a disagreement), the window moves one factor up while there is room.
    const std::vector<double>& f = o.retryFactors;
    const std::size_t window = std::clamp<std::size_t>(o.retryWindow, 1, f.size());
    std::size_t start = 0;
    std::vector<Attempt> rebuilt;  // of the current window
    std::string skipped;           // the factors whose rebuild failed before the window moved up
    double worstVolume = 0, worstRoof = 0;
    bool agreed = true;
    while (true) {
      rebuilt.clear();
      agreed = true;
      for (std::size_t i = 0; i < window && agreed; ++i) {
        rebuilt.push_back(attempt(item, f[start + i], o.keepMeshes && i == 0, o.mergeCoplanar, o.featuresApart,
                                  o.timeLimitSeconds, o.windingRule));
        ++r.builds;
        agreed = rebuilt.back().ok;
        if (!agreed || i == 0) continue;
        worstVolume = std::max(worstVolume, relativeDifference(rebuilt[0].measures.volume, rebuilt[i].measures.volume));
        worstRoof = std::max(worstRoof, relativeDifference(rebuilt[0].measures.roofArea, rebuilt[i].measures.roofArea));
        agreed = worstVolume <= o.retryAgreement && worstRoof <= o.retryAgreement;
      }
      if (rebuilt.size() == 1 && !agreed && start + window < f.size()) {
        skipped += (skipped.empty() ? "" : ", ") + times(f[start]);
        ++start;
        continue;
      }
      break;
    }
    if (agreed) {
      Attempt* chosen = &rebuilt[0];
      r.toleranceFactor = f[start];
      std::string others;
      for (std::size_t i = 1; i < window; ++i)
        others += (i > 1 ? (i + 1 == window ? " and " : ", ") : "") + times(f[start + i]);
      char agree[96];
      std::snprintf(agree, sizeof agree, " agree on volume within %.1e and roof area within %.1e", worstVolume,
                    worstRoof);
      chosen->warnings.insert(chosen->warnings.begin(),
                              "rebuilt with " + times(r.toleranceFactor) +
                                  " tolerances (the first build failed: " + first.error + ")" +
                                  (skipped.empty() ? std::string() : "; the " + skipped + " rebuild failed too") +
                                  (others.empty() ? std::string() : "; rebuilds with " + others + agree));
      finish(r, *chosen, t0);
      return;
    }
    // Say why no rebuild was kept; the first build's error and warnings stand.
    const double at = f[start + rebuilt.size() - 1];
    char why[128];
    if (!rebuilt.back().ok)
      std::snprintf(why, sizeof why, " (rebuilt with wider tolerances: the %s rebuild failed too)", times(at).c_str());
    else
      std::snprintf(why, sizeof why,
                    " (rebuilt with wider tolerances: %s and %s disagree, volume by %.1e, roof area by %.1e)",
                    times(f[start]).c_str(), times(at).c_str(), worstVolume, worstRoof);
    first.error += why;
  }
  finish(r, first, t0);
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
      runOne(items[i], results[i], options);
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
