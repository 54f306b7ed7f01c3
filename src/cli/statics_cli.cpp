// corbel-cli statics arch | example | PROJECT: parse, call the statics kernel, print; --render
// and --landscape draw the editor's statics pictures headless (cli/statics_png.h).
#include "cli/guarded.h"
#include "cli/number_list.h"
#include "cli/project_scene.h"
#include "cli/run.h"
#include "cli/statics_png.h"
#include "core/error.h"
#include "core/project_io.h"
#include "editor/masonry_edits.h"
#include "editor/masonry_view.h"
#include "render/headless_context.h"
#include "statics/analysis.h"
#include "statics/composite.h"
#include "statics/arch.h"
#include "statics/examples.h"
#include "statics/kernel.h"
#include "statics/loads.h"
#include "statics/scene_blocks.h"
#include "statics/search.h"
#include "compose/stone_extrusion.h"
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

statics::AnalysisOptions analysisOptions(const StaticsAnalysis& a, double friction, double kern,
                                         bool conservative = false) {
  statics::AnalysisOptions options;
  options.friction = a.friction.value_or(friction);
  options.conservativeFriction = a.conservativeFriction || conservative;
  options.kernShrink = a.kern.value_or(kern);
  options.contactTolerance = a.contactTolerance;
  options.frictionSides = a.frictionSides;
  return options;
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

Pictures picturesOf(const StaticsModelOptions& m) {
  Pictures p;
  p.render = m.render;
  if (!p.render.empty() && !endsWithPng(p.render))
    throw UsageError("--render: expected a .png file, got '" + p.render + "'");
  p.width = m.size.width;
  p.height = m.size.height;
  p.landscape = m.landscape;
  // CLI11 takes fewer than the three words when the line ends early: count them here.
  if (!p.landscape.empty() && p.landscape.size() != 3)
    throw UsageError("--landscape: expected NAME1 NAME2 PNG, got " + std::to_string(p.landscape.size()) + " word(s)");
  if (!p.landscape.empty() && !endsWithPng(p.landscape[2]))
    throw UsageError("--landscape: expected NAME1 NAME2 PNG, and '" + p.landscape[2] + "' is not a .png file");
  p.samples = m.samples;
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
  spec.conservativeFriction = options.conservativeFriction;
  spec.kern = options.kernShrink;
  if (!pictures.render.empty()) {
    // A masonry object's view comes from its spec; an extrusion in stone and objects analysed
    // together have none.
    const editor::MasonryView view = model.name != base.model
                                         ? editor::analyseModel(model, values, options)
                                         : editor::analyseMasonry(spec, options);
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
// `ended`, when given, gets the values the run ends with: after --set, and with --optimize the
// search's when the model then stands (left empty when it does not).
int runModel(const StaticsModelOptions& a, const StaticsAnalysis& analysis, const statics::ParametricModel& model,
             std::vector<statics::FreeParameter> free, const MasonrySpec& base, const std::string& object,
             std::optional<statics::ParameterSet>* ended = nullptr) {
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
  const bool optimize = a.optimize, json = a.json;
  if (!pictures.landscape.empty()) {
    // The landscape's parameters before any work: known, continuous, two different ones.
    const auto x = axisOf(pictures.landscape[0], values, free, model.suggestedFree, pictures.samples);
    const auto y = axisOf(pictures.landscape[1], values, free, model.suggestedFree, pictures.samples);
    if (x.parameter == y.parameter)
      throw Error("--landscape: two different parameters are needed, not " + x.parameter + " twice");
  }
  statics::SearchOptions options;
  options.analysis = analysisOptions(analysis, base.friction, base.kern, base.conservativeFriction);
  options.algorithm = a.algorithm;
  options.maxEvaluations = a.maxEvaluations;
  options.maxSeconds = a.maxSeconds;

  nlohmann::ordered_json out;
  if (!object.empty()) out["object"] = object;
  out["example"] = model.name;
  out["blocks"] = model.build(values).blocks.size();
  if (!base.loads.empty()) {
    // The object's loads as the analysis applies them: where each acts and its force.
    nlohmann::ordered_json loads = nlohmann::ordered_json::array();
    MasonrySpec bare = base;
    bare.loads.clear();
    const statics::ParametricModel plain = statics::modelOf(bare);
    const std::vector<statics::ResolvedLoad> resolved = statics::resolveLoads(plain.build(values), base.loads);
    for (std::size_t k = 0; k < resolved.size(); ++k) {
      const statics::PointLoad& l = resolved[k].load;
      loads.push_back({{"name", base.loads[k].name},
                       {"block", base.loads[k].block},
                       {"at", {l.at[0], l.at[1], l.at[2]}},
                       {"force", {l.force[0], l.force[1], l.force[2]}}});
    }
    out["loads"] = std::move(loads);
  }
  if (ended && !optimize) *ended = values;
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
    if (ended && r.status == statics::SearchStatus::Feasible) *ended = r.values;
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

int exampleCommand(const StaticsExampleRequest& r) {
  picturesOf(r.model);
  MasonrySpec base;
  base.model = r.name;
  return runModel(r.model, r.analysis, statics::exampleByName(r.name), {}, base, "");
}

// A masonry object, or an extrusion with a masonry section (built in stone).
bool isMasonry(const DocObject& o) {
  if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec)) return e->masonry.has_value();
  return std::holds_alternative<MasonrySpec>(o.spec);
}

// The object's model: a masonry object's, or an extrusion's in stone.
statics::ParametricModel masonryModelOf(const DocObject& o) {
  if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec)) return statics::stoneModel(*e);
  return statics::modelOf(std::get<MasonrySpec>(o.spec));
}

// --save: object `o` of `saved` at the values its run ended with: a masonry object's changed
// parameters set as the editor sets them (editor::setMasonryParameter); an extrusion in stone
// takes its section's values and buttress steps (statics::stoneSpecAt).
void writeBack(Document& saved, const DocObject& o, const statics::ParameterSet& ended) {
  DocObject& target = *saved.find(o.id);
  if (auto* e = std::get_if<ExtrusionSpec>(&target.spec)) {
    *e = statics::stoneSpecAt(*e, ended);
    return;
  }
  // As the editor applies Make It Stand: each changed parameter set, in name order.
  const statics::ParametricModel before = statics::modelOf(std::get<MasonrySpec>(o.spec));
  for (const statics::Parameter& q : ended.all())
    if (q.value != before.parameters[q.name]) editor::setMasonryParameter(saved, o.id, q.name, q.value);
}

// statics PROJECT --together: every masonry object (and extrusion in stone) of the project as one
// structure (statics/composite.h), its parameters "object/parameter", the objects' free ones free
// (their suggested ones when none is), contacts between objects within --contact-tolerance.
int togetherCommand(const StaticsProjectRequest& r, const LoadedProject& p) {
  if (!r.object.empty()) throw UsageError("statics: --together analyses every masonry object; drop --object");
  std::vector<statics::CompositePart> parts;
  std::vector<const DocObject*> objects;
  std::vector<statics::FreeParameter> free;
  MasonrySpec base;  // the first masonry object's friction, α/√2 and kern, unless the flags say
  bool haveBase = false;
  for (const DocObject& o : p.document.objects) {
    if (!isMasonry(o)) continue;
    try {
      parts.push_back({o.name, masonryModelOf(o), o.placement});
    } catch (const InputError& e) {
      throw InputError(o.name + ": " + e.where, e.reason);
    }
    objects.push_back(&o);
    if (const auto* spec = std::get_if<MasonrySpec>(&o.spec)) {
      for (const MasonryFree& f : spec->free) free.push_back({o.name + "/" + f.name, f.lo, f.hi});
      if (!haveBase) {
        base.friction = spec->friction;
        base.kern = spec->kern;
        base.conservativeFriction = spec->conservativeFriction;
        haveBase = true;
      }
    }
  }
  if (parts.size() < 2)
    throw Error("--together analyses two or more masonry objects as one; the project has " +
                std::to_string(parts.size()));
  const statics::ParametricModel model = statics::compositeModel(std::move(parts));
  std::optional<statics::ParameterSet> ended;
  StaticsAnalysis analysis = r.analysis;
  analysis.contactTolerance = r.contactTolerance;
  const int code = runModel(r.model, analysis, model, free, base, "together", &ended);
  if (!r.save) return code;
  if (!ended) {
    std::cerr << "corbel-cli: the objects do not stand together after the search: nothing is saved\n";
    return code;
  }
  Document saved = p.document;
  for (const DocObject* o : objects) {
    statics::ParameterSet own = masonryModelOf(*o).parameters;
    for (const statics::Parameter& q : own.all()) own.set(q.name, (*ended)[o->name + "/" + q.name]);
    writeBack(saved, *o, own);
  }
  if (!(saved == p.document)) saveProject(saved, r.project);
  if (!r.model.json) std::cout << "saved: " << r.project << (saved == p.document ? " (unchanged)" : "") << "\n";
  return code;
}

// statics PROJECT: every masonry object of the project (or the one --object names), with its
// own parameters, free bounds, friction and kern (core/masonry_spec.h).
int projectCommand(const StaticsProjectRequest& r) {
  picturesOf(r.model);  // a bad --render or --landscape before any work
  const LoadedProject p = loadProject(r.project);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << r.project << ": " << w << "\n";
  if (r.together) return togetherCommand(r, p);  // one structure: --render draws all of it
  const std::string& only = r.object;
  if (!r.model.render.empty() || !r.model.landscape.empty()) {
    int matching = 0;
    for (const DocObject& o : p.document.objects)
      matching += isMasonry(o) && (only.empty() || o.name == only);
    if (matching > 1)
      throw UsageError("statics: --render and --landscape draw one masonry object and the project has " +
                       std::to_string(matching) + "; name one with --object");
  }
  int ran = 0, code = 0;
  Document saved = p.document;  // with --save, each object at the values its run ended with
  std::vector<std::string> unsaved, resting;  // resting: objects without a ground, on others
  for (const DocObject& o : p.document.objects) {
    if (!only.empty() && o.name != only) continue;
    std::optional<statics::ParameterSet> ended;
    if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec); e && e->masonry) {
      try {
        const statics::ParametricModel model = statics::stoneModel(*e);
        code = std::max(code, runModel(r.model, r.analysis, model, {}, MasonrySpec{}, o.name, &ended));
      } catch (const InputError& err) {
        throw InputError(o.name + ": extrusion." + err.where, err.reason);
      }
      ++ran;
      if (ended)
        writeBack(saved, o, *ended);
      else
        unsaved.push_back(o.name);
      continue;
    }
    const auto* spec = std::get_if<MasonrySpec>(&o.spec);
    if (!spec) continue;
    if (!spec->ground) {
      resting.push_back(o.name);
      continue;
    }
    std::vector<statics::FreeParameter> free;
    for (const MasonryFree& f : spec->free) free.push_back({f.name, f.lo, f.hi});
    try {
      code = std::max(code, runModel(r.model, r.analysis, statics::modelOf(*spec), free, *spec, o.name, &ended));
    } catch (const InputError& e) {
      throw InputError(o.name + ": " + e.where, e.reason);
    }
    ++ran;
    if (ended)
      writeBack(saved, o, *ended);
    else
      unsaved.push_back(o.name);
  }
  for (const std::string& name : resting)
    std::cerr << "corbel-cli: " << name << " rests on other objects (its ground is off): analysed only with --together\n";
  if (ran == 0 && !resting.empty())
    throw Error("the masonry objects rest on one another (ground off): analyse them with --together");
  if (ran == 0)
    throw Error(only.empty() ? "the project has no masonry object (nor an extrusion with a masonry section)"
                             : "the project has no masonry object (nor an extrusion with a masonry section) named \"" +
                                   only + "\"");
  if (r.save) {
    for (const std::string& name : unsaved)
      std::cerr << "corbel-cli: " << name << " does not stand after the search: its values are not saved\n";
    if (!(saved == p.document)) saveProject(saved, r.project);
    if (!r.model.json) std::cout << "saved: " << r.project << (saved == p.document ? " (unchanged)" : "") << "\n";
  }
  return code;
}

// statics PROJECT --scene: the project built into the Scene, its blocks read from there
// (statics/scene_blocks.h): every object of kind block, or the objects --structural names
// (any kind: boxes, shells), with those --nonstructural names carried as loads.
int sceneCommand(const StaticsProjectRequest& request) {
  const StaticsModelOptions& m = request.model;
  for (const auto& [given, o] : {std::pair{m.optimize, "--optimize"}, {!m.frees.empty(), "--free"},
                                 {!m.sets.empty(), "--set"}, {!m.render.empty(), "--render"},
                                 {!m.landscape.empty(), "--landscape"}, {!request.object.empty(), "--object"}})
    if (given)
      throw UsageError(std::string("statics --scene: ") + o +
                       " works on a masonry object's parameters; --scene analyses the built geometry as it is");
  const LoadedScene l = loadScene(request.project);
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
  for (const std::string& n : request.structural) o.objects.push_back(idOf(n, "--structural"));
  for (const std::string& n : request.nonstructural) o.nonstructural.push_back(idOf(n, "--nonstructural"));
  for (const std::string& d : request.densities) {
    const auto eq = d.find('=');
    char* end = nullptr;
    const std::string v = eq == std::string::npos ? "" : d.substr(eq + 1);
    const double rho = std::strtod(v.c_str(), &end);
    if (eq == 0 || eq == std::string::npos || v.empty() || *end != '\0' || !std::isfinite(rho) || rho <= 0)
      throw UsageError("--density: expected MATERIAL=KG_PER_M3 with a positive number, got '" + d + "'");
    o.densities[d.substr(0, eq)] = rho;
  }
  const statics::AnalysisOptions opt = analysisOptions(request.analysis, 0.7, 0.0);
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
  if (m.json) {
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

int run(const StaticsArchRequest& r) {
  if (!r.minThickness && !r.thickness) throw UsageError("statics arch: --thickness T is required");
  statics::ArchSpec spec;
  spec.blocks = r.blocks;
  spec.thickness = r.thickness.value_or(0.2);
  spec.tiltDeg = r.tilt;
  const statics::AnalysisOptions options = analysisOptions(r.analysis, 0.7, 0.0);
  char text[64];
  if (r.minThickness) {
    std::snprintf(text, sizeof text, "%.6f", statics::minimumArchThickness(spec, options, 1e-6));
  } else if (r.criticalTilt) {
    std::snprintf(text, sizeof text, "%.4f", statics::criticalArchTilt(spec, options, 1e-5));
  } else {
    const statics::AnalysisResult a = statics::analyse(statics::semicircularArch(spec), options);
    if (a.status != statics::SolveStatus::Optimal)
      std::cerr << "corbel-cli: warning: the solver stopped early (" << statics::toString(a.status) << ")\n";
    std::snprintf(text, sizeof text, "%.6g", a.feasible ? 0.0 : a.yNormalised);
  }
  std::cout << text << "\n";
  return 0;
}

int run(const StaticsExampleRequest& r) { return exampleCommand(r); }

int run(const StaticsProjectRequest& r) {
  if (r.project.empty())
    throw UsageError("statics: expected 'arch' (statics arch --blocks N --thickness T ...), 'example NAME' or a PROJECT.corbel");
  if (r.project.size() <= 7 || r.project.compare(r.project.size() - 7, 7, ".corbel") != 0)
    throw UsageError("statics: expected 'arch', 'example NAME' or a PROJECT.corbel, not '" + r.project + "'");
  return r.scene ? sceneCommand(r) : projectCommand(r);
}

}  // namespace corbel::cli
