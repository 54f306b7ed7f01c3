#include "extrude/kernel.h"

#include "core/error.h"
#include "extrude/batch.h"
#include "extrude/extrude.h"
#include "extrude/features.h"

namespace corbel::extrude {

namespace {

// The batch's path for a build that failed: the first build again, then the rebuilds with wider
// tolerances that it accepts only where they agree (extrude/batch.h). Throws the batch's
// reason when none is accepted.
BuildResult rebuilt(const DocObject& o, const ExtrusionSpec& spec) {
  BatchOptions options;
  options.jobs = 1;
  options.keepMeshes = true;
  options.timeLimitSeconds = kEditTimeLimitSeconds;
  const std::vector<BatchResult> results = extrudeBatch({{o.name, spec, {}}}, options);
  const BatchResult& r = results.front();
  if (!r.ok) throw Error(r.error);
  BuildResult b;
  b.kind = Kind::Shell;
  b.mesh = r.mesh;
  b.warnings = r.warnings;
  return b;
}

}  // namespace

void registerKernel(SceneSync& sync) {
  sync.setBuilder<ExtrusionSpec>([](const DocObject& o, Progress* progress) {
    const auto& spec = std::get<ExtrusionSpec>(o.spec);
    ExtrusionResult r;
    try {
      r = extrude(spec, progress, kEditTimeLimitSeconds);
    } catch (const InputError&) {
      throw;  // bad input is never rebuilt
    } catch (const Error& e) {
      if (std::string(e.what()).find("time limit") != std::string::npos) throw;
      return rebuilt(o, spec);
    }
    // A shell that did not close, or has a face crossing itself, is rebuilt as the batch does
    // (`corbel-cli extrude`, towns); a build that passes pays nothing for it.
    if (unpairedEdges(r.shell) || !crossedFace(r.shell).empty()) return rebuilt(o, spec);
    BuildResult b;
    b.kind = Kind::Shell;
    b.mesh = toMeshData(r.shell, spec, spec.material);
    b.warnings = std::move(r.shell.warnings);
    appendFeatures(b.mesh, spec, r, b.warnings);
    return b;
  });
}

}  // namespace corbel::extrude
