#pragma once
// Footprints of a town (Kelly & Wonka Sec. 3.7) from GeoJSON or any vector source GDAL/OGR
// reads: buildings in a local metric frame (city/local_frame.h), street centrelines, and a
// clean-up of each outline whose every change or refusal is reported.
#include "city/local_frame.h"
#include "city/ogr_source.h"
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace corbel::city {

// How the file's coordinates were read: lon/lat or another CRS reprojected (Geographic,
// Projected), or metres taken as they are (Metric: a local site, or corbel's own "frame").
enum class Coordinates { Auto, Geographic, Metric, Projected };

// The local frame of a town. Geographic and projected sources are reprojected by PROJ into a
// transverse Mercator on WGS 84 about the data's centre (lon0, lat0), scale 1 on its meridian;
// `scaleError` bounds the relative error of any length in the data against the ellipsoid (the
// projection's k - 1 at the point farthest east or west). A file in corbel's own "frame"
// (equirectangular about lon0/lat0 on the sphere of radius R, metres) is already local and is
// taken as it is, georeferenced by that projection; its scaleError is |cos lat0 / cos lat - 1|
// over the data's latitudes.
struct Frame {
  Coordinates coordinates = Coordinates::Metric;
  std::string how;  // why the coordinates were taken as they were, for the report
  std::string crs;  // the source's CRS ("EPSG:32632"); "" for metres about a local origin
  // The local frame's PROJ definition, which places (0, 0) on the Earth; "" when the data is not
  // georeferenced (local metres).
  std::string proj;
  double lon0 = 0, lat0 = 0, radius = kEarthRadius;
  double scaleError = 0;
};

// Great-circle distance on the frame's sphere (haversine), metres; lon/lat in degrees.
double haversine(double lon1, double lat1, double lon2, double lat2, double radius = kEarthRadius);
// lon/lat (degrees) to corbel's equirectangular frame's metres about (frame.lon0, frame.lat0).
Vec2 project(const Frame& frame, double lon, double lat);

struct Building {
  std::string id;
  std::vector<std::vector<Vec2>> loops;  // metres; outer counter-clockwise, holes clockwise
  nlohmann::json properties;
  std::vector<std::string> notes;  // what the reader and the clean-up changed, with why
  std::string problem;             // why it is not built ("" = usable)
  double area = 0;                 // outer minus holes, m², after clean-up
  // Twice the radius of the largest circle inside the cleaned outline (clear of its courtyards),
  // m, to 5 cm or half a percent of the outline's narrower extent: the span a roof climbs over
  // from eaves to ridge (a hipped roof of pitch a on a convex outline rises depth / 2 · tan a; a
  // rectangle's depth is its shorter side).
  double depth = 0;
};

struct Street {
  std::string id;
  std::vector<Vec2> points;  // a centreline, metres
};

struct Town {
  Frame frame;
  // Whom the data must be credited to, for the output (OpenStreetMap-derived footprints:
  // "© OpenStreetMap contributors, ODbL 1.0"); "" when the source says nothing.
  std::string attribution;
  std::vector<Building> buildings;
  std::vector<Street> streets;
};

// Thresholds of the clean-up, metres.
struct CleanupOptions {
  // A building wider than this (the largest distance between two of its corners) is refused
  // before any other work: no building is 5 km across, and a typo in a coordinate that makes one
  // 10^9 m wide would otherwise cost gigabytes of neighbour grid and window rows.
  double maxAcross = 5000.0;
  double duplicate = 0.001;   // consecutive corners closer than this are one
  // Corners are dropped where the outline stays within this of where it was: a Douglas-Peucker
  // simplification of each ring at this tolerance (every dropped corner lies within it of the
  // segment between the corners kept around it). The area changes by at most the ring's
  // perimeter times this, however dense the ring.
  double colinear = 0.01;
  double spikeDegrees = 3.0;  // a corner sharper than this (interior angle) is dropped
  double minArea = 4.0;       // a smaller building is refused (m²); a smaller courtyard dropped
  double minWidth = 1.0;      // a building whose mean width 2A/P is less is a sliver, refused
};

// The largest distance between two of the points (convex hull and rotating calipers), m.
double diameter(const std::vector<Vec2>& points);
// The corners of a closed ring that a Douglas-Peucker simplification at `tolerance` keeps, in
// order; every other corner lies within `tolerance` of the segment between the kept corners on
// either side of it. `worst` (when given) gets the largest such distance of a dropped corner.
std::vector<Vec2> simplifyRing(const std::vector<Vec2>& ring, double tolerance, double* worst = nullptr);
// Twice the distance from the boundary of the point of the loops (outer and holes, even-odd)
// farthest inside them, found to within `precision` m (the pole of inaccessibility, searched by
// halving square cells and dropping those that cannot beat the best point found).
double inscribedDepth(const std::vector<std::vector<Vec2>>& loops, double precision = 0.01);

// Cleans one building in place: fixes go to notes, a refusal to problem.
void cleanBuilding(Building& b, const CleanupOptions& options = {});

// How footprints are read.
struct ReadOptions {
  // The source's CRS, for a file that names none or names a wrong one: anything GDAL/PROJ reads
  // (EPSG:32632, a WKT, a PROJ string), or "local" for metres about a local origin.
  std::string crs;
  Coordinates coordinates = Coordinates::Auto;  // Geographic: as crs EPSG:4326; Metric: as "local"
  std::string layer;  // the layer of a source with several (GDAL/OGR)
  std::string where;  // an OGR SQL attribute filter, e.g. "building = 'house'"
  bool clean = true;  // false: outlines as read (oriented, exact repeats gone), not cleaned
  CleanupOptions cleanup;
};

// Reads a FeatureCollection: Polygon and MultiPolygon features are buildings, LineString and
// MultiLineString features streets. The CRS is, in order: options.crs; corbel's "frame" member;
// the GeoJSON "crs" member; lon/lat (RFC 7946) when every position is one and the data spans at
// most 5°; metres about a local origin when every position is within 100 km of (0, 0). Anything
// else is refused (InputError "crs": ... give it with --crs). The file as a whole failing throws
// InputError naming the path, one bad feature is that building's problem. Every building is
// cleaned unless asked not to be.
Town readTown(const std::string& text, const ReadOptions& options);
Town readTown(const std::string& text, Coordinates coordinates = Coordinates::Auto, const CleanupOptions& options = {});
// A GeoJSON file (.geojson, .json) as readTown, or any other vector source GDAL/OGR opens
// (Shapefile, GeoPackage, FlatGeobuf, ...), whose layer's CRS is honoured and which is refused
// when it names none and options.crs gives none. With a layer or a where-clause a GeoJSON file is
// read through OGR too.
Town readTownFile(const std::string& path, const ReadOptions& options);
Town readTownFile(const std::string& path, Coordinates coordinates = Coordinates::Auto,
                  const CleanupOptions& options = {});

// Reading a source in parts (city/town_stream.h) places every part as readTown places the whole:
// in one frame decided up front from the source's CRS and the bounds of all its positions.
struct PositionBounds {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  std::size_t count = 0;
};
struct Placement {
  Frame frame;  // scaleError as far as the bounds tell (a reprojected source's: see placePart)
  std::shared_ptr<const Reprojection> to;  // null: positions are taken as they are
};
// Adds a GeoJSON feature's positions to the bounds.
void addPositions(PositionBounds& bounds, nlohmann::json& feature);
// A LineString or MultiLineString feature: a street.
bool isLineFeature(const nlohmann::json& feature);
// Whom the data must be credited to, by the document's members other than "features" and one
// feature ("" when they say nothing).
std::string creditOf(const nlohmann::json& members, const nlohmann::json& feature);
// The placement of a source in `crs` whose positions span `bounds`.
Placement placementOf(const SourceCrs& crs, const PositionBounds& bounds);
// The placement of a GeoJSON document with these members (all but "features"), as readTown
// decides it (options.crs first, then "frame", "crs", then the positions).
Placement geoJsonPlacement(const nlohmann::json& members, const PositionBounds& bounds, const ReadOptions& options);
// The placement of a layer read through GDAL/OGR (city/ogr_source.h) whose positions span
// `bounds`, as readTownFile decides it; `members` are a GeoJSON document's members but
// "features" (its "frame" and "crs"), else none.
Placement layerPlacement(const SourceLayer& layer, const nlohmann::json& members, const PositionBounds& bounds,
                         const ReadOptions& options);
// Whether readTownFile reads `path` itself as GeoJSON text (a .geojson or .json file, without a
// layer or a where-clause) rather than through GDAL/OGR.
bool readsGeoJsonText(const std::string& path, const ReadOptions& options);
// The streets and buildings of a FeatureCollection in source coordinates, placed (and cleaned
// unless asked not to be) as readTown does; `east` gets the largest |x| of a reprojected
// position (the scale error's argument).
Town placePart(nlohmann::json& collection, const Placement& placement, const ReadOptions& options, double* east = nullptr);

}  // namespace corbel::city
