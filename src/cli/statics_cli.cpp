// corbel-cli statics arch | example | PROJECT: parse, call the statics kernel, print; --render
// and --landscape draw the editor's statics pictures headless (cli/statics_png.h).
#include "cli/statics_cli.h"

#include "cli/guarded.h"
#include "cli/number_list.h"
#include "cli/project_scene.h"
#include "cli/statics_png.h"
#include "core/error.h"
#include "core/project_io.h"
#include "editor/masonry_edits.h"
#include "editor/masonry_view.h"
#include "render/headless_context.h"
#include "statics/analysis.h"
#include "statics/arch.h"
#include "statics/examples.h"
#include "statics/kernel.h"
#include "statics/scene_blocks.h"
#include "statics/search.h"
#include "statics/thresholds.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace corbel::cli {
namespace {

struct UsageError : Error {
  using Error::Error;
};

struct Options {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;  // last value of each single option; flags map to ""
  std::vector<std::string> frees, sets;       // --free and --set, repeatable
  std::vector<std::string> structural, nonstructural, densities;  // --structural, --nonstructural, --density
  std::vector<std::string> landscape;         // --landscape NAME1 NAME2 PNG
};

Options parse(int argc, char** argv, const std::map<std::string, bool>& known) {
  Options o;
  for (int i = 2; i < argc; ++i) {
    const std::string s = argv[i];
    if (s.rfind("--", 0) != 0) {
      o.positional.push_back(s);
      continue;
    }
    const auto it = known.find(s);
    if (it == known.end()) throw UsageError("statics: unknown option " + s);
    if (s == "--landscape") {
      if (i + 3 >= argc) throw UsageError("statics: --landscape needs NAME1 NAME2 PNG");
      o.landscape.assign(argv + i + 1, argv + i + 4);
      o.values[s] = "";
      i += 3;
      continue;
    }
    if (!it->second) {
      o.values[s] = "";
      continue;
    }
    if (i + 1 >= argc) throw UsageError("statics: " + s + " needs a value");
    const std::string v = argv[++i];
    if (s == "--free")
      o.frees.push_back(v);
    else if (s == "--set")
      o.sets.push_back(v);
    else if (s == "--structural")
      o.structural.push_back(v);
    else if (s == "--nonstructural")
      o.nonstructural.push_back(v);
    else if (s == "--density")
      o.densities.push_back(v);
    else
      o.values[s] = v;
  }
  return o;
}

double number(const Options& o, const char* opt, double def, double lo, double hi) {
  const auto it = o.values.find(opt);
  if (it == o.values.end()) return def;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
    throw UsageError(std::string(opt) + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

int sides(const Options& a) {
  const double v = number(a, "--friction-sides", 4, 4, 8);
  if (v != 4 && v != 8) throw UsageError("--friction-sides: expected 4 or 8");
  return int(v);
}

int archCommand(const Options& a) {
  const bool minThickness = a.values.count("--min-thickness") > 0, criticalTilt = a.values.count("--critical-tilt") > 0;
  if (minThickness && criticalTilt) throw UsageError("statics: --min-thickness and --critical-tilt exclude each other");
  if (!a.values.count("--blocks")) throw UsageError("statics arch: --blocks N is required");
  for (const char* o : {"--render", "--size", "--landscape", "--samples"})
    if (a.values.count(o))
      throw UsageError(std::string("statics arch: ") + o + " is for 'statics example NAME' and 'statics PROJECT'");
  if (!minThickness && !a.values.count("--thickness")) throw UsageError("statics arch: --thickness T is required");
  statics::ArchSpec spec;
  const double blocks = number(a, "--blocks", 100, 1, 100000);
  if (blocks != std::floor(blocks)) throw UsageError("--blocks: expected a whole number");
  spec.blocks = int(blocks);
  spec.thickness = number(a, "--thickness", 0.2, 1e-6, 1.999);
  spec.tiltDeg = number(a, "--tilt", 0, -89, 89);
  statics::AnalysisOptions options;
  options.friction = number(a, "--friction", 0.7, 0, 100);
  options.kernShrink = number(a, "--kern", 0, 0, 0.99);
  options.frictionSides = sides(a);
  char text[64];
  if (minThickness) {
    std::snprintf(text, sizeof text, "%.6f", statics::minimumArchThickness(spec, options, 1e-6));
  } else if (criticalTilt) {
    std::snprintf(text, sizeof text, "%.4f", statics::criticalArchTilt(spec, options, 1e-5));
  } else {
    const statics::AnalysisResult r = statics::analyse(statics::semicircularArch(spec), options);
    if (r.status != statics::SolveStatus::Optimal)
      std::cerr << "corbel-cli: warning: the solver stopped early (" << statics::toString(r.status) << ")\n";
    std::snprintf(text, sizeof text, "%.6g", r.feasible ? 0.0 : r.yNormalised);
  }
  std::cout << text << "\n";
  return 0;
}

bool endsWithPng(const std::string& path) {
  if (path.size() < 5) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// What --render, --size, --landscape and --samples ask for, checked before any work.
struct Pictures {
  std::string render;  // PNG of the model after the analysis (or the search)
  int width = 1200, height = 800;
  std::vector<std::string> landscape;  // NAME1[=LO:HI] NAME2[=LO:HI] PNG
  int samples = 41;
};

Pictures picturesOf(const Options& a) {
  Pictures p;
  if (a.values.count("--render")) {
    p.render = a.values.at("--render");
    if (!endsWithPng(p.render)) throw UsageError("--render: expected a .png file, got '" + p.render + "'");
  }
  if (a.values.count("--size")) {
    if (p.render.empty()) throw UsageError("statics: --size needs --render");
    const auto v = numberList(a.values.at("--size"), 'x');
    if (!v || v->size() != 2 || (*v)[0] < 16 || (*v)[1] < 16 || (*v)[0] > 8192 || (*v)[1] > 8192 ||
        (*v)[0] != std::floor((*v)[0]) || (*v)[1] != std::floor((*v)[1]))
      throw UsageError("--size: expected WxH with whole numbers in 16..8192, like 800x600, got '" +
                       a.values.at("--size") + "'");
    p.width = int((*v)[0]);
    p.height = int((*v)[1]);
  }
  p.landscape = a.landscape;
  if (!p.landscape.empty() && !endsWithPng(p.landscape[2]))
    throw UsageError("--landscape: expected NAME1 NAME2 PNG, and '" + p.landscape[2] + "' is not a .png file");
  if (a.values.count("--samples")) {
    if (p.landscape.empty()) throw UsageError("statics: --samples needs --landscape");
    const double n = number(a, "--samples", 41, 2, 1024);
    if (n != std::floor(n)) throw UsageError("--samples: expected a whole number");
    p.samples = int(n);
  }
  return p;
}

// A landscape axis: NAME (its free bounds, else the model's suggested ones, else its value
// ± 50 %) or NAME=LO:HI.
editor::LandscapeAxis axisOf(const std::string& text, const statics::ParameterSet& values,
                             const std::vector<statics::FreeParameter>& free,
                             const std::vector<statics::FreeParameter>& suggested, int samples) {
  editor::LandscapeAxis axis;
  axis.samples = samples;
  if (text.find('=') != std::string::npos) {
    const statics::FreeParameter f = statics::parseFreeParameter(text);
    statics::validateFreeParameters(values, {f});
    axis.parameter = f.name;
    axis.lo = f.lo;
    axis.hi = f.hi;
    return axis;
  }
  const statics::Parameter& p = values.find(text);  // throws naming the known parameters
  if (!p.continuous) throw Error("--landscape: " + text + " is a count, not a continuous parameter");
  axis.parameter = text;
  const auto it =
      std::find_if(free.begin(), free.end(), [&](const statics::FreeParameter& f) { return f.name == text; });
  std::tie(axis.lo, axis.hi) = it != free.end() ? std::make_pair(it->lo, it->hi) : editor::defaultBounds(p, suggested);
  return axis;
}

// The pictures of the model at `values` (after the search when there was one), into `out`.
// `path`: the search's evaluations (values of `free`, in order), drawn over the landscape when
// the search moved exactly its two parameters.
void drawPictures(const Pictures& pictures, const MasonrySpec& base, const statics::ParametricModel& model,
                  const statics::ParameterSet& values, const std::vector<statics::FreeParameter>& free,
                  const statics::AnalysisOptions& options, nlohmann::ordered_json& out,
                  const std::vector<std::vector<double>>& path = {}) {
  MasonrySpec spec = base;
  spec.parameters.clear();
  for (const statics::Parameter& p : values.all()) spec.parameters.push_back({p.name, p.value});
  spec.friction = options.friction;
  spec.kern = options.kernShrink;
  if (!pictures.render.empty()) {
    const editor::MasonryView view = editor::analyseMasonry(spec, options);
    if (!view.error.empty()) throw Error(view.error);
    render::HeadlessContext context;
    render::writePng(renderMasonryView(view, pictures.width, pictures.height), pictures.render);
    out["render"] = pictures.render;
  }
  if (!pictures.landscape.empty()) {
    const editor::LandscapeAxis x = axisOf(pictures.landscape[0], values, free, model.suggestedFree, pictures.samples);
    const editor::LandscapeAxis y = axisOf(pictures.landscape[1], values, free, model.suggestedFree, pictures.samples);
    statics::ParametricModel at = model;
    at.parameters = values;
    const editor::LandscapeGrid grid = editor::sampleLandscapeGrid(at, options, x, y);
    const std::vector<std::pair<double, double>> drawn = editor::searchPathOnGrid(grid, free, path);
    const int side = std::max(x.samples, y.samples);
    render::writePng(landscapeImage(grid, std::max(1, 480 / side), drawn), pictures.landscape[2]);
    nlohmann::ordered_json l;
    l["png"] = pictures.landscape[2];
    l["x"] = {{"parameter", x.parameter}, {"lo", x.lo}, {"hi", x.hi}, {"samples", x.samples}};
    l["y"] = {{"parameter", y.parameter}, {"lo", y.lo}, {"hi", y.hi}, {"samples", y.samples}};
    std::size_t standing = 0;
    for (char c : grid.stands) standing += c != 0;
    l["standing"] = standing;
    const auto [i, j] = grid.minimum();
    if (i >= 0) l["minimum"] = {{x.parameter, x.valueAt(i)}, {y.parameter, y.valueAt(j)}, {"measure", grid.at(i, j)}};
    double largest = 0;
    for (double m : grid.measure)
      if (std::isfinite(m)) largest = std::max(largest, m);
    l["largest_measure"] = largest;
    if (!drawn.empty()) {
      nlohmann::ordered_json p = nlohmann::json::array();
      for (const auto& [px, py] : drawn) p.push_back({px, py});
      l["path"] = p;
    }
    out["landscape"] = l;
  }
}

// One analysis's figures in the commands' JSON: the measure, y, the verdict, the solver's
// status, iterations and gap, the tension sites and the largest pressure gauge (null when a
// contact carries no compression).
void putAnalysis(const statics::AnalysisResult& r, nlohmann::ordered_json& out) {
  out["measure"] = r.yNormalised;
  out["y"] = r.y;
  out["stands"] = r.feasible;
  out["status"] = statics::toString(r.status);
  out["iterations"] = r.iterations;
  out["gap"] = r.gap;
  out["tension_sites"] = r.tensionSites.size();
  double gauge = 0;
  for (const statics::InterfaceForces& f : r.interfaces) gauge = std::max(gauge, f.pressureGauge);
  out["max_pressure_gauge"] = std::isfinite(gauge) ? nlohmann::json(gauge) : nlohmann::json(nullptr);
}

// Analyses (or, with --optimize, searches) one model: an example by name, or a project's
// masonry object (`base`: its spec, for the pictures). `free` and the analysis settings are
// the defaults the command line overrides.
int runModel(const Options& a, const statics::ParametricModel& model, std::vector<statics::FreeParameter> free,
             const MasonrySpec& base, const std::string& object) {
  const double friction = base.friction, kern = base.kern;
  const Pictures pictures = picturesOf(a);
  statics::ParameterSet values = model.parameters;
  for (const std::string& s : a.sets) {
    const auto eq = s.find('=');
    char* end = nullptr;
    const std::string v = eq == std::string::npos ? "" : s.substr(eq + 1);
    const double d = std::strtod(v.c_str(), &end);
    if (eq == std::string::npos || v.empty() || *end != '\0') throw UsageError("--set: expected NAME=VALUE, got '" + s + "'");
    values.set(s.substr(0, eq), d);
  }
  const bool optimize = a.values.count("--optimize") > 0, json = a.values.count("--json") > 0;
  if (!optimize && !a.frees.empty()) throw UsageError("statics: --free needs --optimize");
  if (!pictures.landscape.empty()) {
    // The landscape's parameters before any work: known, continuous, two different ones.
    const auto x = axisOf(pictures.landscape[0], values, free, model.suggestedFree, pictures.samples);
    const auto y = axisOf(pictures.landscape[1], values, free, model.suggestedFree, pictures.samples);
    if (x.parameter == y.parameter)
      throw Error("--landscape: two different parameters are needed, not " + x.parameter + " twice");
  }
  statics::SearchOptions options;
  options.analysis.kernShrink = number(a, "--kern", kern, 0, 0.99);
  options.analysis.friction = number(a, "--friction", friction, 0, 100);
  options.analysis.frictionSides = sides(a);
  if (a.values.count("--algorithm")) options.algorithm = a.values.at("--algorithm");
  options.maxEvaluations = int(number(a, "--max-evaluations", 200, 1, 1e6));
  options.maxSeconds = number(a, "--max-seconds", 0, 0, 1e6);

  nlohmann::ordered_json out;
  if (!object.empty()) out["object"] = object;
  out["example"] = model.name;
  out["blocks"] = model.build(values).blocks.size();
  if (!optimize) {
    putAnalysis(statics::analyse(model.build(values), options.analysis), out);
    drawPictures(pictures, base, model, values, free, options.analysis, out);
  } else {
    if (!a.frees.empty()) free.clear();
    for (const std::string& f : a.frees) free.push_back(statics::parseFreeParameter(f));
    if (free.empty()) free = model.suggestedFree;
    std::vector<std::vector<double>> path;  // the evaluations, for the landscape (Fig. 8's path)
    if (!pictures.landscape.empty())
      options.progress = [&path](const statics::SearchProgress& p) {
        path.push_back(p.values);
        return true;
      };
    const statics::SearchResult r = statics::searchParameters(model, free, options, &values);
    out["measure"] = r.measure;
    out["initial_measure"] = r.initialMeasure;
    out["y"] = r.y;
    out["stands"] = r.status == statics::SearchStatus::Feasible;
    out["stands_strictly"] = r.standsStrictly;
    out["status"] = statics::toString(r.status);
    out["message"] = r.message;
    out["iterations"] = r.evaluations;
    out["seconds"] = r.seconds;
    nlohmann::ordered_json params;
    for (const statics::FreeParameter& f : free) params[f.name] = r.values[f.name];
    out["parameters"] = params;
    if (r.status == statics::SearchStatus::Failed && !json) std::cerr << "corbel-cli: " << r.message << "\n";
    drawPictures(pictures, base, model, r.values.all().empty() ? values : r.values, free, options.analysis, out, path);
  }
  if (json) {
    std::cout << out.dump() << "\n";
    return 0;
  }
  char text[96];
  std::snprintf(text, sizeof text, "%.6g", out["measure"].get<double>());
  if (!object.empty()) std::cout << "object: " << object << "\n";
  std::cout << "example: " << model.name << " (" << out["blocks"].get<std::size_t>() << " blocks with the ground)\n"
            << "y/W²: " << text << "\nstatus: " << out["status"].get<std::string>() << "\n"
            << "iterations: " << out["iterations"].get<int>() << "\n";
  if (optimize) {
    std::cout << "result: " << out["message"].get<std::string>() << "\n";
    for (const auto& [name, v] : out["parameters"].items()) {
      std::snprintf(text, sizeof text, "%.6f", v.get<double>());
      std::cout << name << " = " << text << "\n";
    }
  }
  if (out.contains("render")) std::cout << "render: " << out["render"].get<std::string>() << "\n";
  if (out.contains("landscape")) {
    const auto& l = out["landscape"];
    std::cout << "landscape: " << l["png"].get<std::string>() << " (" << l["x"]["parameter"].get<std::string>()
              << " across, " << l["y"]["parameter"].get<std::string>() << " up; stands at "
              << l["standing"].get<std::size_t>() << " of "
              << l["x"]["samples"].get<int>() * l["y"]["samples"].get<int>() << " samples)\n";
  }
  return 0;
}

int exampleCommand(const Options& a) {
  picturesOf(a);
  if (a.positional.size() != 2) {
    std::string names;
    for (const std::string& n : statics::exampleNames()) names += " " + n;
    throw UsageError("statics example: expected one example name (" + names.substr(1) + ")");
  }
  MasonrySpec base;
  base.model = a.positional[1];
  return runModel(a, statics::exampleByName(a.positional[1]), {}, base, "");
}

// statics PROJECT: every masonry object of the project (or the one --object names), with its
// own parameters, free bounds, friction and kern (core/masonry_spec.h).
int projectCommand(const Options& a) {
  picturesOf(a);  // a bad --render, --size or --landscape before any work
  const LoadedProject p = loadProject(a.positional[0]);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << a.positional[0] << ": " << w << "\n";
  const std::string only = a.values.count("--object") ? a.values.at("--object") : "";
  if (a.values.count("--render") || a.values.count("--landscape")) {
    int matching = 0;
    for (const DocObject& o : p.document.objects)
      matching += std::holds_alternative<MasonrySpec>(o.spec) && (only.empty() || o.name == only);
    if (matching > 1)
      throw UsageError("statics: --render and --landscape draw one masonry object and the project has " +
                       std::to_string(matching) + "; name one with --object");
  }
  int ran = 0, code = 0;
  for (const DocObject& o : p.document.objects) {
    const auto* spec = std::get_if<MasonrySpec>(&o.spec);
    if (!spec || (!only.empty() && o.name != only)) continue;
    std::vector<statics::FreeParameter> free;
    for (const MasonryFree& f : spec->free) free.push_back({f.name, f.lo, f.hi});
    try {
      code = std::max(code, runModel(a, statics::modelOf(*spec), free, *spec, o.name));
    } catch (const InputError& e) {
      throw InputError(o.name + ": " + e.where, e.reason);
    }
    ++ran;
  }
  if (ran == 0)
    throw Error(only.empty() ? "the project has no masonry object" : "the project has no masonry object named \"" + only + "\"");
  return code;
}

// statics PROJECT --scene: the project built into the Scene, its blocks read from there
// (statics/scene_blocks.h): every object of kind block, or the objects --structural names
// (any kind: boxes, shells), with those --nonstructural names carried as loads.
int sceneCommand(const Options& a) {
  for (const char* o : {"--optimize", "--free", "--set", "--render", "--landscape", "--object"})
    if (a.values.count(o) || (std::string(o) == "--free" && !a.frees.empty()) ||
        (std::string(o) == "--set" && !a.sets.empty()))
      throw UsageError(std::string("statics --scene: ") + o +
                       " works on a masonry object's parameters; --scene analyses the built geometry as it is");
  const LoadedScene l = loadScene(a.positional[0]);
  auto idOf = [&](const std::string& name, const char* option) {
    const DocObject* o = l.doc.findByName(name);
    if (!o) {
      std::string names;
      for (const auto& obj : l.doc.objects) names += (names.empty() ? "" : ", ") + ("\"" + obj.name + "\"");
      throw Error(std::string(option) + ": no object named \"" + name +
                  "\" (objects: " + (names.empty() ? "none" : names) + ")");
    }
    return o->id;
  };
  statics::SceneBlockOptions o;
  for (const std::string& n : a.structural) o.objects.push_back(idOf(n, "--structural"));
  for (const std::string& n : a.nonstructural) o.nonstructural.push_back(idOf(n, "--nonstructural"));
  for (const std::string& d : a.densities) {
    const auto eq = d.find('=');
    char* end = nullptr;
    const std::string v = eq == std::string::npos ? "" : d.substr(eq + 1);
    const double rho = std::strtod(v.c_str(), &end);
    if (eq == 0 || eq == std::string::npos || v.empty() || *end != '\0' || !std::isfinite(rho) || rho <= 0)
      throw UsageError("--density: expected MATERIAL=KG_PER_M3 with a positive number, got '" + d + "'");
    o.densities[d.substr(0, eq)] = rho;
  }
  statics::AnalysisOptions opt;
  opt.kernShrink = number(a, "--kern", 0.0, 0, 0.99);
  opt.friction = number(a, "--friction", 0.7, 0, 100);
  opt.frictionSides = sides(a);
  const statics::SceneAssembly s = statics::assemblyFromScene(l.scene, o);
  const statics::AnalysisResult r = statics::analyse(s.assembly, opt);
  const statics::FeasibilityResult strict = statics::checkFeasibility(s.assembly, opt);
  int fixed = 0;
  for (const statics::Block& b : s.assembly.blocks) fixed += b.fixed;
  nlohmann::ordered_json out;
  out["blocks"] = s.assembly.blocks.size() - std::size_t(fixed);
  out["fixed"] = fixed;
  out["ground_plane"] = s.groundPlaneAdded;
  out["nonstructural"] = s.nonstructuralPieces;
  out["nonstructural_weight"] = s.nonstructuralWeight;
  out["weight"] = r.totalWeight;
  out["interfaces"] = r.interfaces.size();
  putAnalysis(r, out);
  out["stands_strictly"] = strict.feasible;
  // Large models have hundreds of edge-only contacts (courses meeting at their corners): the
  // first few are named, the rest counted.
  std::vector<std::string> shown(r.warnings.begin(),
                                 r.warnings.begin() + long(std::min<std::size_t>(r.warnings.size(), 5)));
  if (r.warnings.size() > shown.size())
    shown.push_back("... and " + std::to_string(r.warnings.size() - shown.size()) + " more warnings like these");
  out["warnings"] = shown;
  if (a.values.count("--json")) {
    std::cout << out.dump() << "\n";
    return 0;
  }
  for (const std::string& w : shown) std::cerr << "corbel-cli: warning: " << w << "\n";
  char text[96];
  std::snprintf(text, sizeof text, "%.6g", r.yNormalised);
  std::cout << "scene: " << out["blocks"].get<std::size_t>() << " blocks, " << fixed << " fixed"
            << (s.groundPlaneAdded ? " (a ground plane under the lowest point)" : "") << ", " << s.nonstructuralPieces
            << " nonstructural carried as loads\n"
            << "y/W²: " << text << "\nstatus: " << statics::toString(r.status) << "\n"
            << "stands: " << (r.feasible ? "yes" : "no") << " (strict LP test: " << (strict.feasible ? "yes" : "no")
            << ")\niterations: " << r.iterations << "\n";
  return 0;
}

}  // namespace

int runStatics(int argc, char** argv) {
  return guarded<UsageError>([&] {
    const Options a = parse(argc, argv,
                            {{"--blocks", true},
                             {"--thickness", true},
                             {"--tilt", true},
                             {"--friction", true},
                             {"--kern", true},
                             {"--min-thickness", false},
                             {"--critical-tilt", false},
                             {"--optimize", false},
                             {"--free", true},
                             {"--set", true},
                             {"--json", false},
                             {"--algorithm", true},
                             {"--max-evaluations", true},
                             {"--max-seconds", true},
                             {"--friction-sides", true},
                             {"--object", true},
                             {"--render", true},
                             {"--size", true},
                             {"--landscape", false},
                             {"--samples", true},
                             {"--scene", false},
                             {"--structural", true},
                             {"--nonstructural", true},
                             {"--density", true}});
    if (a.values.count("--scene") == 0 && (!a.structural.empty() || !a.nonstructural.empty() || !a.densities.empty()))
      throw UsageError("statics: --structural, --nonstructural and --density go with --scene");
    if (!a.positional.empty() && a.positional[0] == "arch" && a.positional.size() == 1) return archCommand(a);
    if (!a.positional.empty() && a.positional[0] == "example") return exampleCommand(a);
    if (a.positional.size() == 1 && a.positional[0].size() > 7 &&
        a.positional[0].compare(a.positional[0].size() - 7, 7, ".corbel") == 0)
      return a.values.count("--scene") ? sceneCommand(a) : projectCommand(a);
    if (a.values.count("--scene")) throw UsageError("statics: --scene goes with a PROJECT.corbel");
    throw UsageError("statics: expected 'arch' (statics arch --blocks N --thickness T ...), 'example NAME' or a PROJECT.corbel");
  });
}

}  // namespace corbel::cli
