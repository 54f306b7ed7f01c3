// Footprints through GDAL/OGR and PROJ: the shared Moosburg footprints written by GDAL's own
// ogr2ogr in other CRSs and formats read back as the same buildings, each area checked against
// the area on the WGS 84 ellipsoid of the same outline in lon/lat (in an equal-area projection);
// files without a CRS refused; layers and filters; the CLI's georeference.
#include "city/import.h"
#include "city/kernel.h"
#include "city/ogr_source.h"
#include "core/error.h"

#include <geodesic.h>
#include "../common/glb_read.h"

#include <gtest/gtest.h>
#include <proj.h>
#include <tiny_gltf.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

using namespace corbel;
using namespace corbel::city;
namespace fs = std::filesystem;

namespace {

constexpr double kDeg = std::numbers::pi / 180;
const std::string kSource = std::string(CORBEL_FOOTPRINTS) + "/moosburg_de.geojson";

int shell(const std::string& cmd) { return WEXITSTATUS(std::system(cmd.c_str())); }

// The original file's frame, as its README and its "frame" member describe it.
struct Original {
  double lon0 = 0, lat0 = 0, R = 6371008.8;
  std::string proj;                              // the same, for ogr2ogr's -s_srs
  std::map<std::string, double> ellipsoidArea;   // by id, m² on the WGS 84 ellipsoid
  std::map<std::string, std::string> building;   // by id: src_building
  double latLo = 90, latHi = -90, eastMost = 0;  // of the sample: latitudes; metres from lon0 east or west
};

// Every tenth feature of Moosburg in these files (made once for all tests).
struct Files {
  fs::path dir;
  Original original;
};

struct RemoveAtExit {
  fs::path dir;
  ~RemoveAtExit() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

const Files& files() {
  static const Files f = [] {
    Files f;
    f.dir = fs::temp_directory_path() / ("corbel_gis_" + std::to_string(::getpid()));
    fs::create_directories(f.dir);
    nlohmann::json data = nlohmann::json::parse(std::ifstream(kSource));
    Original& o = f.original;
    o.lon0 = data["frame"]["lon0"];
    o.lat0 = data["frame"]["lat0"];
    char proj[256];
    std::snprintf(proj, sizeof proj, "+proj=eqc +lat_ts=%.10g +lat_0=%.10g +lon_0=%.10g +R=6371008.8 +units=m +no_defs",
                  o.lat0, o.lat0, o.lon0);
    o.proj = proj;
    // The sample, and the area of each outline on the WGS 84 ellipsoid: lon/lat from the frame's
    // inverse by hand (lon = lon0 + x / (R cos lat0), lat = lat0 + y / R), then the shoelace
    // area in PROJ's Lambert azimuthal equal-area projection of the ellipsoid about (lon0, lat0),
    // which keeps every area (an equal-area map; straight edges of a few metres bend by nothing
    // measurable). The geodesic library's polygon area would do too, but its result moves by
    // 2e-5 m² when a corner moves by 1e-12° (0.1 µm), which is more than the tolerance of the
    // smallest buildings here.
    PJ_CONTEXT* ctx = proj_context_create();
    char laea[256];
    std::snprintf(laea, sizeof laea, "+proj=laea +lat_0=%.10g +lon_0=%.10g +datum=WGS84 +units=m +no_defs +type=crs",
                  o.lat0, o.lon0);
    PJ* raw = proj_create_crs_to_crs(ctx, "EPSG:4326", laea, nullptr);
    PJ* equalArea = proj_normalize_for_visualization(ctx, raw);
    proj_destroy(raw);
    if (!equalArea) throw std::runtime_error("PROJ cannot make the equal-area projection");
    nlohmann::json sample = data;
    sample["features"] = nlohmann::json::array();
    for (std::size_t i = 0; i < data["features"].size(); i += 10) {
      const auto& feature = data["features"][i];
      sample["features"].push_back(feature);
      const auto& props = feature["properties"];
      const std::string id = props["source_id"].get<std::string>() + "#" + props["part"].dump();
      double total = 0;
      for (std::size_t r = 0; r < feature["geometry"]["coordinates"].size(); ++r) {
        const auto& ring = feature["geometry"]["coordinates"][r];
        std::vector<Vec2> plane;
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) {  // closed rings: the last repeats the first
          const double x = ring[k][0], y = ring[k][1];
          const double lon = o.lon0 + x / (o.R * std::cos(o.lat0 * kDeg)) / kDeg, lat = o.lat0 + y / o.R / kDeg;
          o.latLo = std::min(o.latLo, lat);
          o.latHi = std::max(o.latHi, lat);
          const PJ_COORD q = proj_trans(equalArea, PJ_FWD, proj_coord(lon, lat, 0, 0));
          plane.emplace_back(q.xy.x, q.xy.y);
        }
        double twice = 0;
        for (std::size_t a = 0, b = plane.size() - 1; a < plane.size(); b = a++)
          twice += (plane[b][0] - plane[a][0]) * (plane[b][1] + plane[a][1]);
        total += std::abs(twice / 2) * (r == 0 ? 1 : -1);
      }
      o.ellipsoidArea[id] = total;
      o.building[id] = props.value("src_building", "");
    }
    proj_destroy(equalArea);
    proj_context_destroy(ctx);
    std::ofstream(f.dir / "original.geojson") << sample.dump();
    const std::string in = (f.dir / "original.geojson").string();
    const std::string s = " -s_srs \"" + o.proj + "\" ";
    auto make = [&](const std::string& out, const std::string& how) {
      const std::string cmd = "ogr2ogr " + how + s + "\"" + (f.dir / out).string() + "\" \"" + in + "\" 2>/dev/null";
      if (shell(cmd) != 0) throw std::runtime_error("failed: " + cmd);
    };
    make("lonlat.geojson", "-f GeoJSON -t_srs EPSG:4326");
    make("utm32n.geojson", "-f GeoJSON -t_srs EPSG:32632");
    make("webmercator.geojson", "-f GeoJSON -t_srs EPSG:3857");
    make("utm32n.shp", "-f \"ESRI Shapefile\" -t_srs EPSG:32632");
    make("lonlat.gpkg", "-f GPKG -t_srs EPSG:4326 -nln buildings");
    make("utm32n.fgb", "-f FlatGeobuf -t_srs EPSG:32632");
    // Without a CRS: the Shapefile without its .prj, the UTM GeoJSON without its "crs" member.
    make("nocrs.shp", "-f \"ESRI Shapefile\" -t_srs EPSG:32632");
    fs::remove(f.dir / "nocrs.prj");
    nlohmann::json utm = nlohmann::json::parse(std::ifstream(f.dir / "utm32n.geojson"));
    utm.erase("crs");
    utm.erase("frame");
    std::ofstream(f.dir / "nocrs.geojson") << utm.dump();
    // A GeoPackage of two layers: every building, and the garages.
    make("two.gpkg", "-f GPKG -t_srs EPSG:4326 -nln all_buildings");
    make("two.gpkg", "-update -f GPKG -t_srs EPSG:4326 -nln garages -where \"src_building = 'garage'\"");
    // The outermost building east or west of the data's centre meridian, for the transverse
    // Mercator's scale error.
    double west = 180, east = -180;
    for (const auto& feature : sample["features"])
      for (const auto& ring : feature["geometry"]["coordinates"])
        for (const auto& p : ring) {
          const double lon = o.lon0 + p[0].get<double>() / (o.R * std::cos(o.lat0 * kDeg)) / kDeg;
          west = std::min(west, lon);
          east = std::max(east, lon);
        }
    // The reader centres its frame on the middle of the data's extent; half the extent in
    // longitude, at the southern edge (where a degree is longest), in metres.
    o.eastMost = (east - west) / 2 * kDeg * 6378137 * std::cos(o.latLo * kDeg);
    return f;
  }();
  static const RemoveAtExit cleanup{f.dir};
  return f;
}

std::string path(const std::string& name) { return (files().dir / name).string(); }

// Outer minus holes by the shoelace formula, m².
double areaOf(const Building& b) {
  double area = 0;
  for (const auto& ring : b.loops) {
    double twice = 0;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
      twice += (ring[j][0] - ring[i][0]) * (ring[j][1] + ring[i][1]);
    area += twice / 2;
  }
  return area;
}

Town readAsRead(const std::string& file, ReadOptions options = {}) {
  options.clean = false;
  return readTownFile(file, options);
}

// Every building of the sample is there under its id, and its area agrees with the one on the
// ellipsoid within `relative` (plus 1e-6 m² for rounding).
void expectSameBuildings(const Town& t, double relative, const std::string& what) {
  const Original& o = files().original;
  ASSERT_EQ(t.buildings.size(), o.ellipsoidArea.size()) << what;
  double worst = 0;
  for (const auto& b : t.buildings) {
    const auto it = o.ellipsoidArea.find(b.id);
    ASSERT_NE(it, o.ellipsoidArea.end()) << what << ": " << b.id;
    EXPECT_EQ(b.problem, "") << what << ": " << b.id;
    const double got = areaOf(b), want = it->second;
    EXPECT_NEAR(got, want, want * relative + 1e-6) << what << ": " << b.id;
    worst = std::max(worst, std::abs(got / want - 1));
  }
  std::cout << what << ": " << t.buildings.size() << " buildings, worst relative area error " << worst << " (allowed "
            << relative << ")\n";
}

// The transverse Mercator's areas: k² - 1 ≈ 2 (k - 1) with k - 1 = x² / (2 N²) at the
// outermost point (N ≥ 6,335 km), doubled for margin; here about 6e-7.
double transverseMercatorTolerance() {
  const double x = files().original.eastMost, n = 6.335e6;
  return 2 * 2 * x * x / (2 * n * n);
}

}  // namespace

TEST(GisInput, EveryFormatAndCrsGivesTheSameBuildingsAsTheOriginal) {
  const Original& o = files().original;
  // The original, in corbel's equirectangular frame on the sphere, taken as it is: its east-west
  // lengths are stretched by cos(lat0) / cos(lat) against the sphere, so areas by up to that
  // (north-south lengths are exact); and the sphere of the mean radius is not the ellipsoid,
  // whose area element at 48.5° N differs from the sphere's by about 0.1 % (checked below by
  // the geodesic library, not assumed).
  const Town original = readAsRead(kSource);
  EXPECT_EQ(original.frame.coordinates, Coordinates::Metric);
  EXPECT_NE(original.frame.proj.find("+proj=eqc"), std::string::npos);
  EXPECT_NEAR(original.frame.lon0, o.lon0, 1e-9);
  EXPECT_NEAR(original.frame.lat0, o.lat0, 1e-9);
  double stretch = 0;
  for (double lat : {o.latLo, o.latHi})
    stretch = std::max(stretch, std::abs(std::cos(o.lat0 * kDeg) / std::cos(lat * kDeg) - 1));
  {
    // The sphere against the ellipsoid, for one square degree-thousandth at lat0: the ratio of
    // the two area elements, by the geodesic library.
    geod_geodesic g;
    geod_init(&g, 6378137, 1 / 298.257223563);
    double lats[] = {o.lat0, o.lat0, o.lat0 + 0.001, o.lat0 + 0.001},
           lons[] = {o.lon0, o.lon0 + 0.001, o.lon0 + 0.001, o.lon0};
    double ellipsoid = 0, perimeter = 0;
    geod_polygonarea(&g, lats, lons, 4, &ellipsoid, &perimeter);
    const double sphere = o.R * o.R * 0.001 * kDeg * 0.001 * kDeg * std::cos((o.lat0 + 0.0005) * kDeg);
    const double sphereError = std::abs(sphere / std::abs(ellipsoid) - 1);
    EXPECT_LT(sphereError, 0.005);
    // Only the sample's buildings: the original file has all of them.
    Town sample;
    for (const auto& b : original.buildings)
      if (o.ellipsoidArea.count(b.id)) sample.buildings.push_back(b);
    expectSameBuildings(sample, 2 * stretch + sphereError + 1e-5, "original (equirectangular frame, sphere)");
  }

  // Everything ogr2ogr wrote, reprojected to a transverse Mercator on WGS 84 about the centre.
  const double tm = transverseMercatorTolerance();
  ASSERT_LT(tm, 2e-6);  // 10 km of data
  for (const auto& [file, crs] : std::vector<std::pair<std::string, std::string>>{{"lonlat.geojson", "EPSG:4326"},
                                                                                  {"utm32n.geojson", "EPSG:32632"},
                                                                                  {"webmercator.geojson", "EPSG:3857"},
                                                                                  {"utm32n.shp", "EPSG:32632"},
                                                                                  {"lonlat.gpkg", "EPSG:4326"},
                                                                                  {"utm32n.fgb", "EPSG:32632"}}) {
    const Town t = readAsRead(path(file));
    EXPECT_EQ(t.frame.crs, crs) << file << ": " << t.frame.how;
    EXPECT_NE(t.frame.proj.find("+proj=tmerc"), std::string::npos) << file;
    // The frame's origin is the middle of the data: within the sample's latitudes.
    EXPECT_GT(t.frame.lat0, o.latLo) << file;
    EXPECT_LT(t.frame.lat0, o.latHi) << file;
    EXPECT_GT(t.frame.scaleError, 0) << file;
    EXPECT_LE(2 * t.frame.scaleError, tm) << file;
    expectSameBuildings(t, tm, file);
    // Coordinates about the centre: no vertex farther than the data's extent (10 km) from it,
    // so a float keeps them to the millimetre.
    for (const auto& b : t.buildings)
      for (const auto& ring : b.loops)
        for (const Vec2& p : ring) ASSERT_LT(p.norm(), 8000) << file << ": " << b.id;
  }
}

TEST(GisInput, OpenStreetMapDataCarriesItsAttribution) {
  for (const char* file : {"lonlat.geojson", "utm32n.shp", "lonlat.gpkg"}) {
    const Town t = readAsRead(path(file));
    EXPECT_NE(t.attribution.find("OpenStreetMap contributors"), std::string::npos) << file;
    EXPECT_NE(t.attribution.find("ODbL"), std::string::npos) << file;
  }
}

TEST(GisInput, AFileWithoutACrsIsRefusedWithHowToGiveOne) {
  for (const char* file : {"nocrs.shp", "nocrs.geojson"}) {
    try {
      readAsRead(path(file));
      ADD_FAILURE() << file << " was read";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(file), std::string::npos) << what;
      EXPECT_NE(what.find("CRS"), std::string::npos) << what;
      EXPECT_NE(what.find("--crs"), std::string::npos) << what;
    }
    // Given, it reads as the others.
    ReadOptions given;
    given.crs = "EPSG:32632";
    expectSameBuildings(readAsRead(path(file), given), transverseMercatorTolerance(), std::string(file) + " --crs");
  }
  // A CRS nobody knows is refused by name.
  ReadOptions bad;
  bad.crs = "EPSG:999999";
  EXPECT_THROW(readAsRead(path("nocrs.shp"), bad), InputError);
}

TEST(GisInput, ALayerAndAFilterChooseTheBuildings) {
  const Original& o = files().original;
  std::size_t garages = 0;
  for (const auto& [id, kind] : o.building) garages += kind == "garage";
  ASSERT_GT(garages, 5u);
  // Two layers: which one must be said.
  try {
    readAsRead(path("two.gpkg"));
    ADD_FAILURE() << "two layers read without --layer";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--layer"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("garages"), std::string::npos) << e.what();
  }
  ReadOptions layer;
  layer.layer = "garages";
  const Town g = readAsRead(path("two.gpkg"), layer);
  EXPECT_EQ(g.buildings.size(), garages);
  for (const auto& b : g.buildings) EXPECT_EQ(o.building.at(b.id), "garage") << b.id;
  layer.layer = "nothing";
  EXPECT_THROW(readAsRead(path("two.gpkg"), layer), InputError);
  // A filter on any source, GeoJSON included, keeps the frame of the whole file.
  ReadOptions filter;
  filter.where = "src_building = 'garage'";
  for (const char* file : {"lonlat.geojson", "lonlat.gpkg"}) {
    const Town t = readAsRead(path(file), filter);
    EXPECT_EQ(t.buildings.size(), garages) << file;
    for (const auto& b : t.buildings)
      EXPECT_NEAR(areaOf(b), o.ellipsoidArea.at(b.id), o.ellipsoidArea.at(b.id) * 1e-6) << b.id;
  }
  // In corbel's frame, through OGR as well: the frame member still holds.
  const Town framed = readAsRead(kSource, filter);
  EXPECT_NE(framed.frame.proj.find("+proj=eqc"), std::string::npos) << framed.frame.how;
  EXPECT_GE(framed.buildings.size(), garages);
  filter.where = "no_such_field > 3";
  try {
    readAsRead(path("lonlat.gpkg"), filter);
    ADD_FAILURE() << "a bad filter was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("where"), std::string::npos) << e.what();
  }
}

// A streamed town's part fetches its features by id (forEachOgrFeatureById): every third
// feature, asked for in reverse order, is the feature the layer's own read gave with that id,
// with and without a filter; an id the layer does not have is refused by name.
TEST(GisInput, FeaturesFetchedByIdAreTheFeaturesReadInOrder) {
  for (const auto& [file, where] : {std::pair{"utm32n.shp", ""},
                                    {"lonlat.gpkg", ""},
                                    {"utm32n.fgb", ""},
                                    {"lonlat.gpkg", "src_building = 'garage'"},
                                    {"lonlat.geojson", ""}}) {
    const SourceOptions options{"", where};
    std::vector<nlohmann::json> read;
    std::vector<std::int64_t> fids;
    const SourceLayer layer = forEachOgrFeature(
        path(file), options, [&](nlohmann::json& f) { read.push_back(f); }, &fids);
    ASSERT_EQ(fids.size(), read.size()) << file;
    ASSERT_GT(read.size(), 5u) << file;
    EXPECT_TRUE(layer.randomRead) << file;
    std::vector<std::int64_t> asked;
    std::vector<std::size_t> which;
    for (std::size_t i = read.size(); i-- > 0;)
      if (i % 3 == 0) {
        asked.push_back(fids[i]);
        which.push_back(i);
      }
    std::size_t k = 0;
    forEachOgrFeatureById(path(file), options, asked, [&](nlohmann::json& f) {
      ASSERT_LT(k, which.size());
      EXPECT_EQ(f, read[which[k]]) << file << " feature " << which[k];
      ++k;
    });
    EXPECT_EQ(k, which.size()) << file;
    const std::int64_t missing = *std::max_element(fids.begin(), fids.end()) + 1000;
    try {
      forEachOgrFeatureById(path(file), options, {missing}, [](nlohmann::json&) {});
      ADD_FAILURE() << file << ": a missing id was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(missing)), std::string::npos) << e.what();
    }
  }
}

TEST(GisInput, ATownObjectReadsAnyFormat) {
  // A project's town names its footprints by file; a GeoPackage in lon/lat works as GeoJSON does.
  TownSpec spec;
  spec.footprints = path("lonlat.gpkg");
  spec.style = std::string(CORBEL_SOURCE_DIR) + "/assets/styles/mixed.json";
  const TownInputs in = readTownInputs(spec);
  EXPECT_EQ(in.town.frame.crs, "EPSG:4326");
  EXPECT_EQ(in.town.buildings.size(), files().original.ellipsoidArea.size());
}

TEST(GisInput, TheFootprintDialogOffersEveryFormatTheTestsWrite) {
  // The editor's footprint dialogs filter by these: every format ogr2ogr writes for the tests
  // above is offered, GeoJSON's first, each once.
  const std::vector<std::string> ext = vectorFileExtensions();
  ASSERT_GE(ext.size(), 2u);
  EXPECT_EQ(ext[0], ".geojson");
  for (const char* e : {".json", ".shp", ".gpkg", ".fgb", ".kml", ".gml"})
    EXPECT_NE(std::find(ext.begin(), ext.end(), e), ext.end()) << e;
  for (std::size_t i = 0; i < ext.size(); ++i) {
    EXPECT_EQ(ext[i][0], '.') << ext[i];
    EXPECT_EQ(std::count(ext.begin(), ext.end(), ext[i]), 1) << ext[i];
  }
}

namespace {

// The first line corbel-cli prints, and its exit code.
std::pair<int, nlohmann::json> cli(const std::string& args) {
  const std::string out = path("cli.out");
  const int rc = shell(std::string(CORBEL_CLI) + " " + args + " > \"" + out + "\" 2>/dev/null");
  std::ifstream in(out);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return {rc, last.empty() ? nlohmann::json() : nlohmann::json::parse(last)};
}

}  // namespace

TEST(GisInput, ExtrudeOnLonLatBuildsBuildingsMetresTall) {
  // The default roof (45° from the eaves, no walls) rises to the straight skeleton's highest
  // point: at most half the outline's extent (under 500 m) and, for an outline at least a metre
  // wide, tens of centimetres or more. Read as metres, lon/lat outlines 1e-4 wide made roofs
  // 6e-5 m tall. The same building is as tall from lon/lat as from UTM.
  std::map<std::string, double> heights;
  for (const char* file : {"lonlat.geojson", "utm32n.shp"}) {
    const std::string out = path("extrude.out");
    ASSERT_EQ(
        shell(std::string(CORBEL_CLI) + " extrude \"" + path(file) + "\" --stats > \"" + out + "\" 2>/dev/null") & ~1,
        0)
        << file;
    std::ifstream in(out);
    std::string line;
    std::size_t ok = 0, metreTall = 0;
    nlohmann::json summary;
    while (std::getline(in, line)) {
      const nlohmann::json j = nlohmann::json::parse(line);
      if (j.contains("summary")) {
        summary = j;
        continue;
      }
      if (!j.contains("max_height")) continue;
      const std::string id = j["id"].get<std::string>();
      const double h = j["max_height"];
      EXPECT_GT(h, 0.1) << file << ": " << id;
      EXPECT_LT(h, 250) << file << ": " << id;
      metreTall += h >= 1;
      if (heights.count(id)) {
        EXPECT_NEAR(h, heights[id], 0.01) << id;
      }
      heights[id] = h;
      ++ok;
    }
    EXPECT_GT(ok, files().original.ellipsoidArea.size() * 9 / 10) << file;
    EXPECT_GT(metreTall, ok * 9 / 10) << file;
    EXPECT_EQ(summary.value("crs", ""), std::string(file).starts_with("lonlat") ? "EPSG:4326" : "EPSG:32632");
  }
}

TEST(GisInput, TheCityGlbRecordsItsPlaceOnTheEarthAndItsAttribution) {
  const std::string glb = path("town.glb");
  const auto [rc, j] = cli("city \"" + path("utm32n.fgb") + "\" --style " + CORBEL_SOURCE_DIR +
                           "/assets/styles/mixed.json --detail massing --textures off --jobs 2 --out \"" + glb + "\"");
  ASSERT_EQ(rc & ~1, 0) << j.dump();
  EXPECT_EQ(j["crs"], "EPSG:32632");
  EXPECT_EQ(j["buildings"], files().original.ellipsoidArea.size());
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, glb)) << err;
  EXPECT_NE(model.asset.copyright.find("OpenStreetMap contributors"), std::string::npos);
  const tinygltf::Value& geo = model.scenes.at(0).extras.Get("georeference");
  ASSERT_TRUE(geo.IsObject());
  EXPECT_EQ(geo.Get("crs").Get<std::string>(), "EPSG:32632");
  const std::string proj = geo.Get("proj").Get<std::string>();
  const double lon = geo.Get("origin").Get(0).GetNumberAsDouble(), lat = geo.Get("origin").Get(1).GetNumberAsDouble();
  // PROJ itself places the glb: a building's lowest corner (glTF x, -z) taken back to lon/lat
  // through the recorded frame lands on that corner as the lon/lat file has it (to the
  // centimetre: float32 at a few km is 0.5 mm).
  PJ_CONTEXT* ctx = proj_context_create();
  PJ* toLonLat = proj_create_crs_to_crs(ctx, proj.c_str(), "EPSG:4326", nullptr);
  ASSERT_TRUE(toLonLat);
  PJ* norm = proj_normalize_for_visualization(ctx, toLonLat);
  ASSERT_TRUE(norm);
  // The origin itself maps to (0, 0).
  const PJ_COORD origin = proj_trans(norm, PJ_INV, proj_coord(lon, lat, 0, 0));
  EXPECT_NEAR(origin.xy.x, 0, 1e-6);
  EXPECT_NEAR(origin.xy.y, 0, 1e-6);
  // Corners of the lon/lat file, in the frame: each glb vertex of the first building lies within
  // 2 cm of one of them (walls stand on the outline).
  nlohmann::json lonlat = nlohmann::json::parse(std::ifstream(path("lonlat.geojson")));
  // The vertices as a client places them (tests/common/glb_read.h: dequantized by the node).
  std::map<std::string, std::vector<std::array<double, 3>>> placed;
  for (const auto& p : corbel::test::worldPrimitives(corbel::test::readGlbFile(glb)))
    placed[p.nodeName].insert(placed[p.nodeName].end(), p.positions.begin(), p.positions.end());
  std::size_t checked = 0;
  for (const auto& node : model.nodes) {
    if (node.mesh < 0 || checked >= 20) continue;
    const std::string id = node.name;
    // The building's corners in lon/lat, from the file ogr2ogr wrote.
    std::vector<Vec2> corners;
    for (const auto& f : lonlat["features"]) {
      const auto& p = f["properties"];
      if (p["source_id"].get<std::string>() + "#" + p["part"].dump() != id) continue;
      for (const auto& ring : f["geometry"]["coordinates"])
        for (const auto& c : ring) {
          const PJ_COORD q = proj_trans(norm, PJ_INV, proj_coord(c[0].get<double>(), c[1].get<double>(), 0, 0));
          corners.emplace_back(q.xy.x, q.xy.y);
        }
    }
    if (corners.empty()) continue;
    std::size_t ground = 0;
    for (const auto& q : placed[id]) {
      if (std::abs(q[1]) > 1e-3) continue;  // ground corners only
      const Vec2 p(q[0], -q[2]);
      double nearest = INFINITY;
      for (const Vec2& c : corners) nearest = std::min(nearest, (c - p).norm());
      EXPECT_LT(nearest, 0.02) << id;
      ++ground;
    }
    EXPECT_GE(ground, 3u) << id;
    ++checked;
  }
  EXPECT_GE(checked, 10u);
  proj_destroy(norm);
  proj_destroy(toLonLat);
  proj_context_destroy(ctx);
}
