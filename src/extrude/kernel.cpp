#include "extrude/kernel.h"

#include "extrude/extrude.h"

namespace corbel::extrude {

void registerKernel(SceneSync& sync) {
  sync.setBuilder<ExtrusionSpec>([](const DocObject& o) {
    const auto& spec = std::get<ExtrusionSpec>(o.spec);
    ExtrusionResult r = extrude(spec);
    BuildResult b;
    b.kind = Kind::Shell;
    b.mesh = toMeshData(r.shell, spec, spec.material);
    b.warnings = std::move(r.shell.warnings);
    return b;
  });
}

}  // namespace corbel::extrude
