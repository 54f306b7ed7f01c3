#include "cli/kifs_command.h"

#include "cli/guarded.h"
#include "cli/number_list.h"

#include "core/error.h"
#include "core/export.h"
#include "core/scene.h"
#include "kifs/mesher.h"
#include "kifs/trace.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include "core/project_io.h"
#include "kifs/kernel.h"
#include <string>
#include <vector>

namespace corbel::cli {

const char* const kKifsUsage =
    R"(  corbel-cli kifs [PRESET|PROJECT.corbel] --out PNG [--preset NAME] [--size WxH] [--mode shaded|preview|facades|floors|cost]
                    [--camera AZ,EL] [--frames N]
                    A KIFS building (McGraw) raymarched on the GPU path (OSMesa). Presets: the files
                    assets/kifs/NAME.json (box, menger, t, h, polar, curved, sparse, crumbling,
                    turned, star; default box);
                    a project gives its first KIFS object (every form below takes it too).
                    --frames N renders N times after one untimed frame (the first draw
                    compiles the shader) and prints the mean milliseconds per frame.
                    --mode preview shades without soft shadow and occlusion, as the
                    editor's coarse frames do; --mode cost writes a heat map of distance evaluations per pixel and prints
                    their means (JSON).
  corbel-cli kifs --mesh FILE.{obj,ply,off,glb} [--preset NAME] [--resolution N]
                    Meshes the building (marching tetrahedra, N cells along the longest side,
                    default 128) and exports it; prints one JSON line (faces, closed, seconds).
  corbel-cli kifs --eval POINTS [--preset NAME]
                    Prints the CPU distance bound and estimate ("bound surface") of each point
                    "x y z" (one a line, world coordinates, Z up) of the file POINTS.
)";

namespace {

struct Usage : Error {
  using Error::Error;
};

std::vector<double> numbers(const std::string& text, char sep, const std::string& what) {
  const auto v = numberList(text, sep);
  if (!v) throw Usage(what + ": '" + text + "' is not a list of numbers");
  return *v;
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

int meshToFile(const kifs::Building& b, std::map<std::string, std::string>& opt) {
  int resolution = 128;
  if (opt.count("--resolution")) {
    const auto v = numbers(opt["--resolution"], ',', "--resolution");
    if (v.size() != 1 || v[0] < 1 || v[0] > kifs::kMaxMeshResolution || v[0] != int(v[0]))
      throw Usage("--resolution: expected a whole number in 1.." + std::to_string(kifs::kMaxMeshResolution));
    resolution = int(v[0]);
  }
  exportFormatFor(opt["--mesh"]);  // refuses an unknown extension before the work
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  scene.replaceObject(1, Kind::Ornament, "kifs", kifs::meshBuilding(b, resolution));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  exportScene(scene, opt["--mesh"]);
  const ValidityReport v = scene.validate(1);
  std::printf("{\"faces\": %zu, \"vertices\": %zu, \"closed_manifold\": %s, \"resolution\": %d, \"seconds\": %.2f}\n",
              v.faces, v.vertices, v.closedManifold() ? "true" : "false", resolution, seconds);
  return v.closedManifold() ? 0 : 1;
}

int run(int argc, char** argv) {
  std::map<std::string, std::string> opt;
  const std::map<std::string, bool> known = {{"--out", true},    {"--preset", true}, {"--size", true},
                                             {"--mode", true},   {"--camera", true}, {"--frames", true},
                                             {"--eval", true},   {"--mesh", true},   {"--resolution", true}};
  std::string source;  // PRESET_OR_PROJECT, the optional first argument
  for (int i = 2; i < argc; ++i) {
    const std::string s = argv[i];
    if (i == 2 && s.rfind("--", 0) != 0) {
      source = s;
      continue;
    }
    auto it = known.find(s);
    if (it == known.end()) throw Usage("kifs: unknown argument " + s);
    if (i + 1 >= argc) throw Usage("kifs: " + s + " needs a value");
    opt[s] = argv[++i];
  }
  if (!source.empty() && opt.count("--preset")) throw Usage("kifs: give a preset or project, or --preset, not both");
  std::string presetName = opt.count("--preset") ? opt["--preset"] : source.empty() ? "box" : source;
  kifs::KifsParams params;
  if (presetName.size() > 7 && presetName.substr(presetName.size() - 7) == ".corbel") {
    // A project: its first KIFS object, with the parameters the project holds.
    const LoadedProject project = loadProject(presetName);
    const KifsSpec* spec = nullptr;
    for (const DocObject& o : project.document.objects)
      if ((spec = std::get_if<KifsSpec>(&o.spec))) break;
    if (!spec) throw Error(presetName + ": the project has no KIFS object");
    params = kifs::paramsOf(*spec);
  } else {
    params = kifs::preset(presetName);
  }
  if (opt.count("--eval")) return evalPoints(kifs::Building(params), opt["--eval"]);
  if (opt.count("--mesh")) return meshToFile(kifs::Building(params), opt);
  if (!opt.count("--out")) throw Usage("kifs: --out PNG (or --mesh FILE, --eval POINTS) is required");

  int width = 640, height = 640;
  if (opt.count("--size")) {
    const auto v = numbers(opt["--size"], 'x', "--size");
    if (v.size() != 2 || v[0] < 1 || v[1] < 1 || v[0] > 8192 || v[1] > 8192 || v[0] != int(v[0]) || v[1] != int(v[1]))
      throw Usage("--size: expected WxH, whole numbers in 1..8192");
    width = int(v[0]), height = int(v[1]);
  }
  render::KifsMode mode = render::KifsMode::Shaded;
  if (opt.count("--mode")) {
    const std::string m = opt["--mode"];
    if (m == "shaded") mode = render::KifsMode::Shaded;
    else if (m == "facades" || m == "ids") mode = render::KifsMode::Facades;
    else if (m == "floors") mode = render::KifsMode::Floors;
    else if (m == "cost") mode = render::KifsMode::Cost;
    else if (m == "preview") mode = render::KifsMode::Preview;  // the editor's coarse frames' shading
    else throw Usage("--mode: expected shaded, preview, facades, floors or cost, got '" + m + "'");
  }
  double az = -60.0, el = 22.0;
  if (opt.count("--camera")) {
    const auto v = numbers(opt["--camera"], ',', "--camera");
    if (v.size() != 2 || v[1] < -89 || v[1] > 89) throw Usage("--camera: expected AZ,EL in degrees, EL in [-89, 89]");
    az = v[0], el = v[1];
  }
  int frames = 1;
  if (opt.count("--frames")) {
    const auto v = numbers(opt["--frames"], ',', "--frames");
    if (v.size() != 1 || v[0] < 1 || v[0] > 1000 || v[0] != int(v[0])) throw Usage("--frames: expected 1..1000");
    frames = int(v[0]);
  }

  const double aspect = double(width) / height;
  const render::OrbitCamera camera = render::kifsCamera(kifs::Building(params), aspect, az, el);
  const kifs::Building building(render::kifsForView(params, camera, height));
  render::HeadlessContext context;
  render::Renderer renderer;
  render::KifsPass pass;
  Scene scene;
  render::RenderSettings settings;
  settings.edges = false;
  if (mode == render::KifsMode::Cost) {
    const render::KifsCost c = render::measureKifsCost(pass, building, camera, width, height);
    render::writePng(c.heat, opt["--out"]);
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
  render::writePng(image, opt["--out"]);
  if (opt.count("--frames"))
    std::printf("%.1f ms/frame at %dx%d (%s, %d frames; %.1f ms CPU/frame, all threads)\n", ms / frames, width, height,
                presetName.c_str(), frames, cpuMs / frames);
  return 0;
}

}  // namespace

int kifsCommand(int argc, char** argv) {
  return guarded<Usage>([&] { return run(argc, argv); });
}

}  // namespace corbel::cli
