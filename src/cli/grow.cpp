// corbel-cli grow: the growth kernel on a site file (docs/growth.md); one JSON line.
#include "cli/grow.h"

#include "cli/guarded.h"
#include "cli/run.h"
#include "cli/scene_png.h"

#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "growth/engine.h"
#include "growth/kernel.h"
#include "growth/openings.h"
#include "growth/roofs.h"
#include "growth/statistics.h"
#include "render/gl_view_mapper.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

namespace corbel::cli {

namespace {

nlohmann::ordered_json statisticsJson(const growth::Statistics& st) {
  nlohmann::ordered_json j;
  j["site_area"] = st.siteArea;
  j["storeys"] = st.storeys;
  j["units"] = st.units;
  j["occupants"] = st.occupants;
  j["occupancy_ratio"] = st.occupancyRatio;
  j["type_a"] = st.typeA;
  j["type_b"] = st.typeB;
  j["type_c"] = st.typeC;
  j["unclassified"] = st.unclassified;
  j["average_view"] = st.averageView;
  j["two_views"] = st.twoViews;
  j["three_views"] = st.threeViews;
  j["four_views"] = st.fourViews;
  j["average_floor_area"] = st.averageFloorArea;
  j["double_volume"] = st.doubleVolume;
  j["outdoor_space"] = st.outdoorSpace;
  return j;
}

}  // namespace

// Units (kind unit), cores and circulation (kind mass) as Scene objects.
Scene modelScene(const growth::Site& site, const std::vector<growth::Unit>& units) {
  Scene scene;
  ObjectId id = 1;
  for (const growth::Unit& u : units)
    scene.replaceObject(id++, Kind::Unit, "unit " + std::to_string(u.id), growth::unitMesh(u));
  auto solid = [&](const growth::Box& b, const std::string& name, const std::string& material) {
    growth::Unit u;
    u.parts = {b};
    MeshData m = growth::unitMesh(u);
    const int mat = m.addMaterial(material);
    for (int& f : m.faceMaterial) f = mat;
    scene.replaceObject(id++, Kind::Mass, name, m);
  };
  for (std::size_t i = 0; i < site.cores.size(); ++i)
    solid(site.coreBox(i), "core " + std::to_string(i + 1), "concrete");
  for (std::size_t i = 0; i < site.circulation.size(); ++i)
    solid(site.circulation[i], "circulation " + std::to_string(i + 1), "slate");
  // What the site asks to finish the units with: one object of roofs, one of doors and windows.
  if (site.roof) {
    const growth::Roofs roofs = growth::buildRoofs(site, units, *site.roof);
    for (const auto& w : roofs.warnings) std::cerr << "corbel-cli: warning: grow: " << w << "\n";
    scene.replaceObject(id++, Kind::Shell, "roofs", roofs.mesh);
  }
  if (site.openings)
    scene.replaceObject(id++, Kind::Mass, "doors and windows",
                        growth::openingsMesh(growth::placeOpenings(site, units, *site.openings)));
  return scene;
}

int run(const GrowRequest& r) {
  const std::string& sitePath = r.site;
  const std::string& out = r.out;
  const std::string& png = r.render;
  const std::string& maps = r.viewMaps;
  if (!out.empty()) {
    try {
      exportFormatFor(out);
    } catch (const Error& e) {
      throw UsageError("grow: " + std::string(e.what()));
    }
  }

  // A site file, or a project's growth object (its site, seed and steps unless given here).
  std::vector<std::string> warnings;
  growth::Site site;
  long long seed = r.seed.value_or(1), steps = r.steps.value_or(100000);
  std::string objectName;
  const bool project = sitePath.size() >= 7 && sitePath.compare(sitePath.size() - 7, 7, ".corbel") == 0;
  if (project) {
    const LoadedProject p = loadProject(sitePath);
    for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << sitePath << ": " << w << "\n";
    std::vector<std::size_t> growths;
    for (std::size_t i = 0; i < p.document.objects.size(); ++i)
      if (std::holds_alternative<GrowthSpec>(p.document.objects[i].spec) &&
          (r.object.empty() || p.document.objects[i].name == r.object))
        growths.push_back(i);
    if (growths.empty())
      throw Error(sitePath + (r.object.empty() ? ": no growth object to grow (the project has none)"
                                               : ": no growth object named \"" + r.object + "\""));
    if (growths.size() > 1) throw Error(sitePath + ": several growth objects; choose one with --object NAME");
    const DocObject& o = p.document.objects[growths[0]];
    const auto& spec = std::get<GrowthSpec>(o.spec);
    objectName = o.name;
    try {
      site = growth::parseSite(spec.site, &warnings);
    } catch (const InputError& e) {
      throw InputError(sitePath + ": objects[" + std::to_string(growths[0]) + "].growth.site" +
                           (e.where.empty() ? "" : "." + e.where),
                       e.reason);
    }
    std::vector<std::string> around;
    growth::placeFixedUnits(site, growth::unitsAround(o, growth::unitObjectsFor(p.document, o), &around));
    warnings.insert(warnings.end(), around.begin(), around.end());
    if (!r.seed) seed = static_cast<long long>(spec.seed);
    if (!r.steps && spec.steps >= 0) steps = spec.steps;
  } else {
    if (!r.object.empty()) throw UsageError("grow: --object needs a project (.corbel), not a site file");
    site = growth::loadSite(sitePath, &warnings);
  }
  for (const auto& w : warnings) std::cerr << "corbel-cli: warning: " << sitePath << ": " << w << "\n";
  const growth::GrowthOptions options = growth::optionsFor(site, std::uint64_t(seed));
  // View maps: exact (default), the CPU rasterizer, or GL through OSMesa, at `pixel` meters.
  std::unique_ptr<render::HeadlessContext> context;
  std::unique_ptr<growth::ViewMapper> mapper;
  if (maps == "gl") {
    context = std::make_unique<render::HeadlessContext>();
    mapper = std::make_unique<render::GlViewMapper>(r.pixel);
  } else if (maps == "raster") {
    mapper = std::make_unique<growth::RasterViewMapper>(r.pixel);
  } else {
    mapper = std::make_unique<growth::ExactViewMapper>();
  }
  const auto t0 = std::chrono::steady_clock::now();
  growth::GrowthEngine engine(site, options, mapper.get());
  const int ran = engine.run(int(steps));
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<growth::Unit> units = engine.units();
  int reached = 0, stuck = 0;
  for (const auto& s : engine.states()) {
    reached += s.status == growth::UnitStatus::Reached;
    stuck += s.status == growth::UnitStatus::Stuck;
  }
  const std::vector<std::string> violations = engine.enforcer().violations(units);

  nlohmann::ordered_json j;
  j["site"] = sitePath;
  if (project) j["object"] = objectName;
  j["seed"] = seed;
  j["steps"] = ran;
  j["moves"] = engine.commits();
  j["finished"] = engine.done();
  j["reached"] = reached;
  j["stuck"] = stuck;
  j["constraints_hold"] = violations.empty();
  j["view_maps"] = maps;
  j["grow_ms"] = ms;
  if (r.stats) j["statistics"] = statisticsJson(growth::computeStatistics(site, units, engine.views()));

  if (!out.empty() || !png.empty()) {
    const Scene scene = modelScene(site, units);
    if (!out.empty()) {
      exportScene(scene, out);
      j["out"] = out;
    }
    if (!png.empty()) {
      if (!context) context = std::make_unique<render::HeadlessContext>();
      writeScenePng(scene, {-75, 30, 0.95}, png);
      j["render"] = png;
    }
  }
  std::cout << j.dump() << "\n";
  for (const auto& v : violations) std::cerr << "corbel-cli: grow: constraint violated: " << v << "\n";
  return violations.empty() ? 0 : 1;
}

}  // namespace corbel::cli
