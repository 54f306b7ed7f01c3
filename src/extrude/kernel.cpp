#include "extrude/kernel.h"

#include "core/error.h"
#include "extrude/extrude.h"
#include "extrude/features.h"

namespace corbel::extrude {

void registerKernel(SceneSync& sync) {
  sync.setBuilder<ExtrusionSpec>([](const DocObject& o, Progress* progress) {
    const auto& spec = std::get<ExtrusionSpec>(o.spec);
    ExtrusionResult r = extrude(spec, progress, kEditTimeLimitSeconds);
    if (const std::size_t open = unpairedEdges(r.shell))
      throw Error("the shell did not close (" + std::to_string(open) +
                  " edges without a partner): a degenerate configuration the kernel cannot resolve yet");
    BuildResult b;
    b.kind = Kind::Shell;
    b.mesh = toMeshData(r.shell, spec, spec.material);
    b.warnings = std::move(r.shell.warnings);
    appendFeatures(b.mesh, spec, r, b.warnings);
    return b;
  });
}

}  // namespace corbel::extrude
