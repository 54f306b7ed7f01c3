#include "extrude/footprints.h"

#include "core/polygon_area.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"

#include <cmath>

namespace corbel::extrude {

namespace {

// One GeoJSON polygon (array of rings) → loops; faults go to fp.problem.
void readPolygon(const JsonReader& rings, Footprint& fp) {
  const auto rs = rings.array(10000);
  if (rs.empty()) {
    fp.problem = rings.path() + ": a polygon needs an outer ring";
    return;
  }
  for (std::size_t ri = 0; ri < rs.size(); ++ri) {
    std::vector<Vec2> ring;
    for (const JsonReader& q : rs[ri].array(1000000)) {
      if (!q.raw().is_array() || q.raw().size() < 2 || !q.raw()[0].is_number() || !q.raw()[1].is_number())
        q.fail("expected [x, y] numbers");
      ring.emplace_back(JsonReader(q.raw()[0], q.path() + "[0]").number(), JsonReader(q.raw()[1], q.path() + "[1]").number());
    }
    if (ring.size() < 4) {
      fp.problem = rs[ri].path() + ": a ring needs at least four positions (closed, three corners)";
      return;
    }
    if (ring.front() != ring.back()) {
      fp.problem = rs[ri].path() + ": the ring is not closed (GeoJSON repeats the first position last)";
      return;
    }
    ring.pop_back();
    // Repeated consecutive positions are one corner.
    std::vector<Vec2> clean;
    for (const Vec2& p : ring)
      if (clean.empty() || clean.back() != p) clean.push_back(p);
    while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
    if (clean.size() != ring.size())
      fp.notes.push_back(rs[ri].path() + ": " + std::to_string(ring.size() - clean.size()) + " repeated position(s) removed");
    if (clean.size() < 3) {
      fp.problem = rs[ri].path() + ": fewer than three distinct corners";
      return;
    }
    const double a = signedArea(clean);
    const bool hole = ri > 0;
    if (a == 0) {
      fp.problem = rs[ri].path() + ": the ring encloses no area";
      return;
    }
    if ((a < 0) != hole) {
      std::reverse(clean.begin(), clean.end());
      fp.notes.push_back(rs[ri].path() + ": reoriented (" + (hole ? "holes run clockwise" : "outer rings run counter-clockwise") + ")");
    }
    fp.loops.push_back(std::move(clean));
  }
}

}  // namespace

std::vector<Footprint> readGeoJson(const std::string& text) {
  const nlohmann::json root = parseJsonText(text);
  JsonReader r(root, "");
  r.expectObject();
  const std::string type = r.at("type").string(64);
  std::vector<JsonReader> features;
  if (type == "FeatureCollection") features = r.at("features").array(10000000);
  else if (type == "Feature") features.push_back(r);
  else r.at("type").fail("expected \"FeatureCollection\" or \"Feature\", found \"" + type + "\"");
  std::vector<Footprint> out;
  for (std::size_t fi = 0; fi < features.size(); ++fi) {
    const JsonReader& f = features[fi];
    std::string id = std::to_string(fi);
    nlohmann::json props = nlohmann::json::object();
    if (f.raw().is_object()) {
      if (auto p = f.raw().find("properties"); p != f.raw().end() && p->is_object()) props = *p;
      if (auto i = f.raw().find("id"); i != f.raw().end() && (i->is_string() || i->is_number()))
        id = i->is_string() ? i->get<std::string>() : i->dump();
      else if (props.contains("source_id") && props["source_id"].is_string())
        id = props["source_id"].get<std::string>() + (props.contains("part") ? "#" + props["part"].dump() : "");
    }
    auto fail = [&](const std::string& why) {
      Footprint fp;
      fp.id = id;
      fp.properties = props;
      fp.problem = why;
      out.push_back(std::move(fp));
    };
    try {
      f.expectObject();
      const JsonReader g = f.at("geometry");
      if (g.raw().is_null()) {
        fail(g.path() + ": no geometry");
        continue;
      }
      const std::string gt = g.at("type").string(64);
      if (gt == "Polygon") {
        Footprint fp;
        fp.id = id;
        fp.properties = props;
        readPolygon(g.at("coordinates"), fp);
        out.push_back(std::move(fp));
      } else if (gt == "MultiPolygon") {
        const auto polys = g.at("coordinates").array(100000);
        for (std::size_t k = 0; k < polys.size(); ++k) {
          Footprint fp;
          fp.id = polys.size() > 1 ? id + "/" + std::to_string(k) : id;
          fp.properties = props;
          readPolygon(polys[k], fp);
          out.push_back(std::move(fp));
        }
      } else {
        fail(g.path() + ".type: \"" + gt + "\" is not a footprint (expected Polygon or MultiPolygon)");
      }
    } catch (const InputError& e) {
      fail(e.what());
    }
  }
  return out;
}

std::vector<Footprint> readGeoJsonFile(const std::string& path) {
  try {
    return readGeoJson(readFile(path, std::size_t(1) << 31));
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

}  // namespace corbel::extrude
