#pragma once
// Footprints of a town from GeoJSON (Kelly & Wonka Sec. 3.7): buildings in a local metric frame,
// street centrelines, and a clean-up of each outline whose every change or refusal is reported.
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace corbel::city {

// How the file's coordinates were read.
enum class Coordinates { Auto, Geographic, Metric };

// The local frame: geographic input is projected by a local equirectangular projection about
// (lon0, lat0) on the sphere of radius R: x = R cos(lat0) (lon - lon0), y = R (lat - lat0), with
// angles in radians. `scaleError` bounds the relative error of an east-west length anywhere in
// the data against the sphere (|cos lat0 / cos lat - 1| over the data's latitudes); north-south
// lengths are exact on the sphere.
struct Frame {
  Coordinates coordinates = Coordinates::Metric;
  std::string how;  // why the coordinates were taken as they were, for the report
  double lon0 = 0, lat0 = 0, radius = 6371008.8;
  double scaleError = 0;
};

// Great-circle distance on the frame's sphere (haversine), metres; lon/lat in degrees.
double haversine(double lon1, double lat1, double lon2, double lat2, double radius = 6371008.8);
// lon/lat (degrees) to the frame's metres.
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

// Reads a FeatureCollection: Polygon and MultiPolygon features are buildings, LineString and
// MultiLineString features streets. Geographic coordinates are projected (see Frame); the file
// as a whole failing throws InputError naming the path, one bad feature is that building's
// problem. Every building is cleaned.
Town readTown(const std::string& text, Coordinates coordinates = Coordinates::Auto, const CleanupOptions& options = {});
Town readTownFile(const std::string& path, Coordinates coordinates = Coordinates::Auto,
                  const CleanupOptions& options = {});

}  // namespace corbel::city
