#pragma once
// corbel-cli's command line, declared once: a request per subcommand (plain fields the parse
// fills) and declareCommands, which gives CLI11 every subcommand, positional and option with
// its description. The usage text, `SUB --help` and docs/cli.md all come from here; the kernels
// do not (cli/run.h holds the run function of each request).
//
// A new subcommand: its request struct below (and in Request), its declaration in
// commands.cpp, its run function (cli/run.h).
#include "core/command_line.h"

#include <CLI/CLI.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace corbel::cli {

struct RenderRequest {
  std::string project, out, camera, object;
  Size size{800, 600};
  bool noGrid = false, noEdges = false, wireframe = false;
  std::string textures = "off";
};

struct ExportRequest {
  std::string project, out, object;
  std::string up;  // "y" or "z"; "" = the format's own (docs/export.md)
  int kifsResolution = 96;  // compose::kExportKifsResolution
  bool compress = false;    // glb: EXT_meshopt_compression
};

struct CheckRequest {
  std::string project;
};

// Edit scripts (extrude/edit.h's JSON lines) applied to a project without a window.
struct EditRequest {
  std::string project, script, out;
};

struct ExtrudeRequest {
  std::string input, out, library;
  std::string crs, layer, where;  // footprints: their CRS, layer and attribute filter (city/import.h)
  std::optional<double> pitch, wallHeight;  // given: every edge gets this roof over walls
  unsigned jobs = 0;
  bool stats = false, mergeCoplanar = false, noRetry = false, windingRule = false;
};

// The analysis settings every statics form takes; unset: the model's own (0.7 and 0 for arch).
struct StaticsAnalysis {
  std::optional<double> friction, kern;
  bool conservativeFriction = false;  // α/√2 (Sec. 3.1), also when the project's object does not ask for it
  int frictionSides = 4;
  double contactTolerance = 0;  // set by statics PROJECT --together (its --contact-tolerance)
};

struct StaticsArchRequest {
  int blocks = 0;
  std::optional<double> thickness;
  double tilt = 0;
  StaticsAnalysis analysis;
  bool minThickness = false, criticalTilt = false;
};

// The search and the pictures of statics example NAME and statics PROJECT.
struct StaticsModelOptions {
  std::vector<std::string> sets, frees;
  bool optimize = false;
  std::string algorithm = "mma";
  int maxEvaluations = 200;
  double maxSeconds = 0;
  std::string render;
  Size size{1200, 800};
  std::vector<std::string> landscape;  // NAME1 NAME2 PNG
  int samples = 41;
  bool json = false;
};

struct StaticsExampleRequest {
  std::string name;
  StaticsAnalysis analysis;
  StaticsModelOptions model;
};

// statics PROJECT.corbel, its masonry objects (or with --scene, the built geometry).
struct StaticsProjectRequest {
  std::string project, object;
  bool save = false;  // write the values the run ends with back into the project
  bool together = false;          // every masonry object as one structure (statics/composite.h)
  double contactTolerance = 0.001;  // with --together: faces of different objects this close touch, m
  StaticsAnalysis analysis;
  StaticsModelOptions model;
  bool scene = false;
  std::vector<std::string> structural, nonstructural, densities;
};

struct SimulateRequest {
  std::string project, object, example;
  std::vector<std::string> sets, removes, breaks;
  double seconds = 5, at = 0, fps = 30;
  std::string shake, drop, frames;
  double dropMass = 100, dropHeight = 0.5;
  std::optional<double> friction;
  std::string solver = "qp";
  Size size{640, 480};
};

struct KifsRequest {
  std::string source;  // a preset's name, a preset file (.json) or a project (.corbel)
  std::string preset, out, mode = "shaded", camera, eval, mesh;
  Size size{640, 640};
  std::optional<int> frames;
  int resolution = 128;
};

struct GrowRequest {
  std::string site, object, out, render, viewMaps = "exact";
  std::optional<long long> seed, steps;  // default: the project's growth object's, or 1 and 100000
  double pixel = 0.1;
  bool stats = false;
};

struct CompleteRequest {
  std::optional<int> seeds, storey;
  std::vector<std::string> entrances;
  std::string from, object, complexity, region, out, render;
  int count = 4;
  long long seed = 1;
};

struct CityRequest {
  std::string footprints, style, out, tiles, tileset, render, around, street, plots, report;
  std::string crs, layer, where;  // the footprints' CRS, layer and attribute filter (city/import.h)
  std::string coordinates = "auto", detail = "full", textures = "on", renderTextures = "off";
  long long seed = 1;
  unsigned jobs = 0;
  double tileSize = 500;
  unsigned tileBuildings = 128;  // --tileset: at most this many buildings in a leaf tile
  double ground = 0;             // --tileset: the ellipsoidal height of the frame's origin, m
  // --tiles/--tileset without --out and --render: the source is read this many buildings (whole
  // tiles) at a time; 0 reads it whole (city/town_stream.h)
  unsigned streamBuildings = 1024;
  bool instances = false, compress = false;  // glb: EXT_mesh_gpu_instancing, EXT_meshopt_compression
};

struct CitySplitRequest {
  std::string source, out;
  std::string crs, layer, where, coordinates = "auto";
  double grid = 1;      // km
  double margin = 200;  // m
};

struct CityMergeRequest {
  std::string dir;
};

using Request = std::variant<RenderRequest, ExportRequest, CheckRequest, EditRequest, ExtrudeRequest, StaticsArchRequest,
                             StaticsExampleRequest, StaticsProjectRequest, SimulateRequest, KifsRequest, GrowRequest,
                             CompleteRequest, CityRequest, CitySplitRequest, CityMergeRequest>;

// The requests of the declared subcommands, each where the parse writes it.
class Requests {
 public:
  // A new request of type R, filled when `command` is parsed.
  template <class R>
  R& add(const CLI::App* command) {
    auto& slot = byCommand_[command] = std::make_unique<Request>(R{});
    return std::get<R>(*slot);
  }
  // After the parse: the request of the subcommand chosen, nullptr when there is none.
  const Request* chosen(const CLI::App& app) const;

 private:
  std::map<const CLI::App*, std::unique_ptr<Request>> byCommand_;
};

// corbel-cli on `app`: its name, description and subcommands, with --help and --version on each.
void declareCommands(CLI::App& app, Requests& requests);

}  // namespace corbel::cli
