// corbel-cli kifs: a KIFS building (a preset, a preset file or a project's) rendered headless,
// meshed into a file, or its CPU distance evaluated at given points (docs/kifs.md).
#include "cli/guarded.h"
#include "cli/number_list.h"
#include "cli/project_scene.h"
#include "cli/run.h"
#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "kifs/follow.h"
#include "kifs/kernel.h"
#include "kifs/mesher.h"
#include "kifs/trace.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace corbel::cli {

namespace {

std::vector<double> numbers(const std::string& text, char sep, const std::string& what) {
  const auto v = numberList(text, sep);
  if (!v) throw UsageError(what + ": '" + text + "' is not a list of numbers");
  return *v;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() > end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// A preset's name, a preset file or a project (its first KIFS object; one that follows a mass
// object follows it in the project's built Scene, kifs/follow.h).
kifs::Building buildingFrom(const std::string& source) {
  if (endsWith(source, ".corbel")) {
    const LoadedProject project = loadProject(source);
    const DocObject* object = nullptr;
    for (const DocObject& o : project.document.objects)
      if (std::holds_alternative<KifsSpec>(o.spec)) {
        object = &o;
        break;
      }
    if (!object) throw Error(source + ": the project has no KIFS object");
    const auto& spec = std::get<KifsSpec>(object->spec);
    if (spec.mass.footprint != "object") return kifs::Building(kifs::paramsOf(spec));
    const LoadedScene loaded = loadScene(source);
    return kifs::buildingOf(loaded.doc, loaded.scene, *loaded.doc.find(object->id), nullptr,
                            city::buildingMeshes(loaded.towns));
  }
  // A preset's name has no '/' and no extension (kifs/params.h); anything else is a file.
  std::error_code ec;
  if (endsWith(source, ".json") || source.find('/') != std::string::npos ||
      std::filesystem::is_regular_file(source, ec))
    return kifs::Building(kifs::loadPreset(source));
  return kifs::Building(kifs::preset(source));
}

int evalPoints(const kifs::Building& b, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read " + path);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::istringstream ls(line);
    double x, y, z;
    if (!(ls >> x >> y >> z)) throw Error(path + ":" + std::to_string(lineNo) + ": expected three numbers x y z");
    const kifs::Sample s = b.evaluate({x, y, z});
    std::printf("%.17g %.17g\n", s.bound, s.surface);
  }
  return 0;
}

int meshToFile(const kifs::Building& b, const std::string& path, int resolution) {
  exportFormatFor(path);  // refuses an unknown extension before the work
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  scene.replaceObject(1, Kind::Ornament, "kifs", kifs::meshBuilding(b, resolution));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  exportScene(scene, path);
  const ValidityReport v = scene.validate(1);
  std::printf("{\"faces\": %zu, \"vertices\": %zu, \"closed_manifold\": %s, \"resolution\": %d, \"seconds\": %.2f}\n",
              v.faces, v.vertices, v.closedManifold() ? "true" : "false", resolution, seconds);
  return v.closedManifold() ? 0 : 1;
}

}  // namespace

int run(const KifsRequest& r) {
  static_assert(kifs::kMaxMeshResolution == 1024, "the --resolution declaration (cli/commands.cpp) says 1..1024");
  const std::string presetName = !r.preset.empty() ? r.preset : r.source.empty() ? "box" : r.source;
  const kifs::Building base = buildingFrom(presetName);
  const kifs::KifsParams& params = base.params();
  if (!r.eval.empty()) return evalPoints(base, r.eval);
  if (!r.mesh.empty()) return meshToFile(base, r.mesh, r.resolution);
  if (r.out.empty()) throw UsageError("kifs: --out PNG (or --mesh FILE, --eval POINTS) is required");

  const int width = r.size.width, height = r.size.height;
  render::KifsMode mode = render::KifsMode::Shaded;
  if (r.mode == "facades" || r.mode == "ids") mode = render::KifsMode::Facades;
  else if (r.mode == "floors") mode = render::KifsMode::Floors;
  else if (r.mode == "cost") mode = render::KifsMode::Cost;
  else if (r.mode == "preview") mode = render::KifsMode::Preview;  // the editor's coarse frames' shading
  else if (r.mode == "bare") mode = render::KifsMode::Bare;
  double az = -60.0, el = 22.0;
  if (!r.camera.empty()) {
    const auto v = numbers(r.camera, ',', "--camera");
    if (v.size() != 2 || v[1] < -89 || v[1] > 89) throw UsageError("--camera: expected AZ,EL in degrees, EL in [-89, 89]");
    az = v[0], el = v[1];
  }
  const int frames = r.frames.value_or(1);

  const double aspect = double(width) / height;
  const render::OrbitCamera camera = render::kifsCamera(base, aspect, az, el);
  const kifs::Building building(render::kifsForView(params, camera, height), base.mass());
  render::HeadlessContext context;
  render::Renderer renderer;
  render::KifsPass pass;
  Scene scene;
  render::RenderSettings settings;
  settings.edges = false;
  if (mode == render::KifsMode::Cost) {
    const render::KifsCost c = render::measureKifsCost(pass, building, camera, width, height);
    render::writePng(c.heat, r.out);
    std::printf("{\"hits\": %d, \"misses\": %d, \"evaluations_per_hit\": %.1f, \"evaluations_per_miss\": %.1f, "
                "\"most_per_hit\": %d}\n",
                c.hits, c.misses, c.meanHit, c.meanMiss, c.maxHit);
    return 0;
  }
  render::Image image;
  // llvmpipe compiles the shader at its first draw (about 0.6 s): time the frames after it.
  if (frames > 1) image = render::renderKifsImage(renderer, pass, building, scene, camera, width, height, mode, settings);
  // Process CPU time counts llvmpipe's threads too: on a shared machine it varies less than
  // the wall clock (CPU ms / threads is the frame time on idle cores).
  const std::clock_t cpuStart = std::clock();
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f)
    image = render::renderKifsImage(renderer, pass, building, scene, camera, width, height, mode, settings);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double cpuMs = 1000.0 * double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  render::writePng(image, r.out);
  if (r.frames)
    std::printf("%.1f ms/frame at %dx%d (%s, %d frames; %.1f ms CPU/frame, all threads)\n", ms / frames, width, height,
                presetName.c_str(), frames, cpuMs / frames);
  return 0;
}

}  // namespace corbel::cli
