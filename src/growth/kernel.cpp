#include "growth/kernel.h"

#include "core/error.h"
#include "growth/engine.h"

#include <cstdlib>
#include <string>

namespace corbel::growth {

namespace {

constexpr const char* kStopped = "every unit stopped after ";

void addSolid(MeshData& out, const Box& b, const std::string& material) {
  Unit u;
  u.parts = {b};
  MeshData m = unitMesh(u);
  const int mat = m.addMaterial(material);
  for (int& f : m.faceMaterial) f = mat;
  out.append(m);
}

}  // namespace

void registerKernel(SceneSync& sync) {
  sync.setBuilder<GrowthSpec>([](const DocObject& o, Progress* progress) {
    const auto& spec = std::get<GrowthSpec>(o.spec);
    Site site;
    try {
      site = parseSite(spec.site);
    } catch (const InputError& e) {
      throw InputError(e.where.empty() ? "growth.site" : "growth.site." + e.where, e.reason);
    }
    GrowthOptions options;
    options.seed = spec.seed;
    GrowthEngine engine(site, options);
    const int limit = spec.steps < 0 ? static_cast<int>(limits::kMaxGrowthSteps) : spec.steps;
    while (engine.steps() < limit && !engine.done()) {
      if (progress && progress->cancelled()) throw Cancelled();
      if (!engine.step()) break;
      if (progress && spec.steps > 0) progress->report(double(engine.steps()) / spec.steps, "growing");
    }
    BuildResult b;
    b.kind = Kind::Unit;
    for (const Unit& u : engine.units()) {
      MeshData m = unitMesh(u);
      const int mat = m.addMaterial("plaster");
      for (int& f : m.faceMaterial) f = mat;
      b.mesh.append(m);
    }
    for (std::size_t i = 0; i < site.cores.size(); ++i) addSolid(b.mesh, site.coreBox(i), "concrete");
    for (const Box& c : site.circulation) addSolid(b.mesh, c, "slate");
    if (engine.done()) b.warnings.push_back(kStopped + std::to_string(engine.steps()) + " steps");
    return b;
  });
}

int stoppedAfter(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (w.rfind(kStopped, 0) == 0) return std::atoi(w.c_str() + std::string(kStopped).size());
  return -1;
}

}  // namespace corbel::growth
