#include "city/ogr_source.h"

#include "core/error.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <sstream>

namespace corbel::city {

namespace {

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};

// GDAL's messages go into our InputErrors, not onto stderr.
struct QuietGdal {
  QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

// GDAL's drivers, registered once for the process.
void registerDrivers() {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
}

std::string lastError(const std::string& otherwise) {
  const char* m = CPLGetLastErrorMsg();
  return m && *m ? std::string(m) : otherwise;
}

nlohmann::json ring(const OGRLineString& line) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < line.getNumPoints(); ++i) a.push_back({line.getX(i), line.getY(i)});
  return a;
}

nlohmann::json polygon(const OGRPolygon& p) {
  nlohmann::json rings = nlohmann::json::array();
  if (const OGRLinearRing* outer = p.getExteriorRing()) rings.push_back(ring(*outer));
  for (int i = 0; i < p.getNumInteriorRings(); ++i) rings.push_back(ring(*p.getInteriorRing(i)));
  return rings;
}

// A geometry as GeoJSON, coordinates as they are (2D); null for a kind a town has no use for,
// which the reader then reports.
nlohmann::json geometry(const OGRGeometry* g) {
  if (!g) return nullptr;
  switch (wkbFlatten(g->getGeometryType())) {
    case wkbPolygon:
      return {{"type", "Polygon"}, {"coordinates", polygon(*g->toPolygon())}};
    case wkbMultiPolygon: {
      nlohmann::json parts = nlohmann::json::array();
      for (const OGRPolygon* p : *g->toMultiPolygon()) parts.push_back(polygon(*p));
      return {{"type", "MultiPolygon"}, {"coordinates", parts}};
    }
    case wkbLineString:
      return {{"type", "LineString"}, {"coordinates", ring(*g->toLineString())}};
    case wkbMultiLineString: {
      nlohmann::json parts = nlohmann::json::array();
      for (const OGRLineString* l : *g->toMultiLineString()) parts.push_back(ring(*l));
      return {{"type", "MultiLineString"}, {"coordinates", parts}};
    }
    default:
      return {{"type", OGRGeometryTypeToName(g->getGeometryType())}};
  }
}

nlohmann::json field(const OGRFeature& f, int i) {
  switch (f.GetFieldDefnRef(i)->GetType()) {
    case OFTInteger:
      return f.GetFieldAsInteger(i);
    case OFTInteger64:
      return static_cast<std::int64_t>(f.GetFieldAsInteger64(i));
    case OFTReal:
      return f.GetFieldAsDouble(i);
    default:
      return std::string(f.GetFieldAsString(i));
  }
}

}  // namespace

SourceFeatures readOgrSource(const std::string& path, const SourceOptions& options) {
  SourceFeatures out;
  out.collection = {{"type", "FeatureCollection"}, {"features", nlohmann::json::array()}};
  nlohmann::json& features = out.collection["features"];
  static_cast<SourceLayer&>(out) =
      forEachOgrFeature(path, options, [&](nlohmann::json& f) { features.push_back(std::move(f)); });
  return out;
}

namespace {

// A source opened and its layer chosen and filtered, as every reader here needs it.
struct OpenLayer {
  std::unique_ptr<GDALDataset, DatasetCloser> data;
  OGRLayer* layer = nullptr;
  SourceLayer about;
};

OpenLayer openLayer(const std::string& path, const SourceOptions& options) {
  registerDrivers();
  CPLErrorReset();
  OpenLayer out;
  out.data.reset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!out.data) throw InputError(path, lastError("GDAL/OGR cannot open it as a vector source"));
  GDALDataset* data = out.data.get();
  out.about.driver = data->GetDriver() ? data->GetDriver()->GetDescription() : "";
  OGRLayer* layer = nullptr;
  const int layers = data->GetLayerCount();
  std::string names;
  for (int i = 0; i < layers; ++i) names += std::string(i ? ", " : "") + data->GetLayer(i)->GetName();
  if (!options.layer.empty()) {
    layer = data->GetLayerByName(options.layer.c_str());
    if (!layer)
      throw InputError(path,
                       "no layer \"" + options.layer + "\" (" + std::to_string(layers) + " layer(s): " + names + ")");
  } else if (layers == 1) {
    layer = data->GetLayer(0);
  } else {
    throw InputError(
        path, layers ? std::to_string(layers) + " layers (" + names + "): choose one with --layer" : "no layers");
  }
  out.layer = layer;
  out.about.layer = layer->GetName();
  out.about.randomRead = layer->TestCapability(OLCRandomRead) != 0;
  if (!options.where.empty()) {
    CPLErrorReset();
    if (layer->SetAttributeFilter(options.where.c_str()) != OGRERR_NONE)
      throw InputError("where", "\"" + options.where + "\" is not an OGR SQL filter of layer \"" + out.about.layer +
                                    "\": " + lastError("GDAL refused it"));
  }
  if (const OGRSpatialReference* srs = layer->GetSpatialRef()) {
    char* wkt = nullptr;
    const char* wktOptions[] = {"FORMAT=WKT2_2018", nullptr};
    if (srs->exportToWkt(&wkt, wktOptions) == OGRERR_NONE && wkt) out.about.crs = wkt;
    CPLFree(wkt);
  }
  return out;
}

// GDAL's failures while reading; those of the caller's own work (PROJ, say) are not the source's.
void throwIfFailed(const std::string& path, const SourceOptions& options, const SourceLayer& about) {
  if (CPLGetLastErrorType() < CE_Failure) return;
  // Some drivers (GeoPackage) check a filter only when they read.
  if (!options.where.empty())
    throw InputError("where",
                     "\"" + options.where + "\" on layer \"" + about.layer + "\": " + lastError("GDAL failed"));
  throw InputError(path, "reading layer \"" + about.layer + "\": " + lastError("GDAL failed"));
}

// A feature as readOgrSource lists it.
nlohmann::json featureJson(const OGRFeature& f) {
  nlohmann::json props = nlohmann::json::object();
  for (int i = 0; i < f.GetFieldCount(); ++i)
    if (f.IsFieldSetAndNotNull(i)) props[f.GetFieldDefnRef(i)->GetNameRef()] = field(f, i);
  nlohmann::json feature = {{"type", "Feature"}};
  // GDAL keeps a GeoJSON feature's string "id" as a field of that name: it names the building.
  if (auto id = props.find("id"); id != props.end() && (id->is_string() || id->is_number_integer()))
    feature["id"] = *id;
  feature["properties"] = std::move(props);
  feature["geometry"] = geometry(f.GetGeometryRef());
  return feature;
}

}  // namespace

SourceLayer forEachOgrFeature(const std::string& path, const SourceOptions& options,
                              const std::function<void(nlohmann::json&)>& visit, std::vector<std::int64_t>* fids) {
  const QuietGdal quiet;
  OpenLayer open = openLayer(path, options);
  open.layer->ResetReading();
  CPLErrorReset();
  while (true) {
    const OGRFeatureUniquePtr f(open.layer->GetNextFeature());
    throwIfFailed(path, options, open.about);
    if (!f) break;
    if (fids) fids->push_back(f->GetFID());
    nlohmann::json feature = featureJson(*f);
    visit(feature);
    CPLErrorReset();
  }
  return open.about;
}

void forEachOgrFeatureById(const std::string& path, const SourceOptions& options, const std::vector<std::int64_t>& fids,
                           const std::function<void(nlohmann::json&)>& visit) {
  const QuietGdal quiet;
  OpenLayer open = openLayer(path, options);
  if (!open.about.randomRead)
    throw InputError(path, "layer \"" + open.about.layer + "\" cannot read a feature by its id");
  for (const std::int64_t fid : fids) {
    CPLErrorReset();
    const OGRFeatureUniquePtr f(open.layer->GetFeature(fid));
    if (!f || CPLGetLastErrorType() >= CE_Failure)
      throw InputError(path, "layer \"" + open.about.layer + "\" has no feature " + std::to_string(fid) + " (" +
                                 lastError("not found") + "): it changed while it was read");
    nlohmann::json feature = featureJson(*f);
    visit(feature);
  }
}

std::vector<std::string> vectorFileExtensions() {
  registerDrivers();
  std::vector<std::string> out = {".geojson", ".json"};
  GDALDriverManager* drivers = GetGDALDriverManager();
  for (int i = 0; i < drivers->GetDriverCount(); ++i) {
    GDALDriver* d = drivers->GetDriver(i);
    if (!d->GetMetadataItem(GDAL_DCAP_VECTOR)) continue;
    const char* list = d->GetMetadataItem(GDAL_DMD_EXTENSIONS);
    if (!list) list = d->GetMetadataItem(GDAL_DMD_EXTENSION);
    std::istringstream words(list ? list : "");
    for (std::string e; words >> e;) {
      std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
      if (!e.empty() && std::find(out.begin(), out.end(), "." + e) == out.end()) out.push_back("." + e);
    }
  }
  std::sort(out.begin() + 2, out.end());
  return out;
}

}  // namespace corbel::city
