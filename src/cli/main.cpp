// corbel-cli: headless entry points (render, export, check, extrude, statics, simulate, kifs, grow, complete, city). Thin: parse, call, report.
#include "city/kernel.h"
#include "cli/city_command.h"
#include "cli/complete.h"
#include "cli/grow.h"
#include "cli/kifs_command.h"
#include "cli/number_list.h"
#include "cli/project_scene.h"
#include "cli/simulate_cli.h"
#include "cli/statics_cli.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "extrude/batch.h"
#include "extrude/footprints.h"
#include "extrude/kernel.h"
#include "growth/kernel.h"
#include "kifs/kernel.h"
#include "render/headless_context.h"
#include "render/kifs_pass.h"
#include "statics/kernel.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <numbers>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace corbel;

constexpr const char* kUsage = R"(corbel-cli — headless tools of corbel

usage:
  corbel-cli render PROJECT --out PNG [--size WxH] [--camera AZ,EL[,DIST]] [--object NAME]
                    [--no-grid] [--no-edges] [--wireframe] [--textures on|off]
                    --textures on draws the built-in textures (docs/city.md) instead of colours.
  corbel-cli export PROJECT --out FILE.{obj,ply,off,glb} [--object NAME]
  corbel-cli check PROJECT        validate the file and every object's shell (JSON lines)
  corbel-cli extrude INPUT [--pitch DEG] [--wall-height M] [--out FILE.{obj,ply,off,glb}] [--stats]
                    [--jobs N] [--library PROJECT] [--merge-coplanar] [--no-retry] [--winding-rule]
                    INPUT: a project (its extrusion objects) or GeoJSON footprints (meters).
                    --pitch gives every edge one roof slope (default 45 for GeoJSON) over walls
                    --wall-height high (default 0). --stats prints one JSON line per building.
                    GeoJSON features may name a profile of the --library project ("profile").
                    --merge-coplanar writes neighbouring faces in one plane as one face.
                    A building whose shell fails is rebuilt with 10-10000x tolerances and kept
                    only where three rebuilds agree (a warning says so); --no-retry does not.
                    --winding-rule rebuilds a plan that overlaps itself after an event by the
                    winding rule (Sec. 4.4) instead of warning; off by default (docs/extrude.md).
  corbel-cli statics arch --blocks N --thickness T [--tilt DEG] [--friction A] [--kern S]
                    [--friction-sides 4|8] [--min-thickness | --critical-tilt]
                    A semicircular arch of N voussoirs (centreline radius 1, radial joints) on
                    rigid ground tilted by DEG. Prints the measure of infeasibility y/W² (0 when
                    it stands); --min-thickness the least t/R that stands (T ignored);
                    --critical-tilt the ground tilt in degrees at which it stops standing.
  corbel-cli statics example NAME [--set NAME=V ...] [--optimize] [--free NAME=LO:HI ...]
                    [--algorithm mma|slsqp|lbfgs] [--max-evaluations N] [--max-seconds S]
                    [--kern S] [--friction A] [--friction-sides 4|8] [--json]
                    NAME: tower (Fig. 11), arch-on-columns (Fig. 8), barrel-vault (Fig. 13),
                    flying-buttresses (Fig. 13 with flyers), bezier-arch (Fig. 12), chapel
                    (Fig. 9, 480 blocks), abbey (Fig. 1, 988 blocks), mosque (Fig. 10 c, a
                    windowed drum with flyers, 296), mosque-hall (Fig. 10 a, d, on a square
                    hall, 336), groin-vault (a groin vault on four corner piers, 80).
                    Prints y/W² and the solver status; --optimize searches the free
                    parameters (the example's own when no --free) until it stands (Sec. 4)
                    and prints the status (feasible or local minimum), iterations, values.
  corbel-cli statics PROJECT.corbel [--object NAME] [the example command's options]
                    [--render PNG [--size WxH]] [--landscape NAME1 NAME2 PNG [--samples N]]
                    A project's masonry objects, each with its own parameters and bounds, as
                    the example command. --render (also for example NAME) draws the model after
                    the analysis or search: blocks by their share of tension, compression red,
                    tension blue, ground reactions green. --landscape samples y/W² on an N x N
                    grid of two parameters (Fig. 8; NAME=LO:HI sets a range): red stands.
  corbel-cli statics PROJECT.corbel --scene [--structural NAME ...] [--nonstructural NAME ...]
                    [--density MATERIAL=KG_PER_M3 ...] [--kern S] [--friction A] [--json]
                    The project as built: every connected piece of its block objects (or of
                    the objects --structural names, any kind) a rigid block, convex or not,
                    weighing by its material; pieces tagged "ground" fixed, else a ground plane
                    under the lowest point; --nonstructural objects carried as loads.
  corbel-cli grow SITE.json [--seed N] [--steps K] [--stats] [--out FILE] [--render PNG]
                    [--view-maps exact|raster|gl] [--pixel M]
                    Grows housing units on a site (docs/growth.md); prints one JSON line.
  corbel-cli complete (--seeds N [--entrance X,Y ...] | --from PROJECT [--object NAME] [--storey K])
                    --complexity LO:HI [--count K] [--region X0,Y0,X1,Y1] [--seed S]
                    [--out FILE] [--render PNG]
                    Completes forms from N seed units with F_q in [LO, HI] (docs/growth.md),
                    fitted and sized into the region, entrances realized (--from: a grown
                    model's gap and its entrances); prints one JSON line.
  corbel-cli city FOOTPRINTS.geojson --style STYLE.json [--seed N] [--jobs N] [--out FILE.glb]
                    [--tiles DIR] [--tile-size M] [--render PNG] [--around X,Y,R]
                    [--coordinates auto|lonlat|metric] [--report FILE.jsonl] [--detail massing|steps|full]
                    [--textures on|off] [--render-textures on|off] | --street X,Y;X,Y;...
                    A styled town (docs/city.md); prints one JSON line, skipped buildings on stderr.
)";
constexpr const char* kUsageEnd = R"(  corbel-cli --version | --help

Exit codes: 0 success, 1 bad input or failed check, 2 bad command line.
)";

struct UsageError : Error {
  using Error::Error;
};

struct Args {
  std::string command;
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // "--out" → value; flags map to ""
};

Args parseArgs(int argc, char** argv, const std::map<std::string, bool>& known /* name → takes value */) {
  Args a;
  a.command = argv[1];
  for (int i = 2; i < argc; ++i) {
    std::string s = argv[i];
    if (s.rfind("--", 0) == 0) {
      auto it = known.find(s);
      if (it == known.end()) throw UsageError(a.command + ": unknown option " + s);
      if (it->second) {
        if (i + 1 >= argc) throw UsageError(a.command + ": " + s + " needs a value");
        a.options[s] = argv[++i];
      } else {
        a.options[s] = "";
      }
    } else {
      a.positional.push_back(s);
    }
  }
  return a;
}

std::vector<double> parseNumbers(const std::string& text, char sep, const std::string& what) {
  const auto v = cli::numberList(text, sep);
  if (!v) throw UsageError(what + ": '" + text + "' is not a list of numbers");
  return *v;
}

using Loaded = cli::LoadedScene;
Loaded load(const std::string& path) { return cli::loadScene(path); }

std::optional<ObjectId> objectByName(const Document& doc, const Args& a) {
  auto it = a.options.find("--object");
  if (it == a.options.end()) return std::nullopt;
  const DocObject* o = doc.findByName(it->second);
  if (!o) {
    std::string names;
    for (const auto& obj : doc.objects) names += (names.empty() ? "" : ", ") + ("\"" + obj.name + "\"");
    throw Error("no object named \"" + it->second + "\" (objects: " + (names.empty() ? "none" : names) + ")");
  }
  return o->id;
}

int cmdRender(const Args& a) {
  if (a.positional.size() != 1) throw UsageError("render: expected one PROJECT");
  auto out = a.options.find("--out");
  if (out == a.options.end()) throw UsageError("render: --out PNG is required");
  int width = 800, height = 600;
  if (auto s = a.options.find("--size"); s != a.options.end()) {
    const auto v = parseNumbers(s->second, 'x', "--size");
    if (v.size() != 2 || v[0] < 1 || v[1] < 1 || v[0] > 8192 || v[1] > 8192 || v[0] != int(v[0]) || v[1] != int(v[1]))
      throw UsageError("--size: expected WxH with whole numbers in 1..8192, like 800x600");
    width = int(v[0]);
    height = int(v[1]);
  }
  Loaded l = load(a.positional[0]);
  const std::optional<ObjectId> only = objectByName(l.doc, a);

  render::RenderSettings settings;
  settings.grid = !a.options.count("--no-grid");
  settings.edges = !a.options.count("--no-edges");
  settings.wireframe = a.options.count("--wireframe") > 0;
  if (auto t = a.options.find("--textures"); t != a.options.end()) {
    if (t->second != "on" && t->second != "off")
      throw UsageError("--textures: expected on or off, not '" + t->second + "'");
    settings.textures = t->second == "on";
    if (settings.textures) settings.tagTextures = l.towns->tagTextures();
  }
  settings.visible = [&](ObjectId id) {
    if (only) return id == *only;
    const DocObject* o = l.doc.find(id);
    return o && o->visible;
  };
  BBox box;
  for (const auto& [id, info] : l.scene.objects())
    if (settings.visible(id)) box.add(l.scene.bounds(id));
  // KIFS buildings that are not meshed are ray-marched over the Scene (render/kifs_pass.h).
  const render::RaymarchedKifs raymarched = render::raymarchedKifs(l.doc, settings.visible);
  box.add(raymarched.bounds);
  render::OrbitCamera camera;
  camera.frame(box, double(width) / height);
  if (auto c = a.options.find("--camera"); c != a.options.end()) {
    const auto v = parseNumbers(c->second, ',', "--camera");
    if (v.size() < 2 || v.size() > 3) throw UsageError("--camera: expected AZ,EL or AZ,EL,DIST (degrees, meters)");
    camera.azimuth_deg = v[0];
    camera.elevation_deg = std::clamp(v[1], -89.9, 90.0);
    if (v.size() == 3) {
      if (!(v[2] > 0)) throw UsageError("--camera: DIST must be positive");
      camera.distance = v[2];
    }
  }
  render::HeadlessContext context;
  render::Renderer renderer;
  const render::Image image =
      render::renderSceneWithKifs(renderer, l.scene, raymarched.buildings, camera, width, height, settings);
  render::writePng(image, out->second);
  std::cout << out->second << "\n";
  return 0;
}

int cmdExport(const Args& a) {
  if (a.positional.size() != 1) throw UsageError("export: expected one PROJECT");
  auto out = a.options.find("--out");
  if (out == a.options.end()) throw UsageError("export: --out FILE is required");
  try {
    exportFormatFor(out->second);  // fail on a bad extension before any work
  } catch (const Error& e) {
    throw UsageError(e.what());  // a bad --out is a command-line fault (exit 2)
  }
  Loaded l = load(a.positional[0]);
  const std::optional<ObjectId> only = objectByName(l.doc, a);
  ExportOptions options;
  options.include = [&](ObjectId id) {
    if (only) return id == *only;
    const DocObject* o = l.doc.find(id);
    return o && o->visible;
  };
  exportScene(l.scene, out->second, options);
  std::cout << out->second << "\n";
  return 0;
}

int cmdExtrude(const Args& a) {
  if (a.positional.size() != 1) throw UsageError("extrude: expected one INPUT (project or GeoJSON)");
  const std::string input = a.positional[0];
  auto number = [&](const char* opt, double def, double lo, double hi) {
    auto it = a.options.find(opt);
    if (it == a.options.end()) return def;
    const auto v = parseNumbers(it->second, ',', opt);
    if (v.size() != 1 || v[0] < lo || v[0] > hi)
      throw UsageError(std::string(opt) + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v[0];
  };
  const bool pitchGiven = a.options.count("--pitch") > 0;
  const double pitch = number("--pitch", 45.0, 0.5, 89.5) * std::numbers::pi / 180.0;
  const double wall = number("--wall-height", 0.0, 0.0, 1000.0);
  const unsigned jobs = static_cast<unsigned>(number("--jobs", 0, 0, 1024));
  std::string out;
  if (auto it = a.options.find("--out"); it != a.options.end()) {
    out = it->second;
    try {
      exportFormatFor(out);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  const Profile uniform = extrude::wallAndRoofProfile(wall, pitch);
  std::vector<Profile> library;
  if (auto it = a.options.find("--library"); it != a.options.end()) {
    for (const auto& o : loadProject(it->second).document.objects)
      if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec))
        for (const Profile& p : e->profiles) library.push_back(p);
  }

  const std::string text = readFile(input, std::size_t(1) << 31);
  std::vector<extrude::BatchItem> items;
  const bool isProject = text.find("\"format\"") != std::string::npos && text.find("\"corbel\"") != std::string::npos;
  if (isProject) {
    const Document doc = loadProject(input).document;
    for (const DocObject& o : doc.objects) {
      const auto* e = std::get_if<ExtrusionSpec>(&o.spec);
      if (!e) continue;
      extrude::BatchItem item{o.name, *e, ""};
      if (pitchGiven || a.options.count("--wall-height")) {
        item.spec.profiles = {uniform};
        for (auto& l : item.spec.loops) l.profile.assign(l.points.size(), 0);
      }
      items.push_back(std::move(item));
    }
  } else {
    std::vector<extrude::Footprint> fps;
    try {
      fps = extrude::readGeoJson(text);
    } catch (const InputError& e) {
      throw InputError(e.where.empty() ? input : input + ": " + e.where, e.reason);
    }
    for (auto& fp : fps) {
      extrude::BatchItem item;
      item.id = fp.id;
      item.problem = fp.problem;
      item.spec.profiles = {uniform};
      if (fp.properties.contains("profile") && fp.properties["profile"].is_string()) {
        const std::string name = fp.properties["profile"].get<std::string>();
        auto found = std::find_if(library.begin(), library.end(), [&](const Profile& p) { return p.name == name; });
        if (found == library.end()) item.problem = "properties.profile: no profile named \"" + name + "\" in the --library";
        else item.spec.profiles = {*found};
      }
      for (auto& l : fp.loops) item.spec.loops.push_back({l, std::vector<int>(l.size(), 0)});
      items.push_back(std::move(item));
    }
  }
  if (items.empty()) throw Error(input + ": no buildings to extrude");

  extrude::BatchOptions options;
  options.jobs = jobs;
  options.keepMeshes = !out.empty();
  options.mergeCoplanar = a.options.count("--merge-coplanar") > 0;
  if (a.options.count("--no-retry")) options.retryFactors.clear();
  options.windingRule = a.options.count("--winding-rule") > 0;
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = extrude::extrudeBatch(items, options);
  const double batchMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  std::size_t failed = 0, withWarnings = 0;
  const bool stats = a.options.count("--stats") > 0;
  for (const auto& r : results) {
    if (!r.ok) ++failed;
    if (!r.warnings.empty()) ++withWarnings;
    if (stats) {
      nlohmann::ordered_json j;
      j["id"] = r.id;
      if (r.ok) {
        j["faces"] = r.measures.faces;
        j["mesh_faces"] = r.meshFaces;
        j["vertices"] = r.meshVertices;
        j["roof_area"] = r.measures.roofArea;
        j["wall_area"] = r.measures.wallArea;
        j["volume"] = r.measures.volume;
        j["max_height"] = r.measures.maxHeight;
        if (!r.anchors.empty()) {
          auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v[0], v[1], v[2]}); };
          nlohmann::ordered_json anchors = nlohmann::ordered_json::array();
          for (const auto& a : r.anchors) {
            nlohmann::ordered_json aj;
            aj["name"] = a.name;
            aj["instanced"] = a.instanced;
            if (a.instanced) {
              aj["position"] = vec(a.position);
              aj["along"] = vec(a.along);
              aj["normal"] = vec(a.normal);
              aj["up"] = vec(a.up);
            }
            anchors.push_back(std::move(aj));
          }
          j["anchors"] = std::move(anchors);
        }
      } else {
        j["error"] = r.error;
      }
      j["watertight"] = r.watertight;
      j["manifold"] = r.manifold;
      j["warnings"] = r.warnings;
      j["tolerance_factor"] = r.toleranceFactor;
      j["builds"] = r.builds;
      j["ms"] = r.ms;
      std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else if (!r.ok) {
      std::cerr << "corbel-cli: " << r.id << ": " << r.error << "\n";
    }
  }
  double exportMs = 0;
  if (!out.empty()) {
    const auto e0 = std::chrono::steady_clock::now();
    Scene scene;
    ObjectId id = 1;
    for (const auto& r : results)
      if (r.ok) scene.replaceObject(id++, Kind::Shell, r.id, r.mesh);
    exportScene(scene, out);
    exportMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
  }
  nlohmann::ordered_json summary;
  summary["summary"] = true;
  summary["buildings"] = results.size();
  summary["ok"] = results.size() - failed;
  summary["failed"] = failed;
  summary["with_warnings"] = withWarnings;
  summary["extrude_ms"] = batchMs;
  if (!out.empty()) {
    summary["export_ms"] = exportMs;
    summary["out"] = out;
  }
  (stats ? std::cout : std::cerr) << summary.dump() << "\n";
  return failed ? 1 : 0;
}

int cmdCheck(const Args& a) {
  if (a.positional.size() != 1) throw UsageError("check: expected one PROJECT");
  Loaded l = load(a.positional[0]);
  int bad = 0;
  for (const DocObject& o : l.doc.objects) {
    nlohmann::ordered_json j;
    j["object"] = o.name;
    if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0) {
      j["raymarched"] = true;  // no shell in the Scene to check; its parameters were validated
      std::cout << j.dump() << "\n";
      continue;
    }
    const ValidityReport r = l.scene.validate(o.id);
    j["faces"] = r.faces;
    j["vertices"] = r.vertices;
    j["edges"] = r.edges;
    j["euler"] = r.euler;
    j["components"] = r.components;
    j["watertight"] = r.watertight();
    j["manifold"] = r.manifold();
    j["consistent"] = r.consistent();
    j["area"] = r.area;
    j["volume"] = r.volume;
    j["problems"] = r.problems();
    std::cout << j.dump() << "\n";
    if (!r.closedManifold()) ++bad;
  }
  std::cout << nlohmann::ordered_json{{"objects", l.doc.objects.size()}, {"failed", bad}}.dump() << "\n";
  return bad ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::cout << kUsage << corbel::cli::kKifsUsage << corbel::cli::kSimulateUsage << kUsageEnd;
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::cout << "corbel-cli 0.1.0 (project format " << corbel::kProjectVersion << ")\n";
    return 0;
  }
  try {
    const std::string cmd = argv[1];
    if (cmd == "render")
      return cmdRender(parseArgs(argc, argv,
                                 {{"--out", true},
                                  {"--size", true},
                                  {"--camera", true},
                                  {"--object", true},
                                  {"--no-grid", false},
                                  {"--no-edges", false},
                                  {"--wireframe", false},
                                  {"--textures", true}}));
    if (cmd == "export") return cmdExport(parseArgs(argc, argv, {{"--out", true}, {"--object", true}}));
    if (cmd == "check") return cmdCheck(parseArgs(argc, argv, {}));
    if (cmd == "extrude")
      return cmdExtrude(parseArgs(argc, argv,
                                  {{"--pitch", true},
                                   {"--wall-height", true},
                                   {"--out", true},
                                   {"--stats", false},
                                   {"--jobs", true},
                                   {"--library", true},
                                   {"--merge-coplanar", false},
                                   {"--no-retry", false},
                                   {"--winding-rule", false}}));
    if (cmd == "kifs") return corbel::cli::kifsCommand(argc, argv);
    if (cmd == "statics") return cli::runStatics(argc, argv);
    if (cmd == "simulate") return cli::runSimulate(argc, argv);
    if (cmd == "grow") return corbel::cli::grow(argc, argv);
    if (cmd == "complete") return corbel::cli::complete(argc, argv);
    if (cmd == "city") return corbel::cli::city(argc, argv);
    throw UsageError("unknown command '" + cmd + "' (try --help)");
  } catch (const UsageError& e) {
    std::cerr << "corbel-cli: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "corbel-cli: error: " << e.what() << "\n";
    return 1;
  }
}
