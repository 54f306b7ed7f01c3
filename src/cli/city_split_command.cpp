// corbel-cli city-split and city-merge: a town cut into tiles whose builds can run apart (on
// GNU parallel, a Slurm job array, a Kubernetes indexed Job), and one tileset over their
// tilesets (docs/city.md, "Beyond one machine").
#include "city/import.h"
#include "city/merge.h"
#include "city/split.h"
#include "cli/guarded.h"
#include "cli/run.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace corbel::cli {

namespace fs = std::filesystem;

int run(const CitySplitRequest& r) {
  std::error_code ec;
  if (fs::exists(r.out, ec) && (!fs::is_directory(r.out, ec) || !fs::is_empty(r.out, ec)))
    throw UsageError("city-split: --out: " + r.out + " is not a new or empty folder");
  city::ReadOptions read;
  read.coordinates = r.coordinates == "lonlat"   ? city::Coordinates::Geographic
                     : r.coordinates == "metric" ? city::Coordinates::Metric
                                                 : city::Coordinates::Auto;
  read.crs = r.crs;
  read.layer = r.layer;
  read.where = r.where;
  read.clean = false;  // each tile's build cleans its buildings, as a whole build does
  const city::Town town = city::readTownFile(r.source, read);
  std::vector<std::size_t> unplaced;
  const std::vector<city::SplitTile> tiles = city::splitTown(town, r.grid * 1000, r.margin, &unplaced);
  for (std::size_t i : unplaced)
    std::cerr << "corbel-cli: city-split: " << town.buildings[i].id << ": no outline, in no tile: "
              << town.buildings[i].problem << "\n";
  fs::create_directories(fs::path(r.out) / "sources", ec);
  if (ec) throw Error("city-split: cannot make " + (fs::path(r.out) / "sources").string() + ": " + ec.message());
  std::string names;
  std::size_t own = 0, margin = 0, largest = 0;
  for (const city::SplitTile& t : tiles) {
    writeFileAtomic((fs::path(r.out) / "sources" / (t.name + ".geojson")).string(), city::tileSource(town, t).dump() + "\n");
    names += t.name + "\n";
    own += t.own.size();
    margin += t.margin.size();
    largest = std::max(largest, t.own.size());
  }
  writeFileAtomic((fs::path(r.out) / "tiles.txt").string(), names);
  nlohmann::ordered_json j;
  j["source"] = r.source;
  j["frame"] = town.frame.how;
  if (!town.frame.proj.empty()) j["local_frame"] = town.frame.proj;
  j["grid_km"] = r.grid;
  j["margin_m"] = r.margin;
  j["tiles"] = tiles.size();
  j["buildings"] = own;
  j["unplaced"] = unplaced.size();
  j["largest_tile"] = largest;
  j["margin_copies"] = margin;
  std::cout << j.dump() << "\n";
  return unplaced.empty() ? 0 : 1;
}

int run(const CityMergeRequest& r) {
  const fs::path dir(r.dir);
  const std::string list = readFile((dir / "tiles.txt").string(), std::size_t(1) << 30);
  std::vector<city::TilesetPart> parts;
  std::size_t empty = 0, tiles = 0;
  std::istringstream lines(list);
  for (std::string name; std::getline(lines, name);) {
    if (name.empty()) continue;
    ++tiles;
    const fs::path at = dir / "tilesets" / name / "tileset.json";
    if (!fs::exists(at))
      throw Error("city-merge: " + at.string() + ": missing (has tile " + name + " been built into " +
                  (dir / "tilesets" / name).string() + "?)");
    city::TilesetPart part{"tilesets/" + name, parseJsonText(readFile(at.string(), std::size_t(1) << 30))};
    const auto& root = part.tileset.at("root");
    if (!root.contains("content") && !root.contains("children")) {  // nothing of the tile was built
      ++empty;
      continue;
    }
    parts.push_back(std::move(part));
  }
  writeFileAtomic((dir / "tileset.json").string(), city::mergeTilesets(parts).dump() + "\n");
  nlohmann::ordered_json j;
  j["tileset"] = (dir / "tileset.json").string();
  j["tiles"] = tiles;
  j["merged"] = parts.size();
  j["empty"] = empty;
  std::cout << j.dump() << "\n";
  return 0;
}

}  // namespace corbel::cli
