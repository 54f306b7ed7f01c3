// corbel-cli render, export and check: a project built into the Scene, drawn, written or
// validated.
#include "cli/guarded.h"
#include "cli/number_list.h"
#include "cli/project_scene.h"
#include "compose/export_scene.h"
#include "cli/run.h"
#include "core/error.h"
#include "core/export.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace corbel::cli {
namespace {

// The object --object names (nullopt when none was named).
std::optional<ObjectId> objectByName(const Document& doc, const std::string& name) {
  if (name.empty()) return std::nullopt;
  const DocObject* o = doc.findByName(name);
  if (!o) {
    std::string names;
    for (const auto& obj : doc.objects) names += (names.empty() ? "" : ", ") + ("\"" + obj.name + "\"");
    throw Error("no object named \"" + name + "\" (objects: " + (names.empty() ? "none" : names) + ")");
  }
  return o->id;
}

}  // namespace

int run(const RenderRequest& r) {
  std::optional<std::vector<double>> view;
  if (!r.camera.empty()) {
    view = numberList(r.camera, ',');
    if (!view || view->size() < 2 || view->size() > 3)
      throw UsageError("--camera: expected AZ,EL or AZ,EL,DIST (degrees, meters), not '" + r.camera + "'");
    if (view->size() == 3 && !((*view)[2] > 0)) throw UsageError("--camera: DIST must be positive");
  }
  LoadedScene l = loadScene(r.project);
  const std::optional<ObjectId> only = objectByName(l.doc, r.object);

  render::RenderSettings settings;
  settings.grid = !r.noGrid;
  settings.edges = !r.noEdges;
  settings.wireframe = r.wireframe;
  settings.textures = r.textures == "on";
  if (settings.textures) settings.tagTextures = l.towns->tagTextures();
  settings.visible = [&](ObjectId id) {
    if (only) return id == *only;
    const DocObject* o = l.doc.find(id);
    return o && o->visible;
  };
  BBox box;
  for (const auto& [id, info] : l.scene.objects())
    if (settings.visible(id)) box.add(l.scene.bounds(id));
  // KIFS buildings that are not meshed are ray-marched over the Scene (render/kifs_pass.h).
  const render::RaymarchedKifs raymarched = render::raymarchedKifs(l.doc, settings.visible, &l.scene, city::buildingMeshes(l.towns));
  if (!raymarched.errors.empty()) throw Error("KIFS building " + raymarched.errors.front());
  box.add(raymarched.bounds);
  const int width = r.size.width, height = r.size.height;
  render::OrbitCamera camera;
  camera.frame(box, double(width) / height);
  if (view) {
    camera.azimuth_deg = (*view)[0];
    camera.elevation_deg = std::clamp((*view)[1], -89.9, 90.0);
    if (view->size() == 3) camera.distance = (*view)[2];
  }
  render::HeadlessContext context;
  render::Renderer renderer;
  const render::Image image =
      render::renderSceneWithKifs(renderer, l.scene, raymarched.buildings, camera, width, height, settings,
                                  raymarched.placements, raymarched.masses);
  render::writePng(image, r.out);
  std::cout << r.out << "\n";
  return 0;
}

int run(const ExportRequest& r) {
  try {
    // fail on a bad extension before any work
    if (exportFormatFor(r.out) != ExportFormat::Glb && r.compress) throw Error("--compress needs a .glb --out");
  } catch (const Error& e) {
    throw UsageError(e.what());  // a bad --out is a command-line fault (exit 2)
  }
  LoadedScene l = loadScene(r.project);
  const std::optional<ObjectId> only = objectByName(l.doc, r.object);
  // Everything the view shows goes into the file: ray-marched KIFS buildings meshed, towns one
  // object per building, textured as `city` writes them (compose/export_scene.h).
  compose::ExportableScene e = compose::exportableScene(
      l.doc, l.scene, l.towns.get(),
      [&](ObjectId id) {
        if (only) return id == *only;
        const DocObject* o = l.doc.find(id);
        return o && o->visible;
      },
      r.kifsResolution);
  for (const std::string& note : e.notes) std::cerr << "corbel-cli: export: " << note << "\n";
  ExportOptions options;
  if (!r.up.empty()) options.up = r.up == "y" ? UpAxis::Y : UpAxis::Z;
  options.textured = e.textured;
  options.tagTextures = e.tagTextures;
  options.georeference = e.georeference;
  options.copyright = e.copyright;
  options.placements = e.placements;
  options.compress = r.compress;
  exportScene(e.scene, r.out, options);
  std::cout << r.out << "\n";
  return 0;
}

int run(const CheckRequest& r) {
  LoadedScene l = loadScene(r.project);
  int bad = 0;
  for (const DocObject& o : l.doc.objects) {
    nlohmann::ordered_json j;
    j["object"] = o.name;
    if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0) {
      j["raymarched"] = true;  // no shell in the Scene to check; its parameters were validated
      std::cout << j.dump() << "\n";
      continue;
    }
    const ValidityReport v = l.scene.validate(o.id);
    j["faces"] = v.faces;
    j["vertices"] = v.vertices;
    j["edges"] = v.edges;
    j["euler"] = v.euler;
    j["components"] = v.components;
    j["watertight"] = v.watertight();
    j["manifold"] = v.manifold();
    j["consistent"] = v.consistent();
    j["area"] = v.area;
    j["volume"] = v.volume;
    j["problems"] = v.problems();
    std::cout << j.dump() << "\n";
    if (!v.closedManifold()) ++bad;
  }
  std::cout << nlohmann::ordered_json{{"objects", l.doc.objects.size()}, {"failed", bad}}.dump() << "\n";
  return bad ? 1 : 0;
}

}  // namespace corbel::cli
