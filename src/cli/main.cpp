// corbel-cli: headless entry points (render, export, check). Thin: parse, call, report.
#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene_sync.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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
                    [--no-grid] [--no-edges] [--wireframe]
  corbel-cli export PROJECT --out FILE.{obj,ply,off,glb} [--object NAME]
  corbel-cli check PROJECT        validate the file and every object's shell (JSON lines)
  corbel-cli --version | --help

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
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, sep)) {
    char* end = nullptr;
    const double d = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(d)) throw UsageError(what + ": '" + text + "' is not a list of numbers");
    out.push_back(d);
  }
  return out;
}

struct Loaded {
  Document doc;
  Scene scene;
};

Loaded load(const std::string& path) {
  Loaded l;
  LoadedProject p = loadProject(path);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << path << ": " << w << "\n";
  l.doc = std::move(p.document);
  SceneSync sync;
  sync.update(l.doc, l.scene);
  return l;
}

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
  settings.visible = [&](ObjectId id) {
    if (only) return id == *only;
    const DocObject* o = l.doc.find(id);
    return o && o->visible;
  };
  BBox box;
  for (const auto& [id, info] : l.scene.objects())
    if (settings.visible(id)) box.add(l.scene.bounds(id));

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
  const render::Image image = render::renderImage(renderer, l.scene, camera, width, height, settings);
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

int cmdCheck(const Args& a) {
  if (a.positional.size() != 1) throw UsageError("check: expected one PROJECT");
  Loaded l = load(a.positional[0]);
  int bad = 0;
  for (const DocObject& o : l.doc.objects) {
    const ValidityReport r = l.scene.validate(o.id);
    nlohmann::ordered_json j;
    j["object"] = o.name;
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
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::cout << "corbel-cli 0.1.0 (project format " << corbel::kProjectVersion << ")\n";
    return 0;
  }
  try {
    const std::string cmd = argv[1];
    if (cmd == "render")
      return cmdRender(parseArgs(argc, argv, {{"--out", true}, {"--size", true}, {"--camera", true}, {"--object", true},
                                              {"--no-grid", false}, {"--no-edges", false}, {"--wireframe", false}}));
    if (cmd == "export") return cmdExport(parseArgs(argc, argv, {{"--out", true}, {"--object", true}}));
    if (cmd == "check") return cmdCheck(parseArgs(argc, argv, {}));
    throw UsageError("unknown command '" + cmd + "' (try --help)");
  } catch (const UsageError& e) {
    std::cerr << "corbel-cli: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "corbel-cli: error: " << e.what() << "\n";
    return 1;
  }
}
