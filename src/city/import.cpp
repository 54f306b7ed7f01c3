#include "city/import.h"

#include "city/ogr_source.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "extrude/footprints.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <numbers>
#include <queue>

namespace corbel::city {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Shoelace formula, positive for counter-clockwise rings.
double signedArea(const std::vector<Vec2>& ring) {
  double twice = 0;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    twice += (ring[j][0] - ring[i][0]) * (ring[j][1] + ring[i][1]);
  return twice / 2;
}

double perimeter(const std::vector<Vec2>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) s += (p[(i + 1) % p.size()] - p[i]).norm();
  return s;
}

// Calls f on every [x, y, ...] position under a GeoJSON coordinates value.
void forEachPosition(nlohmann::json& c, const std::function<void(nlohmann::json&)>& f) {
  if (!c.is_array()) return;
  if (c.size() >= 2 && c[0].is_number() && c[1].is_number()) {
    f(c);
    return;
  }
  for (auto& e : c) forEachPosition(e, f);
}

std::string describe(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Two decimals.
std::string decimals(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// Whole metres up to 10,000 km, else three significant digits.
std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v < 1e7 ? "%.0f" : "%.3g", v);
  return buf;
}

// Drops corners of one ring as `drop(prev, p, next)` says, until none is dropped; returns how many.
std::size_t dropCorners(std::vector<Vec2>& ring,
                        const std::function<bool(const Vec2&, const Vec2&, const Vec2&)>& drop) {
  std::size_t removed = 0;
  for (bool changed = true; changed && ring.size() > 3;) {
    changed = false;
    for (std::size_t i = 0; i < ring.size() && ring.size() > 3;) {
      const Vec2& a = ring[(i + ring.size() - 1) % ring.size()];
      const Vec2& b = ring[(i + 1) % ring.size()];
      if (drop(a, ring[i], b)) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        ++removed;
        changed = true;
      } else {
        ++i;
      }
    }
  }
  return removed;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Distance from p to the segment ab (to a when the segment has no length).
double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.sqrnorm();
  if (len2 == 0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
  return (p - (a + d * t)).norm();
}

// Signed distance from p to the loops' boundary: positive inside (even-odd over all loops).
double signedBoundaryDistance(const Vec2& p, const std::vector<std::vector<Vec2>>& loops) {
  bool inside = false;
  double best = INFINITY;
  for (const auto& ring : loops)
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Vec2 &a = ring[i], &b = ring[j];
      if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0])
        inside = !inside;
      best = std::min(best, segmentDistance(p, a, b));
    }
  return inside ? best : -best;
}

}  // namespace

double haversine(double lon1, double lat1, double lon2, double lat2, double radius) {
  const double p1 = lat1 * kDeg, p2 = lat2 * kDeg;
  const double dp = p2 - p1, dl = (lon2 - lon1) * kDeg;
  const double h =
      std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2 * radius * std::asin(std::min(1.0, std::sqrt(h)));
}

Vec2 project(const Frame& f, double lon, double lat) {
  return {f.radius * std::cos(f.lat0 * kDeg) * (lon - f.lon0) * kDeg, f.radius * (lat - f.lat0) * kDeg};
}

double diameter(const std::vector<Vec2>& points) {
  std::vector<Vec2> p(points);
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p.size() == 2 ? (p[1] - p[0]).norm() : 0.0;
  // Andrew's monotone chain: the hull counter-clockwise, without colinear points.
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  const std::size_t h = hull.size();
  if (h < 3) return (hull.back() - hull.front()).norm();
  // Rotating calipers: for each hull edge the vertex farthest from its line, found by walking on.
  double best = 0;
  for (std::size_t i = 0, j = 1; i < h; ++i) {
    const Vec2 &a = hull[i], &b = hull[(i + 1) % h];
    while (cross(a, b, hull[(j + 1) % h]) > cross(a, b, hull[j])) j = (j + 1) % h;
    best = std::max({best, (hull[j] - a).norm(), (hull[j] - b).norm()});
  }
  return best;
}

std::vector<Vec2> simplifyRing(const std::vector<Vec2>& ring, double tolerance, double* worst) {
  const std::size_t n = ring.size();
  if (worst) *worst = 0;
  if (n <= 3) return ring;
  // Two corners that any simplification keeps: the lowest-leftmost (a vertex of the convex hull)
  // and the corner farthest from it. Each of the two chains between them is split at its corner
  // farthest from the chord until every corner lies within the tolerance of its chord.
  std::size_t a = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (ring[i][0] < ring[a][0] || (ring[i][0] == ring[a][0] && ring[i][1] < ring[a][1])) a = i;
  std::size_t b = a;
  for (std::size_t i = 0; i < n; ++i)
    if ((ring[i] - ring[a]).sqrnorm() > (ring[b] - ring[a]).sqrnorm()) b = i;
  if (b == a) return {ring[a]};
  std::vector<char> keep(n, 0);
  keep[a] = keep[b] = 1;
  double far = 0;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{a, b}, {b, a}};  // chains from first to second, forward
  while (!todo.empty()) {
    const auto [from, to] = todo.back();
    todo.pop_back();
    std::size_t split = n;
    double most = -1;
    for (std::size_t k = (from + 1) % n; k != to; k = (k + 1) % n)
      if (const double d = segmentDistance(ring[k], ring[from], ring[to]); d > most) {
        most = d;
        split = k;
      }
    if (split == n) continue;  // neighbours
    if (most > tolerance) {
      keep[split] = 1;
      todo.push_back({from, split});
      todo.push_back({split, to});
    } else {
      far = std::max(far, most);
    }
  }
  // The two starting corners go too where the outline stays within the tolerance without them.
  std::size_t kept = 0;
  for (char c : keep) kept += c;
  for (const std::size_t s : {a, b}) {
    if (kept <= 3) break;
    std::size_t prev = (s + n - 1) % n, next = (s + 1) % n;
    while (!keep[prev]) prev = (prev + n - 1) % n;
    while (!keep[next]) next = (next + 1) % n;
    double most = 0;
    for (std::size_t k = (prev + 1) % n; k != next; k = (k + 1) % n)
      most = std::max(most, segmentDistance(ring[k], ring[prev], ring[next]));
    if (most <= tolerance) {
      keep[s] = 0;
      --kept;
      far = std::max(far, most);
    }
  }
  std::vector<Vec2> out;
  out.reserve(kept);
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) out.push_back(ring[i]);
  if (worst) *worst = far;
  return out;
}

double inscribedDepth(const std::vector<std::vector<Vec2>>& loops, double precision) {
  if (loops.empty() || loops[0].size() < 3) return 0;
  Vec2 lo = loops[0][0], hi = loops[0][0];
  for (const Vec2& p : loops[0]) {
    lo = lo.min(p);
    hi = hi.max(p);
  }
  const double size = std::min(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(size > 0)) return 0;
  struct Cell {
    Vec2 c;
    double half, d, bound;  // half its side; the distance at its centre; the most any point in it can have
  };
  auto cell = [&](const Vec2& c, double half) {
    const double d = signedBoundaryDistance(c, loops);
    return Cell{c, half, d, d + half * std::numbers::sqrt2};
  };
  auto lower = [](const Cell& x, const Cell& y) { return x.bound < y.bound; };
  std::priority_queue<Cell, std::vector<Cell>, decltype(lower)> cells(lower);
  for (double x = lo[0]; x < hi[0]; x += size)
    for (double y = lo[1]; y < hi[1]; y += size) cells.push(cell(Vec2(x + size / 2, y + size / 2), size / 2));
  Cell best = cell((lo + hi) / 2, 0);
  while (!cells.empty()) {
    const Cell c = cells.top();
    cells.pop();
    if (c.d > best.d) best = c;
    if (c.bound - best.d <= precision) continue;
    const double h = c.half / 2;
    for (const Vec2 off : {Vec2(-h, -h), Vec2(h, -h), Vec2(-h, h), Vec2(h, h)}) cells.push(cell(c.c + off, h));
  }
  return 2 * std::max(best.d, 0.0);
}

void cleanBuilding(Building& b, const CleanupOptions& o) {
  if (!b.problem.empty()) return;
  // Its size first, before any work that grows with it (the neighbour grid of the labels, rows
  // of windows and dormers).
  if (!b.loops.empty())
    if (const double across = diameter(b.loops[0]); !(across <= o.maxAcross)) {
      b.problem = "too large: " + metres(across) + " m across (the farthest two corners), over the " +
                  metres(o.maxAcross) + " m a building may span";
      return;
    }
  std::vector<std::vector<Vec2>> kept;
  for (std::size_t li = 0; li < b.loops.size(); ++li) {
    auto& ring = b.loops[li];
    const std::string where = "loops[" + std::to_string(li) + "]: ";
    // Near-duplicate consecutive corners (the reader already removed exact repeats).
    std::vector<Vec2> merged;
    for (const Vec2& p : ring)
      if (merged.empty() || (merged.back() - p).norm() >= o.duplicate) merged.push_back(p);
    while (merged.size() > 1 && (merged.front() - merged.back()).norm() < o.duplicate) merged.pop_back();
    if (merged.size() != ring.size())
      b.notes.push_back(where + std::to_string(ring.size() - merged.size()) + " duplicate corner(s) within " +
                        describe(o.duplicate) + " m merged");
    ring = std::move(merged);
    // Spikes: a corner where the outline turns back on itself.
    const double spikeCos = std::cos(o.spikeDegrees * kDeg);
    const std::size_t spikes = dropCorners(ring, [&](const Vec2& a, const Vec2& p, const Vec2& c) {
      const Vec2 u = a - p, v = c - p;
      const double nu = u.norm(), nv = v.norm();
      return nu > 0 && nv > 0 && u.dot(v) / (nu * nv) > spikeCos;
    });
    if (spikes)
      b.notes.push_back(where + std::to_string(spikes) + " spike corner(s) sharper than " + describe(o.spikeDegrees) +
                        "° removed");
    // Corners the outline does without: Douglas-Peucker within `colinear`, which never chains
    // (each dropped corner is measured against the corners kept around it, not against a
    // neighbour that was itself dropped), so a dense ring keeps its shape.
    if (ring.size() > 3) {
      double off = 0;
      std::vector<Vec2> simple = simplifyRing(ring, o.colinear, &off);
      if (simple.size() != ring.size()) {
        const double before = std::abs(signedArea(ring)), after = std::abs(signedArea(simple));
        b.notes.push_back(where + std::to_string(ring.size() - simple.size()) + " corner(s) within " +
                          describe(o.colinear) + " m of the outline through the corners kept removed (the farthest " +
                          describe(off) + " m off; area " + decimals(before) + " -> " + decimals(after) + " m²)");
        ring = std::move(simple);
      }
    }
    const double area = std::abs(signedArea(ring));
    if (ring.size() < 3 || area == 0) {
      if (li == 0) {
        b.problem = where + "fewer than three corners are left after clean-up";
        return;
      }
      b.notes.push_back(where + "courtyard dropped: nothing is left of it after clean-up");
      continue;
    }
    if (li > 0 && area < o.minArea) {
      b.notes.push_back(where + "courtyard dropped: " + describe(area) + " m² is under " + describe(o.minArea) + " m²");
      continue;
    }
    kept.push_back(std::move(ring));
  }
  b.loops = std::move(kept);
  double area = 0, per = 0;
  for (const auto& r : b.loops) {
    area += signedArea(r);
    per += perimeter(r);
  }
  b.area = area;
  if (area < o.minArea) {
    b.problem = "tiny building: " + describe(area) + " m² is under " + describe(o.minArea) + " m²";
    return;
  }
  if (const double width = 2 * area / per; width < o.minWidth) {
    b.problem = "sliver: about " + describe(width) + " m wide on average (2 area / perimeter), under " +
                describe(o.minWidth) + " m";
    return;
  }
  // Depth to 5 cm or half a percent of the outline's narrower extent, whichever is more: size
  // rules need no finer, and the search's cost grows as the ridge's length over the precision.
  Vec2 lo = b.loops[0][0], hi = b.loops[0][0];
  for (const Vec2& p : b.loops[0]) {
    lo = lo.min(p);
    hi = hi.max(p);
  }
  b.depth = inscribedDepth(b.loops, std::max(0.05, 0.005 * std::min(hi[0] - lo[0], hi[1] - lo[1])));
}

namespace {

// Every position of the features' geometries.
struct Positions : PositionBounds {
  std::vector<nlohmann::json*> at;
};

Positions positionsOf(nlohmann::json& features) {
  Positions p;
  for (auto& f : features) {
    if (!f.is_object() || !f.contains("geometry") || !f["geometry"].is_object()) continue;
    auto& g = f["geometry"];
    if (!g.contains("coordinates")) continue;
    forEachPosition(g["coordinates"], [&](nlohmann::json& q) {
      if (!q[0].is_number() || !q[1].is_number()) return;
      for (int k = 0; k < 2; ++k) {
        const double v = q[k].get<double>();
        p.lo[k] = std::min(p.lo[k], v);
        p.hi[k] = std::max(p.hi[k], v);
      }
      p.at.push_back(&q);
    });
  }
  p.count = p.at.size();
  return p;
}

std::string range(const PositionBounds& p) {
  return "x from " + describe(p.lo[0]) + " to " + describe(p.hi[0]) + ", y from " + describe(p.lo[1]) + " to " +
         describe(p.hi[1]);
}

const char* const kCrsHelp =
    "give it with --crs (in a project, the town's \"crs\"): an EPSG code such as EPSG:32632 (UTM zone 32N) or "
    "EPSG:3857 (web Mercator), a WKT or a PROJ string; or --crs local for metres about a local origin";

// The CRS the user gave, if any.
std::optional<SourceCrs> givenCrs(const ReadOptions& o) {
  if (o.crs == "local" || (o.crs.empty() && o.coordinates == Coordinates::Metric))
    return SourceCrs{SourceCrs::Kind::Local, "", o.crs.empty() ? "metres, as asked" : "metres about a local origin (--crs local)"};
  if (o.crs.empty() && o.coordinates == Coordinates::Geographic)
    return SourceCrs{SourceCrs::Kind::Reproject, "EPSG:4326", "lon/lat, as asked"};
  if (!o.crs.empty()) return SourceCrs{SourceCrs::Kind::Reproject, o.crs, crsName(o.crs) + ", as asked"};
  return std::nullopt;
}

// The CRS of a GeoJSON document whose CRS was not given.
SourceCrs geoJsonCrs(const nlohmann::json& root, const PositionBounds& p) {
  // A "crs" member first: ogr2ogr copies corbel's "frame" member into the files it writes, in
  // whatever CRS it writes them.
  if (const auto crs = root.find("crs"); crs != root.end() && crs->is_object()) {
    const auto props = crs->find("properties");
    if (props != crs->end() && props->is_object() && props->contains("name") && (*props)["name"].is_string()) {
      const std::string name = (*props)["name"].get<std::string>();
      return {SourceCrs::Kind::Reproject, name, "the file's \"crs\" member: " + crsName(name)};
    }
    throw InputError("crs", "the \"crs\" member names no CRS (expected {\"type\": \"name\", \"properties\": {\"name\": ...}}); " +
                                std::string(kCrsHelp));
  }
  if (const auto fm = root.find("frame"); fm != root.end() && fm->is_object() && fm->value("units", std::string()) == "m") {
    const std::string projection = fm->value("projection", std::string());
    const auto lon0 = fm->find("lon0"), lat0 = fm->find("lat0");
    if (projection == "equirectangular" && lon0 != fm->end() && lat0 != fm->end() && lon0->is_number() &&
        lat0->is_number()) {
      const double r = fm->contains("R_m") && (*fm)["R_m"].is_number() ? (*fm)["R_m"].get<double>() : kEarthRadius;
      const double x0 = lon0->get<double>(), y0 = lat0->get<double>();
      // Metres about the origin lie around (0, 0); positions all within 1° of (lon0, lat0) are
      // lon/lat written under a copied member (by ogr2ogr, without a "crs" member for WGS 84).
      if (p.count && std::abs(x0) + std::abs(y0) > 2 && p.lo[0] >= x0 - 1 && p.hi[0] <= x0 + 1 &&
          p.lo[1] >= y0 - 1 && p.hi[1] <= y0 + 1)
        return {SourceCrs::Kind::Reproject, "EPSG:4326",
                "the file's \"frame\" member says metres about lon0/lat0, but every position lies within 1° of "
                "(lon0, lat0): taken as RFC 7946 lon/lat"};
      return {SourceCrs::Kind::Frame, equirectangularDefinition(lon0->get<double>(), lat0->get<double>(), r),
              "the file's \"frame\" member: metres, equirectangular about lon0/lat0"};
    }
    return {SourceCrs::Kind::Local, "",
            "the file's \"frame\" member gives metres (" + (projection.empty() ? std::string("a projection") : projection) +
                "), not placed on the Earth"};
  }
  if (!p.count) return {SourceCrs::Kind::Local, "", "no positions"};
  if (p.lo[0] >= -180 && p.hi[0] <= 180 && p.lo[1] >= -90 && p.hi[1] <= 90 && p.hi[0] - p.lo[0] <= 5 &&
      p.hi[1] - p.lo[1] <= 5)
    return {SourceCrs::Kind::Reproject, "EPSG:4326",
            "all " + std::to_string(p.count) + " positions are valid lon/lat and span " + describe(p.hi[0] - p.lo[0]) +
                "° × " + describe(p.hi[1] - p.lo[1]) + "°: taken as RFC 7946 lon/lat"};
  const double reach = 100000;
  if (p.lo[0] >= -reach && p.hi[0] <= reach && p.lo[1] >= -reach && p.hi[1] <= reach)
    return {SourceCrs::Kind::Local, "",
            "no CRS named and every position within 100 km of (0, 0) (" + range(p) + "): taken as metres about a local origin"};
  throw InputError("crs", "the file names no CRS and its coordinates (" + range(p) +
                              ") are neither lon/lat nor metres about a local origin; " + kCrsHelp);
}

// The CRS of a layer read through GDAL/OGR whose document has these members (a GeoJSON file's
// own, else none): the one given, a GeoJSON file's as when it is read directly (GDAL takes one
// without a "crs" member as lon/lat), else the layer's; refused when it names none.
SourceCrs layerCrs(const SourceLayer& layer, const nlohmann::json& members, const PositionBounds& p,
                   const ReadOptions& options) {
  if (const std::optional<SourceCrs> given = givenCrs(options)) return *given;
  if (layer.driver == "GeoJSON") return geoJsonCrs(members, p);
  if (layer.crs.empty())
    throw InputError("crs", "layer \"" + layer.layer + "\" (" + layer.driver + ") names no CRS; " + kCrsHelp);
  return SourceCrs{SourceCrs::Kind::Reproject, layer.crs, "the layer's CRS: " + crsName(layer.crs)};
}

// Who to credit: OpenStreetMap data must carry its ODbL attribution.
std::string attributionOf(const nlohmann::json& root, const nlohmann::json& features) {
  const std::string osm = "© OpenStreetMap contributors, ODbL 1.0 (https://www.openstreetmap.org/copyright)";
  if (const auto s = root.find("source"); s != root.end() && s->is_object())
    for (const char* key : {"license", "attribution"})
      if (s->contains(key) && (*s)[key].is_string()) {
        const std::string v = (*s)[key].get<std::string>();
        if (v.find("ODbL") != std::string::npos || v.find("OpenStreetMap") != std::string::npos) return osm;
      }
  for (const auto& f : features) {
    if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object()) continue;
    const auto& props = f["properties"];
    for (const char* key : {"osm_id", "osm_way_id", "@id"})
      if (props.contains(key)) return osm;
    for (const char* key : {"source_id", "id"})
      if (props.contains(key) && props[key].is_string() && props[key].get<std::string>().starts_with("osm:")) return osm;
  }
  return "";
}

// The streets and buildings of a collection in source coordinates, placed as `placement` says.
// `text`, when given, is the document as it was (read again where nothing moved); `east` gets
// the largest |x| of a moved position.
Town placeFeatures(nlohmann::json& root, const Placement& placement, const ReadOptions& options, const std::string* text,
                   double* east) {
  Town town;
  town.frame = placement.frame;
  nlohmann::json& features = root["features"];
  bool moved = false;
  if (placement.to) {
    Positions positions = positionsOf(features);
    const std::size_t n = positions.at.size();
    if (n) {
      std::vector<double> x(n), y(n);
      for (std::size_t i = 0; i < n; ++i) {
        x[i] = (*positions.at[i])[0].get<double>();
        y[i] = (*positions.at[i])[1].get<double>();
      }
      if (!placement.to->transform(n, x.data(), y.data()))
        throw InputError("crs", "PROJ cannot transform every position from " + placement.frame.crs + " (" +
                                    range(positions) + ") to the local frame; is the CRS right? " + kCrsHelp);
      for (std::size_t i = 0; i < n; ++i) {
        (*positions.at[i])[0] = x[i];
        (*positions.at[i])[1] = y[i];
        if (east) *east = std::max(*east, std::abs(x[i]));
      }
      moved = true;
    }
  }

  // Streets.
  std::vector<std::size_t> lineFeatures;
  for (std::size_t i = 0; i < features.size(); ++i)
    if (isLineFeature(features[i])) lineFeatures.push_back(i);
  for (std::size_t i : lineFeatures) {
    const auto& g = features[i]["geometry"];
    const std::string path = "features[" + std::to_string(i) + "].geometry.coordinates";
    const std::string id = features[i].contains("id") ? features[i]["id"].dump() : "street " + std::to_string(i);
    auto line = [&](const nlohmann::json& pts, const std::string& where) {
      Street s{id, {}};
      for (std::size_t k = 0; k < pts.size(); ++k)
        s.points.push_back(JsonReader(pts[k], where + "[" + std::to_string(k) + "]").vec2());
      if (s.points.size() >= 2) town.streets.push_back(std::move(s));
    };
    JsonReader c(g.at("coordinates"), path);
    if (g["type"] == "LineString")
      line(g["coordinates"], path);
    else
      for (const JsonReader& part : c.array(100000)) line(part.raw(), part.path());
  }

  // Buildings, through the extrusion kernel's reader (streets left out so they are not refused).
  std::vector<extrude::Footprint> fps;
  if (moved || !lineFeatures.empty() || !text) {
    for (auto it = lineFeatures.rbegin(); it != lineFeatures.rend(); ++it) features.erase(*it);
    fps = extrude::readGeoJson(root.dump());
  } else {
    fps = extrude::readGeoJson(*text);
  }
  town.buildings.reserve(fps.size());
  for (auto& fp : fps) {
    Building b;
    b.id = std::move(fp.id);
    b.loops = std::move(fp.loops);
    b.properties = std::move(fp.properties);
    b.notes = std::move(fp.notes);
    b.problem = std::move(fp.problem);
    if (options.clean) cleanBuilding(b, options.cleanup);
    town.buildings.push_back(std::move(b));
  }
  return town;
}

// Places a FeatureCollection in source coordinates into the local frame and reads its streets
// and buildings. `text`, when given, is the document as it was (read again where nothing moved).
Town placeTown(nlohmann::json& root, const std::function<SourceCrs(const PositionBounds&)>& crsOf,
               const ReadOptions& options, const std::string* text) {
  nlohmann::json& features = root["features"];
  const std::string attribution = attributionOf(root, features);
  const Positions positions = positionsOf(features);
  const Placement placement = placementOf(crsOf(positions), positions);
  double east = 0;
  Town town = placeFeatures(root, placement, options, text, &east);
  town.attribution = attribution;
  if (placement.to) town.frame.scaleError = transverseMercatorScaleError(east);
  return town;
}

void checkCollection(const nlohmann::json& root) {
  JsonReader r(root, "");
  r.expectObject();
  const std::string type = r.at("type").string(64);
  if (type != "FeatureCollection") r.at("type").fail("expected \"FeatureCollection\", found \"" + type + "\"");
  r.at("features").array(10000000);  // checks it is an array within the limit
}

bool isGeoJsonName(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".geojson" || ext == ".json";
}

}  // namespace

Town readTown(const std::string& text, const ReadOptions& options) {
  nlohmann::json root = parseJsonText(text);
  checkCollection(root);
  const std::optional<SourceCrs> given = givenCrs(options);
  return placeTown(
      root, [&](const PositionBounds& p) { return given ? *given : geoJsonCrs(root, p); }, options, &text);
}

Town readTown(const std::string& text, Coordinates coordinates, const CleanupOptions& cleanup) {
  ReadOptions options;
  options.coordinates = coordinates;
  options.cleanup = cleanup;
  return readTown(text, options);
}

Town readTownFile(const std::string& path, const ReadOptions& options) {
  try {
    if (readsGeoJsonText(path, options))
      return readTown(readFile(path, std::size_t(1) << 31), options);
    SourceFeatures source = readOgrSource(path, {options.layer, options.where});
    if (source.driver == "GeoJSON") {
      // GDAL takes a GeoJSON without a "crs" member as lon/lat: the document's own members
      // ("frame", "crs", "source") say what it is, as when it is read directly.
      nlohmann::json root = parseJsonText(readFile(path, std::size_t(1) << 31));
      checkCollection(root);
      for (auto it = root.begin(); it != root.end(); ++it)
        if (it.key() != "features" && it.key() != "type") source.collection[it.key()] = it.value();
    }
    return placeTown(
        source.collection, [&](const PositionBounds& p) { return layerCrs(source, source.collection, p, options); },
        options, nullptr);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

Town readTownFile(const std::string& path, Coordinates coordinates, const CleanupOptions& cleanup) {
  ReadOptions options;
  options.coordinates = coordinates;
  options.cleanup = cleanup;
  return readTownFile(path, options);
}

bool isLineFeature(const nlohmann::json& f) {
  if (!f.is_object() || !f.contains("geometry") || !f["geometry"].is_object()) return false;
  const auto& g = f["geometry"];
  if (!g.contains("type") || !g["type"].is_string()) return false;
  const std::string gt = g["type"].get<std::string>();
  return gt == "LineString" || gt == "MultiLineString";
}

void addPositions(PositionBounds& bounds, nlohmann::json& feature) {
  nlohmann::json features = nlohmann::json::array();
  features.push_back(std::move(feature));
  const Positions p = positionsOf(features);
  for (int k = 0; k < 2; ++k) {
    bounds.lo[k] = std::min(bounds.lo[k], p.lo[k]);
    bounds.hi[k] = std::max(bounds.hi[k], p.hi[k]);
  }
  bounds.count += p.count;
  feature = std::move(features[0]);
}

std::string creditOf(const nlohmann::json& members, const nlohmann::json& feature) {
  nlohmann::json features = nlohmann::json::array();
  if (feature.is_object()) features.push_back(feature);
  return attributionOf(members, features);
}

Placement placementOf(const SourceCrs& crs, const PositionBounds& bounds) {
  Placement placement;
  Frame& frame = placement.frame;
  frame.how = crs.how;
  frame.coordinates = Coordinates::Metric;
  if (crs.kind == SourceCrs::Kind::Frame) {
    frame.crs = crsName(crs.definition);
    frame.proj = crs.definition;
    const Vec2 origin = toLonLat(crs.definition, Vec2(0, 0));
    frame.lon0 = origin[0];
    frame.lat0 = origin[1];
    if (bounds.count)
      for (double y : {bounds.lo[1], bounds.hi[1]}) {
        const double lat = frame.lat0 + y / frame.radius / kDeg;
        frame.scaleError =
            std::max(frame.scaleError, std::abs(std::cos(frame.lat0 * kDeg) / std::cos(lat * kDeg) - 1));
      }
  } else if (crs.kind == SourceCrs::Kind::Reproject && bounds.count) {
    const bool geographic = crsIsGeographic(crs.definition);
    frame.coordinates = geographic ? Coordinates::Geographic : Coordinates::Projected;
    frame.crs = crsName(crs.definition);
    const Vec2 centre((bounds.lo[0] + bounds.hi[0]) / 2, (bounds.lo[1] + bounds.hi[1]) / 2);
    auto to = std::make_shared<const Reprojection>(crs.definition, centre);
    frame.lon0 = to->lon0();
    frame.lat0 = to->lat0();
    frame.proj = to->definition();
    placement.to = std::move(to);
  }
  return placement;
}

Placement geoJsonPlacement(const nlohmann::json& members, const PositionBounds& bounds, const ReadOptions& options) {
  const std::optional<SourceCrs> given = givenCrs(options);
  return placementOf(given ? *given : geoJsonCrs(members, bounds), bounds);
}

Placement layerPlacement(const SourceLayer& layer, const nlohmann::json& members, const PositionBounds& bounds,
                         const ReadOptions& options) {
  return placementOf(layerCrs(layer, members, bounds, options), bounds);
}

bool readsGeoJsonText(const std::string& path, const ReadOptions& options) {
  return isGeoJsonName(path) && options.layer.empty() && options.where.empty();
}

Town placePart(nlohmann::json& collection, const Placement& placement, const ReadOptions& options, double* east) {
  return placeFeatures(collection, placement, options, nullptr, east);
}

}  // namespace corbel::city
