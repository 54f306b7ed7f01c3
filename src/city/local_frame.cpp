#include "city/local_frame.h"

#include "core/error.h"

#include <cpl_error.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace corbel::city {

namespace {

std::string number(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

// A CRS from anything SetFromUserInput reads, with positions in GIS order (lon, lat; easting,
// northing) whatever the CRS's own axis order.
OGRSpatialReference spatialReference(const std::string& definition) {
  OGRSpatialReference srs;
  CPLPushErrorHandler(CPLQuietErrorHandler);  // the fault is ours to report
  const OGRErr read = definition.empty() ? OGRERR_FAILURE : srs.SetFromUserInput(definition.c_str());
  CPLPopErrorHandler();
  if (read != OGRERR_NONE)
    throw InputError("crs", "GDAL/PROJ cannot read the CRS \"" + definition.substr(0, 200) +
                                "\" (give an EPSG code such as EPSG:32632, a WKT or a PROJ string)");
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

OGRSpatialReference wgs84() {
  OGRSpatialReference srs;
  srs.importFromEPSG(4326);
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

struct TransformDeleter {
  void operator()(OGRCoordinateTransformation* t) const { OGRCoordinateTransformation::DestroyCT(t); }
};
using Transform = std::unique_ptr<OGRCoordinateTransformation, TransformDeleter>;

Transform makeTransform(const OGRSpatialReference& from, const OGRSpatialReference& to) {
  Transform t(OGRCreateCoordinateTransformation(&from, &to));
  if (!t) throw InputError("crs", "PROJ finds no transformation from the source's CRS to WGS 84");
  return t;
}

}  // namespace

std::string equirectangularDefinition(double lon0, double lat0, double radius) {
  return "+proj=eqc +lat_ts=" + number(lat0) + " +lat_0=" + number(lat0) + " +lon_0=" + number(lon0) +
         " +x_0=0 +y_0=0 +R=" + number(radius) + " +units=m +no_defs +type=crs";
}

std::string transverseMercatorDefinition(double lon0, double lat0) {
  return "+proj=tmerc +lat_0=" + number(lat0) + " +lon_0=" + number(lon0) +
         " +k=1 +x_0=0 +y_0=0 +datum=WGS84 +units=m +no_defs +type=crs";
}

std::string crsName(const std::string& definition) {
  OGRSpatialReference srs = spatialReference(definition);
  const char* node = srs.IsProjected() ? "PROJCS" : srs.IsGeographic() ? "GEOGCS" : nullptr;
  // A Shapefile's .prj names no authority: GDAL recognises the common ones (UTM, WGS 84).
  if (!srs.GetAuthorityName(node)) srs.AutoIdentifyEPSG();
  if (const char* authority = srs.GetAuthorityName(node))
    if (const char* code = srs.GetAuthorityCode(node)) return std::string(authority) + ":" + code;
  if (const char* name = srs.GetName(); name && *name && std::string(name) != "unknown") return name;
  return definition.substr(0, 200);
}

bool crsIsGeographic(const std::string& definition) { return spatialReference(definition).IsGeographic(); }

struct Reprojection::Impl {
  OGRSpatialReference source, local;
  Transform toLocal;
};

Reprojection::Reprojection(const std::string& sourceDefinition, const Vec2& centre) : impl_(std::make_unique<Impl>()) {
  impl_->source = spatialReference(sourceDefinition);
  const Vec2 ll = toLonLat(sourceDefinition, centre);
  lon0_ = ll[0];
  lat0_ = ll[1];
  definition_ = transverseMercatorDefinition(lon0_, lat0_);
  impl_->local = spatialReference(definition_);
  impl_->toLocal = makeTransform(impl_->source, impl_->local);
}

Reprojection::~Reprojection() = default;

bool Reprojection::transform(std::size_t n, double* x, double* y) const {
  // In pieces, since OGR counts in int.
  for (std::size_t from = 0; from < n; from += 1 << 20) {
    const int count = static_cast<int>(std::min<std::size_t>(n - from, 1 << 20));
    if (!impl_->toLocal->Transform(count, x + from, y + from, nullptr)) return false;
    for (int i = 0; i < count; ++i)
      if (!std::isfinite(x[from + i]) || !std::isfinite(y[from + i])) return false;
  }
  return true;
}

Vec2 toLonLat(const std::string& definition, const Vec2& p) {
  const OGRSpatialReference source = spatialReference(definition), geographic = wgs84();
  const Transform t = makeTransform(source, geographic);
  double x = p[0], y = p[1];
  if (!t->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y) || std::abs(y) > 90)
    throw InputError("crs", "the data's centre (" + number(p[0]) + ", " + number(p[1]) +
                                ") has no place on the Earth in the CRS " + crsName(definition));
  return {x, y};
}

double transverseMercatorScaleError(double east) {
  // k = 1 + (1 + C) A² / 2 + O(A⁴) with A = x / N and C = e'² cos² lat < 0.0068; N is at least
  // 6,335 km (the meridional radius at the equator), so 1.01 x² / (2 · 6.3e6²) bounds it for
  // any x up to a few hundred kilometres.
  const double r = 6.3e6;
  return 1.01 * east * east / (2 * r * r);
}

}  // namespace corbel::city
