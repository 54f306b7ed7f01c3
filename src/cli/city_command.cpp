// corbel-cli city FOOTPRINTS.geojson --style STYLE.json [--seed N] [--jobs N] --out town.glb
//   [--tiles DIR] [--tile-size M] [--render PNG] [--around X,Y,R] [--street X,Y;X,Y;...]
//   [--coordinates auto|lonlat|metric] [--report FILE.jsonl] [--detail massing|steps|full]
//   [--textures on|off] [--render-textures on|off]
#include "cli/city_command.h"

#include "city/import.h"
#include "city/labels.h"
#include "city/street.h"
#include "city/style.h"
#include "city/town.h"
#include "cli/number_list.h"
#include "cli/scene_png.h"
#include "core/error.h"
#include "core/export.h"
#include "core/scene.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <set>

namespace corbel::cli {

namespace {

constexpr const char* kCityUsage =
    "usage: corbel-cli city FOOTPRINTS.geojson --style STYLE.json [--seed N] [--jobs N] [--out FILE.glb]\n"
    "         [--tiles DIR] [--tile-size M] [--render PNG] [--around X,Y,R]\n"
    "         [--coordinates auto|lonlat|metric] [--report FILE.jsonl] [--detail massing|steps|full]\n"
    "         [--textures on|off] [--render-textures on|off]\n"
    "       corbel-cli city --street X,Y;X,Y;... [--plots normals|skeleton] --style STYLE.json [...]\n"
    "         (town houses along a spline; skeleton: plots grown from seeds, Fig. 26)\n";

Vec2 centroidOf(const std::vector<Vec2>& ring) {
  Vec2 c{0, 0};
  for (const Vec2& p : ring) c += p;
  return c / static_cast<double>(ring.size());
}

void drawBar(std::size_t done, std::size_t total, double seconds) {
  const int width = 30;
  const int filled = total ? static_cast<int>(width * done / total) : width;
  std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done << "/" << total
            << " buildings, " << static_cast<int>(seconds * 10) / 10.0 << " s" << std::flush;
  if (done == total) std::cerr << "\n";
}

}  // namespace

int city(int argc, char** argv) {
  std::map<std::string, std::string> opt;
  std::vector<std::string> positional;
  const std::set<std::string> known = {
      "--style",  "--seed",        "--jobs",   "--out",    "--tiles",    "--tile-size",       "--render", "--around",
      "--street", "--coordinates", "--report", "--detail", "--textures", "--render-textures", "--plots"};
  for (int i = 2; i < argc; ++i) {
    const std::string s = argv[i];
    if (s.rfind("--", 0) == 0) {
      if (!known.count(s)) {
        std::cerr << "corbel-cli: city: unknown option " << s << "\n" << kCityUsage;
        return 2;
      }
      if (i + 1 >= argc) {
        std::cerr << "corbel-cli: city: " << s << " needs a value\n" << kCityUsage;
        return 2;
      }
      opt[s] = argv[++i];
    } else {
      positional.push_back(s);
    }
  }
  auto usage = [&](const std::string& why) {
    std::cerr << "corbel-cli: city: " << why << "\n" << kCityUsage;
    return 2;
  };
  if (positional.size() + opt.count("--street") != 1) return usage("expected one FOOTPRINTS file or a --street");
  if (opt.count("--plots") && !opt.count("--street")) return usage("--plots: only with --street");
  if (!opt.count("--style")) return usage("--style STYLE.json is required");
  if (!opt.count("--out") && !opt.count("--tiles") && !opt.count("--render"))
    return usage("nothing to write: give --out, --tiles or --render");
  auto number = [&](const char* name, double def, double lo, double hi, bool whole) -> std::optional<double> {
    auto it = opt.find(name);
    if (it == opt.end()) return def;
    const auto v = numberList(it->second, ',');
    if (!v || v->size() != 1 || (*v)[0] < lo || (*v)[0] > hi || (whole && std::floor((*v)[0]) != (*v)[0]))
      return std::nullopt;
    return (*v)[0];
  };
  const auto seed = number("--seed", 1, 0, 9007199254740992.0, true);
  const auto jobs = number("--jobs", 0, 0, 1024, true);
  const auto tileSize = number("--tile-size", 500, 1, 1e6, false);
  if (!seed) return usage("--seed: expected a whole number from 0");
  if (!jobs) return usage("--jobs: expected a whole number from 0 to 1024");
  if (!tileSize) return usage("--tile-size: expected metres, at least 1");
  if (auto it = opt.find("--out"); it != opt.end()) {
    try {
      exportFormatFor(it->second);
    } catch (const Error& e) {
      return usage(std::string("--out: ") + e.what());
    }
  }
  std::optional<std::array<double, 3>> around;
  if (auto it = opt.find("--around"); it != opt.end()) {
    const auto v = numberList(it->second, ',');
    if (!v || v->size() != 3 || !((*v)[2] > 0)) return usage("--around: expected X,Y,R (metres, R > 0)");
    around = std::array<double, 3>{(*v)[0], (*v)[1], (*v)[2]};
  }
  // An option that names one of a few values; false when it names none of them.
  auto pick = [&](const char* name, const auto& table, auto& value) {
    auto it = opt.find(name);
    if (it == opt.end()) return true;
    for (const auto& [word, v] : table)
      if (it->second == word) {
        value = v;
        return true;
      }
    return false;
  };
  city::Coordinates coordinates = city::Coordinates::Auto;
  const std::pair<const char*, city::Coordinates> coordinateNames[] = {{"auto", city::Coordinates::Auto},
                                                                       {"lonlat", city::Coordinates::Geographic},
                                                                       {"metric", city::Coordinates::Metric}};
  if (!pick("--coordinates", coordinateNames, coordinates))
    return usage("--coordinates: expected auto, lonlat or metric");
  city::Detail detail = city::Detail::Full;
  const std::pair<const char*, city::Detail> detailNames[] = {
      {"massing", city::Detail::Massing}, {"steps", city::Detail::Steps}, {"full", city::Detail::Full}};
  if (!pick("--detail", detailNames, detail)) return usage("--detail: expected massing, steps or full");

  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const city::Style style = city::loadStyle(opt["--style"]);
  city::Town town;
  std::string source;
  if (auto it = opt.find("--street"); it != opt.end()) {
    std::vector<Vec2> control;
    std::size_t k = 0;
    for (std::size_t from = 0; from <= it->second.size(); ++k) {
      const std::size_t semi = std::min(it->second.find(';', from), it->second.size());
      const auto v = numberList(it->second.substr(from, semi - from), ',');
      if (!v || v->size() != 2) return usage("--street: point " + std::to_string(k + 1) + ": expected X,Y");
      control.emplace_back((*v)[0], (*v)[1]);
      from = semi + 1;
    }
    city::PlotOptions plots;
    if (auto p = opt.find("--plots"); p != opt.end()) {
      if (p->second == "skeleton")
        plots.method = city::PlotMethod::Skeleton;
      else if (p->second != "normals")
        return usage("--plots: expected normals or skeleton");
    }
    town = city::streetTown(control, plots);
    source = "street";
  } else {
    source = positional[0];
    town = city::readTownFile(source, coordinates);
  }
  const std::vector<city::BuildingLabels> labels = city::labelTown(town, style.labels, static_cast<unsigned>(*jobs));
  const double readS = seconds();

  // Tiles: buildings sorted by the tile of their first corner's centroid, so one tile is in
  // memory at a time.
  const bool tiled = opt.count("--tiles") > 0;
  std::vector<std::pair<long, long>> tileOf(town.buildings.size(), {0, 0});
  std::vector<std::size_t> order(town.buildings.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<Vec2> centres(town.buildings.size(), Vec2(0, 0));
  for (std::size_t i = 0; i < town.buildings.size(); ++i)
    if (!town.buildings[i].loops.empty()) {
      centres[i] = centroidOf(town.buildings[i].loops[0]);
      tileOf[i] = {static_cast<long>(std::floor(centres[i][0] / *tileSize)),
                   static_cast<long>(std::floor(centres[i][1] / *tileSize))};
    }
  if (around)  // only the buildings whose corners' mean lies within R of (X, Y)
    std::erase_if(order,
                  [&](std::size_t i) { return (centres[i] - Vec2((*around)[0], (*around)[1])).norm() > (*around)[2]; });
  if (tiled) {
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tileOf[a] < tileOf[b]; });
    std::filesystem::create_directories(opt["--tiles"]);
  }

  std::unique_ptr<Scene> whole, tile, view;
  ExportOptions exportOptions;  // textured by tag: a PNG per built-in material, UVs from the faces' planes
  const std::string textures = opt.count("--textures") ? opt["--textures"] : "on";
  if (textures != "on" && textures != "off") return usage("--textures: expected on or off, not '" + textures + "'");
  exportOptions.textures = textures == "on";
  exportOptions.tagTextures = city::tagTexturesOf(style);  // the style's tag_textures
  // The PNG of --render: colours unless asked for (the renderer's textured mode).
  const std::string renderTextures = opt.count("--render-textures") ? opt["--render-textures"] : "off";
  if (renderTextures != "on" && renderTextures != "off")
    return usage("--render-textures: expected on or off, not '" + renderTextures + "'");
  if (opt.count("--out")) whole = std::make_unique<Scene>();
  if (opt.count("--render") && !whole) view = std::make_unique<Scene>();  // else the output's Scene is rendered
  ObjectId wholeId = 1, tileId = 1, viewId = 1;
  std::optional<std::pair<long, long>> currentTile;
  std::size_t tilesWritten = 0;
  auto flushTile = [&] {
    if (!tile || !currentTile) return;
    if (tileId > 1) {
      exportScene(*tile,
                  (std::filesystem::path(opt["--tiles"]) /
                   ("tile_" + std::to_string(currentTile->first) + "_" + std::to_string(currentTile->second) + ".glb"))
                      .string(),
                  exportOptions);
      ++tilesWritten;
    }
    tile.reset();
  };
  std::unique_ptr<std::ofstream> report;
  if (auto it = opt.find("--report"); it != opt.end()) {
    report = std::make_unique<std::ofstream>(it->second);
    if (!*report) throw Error(it->second + ": cannot write the report");
  }
  std::map<std::string, std::size_t> reasons;
  auto sink = [&](const city::BuildingReport& r, MeshData* mesh) {
    if (report) {
      nlohmann::ordered_json j;
      j["id"] = r.id;
      j["type"] = r.type;
      j["ok"] = r.ok;
      if (!r.ok) j["error"] = r.error;
      if (!r.notes.empty()) j["notes"] = r.notes;
      if (!r.warnings.empty()) j["warnings"] = r.warnings;
      *report << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    if (!r.ok) {
      std::cerr << "\rcorbel-cli: city: " << r.id << ": skipped: " << r.error << "\n";
      const std::string head = r.error.substr(0, r.error.find(':'));
      ++reasons[head.find('[') == std::string::npos ? head : "geometry"];
      return;
    }
    if (tiled && (!currentTile || *currentTile != tileOf[r.index])) {
      flushTile();
      currentTile = tileOf[r.index];
    }
    if (tiled && !tile) {
      tile = std::make_unique<Scene>();
      tileId = 1;
    }
    if (view) view->replaceObject(viewId++, Kind::Shell, r.id, *mesh);
    if (tile) tile->replaceObject(tileId++, Kind::Shell, r.id, *mesh);
    if (whole) whole->replaceObject(wholeId++, Kind::Shell, r.id, *mesh);
  };
  city::TownOptions options;
  options.seed = static_cast<std::uint64_t>(*seed);
  options.jobs = static_cast<unsigned>(*jobs);
  options.detail = detail;
  const city::TownSummary sum = city::buildTown(town, labels, style, options, sink, order,
                                                [&](std::size_t d, std::size_t n) { drawBar(d, n, seconds()); });
  flushTile();
  const double buildS = seconds();
  if (whole) exportScene(*whole, opt["--out"], exportOptions);
  if (opt.count("--render")) {
    render::HeadlessContext context;
    writeScenePng(whole ? *whole : *view, {-60, 35, 0.75, renderTextures == "on", exportOptions.tagTextures},
                  opt["--render"]);
  }
  whole.reset();
  view.reset();

  nlohmann::ordered_json j;
  j["source"] = source;
  j["frame"] = town.frame.how;
  if (town.frame.coordinates == city::Coordinates::Geographic) {
    j["lon0"] = town.frame.lon0;
    j["lat0"] = town.frame.lat0;
    j["scale_error"] = town.frame.scaleError;
  }
  j["streets"] = town.streets.size();
  j["style"] = style.name;
  j["seed"] = options.seed;
  j["buildings"] = sum.buildings;
  j["ok"] = sum.ok;
  j["refused"] = sum.refused;
  j["failed"] = sum.failed;
  j["types"] = sum.types;
  j["faces"] = sum.faces;
  j["skipped_by_reason"] = reasons;
  if (tiled) j["tiles"] = tilesWritten;
  j["read_s"] = readS;
  j["build_s"] = buildS - readS;
  j["total_s"] = seconds();
  std::cout << j.dump() << "\n";
  return sum.ok == sum.buildings ? 0 : 1;
}

}  // namespace corbel::cli
