// corbel-cli extrude: a project's extrusion objects or GeoJSON footprints through the batch
// (extrude/batch.h); one JSON line per building with --stats, then a summary.
#include "city/import.h"
#include "cli/guarded.h"
#include "cli/run.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "extrude/batch.h"
#include "extrude/footprints.h"
#include "extrude/kernel.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace corbel::cli {

int run(const ExtrudeRequest& request) {
  const std::string& input = request.input;
  const std::string& out = request.out;
  const double pitch = request.pitch.value_or(45.0) * std::numbers::pi / 180.0;
  const double wall = request.wallHeight.value_or(0.0);
  if (!request.out.empty()) {
    try {
      exportFormatFor(request.out);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  const Profile uniform = extrude::wallAndRoofProfile(wall, pitch);
  std::vector<Profile> library;
  if (!request.library.empty()) {
    for (const auto& o : loadProject(request.library).document.objects)
      if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec))
        for (const Profile& p : e->profiles) library.push_back(p);
  }

  std::vector<extrude::BatchItem> items;
  // A project is a .corbel file or JSON that says it is one; anything else is footprints.
  std::string ext = std::filesystem::path(input).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  bool isProject = ext == ".corbel";
  if (!isProject && (ext == ".json" || ext == ".geojson" || ext.empty()) && std::filesystem::is_regular_file(input)) {
    const std::string text = readFile(input, std::size_t(1) << 31);
    isProject = text.find("\"format\"") != std::string::npos && text.find("\"corbel\"") != std::string::npos;
  }
  city::Frame frame;
  std::string attribution;
  if (isProject) {
    const Document doc = loadProject(input).document;
    for (const DocObject& o : doc.objects) {
      const auto* e = std::get_if<ExtrusionSpec>(&o.spec);
      if (!e) continue;
      extrude::BatchItem item{o.name, *e, ""};
      if (request.pitch || request.wallHeight) {
        item.spec.profiles = {uniform};
        for (auto& loop : item.spec.loops) loop.profile.assign(loop.points.size(), 0);
      }
      items.push_back(std::move(item));
    }
  } else {
    // Through the town's reader: any GDAL/OGR source in its CRS, reprojected to a local metric
    // frame, outlines as read (not cleaned).
    city::ReadOptions read;
    read.crs = request.crs;
    read.layer = request.layer;
    read.where = request.where;
    read.clean = false;
    city::Town town = city::readTownFile(input, read);
    frame = town.frame;
    attribution = town.attribution;
    for (auto& fp : town.buildings) {
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
  options.jobs = request.jobs;
  options.keepMeshes = !request.out.empty();
  options.mergeCoplanar = request.mergeCoplanar;
  if (request.noRetry) options.retryFactors.clear();
  options.windingRule = request.windingRule;
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = extrude::extrudeBatch(items, options);
  const double batchMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  std::size_t failed = 0, withWarnings = 0;
  const bool stats = request.stats;
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
    ExportOptions exportOptions;
    exportOptions.georeference = {frame.crs, frame.proj, frame.lon0, frame.lat0, 0};
    exportOptions.copyright = attribution;
    exportScene(scene, out, exportOptions);
    exportMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
  }
  nlohmann::ordered_json summary;
  summary["summary"] = true;
  summary["buildings"] = results.size();
  summary["ok"] = results.size() - failed;
  summary["failed"] = failed;
  summary["with_warnings"] = withWarnings;
  summary["extrude_ms"] = batchMs;
  if (!isProject) {
    summary["frame"] = frame.how;
    if (!frame.proj.empty()) {
      summary["crs"] = frame.crs;
      summary["scale_error"] = frame.scaleError;
    }
  }
  if (!out.empty()) {
    summary["export_ms"] = exportMs;
    summary["out"] = out;
  }
  (stats ? std::cout : std::cerr) << summary.dump() << "\n";
  return failed ? 1 : 0;
}

}  // namespace corbel::cli
