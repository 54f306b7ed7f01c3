#include "growth/kernel.h"

#include "core/error.h"
#include "growth/engine.h"
#include "growth/openings.h"
#include "growth/roofs.h"

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

void registerKernel(SceneSync& sync) { registerKernelWith(sync, {}); }

void registerKernelWith(SceneSync& sync, MapperSource mappers) {
  sync.setBuilder<GrowthSpec>([mappers](const DocObject& o, Progress* progress) {
    const auto& spec = std::get<GrowthSpec>(o.spec);
    const std::shared_ptr<ViewMapper> mapper = mappers ? mappers() : nullptr;
    GrownModel grown = grow(spec, progress, mapper.get());
    const Site& site = grown.site;
    BuildResult b;
    b.kind = Kind::Unit;
    for (const Unit& u : grown.units) {
      MeshData m = unitMesh(u);
      const int mat = m.addMaterial("plaster");
      for (int& f : m.faceMaterial) f = mat;
      b.mesh.append(m);
    }
    MeshData finish = finishMesh(site, grown.units, b.warnings);
    b.mesh.append(finish);
    for (std::size_t i = 0; i < site.cores.size(); ++i) addSolid(b.mesh, site.coreBox(i), "concrete");
    for (const Box& c : site.circulation) addSolid(b.mesh, c, "slate");
    if (grown.stopped) b.warnings.push_back(kStopped + std::to_string(grown.steps) + " steps");
    return b;
  });
  sync.setBuilder<UnitSpec>([](const DocObject& o, Progress*) {
    const auto& spec = std::get<UnitSpec>(o.spec);
    if (auto problem = checkUnitSpec(spec)) {
      const auto colon = problem->find(": ");
      throw InputError("unit." + problem->substr(0, colon), problem->substr(colon + 2));
    }
    Unit u;
    u.id = 1;
    for (const UnitPart& p : spec.parts) u.parts.push_back({p.lo, p.hi});
    BuildResult b;
    b.kind = Kind::Unit;
    b.mesh = unitMesh(u);
    const int mat = b.mesh.addMaterial(spec.material);
    for (int& f : b.mesh.faceMaterial) f = mat;
    return b;
  });
}

GrownModel grow(const GrowthSpec& spec, Progress* progress, ViewMapper* mapper) {
  GrownModel out;
  try {
    out.site = parseSite(spec.site);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? "growth.site" : "growth.site." + e.where, e.reason);
  }
  const GrowthOptions options = optionsFor(out.site, spec.seed);
  GrowthEngine engine(out.site, options, mapper);
  const int limit = spec.steps < 0 ? static_cast<int>(limits::kMaxGrowthSteps) : spec.steps;
  while (engine.steps() < limit && !engine.done()) {
    if (progress && progress->cancelled()) throw Cancelled();
    if (!engine.step()) break;
    if (progress && spec.steps > 0) progress->report(double(engine.steps()) / spec.steps, "growing");
  }
  out.units = engine.units();
  out.steps = engine.steps();
  out.stopped = engine.done();
  return out;
}

MeshData finishMesh(const Site& site, const std::vector<Unit>& units, std::vector<std::string>& warnings) {
  MeshData out;
  if (site.roof) {
    Roofs roofs = buildRoofs(site, units, *site.roof);
    out.append(roofs.mesh);
    warnings.insert(warnings.end(), roofs.warnings.begin(), roofs.warnings.end());
  }
  if (site.openings) out.append(openingsMesh(placeOpenings(site, units, *site.openings)));
  return out;
}

int stoppedAfter(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (w.rfind(kStopped, 0) == 0) return std::atoi(w.c_str() + std::string(kStopped).size());
  return -1;
}

}  // namespace corbel::growth
