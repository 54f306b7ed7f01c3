#pragma once
// Footprints from any vector source GDAL/OGR reads (GeoJSON, Shapefile, GeoPackage, FlatGeobuf,
// ...): one layer's features, optionally filtered by an OGR SQL where-clause, as a GeoJSON
// FeatureCollection in the source's own coordinates, with the layer's CRS.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace corbel::city {

struct SourceOptions {
  std::string layer;  // "" = the only layer (a source with several must be told which)
  std::string where;  // OGR SQL attribute filter ("" = every feature), e.g. "height > 3"
};

// What a source's layer is.
struct SourceLayer {
  std::string crs;          // the layer's CRS as WKT; "" when it names none
  std::string driver;       // GDAL's short name of the format ("GPKG", "ESRI Shapefile", ...)
  std::string layer;        // the layer read
  bool randomRead = false;  // the layer reads a feature by its id (OGR's OLCRandomRead)
};

struct SourceFeatures : SourceLayer {
  nlohmann::json collection;  // {"type": "FeatureCollection", "features": [...]}
};

// Reads `path` (a file, a folder or any dataset name GDAL opens). Polygons, multipolygons and
// lines become GeoJSON geometries with every coordinate kept in double; fields become properties
// (numbers as numbers); a feature without geometry is kept with a null one (the reader reports
// it). Throws InputError naming the path, the layer or "where" when GDAL cannot open the source,
// the layer is not there or ambiguous, or the filter is not valid OGR SQL.
SourceFeatures readOgrSource(const std::string& path, const SourceOptions& options = {});

// The same features one at a time: `visit` gets each as readOgrSource would list it, in the
// layer's order, and may keep or drop it; only the feature being visited is held (GDAL's drivers
// read Shapefile, GeoPackage and FlatGeobuf a feature at a time). With `fids`, each feature's id
// (GDAL's FID) is appended to it. Throws as readOgrSource does, and passes on what `visit` throws.
SourceLayer forEachOgrFeature(const std::string& path, const SourceOptions& options,
                              const std::function<void(nlohmann::json&)>& visit,
                              std::vector<std::int64_t>* fids = nullptr);

// The features with these ids (as forEachOgrFeature gave them), in this order, each fetched by
// its id: a part of a streamed town costs its own features, not a pass over the layer. Needs a
// layer with random reads (SourceLayer::randomRead; Shapefile, GeoPackage, FlatGeobuf and GeoJSON
// have them); throws InputError for one without, or when an id is no longer there.
void forEachOgrFeatureById(const std::string& path, const SourceOptions& options, const std::vector<std::int64_t>& fids,
                           const std::function<void(nlohmann::json&)>& visit);

// The file extensions of every vector format this GDAL reads (".geojson", ".shp", ".gpkg",
// ".fgb", ...), as its drivers declare them, GeoJSON's first: what a footprint dialog offers.
std::vector<std::string> vectorFileExtensions();

}  // namespace corbel::city
