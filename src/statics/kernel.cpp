#include "statics/kernel.h"

#include "core/error.h"
#include "statics/examples.h"
#include "statics/loads.h"

namespace corbel::statics {

ParametricModel modelOf(const MasonrySpec& spec) {
  ParametricModel model;
  try {
    model = exampleByName(spec.model);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError("masonry.model", e.what());
  }
  for (const MasonryParameter& p : spec.parameters) {
    try {
      model.parameters.set(p.name, p.value);
    } catch (const Error& e) {
      throw InputError("masonry.parameters." + p.name, e.what());
    }
  }
  if (!spec.ground) {
    // Resting on other objects: the model's fixed blocks go, so the object is drawn without its
    // slab; analysed alone it then reaches nothing fixed, and says so.
    model.build = [inner = model.build](const ParameterSet& p) {
      Assembly a = inner(p);
      std::erase_if(a.blocks, [](const Block& b) { return b.fixed; });
      return a;
    };
  }
  if (!spec.loads.empty()) {
    // The artist's loads ride on every assembly the model builds: the analysis, the search's
    // evaluations and the simulation all see them.
    model.build = [inner = model.build, loads = spec.loads](const ParameterSet& p) {
      Assembly a = inner(p);
      applyLoads(a, loads);
      return a;
    };
  }
  return model;
}

void registerKernel(SceneSync& sync) {
  sync.setBuilder<MasonrySpec>([](const DocObject& o, Progress*) {
    const auto& spec = std::get<MasonrySpec>(o.spec);
    const ParametricModel model = modelOf(spec);
    const Assembly assembly = model.build(model.parameters);
    BuildResult b;
    b.kind = Kind::Block;
    const int material = b.mesh.addMaterial(spec.material);
    const int block = b.mesh.addTag("block"), ground = b.mesh.addTag("ground");
    for (const Block& k : assembly.blocks) {
      const int first = static_cast<int>(b.mesh.points.size());
      for (const Vec3& p : k.vertices) b.mesh.addPoint(p);
      for (const auto& f : k.faces) {
        std::vector<int> loop;
        for (int v : f) loop.push_back(first + v);
        b.mesh.addFace(std::move(loop), k.fixed ? ground : block, material);
      }
    }
    return b;
  });
}

}  // namespace corbel::statics
