#include "growth/kernel.h"

#include "core/error.h"
#include "growth/engine.h"
#include "growth/openings.h"
#include "growth/roofs.h"

#include <algorithm>
#include <cmath>
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
  sync.setBuilder<GrowthSpec>(unitObjectsFor, [mappers](const DocObject& o, const std::vector<DocObject>& inputs,
                                                      Progress* progress) {
    const auto& spec = std::get<GrowthSpec>(o.spec);
    const std::shared_ptr<ViewMapper> mapper = mappers ? mappers() : nullptr;
    BuildResult b;
    GrownModel grown = grow(GrowthInput{spec, unitsAround(o, inputs, &b.warnings)}, progress, mapper.get());
    const Site& site = grown.site;
    b.kind = Kind::Unit;
    for (const Unit& u : grown.units) {
      if (u.id > int(site.seeds.size())) continue;  // a unit already there: its own object meshes it
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

std::vector<DocObject> unitObjectsFor(const Document& doc, const DocObject& growthObject) {
  std::vector<DocObject> out;
  const auto* spec = std::get_if<GrowthSpec>(&growthObject.spec);
  if (!spec || !spec->aroundUnits) return out;
  for (const DocObject& o : doc.objects)
    if (o.id != growthObject.id && std::holds_alternative<UnitSpec>(o.spec)) out.push_back(o);
  return out;
}

std::vector<Site::FixedUnit> unitsAround(const DocObject& growthObject, const std::vector<DocObject>& others,
                                         std::vector<std::string>* warnings) {
  std::vector<Site::FixedUnit> out;
  const Placement& site = growthObject.placement;
  for (const DocObject& o : others) {
    const auto* spec = std::get_if<UnitSpec>(&o.spec);
    if (!spec || spec->parts.empty() || checkUnitSpec(*spec)) continue;  // a bad unit fails its own build
    const double turn = std::remainder(o.placement.rotation_deg - site.rotation_deg, 90.0);
    if (std::abs(turn) > 1e-9 || o.placement.scale != site.scale) {
      if (warnings)
        warnings->push_back("unit \"" + o.name + "\" is turned or scaled against the site: growth does not see it");
      continue;
    }
    Site::FixedUnit f;
    f.name = o.name;
    for (const UnitPart& p : spec->parts) {
      if (o.placement == site) {  // frozen from this site: the same frame, no rounding
        f.parts.push_back({p.lo, p.hi});
        continue;
      }
      // The part's corners in world space, then in the site's frame (a quarter turn keeps the box).
      const Vec3 a = site.unapply(o.placement.apply(p.lo)), c = site.unapply(o.placement.apply(p.hi));
      Box b;
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(a[k], c[k]);
        b.hi[k] = std::max(a[k], c[k]);
      }
      f.parts.push_back(b);
    }
    out.push_back(std::move(f));
  }
  return out;
}

GrowthInput growthInputOf(const Document& doc, const DocObject& growthObject) {
  GrowthInput in;
  if (const auto* spec = std::get_if<GrowthSpec>(&growthObject.spec)) in.spec = *spec;
  in.fixed = unitsAround(growthObject, unitObjectsFor(doc, growthObject));
  return in;
}

void placeFixedUnits(Site& site, std::vector<Site::FixedUnit> fixed) {
  const Box bounds = site.bounds();
  for (Site::FixedUnit& f : fixed) {
    const bool inside = std::any_of(f.parts.begin(), f.parts.end(), [&](const Box& p) {
      for (int k = 0; k < 3; ++k)
        if (p.hi[k] <= bounds.lo[k] || p.lo[k] >= bounds.hi[k]) return false;
      return true;
    });
    if (inside) site.fixed.push_back(std::move(f));
  }
}

GrownModel grow(const GrowthInput& input, Progress* progress, ViewMapper* mapper) {
  const GrowthSpec& spec = input.spec;
  GrownModel out;
  try {
    out.site = parseSite(spec.site);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? "growth.site" : "growth.site." + e.where, e.reason);
  }
  placeFixedUnits(out.site, input.fixed);
  try {
    validateSite(out.site);
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
