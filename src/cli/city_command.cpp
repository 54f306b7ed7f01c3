// corbel-cli city: a styled town from footprints or along a street (docs/city.md); tiles,
// a whole glb, a render and a per-building report.
#include "city/blocks.h"
#include "city/import.h"
#include "city/instances.h"
#include "city/labels.h"
#include "city/split.h"
#include "city/street.h"
#include "city/style.h"
#include "city/tileset.h"
#include "city/town.h"
#include "city/town_stream.h"
#include "cli/guarded.h"
#include "cli/number_list.h"
#include "cli/run.h"
#include "cli/scene_png.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/export.h"
#include "core/glb_writer.h"
#include "core/scene.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <thread>

namespace corbel::cli {

namespace {

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

// Tile boxes are grown by this on each side: glb positions are quantized to steps of at most
// 1 mm (docs/export.md), so a written vertex lies within 0.5 mm of the built one.
constexpr double kTilesetPad = 0.01;

// A tileset's leaf cells are at most this across, so no building is more than 283 m from the
// point its leaf is placed by (docs/city.md, "Tilesets").
constexpr double kMaxLeafSide = 400;

// Streamed, buildTown extrudes this many buildings a round for each worker thread: a round's
// meshes are held until they are written, and the next round's are made meanwhile, so that two
// rounds' meshes (at full detail, about 65 kB a building) are what a streamed town's peak rises
// and falls by.
constexpr std::size_t kStreamRoundPerJob = 32;

// Hands the pages that freed memory left unused back to the system (the allocator keeps them
// otherwise, and a streamed town's parts would leave their read JSON's pages behind each time):
// jemalloc's, when the program runs on it (CMake's CORBEL_JEMALLOC), else glibc's.
void releaseFreedMemory() {
  using Mallctl = int (*)(const char*, void*, std::size_t*, void*, std::size_t);
  static const auto mallctl = reinterpret_cast<Mallctl>(dlsym(RTLD_DEFAULT, "mallctl"));
  if (mallctl) {
    mallctl("arena.4096.purge", nullptr, nullptr, nullptr, 0);  // 4096: MALLCTL_ARENAS_ALL
    return;
  }
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

// A usage fault of city, named as the other commands name theirs.
UsageError bad(const std::string& message) { return UsageError("city: " + message); }

// --tileset's folder: new or empty, and writable (checked by making and removing a folder in
// it), before any building is built.
void checkTilesetFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw bad("--tileset: " + dir + " exists and is not a folder");
    if (!fs::is_empty(dir, ec))
      throw bad("--tileset: " + dir + " is not empty; give a new or empty folder (a tileset is not mixed with other files)");
  }
  const bool made = fs::create_directories(dir, ec);
  const fs::path probe = fs::path(dir) / "tiles";
  if (!ec) fs::create_directory(probe, ec);
  if (ec) throw Error("city: --tileset: cannot write into " + dir + ": " + ec.message());
  fs::remove(probe, ec);
  if (made) fs::remove(dir, ec);
}

// The axis-aligned box of a town's features as they are placed.
void addFeatures(BBox& box, const std::vector<InstancedMesh>& meshes) {
  for (const InstancedMesh& im : meshes)
    for (const RigidPlacement& p : im.placements)
      for (const Vec3& v : im.mesh.points) box.add(p.translation + p.ex * v[0] + p.ey * v[1] + p.ez * v[2]);
}

}  // namespace

int run(const CityRequest& r) {
  if (r.footprints.empty() && r.street.empty()) throw bad("expected one FOOTPRINTS file or a --street");
  if (r.out.empty() && r.tiles.empty() && r.tileset.empty() && r.render.empty())
    throw bad("nothing to write: give --out, --tiles, --tileset or --render");
  if (!r.tileset.empty()) checkTilesetFolder(r.tileset);
  if (!r.out.empty()) {
    try {
      exportFormatFor(r.out);
    } catch (const Error& e) {
      throw bad(std::string("--out: ") + e.what());
    }
    if ((r.instances || r.compress) && exportFormatFor(r.out) != ExportFormat::Glb)
      throw bad("--instances and --compress write glb: give a .glb --out");
  }
  std::optional<std::array<double, 3>> around;
  if (!r.around.empty()) {
    const auto v = numberList(r.around, ',');
    if (!v || v->size() != 3 || !((*v)[2] > 0)) throw bad("--around: expected X,Y,R (metres, R > 0)");
    around = std::array<double, 3>{(*v)[0], (*v)[1], (*v)[2]};
  }
  city::ReadOptions read;
  read.coordinates = r.coordinates == "lonlat"   ? city::Coordinates::Geographic
                     : r.coordinates == "metric" ? city::Coordinates::Metric
                                                 : city::Coordinates::Auto;
  read.crs = r.crs;
  read.layer = r.layer;
  read.where = r.where;
  const city::Detail detail = r.detail == "massing" ? city::Detail::Massing
                              : r.detail == "steps" ? city::Detail::Steps
                                                    : city::Detail::Full;
  const double tileSize = r.tileSize;

  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const city::Style style = city::loadStyle(r.style);
  city::Town town;  // the whole town, or (streamed) the part being built
  std::string source;
  // Streamed: the source read a part at a time (city/town_stream.h), when nothing needs the whole
  // town at once.
  std::optional<city::TownStream> stream;
  std::vector<std::size_t> globalOf;  // streamed: the part's building k is the source's globalOf[k]
  if (!r.street.empty()) {
    std::vector<Vec2> control;
    std::size_t k = 0;
    for (std::size_t from = 0; from <= r.street.size(); ++k) {
      const std::size_t semi = std::min(r.street.find(';', from), r.street.size());
      const auto v = numberList(r.street.substr(from, semi - from), ',');
      if (!v || v->size() != 2) throw bad("--street: point " + std::to_string(k + 1) + ": expected X,Y");
      control.emplace_back((*v)[0], (*v)[1]);
      from = semi + 1;
    }
    city::PlotOptions plots;
    if (r.plots == "skeleton") plots.method = city::PlotMethod::Skeleton;
    town = city::streetTown(control, plots);
    source = "street";
  } else {
    source = r.footprints;
    // Every output takes the buildings one at a time but a --render's picture and an --out other
    // than glb (made from a whole Scene).
    const bool outGlb = !r.out.empty() && exportFormatFor(r.out) == ExportFormat::Glb;
    if (r.streamBuildings > 0 && r.render.empty() && (r.out.empty() || outGlb))
      stream.emplace(source, read);
    else
      town = city::readTownFile(source, read);
  }
  const city::Frame townFrame = stream ? stream->frame() : town.frame;
  const std::string attribution = stream ? stream->attribution() : town.attribution;
  const std::size_t count = stream ? stream->size() : town.buildings.size();
  if (!r.tileset.empty() && townFrame.proj.empty())
    throw bad("--tileset: the town is in local metres, with no place on the Earth to put it (footprints: give their "
              "CRS with --crs)");
  std::vector<city::BuildingLabels> labels;
  if (!stream) labels = city::labelTown(town, style.labels, r.jobs);
  const double readS = seconds();

  // Tiles: buildings sorted by the tile of their first corner's centroid (--tile-size squares),
  // so that one tile is in memory at a time; without --tileset (which sorts them by its leaves)
  // whatever the outputs, so that a glb --out's buildings come in that order too, read whole or
  // streamed, and a streamed part is a few tiles' buildings and their neighbours.
  const bool tiled = !r.tiles.empty();
  std::vector<std::pair<long, long>> tileOf(count, {0, 0});
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::vector<Vec2> centres(count, Vec2(0, 0));
  for (std::size_t i = 0; i < count; ++i)
    if (stream ? stream->centre(i) != Vec2(0, 0) : !town.buildings[i].loops.empty()) {
      centres[i] = stream ? stream->centre(i) : centroidOf(town.buildings[i].loops[0]);
      tileOf[i] = {static_cast<long>(std::floor(centres[i][0] / tileSize)),
                   static_cast<long>(std::floor(centres[i][1] / tileSize))};
    }
  if (around)  // only the buildings whose corners' mean lies within R of (X, Y)
    std::erase_if(order,
                  [&](std::size_t i) { return (centres[i] - Vec2((*around)[0], (*around)[1])).norm() > (*around)[2]; });
  // A tile's source from city-split: its margin buildings are labelled with the rest but built
  // by their own tile.
  const std::size_t before = order.size();
  std::erase_if(order,
                [&](std::size_t i) { return stream ? stream->margin(i) : city::marksMargin(town.buildings[i].properties); });
  const std::size_t margin = before - order.size();
  if (r.tileset.empty())
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tileOf[a] < tileOf[b]; });
  if (tiled) std::filesystem::create_directories(r.tiles);
  // Tileset: a quadtree over the corners' means of the buildings in `order`, which is sorted by
  // leaf so that one leaf's buildings are in memory at a time.
  std::optional<city::Quadtree> tree;
  std::vector<int> leafOf(count, -1);
  if (!r.tileset.empty()) {
    std::vector<Vec2> points;
    for (std::size_t i : order) points.push_back(centres[i]);
    tree = city::buildQuadtree(points, r.tileBuildings, kMaxLeafSide);
    for (std::size_t k = 0; k < order.size(); ++k) leafOf[order[k]] = tree->leafOf[k];
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return leafOf[a] < leafOf[b]; });
    std::filesystem::create_directories(std::filesystem::path(r.tileset) / "tiles");
  }

  std::unique_ptr<Scene> whole, tile, view;
  ExportOptions exportOptions;  // textured by tag: a PNG per built-in material, UVs from the faces' planes
  exportOptions.textures = r.textures == "on";
  exportOptions.tagTextures = city::tagTexturesOf(style);  // the style's tag_textures
  // The georeference and the data's attribution go into every glb.
  exportOptions.georeference = {townFrame.crs, townFrame.proj, townFrame.lon0, townFrame.lat0, r.ground};
  exportOptions.copyright = attribution;
  exportOptions.compress = r.compress;
  // --instances: the features of the buildings in a file (the whole town's, the tile's), once per shape.
  city::FeatureInstances wholeFeatures(style), tileFeatures(style);
  // The PNG of --render: colours unless asked for (the renderer's textured mode).
  // A glb --out is written building by building as they come (no Scene holds the town), unless
  // --render needs the Scene.
  std::unique_ptr<GlbWriter> glbOut;
  if (!r.out.empty() && r.render.empty() && exportFormatFor(r.out) == ExportFormat::Glb) {
    ExportOptions o = exportOptions;
    o.instances = &wholeFeatures.meshes();
    glbOut = std::make_unique<GlbWriter>(o);
  } else if (!r.out.empty()) {
    whole = std::make_unique<Scene>();
  }
  if (!r.render.empty() && !whole) view = std::make_unique<Scene>();  // else the output's Scene is rendered
  ObjectId wholeId = 1, tileId = 1, viewId = 1;
  std::optional<std::pair<long, long>> currentTile;
  std::size_t tilesWritten = 0;
  auto flushTile = [&] {
    if (!tile || !currentTile) return;
    if (tileId > 1) {
      exportOptions.instances = &tileFeatures.meshes();
      exportScene(*tile,
                  (std::filesystem::path(r.tiles) /
                   ("tile_" + std::to_string(currentTile->first) + "_" + std::to_string(currentTile->second) + ".glb"))
                      .string(),
                  exportOptions);
      ++tilesWritten;
    }
    tile.reset();
    tileFeatures.clear();
  };
  // --tileset: the leaf being filled, its buildings and their blocks.
  std::vector<city::LeafContent> leaves(tree ? tree->leafCells.size() : 0);
  std::unique_ptr<Scene> leafScene, blockScene;
  city::FeatureInstances leafFeatures(style);
  ObjectId leafId = 1;
  int currentLeaf = -1;
  city::LeafContent leaf;
  city::LeafFrame frame;  // the leaf's
  std::array<double, 16> rootFrame{};
  if (tree) rootFrame = city::enuToEcef(townFrame.lon0, townFrame.lat0, r.ground);
  std::size_t tilesetFiles = 0;
  auto flushLeaf = [&] {
    if (currentLeaf < 0 || !leafScene) return;
    const city::QuadCell& cell = tree->cells[tree->leafCells[currentLeaf]];
    const std::string name = std::to_string(cell.level) + "-" + std::to_string(cell.x) + "-" + std::to_string(cell.y);
    leaf.detailUri = "tiles/" + name + ".glb";
    leaf.blocksUri = "tiles/" + name + "-blocks.glb";
    // The tile's glb is in the leaf's frame, and says so.
    ExportOptions leafOptions = exportOptions;
    leafOptions.georeference = {townFrame.crs, city::leafFrameDefinition(frame, r.ground), frame.lon, frame.lat, r.ground};
    leafOptions.instances = &leafFeatures.meshes();
    addFeatures(leaf.detail, leafFeatures.meshes());
    exportScene(*leafScene, (std::filesystem::path(r.tileset) / leaf.detailUri).string(), leafOptions);
    ExportOptions blockOptions = leafOptions;  // plain colours: the far view
    blockOptions.instances = nullptr;
    blockOptions.textures = false;
    blockOptions.tagTextures = {};
    exportScene(*blockScene, (std::filesystem::path(r.tileset) / leaf.blocksUri).string(), blockOptions);
    tilesetFiles += 2;
    leaves[currentLeaf] = std::move(leaf);
    leaf = {};
    leafScene.reset();
    blockScene.reset();
    leafFeatures.clear();
    leafId = 1;
  };
  std::unique_ptr<std::ofstream> report;
  if (!r.report.empty()) {
    report = std::make_unique<std::ofstream>(r.report);
    if (!*report) throw Error(r.report + ": cannot write the report");
  }
  std::map<std::string, std::size_t> reasons;
  std::size_t instancedFeatures = 0;
  auto sink = [&](const city::BuildingReport& b, MeshData* mesh) {
    const std::size_t g = stream ? globalOf[b.index] : b.index;  // the building's number in the source
    if (report) {
      nlohmann::ordered_json j;
      j["id"] = b.id;
      j["type"] = b.type;
      j["ok"] = b.ok;
      if (const city::Building& f = town.buildings[b.index]; f.problem.empty()) {
        // What the style's size rules look at, to the centimetre.
        j["area"] = std::round(f.area * 100) / 100;
        j["depth"] = std::round(f.depth * 100) / 100;
      }
      if (!b.ok) j["error"] = b.error;
      if (!b.notes.empty()) j["notes"] = b.notes;
      if (!b.warnings.empty()) j["warnings"] = b.warnings;
      *report << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    if (!b.ok) {
      std::cerr << "\rcorbel-cli: city: " << b.id << ": skipped: " << b.error << "\n";
      const std::string head = b.error.substr(0, b.error.find(':'));
      ++reasons[head.find('[') == std::string::npos ? head : "geometry"];
      return;
    }
    if (tiled && (!currentTile || *currentTile != tileOf[g])) {
      flushTile();
      currentTile = tileOf[g];
    }
    if (tiled && !tile) {
      tile = std::make_unique<Scene>();
      tileId = 1;
    }
    if (tree) {
      if (currentLeaf != leafOf[g]) {
        flushLeaf();
        currentLeaf = leafOf[g];
        const city::QuadCell& cell = tree->cells[tree->leafCells[currentLeaf]];
        frame = city::leafFrame(townFrame.proj, Vec2(cell.x0 + cell.size / 2, cell.y0 + cell.size / 2), rootFrame,
                                r.ground);
        leaf.transform = frame.toRoot;
      }
      if (!leafScene) {
        leafScene = std::make_unique<Scene>();
        blockScene = std::make_unique<Scene>();
      }
      // The building in the leaf's frame, and its block: the footprint from the mesh's lowest to
      // its highest point.
      MeshData local = *mesh;
      BBox box;
      for (Vec3& p : local.points) box.add(p = frame(p));
      leaf.detail.add(box);
      std::vector<std::vector<Vec2>> loops = town.buildings[b.index].loops;
      for (auto& loop : loops)
        for (Vec2& p : loop) {
          const Vec3 q = frame(Vec3(p[0], p[1], 0));
          p = Vec2(q[0], q[1]);
        }
      const auto [wall, top] = city::dominantMaterials(local);
      const MeshData block = city::extrudedBlock(loops, box.lo[2], box.hi[2], wall, top);
      for (const Vec3& p : block.points) leaf.blocks.add(p);
      // The height, and the quantization's allowance at either end (the same as the boxes').
      leaf.blockError = std::max(leaf.blockError, box.hi[2] - box.lo[2] + 2 * kTilesetPad);
      blockScene->replaceObject(leafId, Kind::Shell, b.id, block);
      leafScene->replaceObject(leafId++, Kind::Shell, b.id, local);
      if (r.instances) {
        std::vector<extrude::FeaturePlacement> features = b.features;
        for (extrude::FeaturePlacement& f : features) {
          f.origin = frame(f.origin);
          f.ex = frame.direction(f.ex);
          f.ey = frame.direction(f.ey);
          f.ez = frame.direction(f.ez);
        }
        leafFeatures.add(features);
      }
    }
    if (view) view->replaceObject(viewId++, Kind::Shell, b.id, *mesh);
    if (tile) tile->replaceObject(tileId++, Kind::Shell, b.id, *mesh);
    if (whole) whole->replaceObject(wholeId++, Kind::Shell, b.id, *mesh);
    if (glbOut) glbOut->add(wholeId++, Kind::Shell, b.id, *mesh);
    if (r.instances) {
      if (tile) tileFeatures.add(b.features);
      if (whole) wholeFeatures.add(b.features);
      // Into the glb being written: the placements to its temporary file, only the shapes kept.
      if (glbOut) wholeFeatures.add(b.features, [&](std::size_t m, const RigidPlacement& p) { glbOut->place(m, p); });
      instancedFeatures += b.features.size();
    }
  };
  city::TownOptions options;
  options.seed = static_cast<std::uint64_t>(r.seed);
  options.jobs = r.jobs;
  options.detail = detail;
  options.featuresApart = r.instances;
  // (buildTown takes an empty order as every building: none are left to build here.)
  city::TownSummary sum;
  if (!stream) {
    if (!order.empty())
      sum = city::buildTown(town, labels, style, options, sink, order,
                            [&](std::size_t d, std::size_t n) { drawBar(d, n, seconds()); });
  } else {
    // Parts of about --stream-buildings buildings in `order`, cut between tiles; each read with
    // its neighbours within the labels' reach, labelled, built, written and dropped. A label
    // looks at other buildings' walls within gap_reach of its edges (the gap search), and at
    // streets within street_reach of its centroid.
    const double reach = style.labels.gapReach + 1;
    const double streetReach = std::max(style.labels.gapReach, style.labels.streetReach) + 1;
    const unsigned jobs = r.jobs ? r.jobs : std::max(1u, std::thread::hardware_concurrency());
    options.chunk = std::min(options.chunk, kStreamRoundPerJob * jobs);
    auto sameTile = [&](std::size_t a, std::size_t b) { return tree ? leafOf[a] == leafOf[b] : tileOf[a] == tileOf[b]; };
    for (std::size_t start = 0; start < order.size();) {
      std::size_t end = std::min(order.size(), start + r.streamBuildings);
      while (end < order.size() && sameTile(order[end - 1], order[end])) ++end;
      std::vector<std::vector<std::size_t>> tiles;  // the part's buildings by tile
      for (std::size_t k = start; k < end; ++k) {
        if (k == start || !sameTile(order[k - 1], order[k])) tiles.emplace_back();
        tiles.back().push_back(order[k]);
      }
      town = {};  // the last part's, dropped before the next is read
      labels = {};
      town = stream->part(tiles, reach, streetReach, globalOf);
      releaseFreedMemory();  // the part's reading (its JSON) is done with
      std::vector<std::size_t> partOrder;  // `order`'s run in the part's numbers
      for (std::size_t k = start; k < end; ++k)
        partOrder.push_back(static_cast<std::size_t>(std::lower_bound(globalOf.begin(), globalOf.end(), order[k]) -
                                                     globalOf.begin()));
      // Only the part's buildings are labelled: the neighbours read with them are not built.
      labels = city::labelTown(town, style.labels, r.jobs, &partOrder);
      const city::TownSummary s =
          city::buildTown(town, labels, style, options, sink, partOrder,
                          [&](std::size_t d, std::size_t) { drawBar(start + d, order.size(), seconds()); });
      sum.buildings += s.buildings;
      sum.ok += s.ok;
      sum.refused += s.refused;
      sum.failed += s.failed;
      sum.faces += s.faces;
      for (const auto& [type, n] : s.types) sum.types[type] += n;
      start = end;
    }
    town = {};
    labels.clear();
  }
  flushTile();
  flushLeaf();
  if (tree) {
    // Placed on the globe: the root's frame is east-north-up at the town's origin, each leaf's at
    // its centre (docs/city.md).
    writeFileAtomic((std::filesystem::path(r.tileset) / "tileset.json").string(),
                    city::tilesetJson(*tree, leaves, &rootFrame, kTilesetPad).dump() + "\n");
  }
  const double buildS = seconds();
  if (whole) {
    exportOptions.instances = &wholeFeatures.meshes();
    exportScene(*whole, r.out, exportOptions);
  }
  if (glbOut) glbOut->write(r.out);
  glbOut.reset();
  if (!r.render.empty()) {
    render::HeadlessContext context;
    writeScenePng(whole ? *whole : *view, {-60, 35, 0.75, r.renderTextures == "on", exportOptions.tagTextures},
                  r.render);
  }
  whole.reset();
  view.reset();

  nlohmann::ordered_json j;
  j["source"] = source;
  j["frame"] = townFrame.how;
  if (!townFrame.proj.empty()) {
    j["crs"] = townFrame.crs;
    j["local_frame"] = townFrame.proj;
    j["lon0"] = townFrame.lon0;
    j["lat0"] = townFrame.lat0;
    j["scale_error"] = townFrame.scaleError;
  }
  if (!attribution.empty()) j["attribution"] = attribution;
  j["streets"] = stream ? stream->streets().size() : town.streets.size();
  if (stream) j["streamed"] = true;
  j["style"] = style.name;
  j["seed"] = options.seed;
  j["buildings"] = sum.buildings;
  j["ok"] = sum.ok;
  j["refused"] = sum.refused;
  j["failed"] = sum.failed;
  j["types"] = sum.types;
  j["faces"] = sum.faces;
  j["skipped_by_reason"] = reasons;
  if (margin) j["margin"] = margin;
  if (tiled) j["tiles"] = tilesWritten;
  if (tree) j["tileset_files"] = tilesetFiles;
  if (r.instances) {
    j["instanced_features"] = instancedFeatures;
    j["feature_meshes"] = wholeFeatures.meshes().size();
  }
  j["read_s"] = readS;
  j["build_s"] = buildS - readS;
  j["total_s"] = seconds();
  std::cout << j.dump() << "\n";
  return sum.ok == sum.buildings ? 0 : 1;
}

}  // namespace corbel::cli
