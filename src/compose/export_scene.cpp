#include "compose/export_scene.h"

#include "kifs/follow.h"
#include "kifs/kernel.h"
#include "kifs/mesher.h"

#include <map>

namespace corbel::compose {

ExportableScene exportableScene(const Document& doc, const Scene& built, const city::TownCache* towns,
                                const std::function<bool(ObjectId)>& include, int kifsResolution) {
  ExportableScene out;
  out.scene = built;
  const int resolution = kifsResolution > 0 ? kifsResolution : kExportKifsResolution;
  auto picked = [&](const DocObject& o) { return include ? include(o.id) : o.visible; };
  for (const auto& [id, info] : built.objects()) {
    const DocObject* o = doc.find(id);
    if (!o || !picked(*o)) out.scene.removeObject(id);
  }
  for (const DocObject& o : doc.objects) {
    const auto* k = std::get_if<KifsSpec>(&o.spec);
    const bool follower = k && k->mass.footprint == "object";  // it stands in its mass object, in world space
    if (!o.placement.identity() && picked(o) && !follower) out.placements[o.id] = o.placement;
  }
  ObjectId next = doc.nextId();
  std::map<ObjectId, ObjectId> townOf;  // a building's object → its town's
  for (const DocObject& o : doc.objects) {
    if (!picked(o)) continue;
    if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0) {
      kifs::TownBuildings buildings;
      if (towns) buildings = [towns](const DocObject& town, const std::string& id) { return city::buildingMesh(*towns, town, id); };
      const kifs::Building building = kifs::buildingOf(doc, built, o, nullptr, buildings);
      MeshData mesh = kifs::meshBuilding(building, resolution);
      if (building.mass()) out.placements.erase(o.id);  // it stands in its mass object, in world space
      else applyPlacement(mesh, o.placement);
      out.scene.replaceObject(o.id, Kind::Ornament, o.name, mesh);
      out.notes.push_back("KIFS building \"" + o.name + "\" is ray-marched in the view: meshed at " +
                          std::to_string(resolution) + " cells along its longest side for the file");
    } else if (std::holds_alternative<TownSpec>(o.spec) && towns) {
      out.scene.removeObject(o.id);
      std::size_t split = 0;
      for (const city::BuiltBuilding& b : towns->buildings(o.id)) {
        if (!b.error.empty()) continue;
        MeshData mesh = towns->mesh(o.id, b.id);
        applyPlacement(mesh, o.placement);
        out.scene.replaceObject(next, Kind::Shell, b.id, mesh);
        if (!o.placement.identity()) out.placements[next] = o.placement;
        townOf[next++] = o.id;
        ++split;
      }
      out.notes.push_back("town \"" + o.name + "\": one object per building (" + std::to_string(split) + ")");
      if (const auto in = towns->inputs(o.id)) {
        const city::Frame& f = in->town.frame;
        if (out.georeference.proj.empty() && !f.proj.empty()) out.georeference = {f.crs, f.proj, f.lon0, f.lat0, 0};
        else if (!f.proj.empty() && f.proj != out.georeference.proj)
          out.notes.push_back("town \"" + o.name + "\" lies in another frame than the first town's: the file records the first's");
        if (!in->town.attribution.empty() && out.copyright.find(in->town.attribution) == std::string::npos)
          out.copyright += (out.copyright.empty() ? "" : "; ") + in->town.attribution;
      }
    }
  }
  out.textured = [townOf](ObjectId id) { return townOf.count(id) > 0; };
  if (towns && !townOf.empty())
    out.tagTextures = [townOf, base = towns->tagTextures()](ObjectId id, const std::string& tag) -> const SurfaceTexture* {
      const auto it = townOf.find(id);
      return base ? base(it == townOf.end() ? id : it->second, tag) : nullptr;
    };
  return out;
}

}  // namespace corbel::compose
