#include "city/split.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace corbel::city {

namespace {

struct Box {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  void add(const Vec2& p) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  void add(const Box& b) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  bool near(const Box& b, double d) const {
    for (int k = 0; k < 2; ++k)
      if (b.lo[k] > hi[k] + d || b.hi[k] < lo[k] - d) return false;
    return true;
  }
};

Box boxOf(const std::vector<std::vector<Vec2>>& loops) {
  Box b;
  for (const auto& loop : loops)
    for (const Vec2& p : loop) b.add(p);
  return b;
}

// A ring closed as GeoJSON writes it.
nlohmann::json ringJson(const std::vector<Vec2>& ring) {
  nlohmann::json r = nlohmann::json::array();
  for (const Vec2& p : ring) r.push_back({p[0], p[1]});
  if (!ring.empty()) r.push_back({ring[0][0], ring[0][1]});
  return r;
}

// The sphere's radius in an equirectangular definition ("+R=..."), else the default.
double radiusOf(const std::string& proj) {
  const std::size_t at = proj.find("+R=");
  return at == std::string::npos ? kEarthRadius : std::strtod(proj.c_str() + at + 3, nullptr);
}

}  // namespace

std::vector<SplitTile> splitTown(const Town& town, double grid, double margin, std::vector<std::size_t>* unplaced) {
  std::map<std::pair<long, long>, SplitTile> tiles;  // by (y, x)
  std::vector<Box> boxes(town.buildings.size());
  for (std::size_t i = 0; i < town.buildings.size(); ++i) {
    const Building& b = town.buildings[i];
    if (b.loops.empty() || b.loops[0].empty()) {
      if (unplaced) unplaced->push_back(i);
      continue;
    }
    boxes[i] = boxOf(b.loops);
    Vec2 c(0, 0);
    for (const Vec2& p : b.loops[0]) c += p;
    c /= static_cast<double>(b.loops[0].size());
    const long x = static_cast<long>(std::floor(c[0] / grid)), y = static_cast<long>(std::floor(c[1] / grid));
    SplitTile& t = tiles[{y, x}];
    t.x = x;
    t.y = y;
    t.own.push_back(i);
  }
  std::vector<Box> streets(town.streets.size());
  for (std::size_t s = 0; s < town.streets.size(); ++s)
    for (const Vec2& p : town.streets[s].points) streets[s].add(p);
  std::vector<SplitTile> out;
  for (auto& [key, t] : tiles) {
    t.name = std::to_string(t.x) + "_" + std::to_string(t.y);
    Box own;
    for (std::size_t i : t.own) own.add(boxes[i]);
    std::vector<bool> mine(town.buildings.size(), false);
    for (std::size_t i : t.own) mine[i] = true;
    for (std::size_t i = 0; i < town.buildings.size(); ++i)
      if (!mine[i] && std::isfinite(boxes[i].lo[0]) && own.near(boxes[i], margin)) t.margin.push_back(i);
    for (std::size_t s = 0; s < streets.size(); ++s)
      if (own.near(streets[s], margin)) t.streets.push_back(s);
    out.push_back(std::move(t));
  }
  return out;
}

nlohmann::json tileSource(const Town& town, const SplitTile& tile) {
  nlohmann::json fc = {{"type", "FeatureCollection"}};
  const Frame& f = town.frame;
  if (f.proj.rfind("+proj=eqc", 0) == 0)
    fc["frame"] = {{"projection", "equirectangular"}, {"lon0", f.lon0}, {"lat0", f.lat0}, {"R_m", radiusOf(f.proj)}, {"units", "m"}};
  else if (!f.proj.empty())
    fc["crs"] = {{"type", "name"}, {"properties", {{"name", f.proj}}}};
  if (!town.attribution.empty()) fc["source"] = {{"attribution", town.attribution}};
  nlohmann::json& features = fc["features"] = nlohmann::json::array();
  auto building = [&](std::size_t i, bool margin) {
    const Building& b = town.buildings[i];
    nlohmann::json rings = nlohmann::json::array();
    for (const auto& loop : b.loops) rings.push_back(ringJson(loop));
    nlohmann::json props = b.properties.is_object() ? b.properties : nlohmann::json::object();
    if (margin) props[kMarginProperty] = true;
    features.push_back({{"type", "Feature"},
                        {"id", b.id},
                        {"properties", std::move(props)},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", std::move(rings)}}}});
  };
  for (std::size_t i : tile.own) building(i, false);
  for (std::size_t i : tile.margin) building(i, true);
  for (std::size_t s : tile.streets) {
    nlohmann::json line = nlohmann::json::array();
    for (const Vec2& p : town.streets[s].points) line.push_back({p[0], p[1]});
    features.push_back({{"type", "Feature"},
                        {"id", town.streets[s].id},
                        {"properties", nlohmann::json::object()},
                        {"geometry", {{"type", "LineString"}, {"coordinates", std::move(line)}}}});
  }
  return fc;
}

}  // namespace corbel::city
