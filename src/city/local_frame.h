#pragma once
// The local metric frame a town is built in, and the source coordinate reference system (CRS)
// its footprints come in: positions are reprojected by PROJ (through GDAL/OGR's
// OGRCoordinateTransformation) into a transverse Mercator about the data's centre, in double
// precision, so every coordinate is a few hundred metres at most before anything becomes float.
#include "core/geometry.h"

#include <memory>
#include <string>

namespace corbel::city {

// The mean Earth radius, m (the sphere corbel's own "frame" member is on).
inline constexpr double kEarthRadius = 6371008.8;

// How a source's positions become the local frame's.
struct SourceCrs {
  enum class Kind {
    Local,       // metres about a local origin, taken as they are; no georeference
    Frame,       // metres in a frame that is already local about its origin (corbel's "frame"
                 // member): taken as they are, georeferenced by `definition`
    Reproject,   // any CRS PROJ knows (`definition`): reprojected to a transverse Mercator
  };
  Kind kind = Kind::Local;
  std::string definition;  // what OGRSpatialReference::SetFromUserInput reads (EPSG:n, WKT, PROJ)
  std::string how;         // why, for the report
};

// The PROJ definition of corbel's equirectangular "frame": x = R cos(lat0) (lon - lon0),
// y = R (lat - lat0) on the sphere of radius R.
std::string equirectangularDefinition(double lon0, double lat0, double radius = kEarthRadius);
// A transverse Mercator on WGS 84 whose origin (0, 0) is (lon0, lat0), scale 1 on its meridian.
std::string transverseMercatorDefinition(double lon0, double lat0);

// A short name of a CRS ("EPSG:32632", else its name); throws InputError("crs", ...) when
// GDAL/PROJ cannot read it.
std::string crsName(const std::string& definition);
// Whether the CRS is geographic (lon/lat).
bool crsIsGeographic(const std::string& definition);

// A transformation of source positions (x, y in the source's axis order as GIS data stores
// them: lon before lat, easting before northing) into a transverse Mercator about a centre.
class Reprojection {
 public:
  // `centre` in source coordinates; throws InputError("crs", ...) when the CRS is unknown or the
  // centre has no place on the Earth.
  Reprojection(const std::string& sourceDefinition, const Vec2& centre);
  ~Reprojection();
  Reprojection(const Reprojection&) = delete;
  Reprojection& operator=(const Reprojection&) = delete;
  // Transforms n positions in place; returns false when one cannot be transformed.
  bool transform(std::size_t n, double* x, double* y) const;
  double lon0() const { return lon0_; }
  double lat0() const { return lat0_; }
  const std::string& definition() const { return definition_; }  // the local frame's PROJ string

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double lon0_ = 0, lat0_ = 0;
  std::string definition_;
};

// Geographic (WGS 84 lon/lat, degrees) of a point of a CRS; throws InputError("crs", ...).
Vec2 toLonLat(const std::string& definition, const Vec2& p);

// The largest relative error of a length in a transverse Mercator of scale 1 on its central
// meridian for points at most `east` m east or west of it: k - 1 = x² / (2 R²) to second order,
// bounded here with a margin for the higher terms.
double transverseMercatorScaleError(double east);

}  // namespace corbel::city
