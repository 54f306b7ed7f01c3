#include "city/import.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "extrude/footprints.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

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

void cleanBuilding(Building& b, const CleanupOptions& o) {
  if (!b.problem.empty()) return;
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
    // Colinear corners: within `colinear` of the chord between their neighbours, and between them.
    const std::size_t straight = dropCorners(ring, [&](const Vec2& a, const Vec2& p, const Vec2& c) {
      const Vec2 d = c - a;
      const double len = d.norm();
      if (len == 0) return false;
      const double t = (p - a).dot(d) / (len * len);
      const double off = std::abs(d[0] * (p[1] - a[1]) - d[1] * (p[0] - a[0])) / len;
      return t > 0 && t < 1 && off < o.colinear;
    });
    if (straight)
      b.notes.push_back(where + std::to_string(straight) + " colinear corner(s) within " + describe(o.colinear) +
                        " m of their neighbours' line removed");
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
  if (const double width = 2 * area / per; width < o.minWidth)
    b.problem = "sliver: about " + describe(width) + " m wide on average (2 area / perimeter), under " +
                describe(o.minWidth) + " m";
}

Town readTown(const std::string& text, Coordinates coordinates, const CleanupOptions& options) {
  nlohmann::json root = parseJsonText(text);
  JsonReader r(root, "");
  r.expectObject();
  const std::string type = r.at("type").string(64);
  if (type != "FeatureCollection") r.at("type").fail("expected \"FeatureCollection\", found \"" + type + "\"");
  r.at("features").array(10000000);  // checks it is an array within the limit
  Town town;
  nlohmann::json& features = root["features"];

  // Which features are streets, and the extent of every position.
  std::vector<std::size_t> lineFeatures;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, sum[2] = {0, 0};
  std::size_t count = 0;
  for (std::size_t i = 0; i < features.size(); ++i) {
    auto& f = features[i];
    if (!f.is_object() || !f.contains("geometry") || !f["geometry"].is_object()) continue;
    auto& g = f["geometry"];
    if (g.contains("type") && g["type"].is_string()) {
      const std::string gt = g["type"].get<std::string>();
      if (gt == "LineString" || gt == "MultiLineString") lineFeatures.push_back(i);
    }
    if (g.contains("coordinates"))
      forEachPosition(g["coordinates"], [&](nlohmann::json& p) {
        for (int k = 0; k < 2; ++k) {
          const double v = p[k].get<double>();
          lo[k] = std::min(lo[k], v);
          hi[k] = std::max(hi[k], v);
          sum[k] += v;
        }
        ++count;
      });
  }

  Frame& frame = town.frame;
  if (coordinates == Coordinates::Auto) {
    const auto fm = root.find("frame");
    if (fm != root.end() && fm->is_object() && fm->value("units", std::string()) == "m") {
      coordinates = Coordinates::Metric;
      frame.how =
          "the file's \"frame\" member gives metres (" + fm->value("projection", std::string("a projection")) + ")";
    } else if (count && lo[0] >= -180 && hi[0] <= 180 && lo[1] >= -90 && hi[1] <= 90 && hi[0] - lo[0] <= 5 &&
               hi[1] - lo[1] <= 5) {
      coordinates = Coordinates::Geographic;
      frame.how = "all " + std::to_string(count) + " positions are valid lon/lat and span " + describe(hi[0] - lo[0]) +
                  "° × " + describe(hi[1] - lo[1]) + "°: taken as RFC 7946 lon/lat";
    } else {
      coordinates = Coordinates::Metric;
      frame.how = count ? "positions beyond lon/lat bounds or spanning more than 5°: taken as metres" : "no positions";
    }
  } else {
    frame.how = coordinates == Coordinates::Geographic ? "lon/lat, as asked" : "metres, as asked";
  }
  frame.coordinates = coordinates;
  const bool geographic = coordinates == Coordinates::Geographic && count;
  if (geographic) {
    frame.lon0 = sum[0] / count;
    frame.lat0 = sum[1] / count;
    for (double lat : {lo[1], hi[1]}) {
      if (std::abs(lat) >= 89.9) throw InputError("features", "lon/lat data reaches a pole; project it first");
      frame.scaleError = std::max(frame.scaleError, std::abs(std::cos(frame.lat0 * kDeg) / std::cos(lat * kDeg) - 1));
    }
    for (auto& f : features)
      if (f.is_object() && f.contains("geometry") && f["geometry"].is_object() && f["geometry"].contains("coordinates"))
        forEachPosition(f["geometry"]["coordinates"], [&](nlohmann::json& p) {
          const Vec2 q = project(frame, p[0].get<double>(), p[1].get<double>());
          p[0] = q[0];
          p[1] = q[1];
        });
  }

  // Streets.
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
  if (geographic || !lineFeatures.empty()) {
    for (auto it = lineFeatures.rbegin(); it != lineFeatures.rend(); ++it) features.erase(*it);
    fps = extrude::readGeoJson(root.dump());
  } else {
    fps = extrude::readGeoJson(text);
  }
  town.buildings.reserve(fps.size());
  for (auto& fp : fps) {
    Building b;
    b.id = std::move(fp.id);
    b.loops = std::move(fp.loops);
    b.properties = std::move(fp.properties);
    b.notes = std::move(fp.notes);
    b.problem = std::move(fp.problem);
    cleanBuilding(b, options);
    town.buildings.push_back(std::move(b));
  }
  return town;
}

Town readTownFile(const std::string& path, Coordinates coordinates, const CleanupOptions& options) {
  try {
    return readTown(readFile(path, std::size_t(1) << 31), coordinates, options);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

}  // namespace corbel::city
