#include "core/project_io.h"

#include "core/atomic_file.h"
#include "core/json_reader.h"
#include "core/kifs_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace corbel {

namespace {

using ojson = nlohmann::ordered_json;

ojson vec(const Vec3& v) { return ojson::array({v[0], v[1], v[2]}); }

ojson boxToJson(const BoxSpec& b) {
  ojson j;
  j["origin"] = vec(b.origin);
  j["size"] = vec(b.size);
  j["rotation"] = b.rotation_deg;
  j["material"] = b.material;
  j["repeat"] = {{"count", {b.repeat_x, b.repeat_y}}, {"spacing", {b.spacing_x, b.spacing_y}}};
  return j;
}

ojson masonryToJson(const MasonrySpec& m) {
  ojson j;
  j["model"] = m.model;
  ojson params = ojson::object();
  for (const MasonryParameter& p : m.parameters) params[p.name] = p.value;
  j["parameters"] = std::move(params);
  ojson free = ojson::object();
  for (const MasonryFree& f : m.free) free[f.name] = {f.lo, f.hi};
  j["free"] = std::move(free);
  j["friction"] = m.friction;
  if (m.conservativeFriction) j["conservative_friction"] = true;
  j["kern"] = m.kern;
  if (!m.loads.empty()) {
    ojson loads = ojson::array();
    for (const MasonryLoad& l : m.loads) {
      ojson o;
      o["name"] = l.name;
      o["block"] = l.block;
      if (l.face >= 0) {
        o["face"] = l.face;
        o["pressure"] = l.pressure;
      } else {
        o["offset"] = vec(l.offset);
        o["force"] = vec(l.force);
      }
      loads.push_back(std::move(o));
    }
    j["loads"] = std::move(loads);
  }
  if (!m.ground) j["ground"] = false;
  j["material"] = m.material;
  return j;
}

MasonrySpec masonryFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"model", "parameters", "free", "friction", "conservative_friction", "kern", "loads", "ground", "material"}))
    warnings.push_back(k + ": unknown key kept");
  MasonrySpec m;
  const JsonReader model = r.at("model");
  m.model = model.string(limits::kMaxNameLength);
  if (m.model.empty()) model.fail("the model name must not be empty");
  // Both maps are JSON objects keyed by parameter name (so a name cannot appear twice).
  auto entries = [](const JsonReader& o) {
    o.expectObject();
    if (o.raw().size() > limits::kMaxMasonryParameters)
      o.fail(std::to_string(o.raw().size()) + " parameters exceed the limit of " +
             std::to_string(limits::kMaxMasonryParameters));
    std::vector<std::pair<std::string, JsonReader>> out;
    for (auto it = o.raw().begin(); it != o.raw().end(); ++it) {
      if (it.key().empty() || it.key().size() > limits::kMaxNameLength)
        o.fail("a parameter name must have 1 to " + std::to_string(limits::kMaxNameLength) + " characters");
      out.emplace_back(it.key(), o.member(it.key(), o.path() + "." + it.key()));
    }
    return out;
  };
  if (auto p = r.find("parameters"))
    for (const auto& [name, v] : entries(*p)) m.parameters.push_back({name, v.number()});
  if (auto f = r.find("free"))
    for (const auto& [name, v] : entries(*f)) {
      const Vec2 b = v.vec2();
      if (b[0] > b[1]) v.fail("the lower bound " + std::to_string(b[0]) + " is above the upper bound " + std::to_string(b[1]));
      m.free.push_back({name, b[0], b[1]});
    }
  if (auto v = r.find("friction")) m.friction = v->number(0.0, 100.0);
  if (auto v = r.find("conservative_friction")) m.conservativeFriction = v->boolean();
  if (auto v = r.find("kern")) {
    m.kern = v->number(0.0, 1.0);
    if (m.kern >= 1.0) v->fail("the kern factor must be below 1 (1 would shrink every contact to a point)");
  }
  if (auto v = r.find("loads"))
    for (const JsonReader& e : v->array(limits::kMaxMasonryLoads)) {
      e.expectObject();
      for (auto& k : e.unknownKeys({"name", "block", "offset", "force", "face", "pressure"}))
        warnings.push_back(k + ": unknown key kept");
      MasonryLoad l;
      if (auto n = e.find("name")) l.name = n->string(limits::kMaxNameLength);
      l.block = e.at("block").string(limits::kMaxNameLength);
      if (auto f = e.find("face")) {
        // A load per area: a face and a pressure, no point force.
        if (e.find("force") || e.find("offset")) e.fail("a load has either a face and a pressure or a force, not both");
        l.face = static_cast<int>(f->integer(0, 1000000));
        l.pressure = e.at("pressure").number(-1e9, 1e9);
      } else {
        if (e.find("pressure")) e.fail("a pressure needs the face it acts on (\"face\": index in the block)");
        l.force = e.at("force").vec3();
        if (auto o = e.find("offset")) l.offset = o->vec3();
      }
      m.loads.push_back(std::move(l));
    }
  if (auto v = r.find("ground")) m.ground = v->boolean();
  if (auto v = r.find("material")) m.material = v->string(limits::kMaxNameLength);
  return m;
}

BoxSpec boxFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"origin", "size", "rotation", "material", "repeat"}))
    warnings.push_back(k + ": unknown key kept");
  BoxSpec b;
  if (auto v = r.find("origin")) b.origin = v->vec3();
  b.size = r.at("size").vec3();
  if (auto v = r.find("rotation")) b.rotation_deg = v->number();
  if (auto v = r.find("material")) b.material = v->string(limits::kMaxNameLength);
  if (auto rep = r.find("repeat")) {
    rep->expectObject();
    for (auto& k : rep->unknownKeys({"count", "spacing"})) warnings.push_back(k + ": unknown key kept");
    if (auto c = rep->find("count")) {
      auto [nx, ny] = c->integerPair(1, limits::kMaxRepeat);
      if (nx * ny > limits::kMaxRepeat)
        c->fail(std::to_string(nx) + " x " + std::to_string(ny) + " boxes exceeds the limit of " +
                std::to_string(limits::kMaxRepeat));
      b.repeat_x = static_cast<int>(nx);
      b.repeat_y = static_cast<int>(ny);
    }
    if (auto s = rep->find("spacing")) {
      const Vec2 sp = s->vec2();
      b.spacing_x = sp[0];
      b.spacing_y = sp[1];
    }
  }
  if (auto problem = checkBoxSpec(b)) {
    // checkBoxSpec names the field ("size: ..."); anchor it at this spec's path.
    const auto colon = problem->find(": ");
    const std::string field = colon == std::string::npos ? std::string() : problem->substr(0, colon);
    throw InputError(field.empty() ? r.path() : r.path() + "." + field,
                     colon == std::string::npos ? *problem : problem->substr(colon + 2));
  }
  return b;
}

ojson vec2(const Vec2& v) { return ojson::array({v[0], v[1]}); }

// An object's placement (format version 2); written only when it moves the object.
ojson placementToJson(const Placement& p) {
  ojson j;
  j["translation"] = vec(p.translation);
  j["rotation"] = p.rotation_deg;
  j["scale"] = p.scale;
  return j;
}

Placement placementFromJson(const JsonReader& r, const Spec& spec, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"translation", "rotation", "scale"})) warnings.push_back(k + ": unknown key kept");
  Placement p;
  if (auto v = r.find("translation")) p.translation = v->vec3();
  if (auto v = r.find("rotation")) p.rotation_deg = v->number();
  if (auto v = r.find("scale")) {
    p.scale = v->number();
    if (p.scale != 1.0 && !scalable(spec))
      v->fail("this kind of object cannot be scaled (only boxes, extrusions and units can); it must be 1");
  }
  if (auto problem = checkPlacement(p)) {
    const auto colon = problem->find(": ");
    throw InputError(r.path() + "." + problem->substr(0, colon), problem->substr(colon + 2));
  }
  return p;
}

}  // namespace

// KIFS keys are the field names of core/kifs_spec.h (and kifs/params.h), so the kernel's
// messages ("kifs.mass.shell: ...") name the place in the file.
ojson kifsToJson(const KifsSpec& k) {
  ojson j;
  if (!k.preset.empty()) j["preset"] = k.preset;
  j["iterations"] = k.iterations;
  j["scale"] = k.scale;
  j["centre"] = vec(k.centre);
  j["r1"] = vec(k.r1);
  j["r2"] = vec(k.r2);
  j["bailout"] = k.bailout;
  j["mass"] = {{"footprint", k.mass.footprint}, {"halfWidth", k.mass.halfWidth}, {"halfDepth", k.mass.halfDepth},
               {"height", k.mass.height},       {"wing", k.mass.wing},           {"shell", k.mass.shell}};
  // Written when used or set (a file may name an object under another footprint: kept, not
  // lost), so other files stay as they were.
  if (k.mass.footprint == "object" || !k.mass.object.empty()) j["mass"]["object"] = k.mass.object;
  if (!k.mass.building.empty()) j["mass"]["building"] = k.mass.building;
  if (k.mass.footprint == "object" || k.mass.resolution != KifsSpec::Mass{}.resolution)
    j["mass"]["resolution"] = k.mass.resolution;
  j["facade"] = {{"period", k.facade.period}, {"r", vec(k.facade.r)}, {"a1", k.facade.a1},
                 {"a2", k.facade.a2},         {"b1", k.facade.b1},    {"b2", k.facade.b2}};
  j["floors"] = {{"height", k.floors.height}, {"y0", k.floors.y0}, {"sy", k.floors.sy}};
  j["curvilinear"] = {{"enabled", k.curvilinear.enabled}, {"sTheta", k.curvilinear.sTheta},
                      {"cTheta", k.curvilinear.cTheta},   {"sR", k.curvilinear.sR},
                      {"cR", k.curvilinear.cR},           {"z0", k.curvilinear.z0}};
  j["trace"] = {{"maxSteps", k.trace.maxSteps},
                {"lipschitz", k.trace.lipschitz},
                {"overRelax", k.trace.overRelax},
                {"hitFactor", k.trace.hitFactor}};
  j["meshResolution"] = k.meshResolution;
  j["material"] = k.material;
  return j;
}

// Types here, values in the kifs kernel (kifs::validate) when the object is built; every key
// is optional and defaults to kifs_spec.h.
KifsSpec kifsFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  const std::set<std::string> top = {"preset", "iterations", "scale",  "centre",      "r1",    "r2",
                                     "bailout", "mass",      "facade", "floors", "curvilinear", "trace",
                                     "meshResolution", "material"};
  for (auto& k : r.unknownKeys(top)) warnings.push_back(k + ": unknown key kept");
  KifsSpec k;
  auto group = [&](const char* key, const std::set<std::string>& known) -> std::optional<JsonReader> {
    auto g = r.find(key);
    if (!g) return std::nullopt;
    g->expectObject();
    for (auto& u : g->unknownKeys(known)) warnings.push_back(u + ": unknown key kept");
    return g;
  };
  auto number = [](const std::optional<JsonReader>& g, const char* key, double& out) {
    if (g)
      if (auto v = g->find(key)) out = v->number();
  };
  auto vector = [](const std::optional<JsonReader>& g, const char* key, Vec3& out) {
    if (g)
      if (auto v = g->find(key)) out = v->vec3();
  };
  const std::optional<JsonReader> root = r;
  if (auto v = r.find("preset")) k.preset = v->string(limits::kMaxNameLength);
  if (auto v = r.find("iterations")) k.iterations = static_cast<int>(v->integer(0, limits::kMaxKifsCount));
  number(root, "scale", k.scale);
  vector(root, "centre", k.centre);
  vector(root, "r1", k.r1);
  vector(root, "r2", k.r2);
  number(root, "bailout", k.bailout);
  if (auto g = group("mass", {"footprint", "halfWidth", "halfDepth", "height", "wing", "shell", "object", "building", "resolution"})) {
    if (auto v = g->find("footprint")) {
      k.mass.footprint = v->string(limits::kMaxNameLength);
      if (k.mass.footprint != "box" && k.mass.footprint != "T" && k.mass.footprint != "H" &&
          k.mass.footprint != "object")
        v->fail("expected \"box\", \"T\", \"H\" or \"object\", found \"" + k.mass.footprint + "\"");
    }
    if (auto v = g->find("object")) k.mass.object = v->string(limits::kMaxNameLength);
    if (auto v = g->find("building")) k.mass.building = v->string(limits::kMaxNameLength);
    if (auto v = g->find("resolution")) k.mass.resolution = static_cast<int>(v->integer(1, 512));  // kifs::kMaxMassResolution
    for (auto [key, out] : {std::pair{"halfWidth", &k.mass.halfWidth}, std::pair{"halfDepth", &k.mass.halfDepth},
                            std::pair{"height", &k.mass.height}, std::pair{"wing", &k.mass.wing},
                            std::pair{"shell", &k.mass.shell}})
      number(g, key, *out);
  }
  if (auto g = group("facade", {"period", "r", "a1", "a2", "b1", "b2"})) {
    vector(g, "r", k.facade.r);
    for (auto [key, out] : {std::pair{"period", &k.facade.period}, std::pair{"a1", &k.facade.a1},
                            std::pair{"a2", &k.facade.a2}, std::pair{"b1", &k.facade.b1}, std::pair{"b2", &k.facade.b2}})
      number(g, key, *out);
  }
  if (auto g = group("floors", {"height", "y0", "sy"}))
    for (auto [key, out] : {std::pair{"height", &k.floors.height}, std::pair{"y0", &k.floors.y0},
                            std::pair{"sy", &k.floors.sy}})
      number(g, key, *out);
  if (auto g = group("curvilinear", {"enabled", "sTheta", "cTheta", "sR", "cR", "z0"})) {
    if (auto v = g->find("enabled")) k.curvilinear.enabled = v->boolean();
    for (auto [key, out] : {std::pair{"sTheta", &k.curvilinear.sTheta}, std::pair{"cTheta", &k.curvilinear.cTheta},
                            std::pair{"sR", &k.curvilinear.sR}, std::pair{"cR", &k.curvilinear.cR},
                            std::pair{"z0", &k.curvilinear.z0}})
      number(g, key, *out);
  }
  if (auto g = group("trace", {"maxSteps", "lipschitz", "overRelax", "hitFactor"})) {
    if (auto v = g->find("maxSteps")) k.trace.maxSteps = static_cast<int>(v->integer(1, limits::kMaxKifsCount));
    for (auto [key, out] : {std::pair{"lipschitz", &k.trace.lipschitz}, std::pair{"overRelax", &k.trace.overRelax},
                            std::pair{"hitFactor", &k.trace.hitFactor}})
      number(g, key, *out);
  }
  if (auto v = r.find("meshResolution"))
    k.meshResolution = static_cast<int>(v->integer(0, limits::kMaxKifsMeshResolution));
  if (auto v = r.find("material")) k.material = v->string(limits::kMaxNameLength);
  return k;
}

namespace {

// The site is written as the JSON object it holds, so a project embeds a site file verbatim.
ojson growthToJson(const GrowthSpec& g) {
  ojson j;
  j["site"] = ojson::parse(g.site);
  j["seed"] = g.seed;
  j["steps"] = g.steps;
  if (g.aroundUnits) j["around_units"] = true;
  return j;
}

// The site's own keys are checked by the growth kernel (growth/site.h) when it builds the object.
GrowthSpec growthFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"site", "seed", "steps", "around_units"})) warnings.push_back(k + ": unknown key kept");
  GrowthSpec g;
  const JsonReader site = r.at("site");
  site.expectObject();
  g.site = site.raw().dump();
  if (auto v = r.find("seed")) g.seed = static_cast<std::uint64_t>(v->integer(0, (1L << 53)));
  if (auto v = r.find("steps")) g.steps = static_cast<int>(v->integer(-1, limits::kMaxGrowthSteps));
  if (auto v = r.find("around_units")) g.aroundUnits = v->boolean();
  return g;
}

// A unit's parts as [x0, y0, z0, x1, y1, z1] rows.
ojson unitToJson(const UnitSpec& u) {
  ojson j;
  ojson parts = ojson::array();
  for (const UnitPart& p : u.parts) parts.push_back(ojson::array({p.lo[0], p.lo[1], p.lo[2], p.hi[0], p.hi[1], p.hi[2]}));
  j["parts"] = std::move(parts);
  j["material"] = u.material;
  return j;
}

UnitSpec unitFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"parts", "material"})) warnings.push_back(k + ": unknown key kept");
  UnitSpec u;
  for (const JsonReader& p : r.at("parts").array(limits::kMaxUnitParts)) {
    const std::vector<JsonReader> v = p.array(6);
    if (v.size() != 6) p.fail("expected [x0, y0, z0, x1, y1, z1]");
    UnitPart part;
    for (int k = 0; k < 3; ++k) part.lo[k] = v[std::size_t(k)].number(), part.hi[k] = v[std::size_t(k + 3)].number();
    u.parts.push_back(part);
  }
  if (auto v = r.find("material")) u.material = v->string(limits::kMaxNameLength);
  if (auto problem = checkUnitSpec(u)) {
    const auto colon = problem->find(": ");
    throw InputError(r.path() + "." + problem->substr(0, colon), problem->substr(colon + 2));
  }
  return u;
}

// A path written relative to `folder` where it lies under it or near it (as background images).
std::string relativeTo(const std::string& path, const std::string& folder) {
  if (folder.empty() || !std::filesystem::path(path).is_absolute()) return path;
  const std::filesystem::path rel =
      std::filesystem::path(path).lexically_relative(std::filesystem::path(folder).lexically_normal());
  return rel.empty() ? path : rel.generic_string();
}

std::string resolvedPath(const JsonReader& r, const std::string& folder) {
  std::string path = r.string(limits::kMaxPathLength);
  if (path.empty()) r.fail("the path must not be empty");
  if (path.find('\0') != std::string::npos) r.fail("a path cannot hold a NUL character");
  if (!folder.empty() && std::filesystem::path(path).is_relative())
    path = (std::filesystem::path(folder) / path).lexically_normal().string();
  return path;
}

// Footprints and style: a path (a string) or the JSON itself (an object), kept as compact text.
ojson pathOrJson(const std::string& path, const std::string& text, const std::string& folder) {
  if (!path.empty()) return relativeTo(path, folder);
  return ojson::parse(text);
}

ojson townToJson(const TownSpec& t, const std::string& folder) {
  ojson j;
  j["footprints"] = pathOrJson(t.footprints, t.footprintsJson, folder);
  if (!t.crs.empty()) j["crs"] = t.crs;
  if (!t.layer.empty()) j["layer"] = t.layer;
  if (!t.where.empty()) j["where"] = t.where;
  j["style"] = pathOrJson(t.style, t.styleJson, folder);
  j["seed"] = t.seed;
  j["detail"] = t.detail;
  if (!t.overrides.empty()) {
    ojson overrides = ojson::object();
    for (const auto& [id, o] : t.overrides) {
      ojson oj;
      if (!o.type.empty()) oj["type"] = o.type;
      if (!o.profiles.empty()) {
        ojson profiles = ojson::object();
        for (const auto& [side, name] : o.profiles) profiles[side] = name;
        oj["profiles"] = std::move(profiles);
      }
      if (!o.edges.empty()) {
        ojson edges = ojson::object();
        for (const auto& [key, name] : o.edges) edges[key] = name;
        oj["edges"] = std::move(edges);
      }
      overrides[id] = std::move(oj);
    }
    j["overrides"] = std::move(overrides);
  }
  if (!t.streets.empty()) {
    ojson streets = ojson::array();
    for (const TownStreet& st : t.streets) {
      ojson sj;
      ojson points = ojson::array();
      for (const auto& p : st.points) points.push_back({p[0], p[1]});
      sj["points"] = std::move(points);
      sj["width"] = st.width;
      sj["setback"] = st.setback;
      sj["depth"] = st.depth;
      sj["plot_width"] = st.plotWidth;
      sj["both_sides"] = st.bothSides;
      if (st.skeletonPlots) sj["plots"] = "skeleton";
      streets.push_back(std::move(sj));
    }
    j["streets"] = std::move(streets);
  }
  return j;
}

// The footprints' and the style's own keys are checked by the city kernel when it builds the object.
TownSpec townFromJson(const JsonReader& r, const std::string& folder, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"footprints", "crs", "layer", "where", "style", "seed", "detail", "overrides", "streets"}))
    warnings.push_back(k + ": unknown key kept");
  TownSpec t;
  const auto pathOrText = [&](const JsonReader& v, std::string& path, std::string& text) {
    if (v.raw().is_string()) path = resolvedPath(v, folder);
    else if (v.raw().is_object()) {
      text = v.raw().dump();
      if (text.size() > limits::kMaxEmbeddedBytes) v.fail("embedded JSON is too large");
    } else
      v.fail("expected a file path (a string) or the JSON itself (an object), found " + std::string(v.raw().is_array() ? "an array" : v.raw().is_null() ? "null" : std::string("a ") + v.raw().type_name()));
  };
  pathOrText(r.at("footprints"), t.footprints, t.footprintsJson);
  if (auto v = r.find("crs")) t.crs = v->string(100000);
  if (auto v = r.find("layer")) t.layer = v->string(1000);
  if (auto v = r.find("where")) t.where = v->string(100000);
  pathOrText(r.at("style"), t.style, t.styleJson);
  if (auto v = r.find("seed")) t.seed = static_cast<std::uint64_t>(v->integer(0, (1L << 53)));
  if (auto v = r.find("detail")) {
    t.detail = v->string(16);
    if (t.detail != "massing" && t.detail != "steps" && t.detail != "full")
      v->fail("expected \"massing\", \"steps\" or \"full\", found \"" + t.detail + "\"");
  }
  if (auto ov = r.find("overrides")) {
    ov->expectObject();
    if (ov->raw().size() > limits::kMaxTownOverrides) ov->fail("too many overrides");
    for (const auto& [id, value] : ov->raw().items()) {
      const JsonReader o = ov->member(id, ov->path() + "[\"" + id + "\"]");
      o.expectObject();
      if (id.empty()) o.fail("a footprint id must not be empty");
      if (id.size() > limits::kMaxNameLength) o.fail("the footprint id is too long");
      for (auto& k : o.unknownKeys({"type", "profiles", "edges"})) warnings.push_back(k + ": unknown key kept");
      TownOverride over;
      if (auto ty = o.find("type")) {
        over.type = ty->string(limits::kMaxNameLength);
        if (over.type.empty()) ty->fail("the type name must not be empty");
      }
      if (auto pr = o.find("profiles")) {
        pr->expectObject();
        for (const auto& [side, name] : pr->raw().items()) {
          const JsonReader n = pr->member(side, pr->path() + "." + side);
          if (side != "street" && side != "side" && side != "back")
            n.fail("expected \"street\", \"side\" or \"back\", found \"" + side + "\"");
          const std::string profile = n.string(limits::kMaxNameLength);
          if (profile.empty()) n.fail("the profile name must not be empty");
          over.profiles[side] = profile;
        }
      }
      if (auto ed = o.find("edges")) {
        ed->expectObject();
        for (const auto& [key, name] : ed->raw().items()) {
          const JsonReader n = ed->member(key, ed->path() + "[\"" + key + "\"]");
          if (!parseTownEdgeKey(key)) n.fail("expected an edge \"LOOP:EDGE\" (as \"0:3\"), found \"" + key + "\"");
          const std::string profile = n.string(limits::kMaxNameLength);
          if (profile.empty()) n.fail("the profile name must not be empty");
          over.edges[key] = profile;
        }
      }
      if (over.empty()) o.fail("overrides nothing: expected \"type\", \"profiles\" or \"edges\"");
      t.overrides[id] = std::move(over);
    }
  }
  if (auto sv = r.find("streets")) {
    if (!sv->raw().is_array()) sv->fail("expected an array of streets");
    if (sv->raw().size() > limits::kMaxTownStreets) sv->fail("too many streets (at most 256)");
    for (std::size_t k = 0; k < sv->raw().size(); ++k) {
      const JsonReader st = sv->element(k);
      st.expectObject();
      for (auto& key : st.unknownKeys({"points", "width", "setback", "depth", "plot_width", "both_sides", "plots"}))
        warnings.push_back(key + ": unknown key kept");
      TownStreet street;
      const JsonReader pts = st.at("points");
      if (!pts.raw().is_array()) pts.fail("expected an array of [x, y] points");
      if (pts.raw().size() < 2 || pts.raw().size() > limits::kMaxStreetPoints)
        pts.fail("expected 2 to 64 control points, found " + std::to_string(pts.raw().size()));
      for (std::size_t i = 0; i < pts.raw().size(); ++i) {
        const JsonReader p = pts.element(i);
        if (!p.raw().is_array() || p.raw().size() != 2) p.fail("expected [x, y]");
        std::array<double, 2> xy{};
        for (int c = 0; c < 2; ++c)
          xy[std::size_t(c)] = p.element(std::size_t(c))
                                   .number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
        if (!street.points.empty() && street.points.back() == xy) p.fail("repeats the point before it");
        street.points.push_back(xy);
      }
      if (auto v = st.find("width")) street.width = v->number(1, 100);
      if (auto v = st.find("setback")) street.setback = v->number(0, 50);
      if (auto v = st.find("depth")) street.depth = v->number(3, 200);
      if (auto v = st.find("plot_width")) street.plotWidth = v->number(3, 200);
      if (auto v = st.find("both_sides")) street.bothSides = v->boolean();
      if (auto v = st.find("plots")) {
        const std::string how = v->string(16);
        if (how != "normals" && how != "skeleton")
          v->fail("expected \"normals\" or \"skeleton\", found \"" + how + "\"");
        street.skeletonPlots = how == "skeleton";
      }
      t.streets.push_back(std::move(street));
    }
  }
  return t;
}

ojson stoneToJson(const StoneWalls& m) {
  ojson j;
  j["course_height"] = m.courseHeight;
  j["block_length"] = m.blockLength;
  j["thickness"] = m.thickness;
  j["density"] = m.density;
  j["covering_weight"] = m.coveringWeight;
  j["ties"] = m.ties;
  if (m.windPressure != 0 || m.windDirection != 0) {
    j["wind_pressure"] = m.windPressure;
    j["wind_direction"] = m.windDirection;
  }
  if (!m.openings.empty()) {
    ojson o = ojson::object();
    for (const StoneOpening& op : m.openings) o[op.anchor] = openingHeadName(op.head);
    j["openings"] = std::move(o);
  }
  return j;
}

ojson extrusionToJson(const ExtrusionSpec& e) {
  ojson j;
  j["material"] = e.material;
  if (!e.roofMaterial.empty()) j["roof_material"] = e.roofMaterial;
  j["base"] = e.baseZ;
  j["priority"] = e.priority == Priority::MaximiseVolume   ? "maximise_volume"
                  : e.priority == Priority::MinimiseVolume ? "minimise_volume"
                                                           : "manual";
  ojson loops = ojson::array();
  bool uniform = true;
  for (const PlanLoop& l : e.loops)
    for (int p : l.profile) uniform = uniform && p == e.loops.front().profile.front();
  ojson edgeProfiles = ojson::array();
  for (const PlanLoop& l : e.loops) {
    ojson pts = ojson::array();
    for (const Vec2& p : l.points) pts.push_back(vec2(p));
    loops.push_back(std::move(pts));
    ojson names = ojson::array();
    for (int p : l.profile) names.push_back(e.profiles[p].name);
    edgeProfiles.push_back(std::move(names));
  }
  ojson plan;
  plan["loops"] = std::move(loops);
  if (uniform && !e.loops.empty() && !e.loops.front().profile.empty())
    plan["profile"] = e.profiles[e.loops.front().profile.front()].name;
  else
    plan["edge_profiles"] = std::move(edgeProfiles);
  // Walls are written once an edit has made them other than one per edge, numbered in order.
  if (!wallsAreEdges(e)) plan["walls"] = numberedWalls(e);
  j["plan"] = std::move(plan);
  ojson profiles = ojson::array();
  for (const Profile& p : e.profiles) {
    ojson pj;
    pj["name"] = p.name;
    ojson pts = ojson::array();
    for (const Vec2& q : p.points) pts.push_back(vec2(q));
    pj["points"] = std::move(pts);
    pj["tags"] = p.tags;
    profiles.push_back(std::move(pj));
  }
  j["profiles"] = std::move(profiles);
  auto anchorJson = [&](const Anchor& a) {
    ojson aj;
    aj["loop"] = a.loop;
    aj["edge"] = a.edge;
    aj[a.absolute ? "at" : "fraction"] = a.along;
    aj["height"] = a.height;
    return aj;
  };
  auto repeatJson = [&](const Repeat& rep) {
    ojson rj;
    rj["kind"] = rep.kind == RepeatKind::Grid ? "grid" : "row";
    rj["along"] = rep.along;
    rj["spacing"] = rep.spacing;
    if (rep.kind == RepeatKind::Grid) {
      rj["height"] = rep.height;
      rj["row_spacing"] = rep.rowSpacing;
    }
    return rj;
  };
  if (!e.steps.empty()) {
    ojson steps = ojson::array();
    for (const PlanStep& st : e.steps) {
      ojson sj;
      if (!st.name.empty()) sj["name"] = st.name;
      sj["anchor"] = anchorJson(st.anchor);
      sj["shape"] = st.shape == StepShape::Bay ? "bay" : st.shape == StepShape::Forced ? "forced" : "rectangle";
      if (!st.points.empty()) {
        ojson pts = ojson::array();
        for (const Vec2& q : st.points) pts.push_back(vec2(q));
        sj["points"] = std::move(pts);
      }
      if (st.shape != StepShape::Forced) {
        sj["width"] = st.width;
        sj["depth"] = st.depth;
      }
      if (st.shape == StepShape::Bay || st.cant != 0) sj["cant"] = st.cant;
      sj["front_profile"] = e.profiles[st.frontProfile].name;
      sj["side_profile"] = e.profiles[st.sideProfile].name;
      if (st.repeat.kind != RepeatKind::None) sj["repeat"] = repeatJson(st.repeat);
      steps.push_back(std::move(sj));
    }
    j["steps"] = std::move(steps);
  }
  if (!e.offsets.empty()) {
    ojson offsets = ojson::array();
    for (const OffsetEvent& o : e.offsets) {
      ojson oj;
      oj["height"] = o.height;
      oj["side_profile"] = e.profiles[o.sideProfile].name;
      ojson edges = ojson::array();
      for (const OffsetEdge& t : o.edges) {
        ojson tj;
        tj["profile"] = e.profiles[t.profile].name;
        tj["inside"] = t.inside;
        tj["outside"] = t.outside;
        tj["inside_profile"] = e.profiles[t.insideProfile].name;
        tj["outside_profile"] = e.profiles[t.outsideProfile].name;
        edges.push_back(std::move(tj));
      }
      oj["edges"] = std::move(edges);
      offsets.push_back(std::move(oj));
    }
    j["offsets"] = std::move(offsets);
  }
  if (!e.anchors.empty()) {
    ojson anchors = ojson::array();
    for (const MeshAnchor& m : e.anchors) {
      ojson mj = anchorJson(m.anchor);
      mj["name"] = m.name;
      if (m.feature != FeatureKind::None) {
        mj["feature"] = featureName(m.feature);
        mj["size"] = ojson::array({m.size.width, m.size.height, m.size.depth});
      }
      if (m.repeat.kind != RepeatKind::None) mj["repeat"] = repeatJson(m.repeat);
      anchors.push_back(std::move(mj));
    }
    j["anchors"] = std::move(anchors);
  }
  if (e.masonry) j["masonry"] = stoneToJson(*e.masonry);
  return j;
}

StoneWalls stoneFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"course_height", "block_length", "thickness", "density", "covering_weight", "ties", "wind_pressure",
                                    "wind_direction", "openings"}))
    warnings.push_back(k + ": unknown key kept");
  StoneWalls m;
  auto length = [&](const char* key, double& out) {
    if (auto v = r.find(key)) {
      out = v->number(0.0, 1000.0);
      if (!(out > 0)) v->fail("must be greater than 0 and at most 1000 m");
    }
  };
  length("course_height", m.courseHeight);
  length("block_length", m.blockLength);
  length("thickness", m.thickness);
  if (auto v = r.find("density")) {
    m.density = v->number(0.0, 1e5);
    if (!(m.density > 0)) v->fail("must be greater than 0 and at most 100000 kg/m³");
  }
  if (auto v = r.find("covering_weight")) m.coveringWeight = v->number(0.0, 1e6);
  if (auto v = r.find("ties")) m.ties = v->boolean();
  if (auto v = r.find("wind_pressure")) m.windPressure = v->number(0.0, 1e5);
  if (auto v = r.find("wind_direction")) m.windDirection = v->number(-360.0, 360.0);
  if (auto o = r.find("openings")) {
    o->expectObject();
    if (o->raw().size() > limits::kMaxSteps) o->fail("more openings than the limit of " + std::to_string(limits::kMaxSteps));
    for (auto it = o->raw().begin(); it != o->raw().end(); ++it) {
      const JsonReader v = o->member(it.key(), o->path() + "." + it.key());
      StoneOpening op;
      op.anchor = it.key();
      const std::string name = v.string(32);
      if (!openingHeadFromName(name, op.head)) v.fail("expected \"lintel\", \"flat_arch\" or \"semicircular_arch\", found \"" + name + "\"");
      m.openings.push_back(std::move(op));
    }
  }
  return m;
}

ExtrusionSpec extrusionFromJson(const JsonReader& r, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"material", "roof_material", "base", "priority", "plan", "profiles", "steps", "offsets", "anchors", "masonry"}))
    warnings.push_back(k + ": unknown key kept");
  ExtrusionSpec e;
  if (auto v = r.find("material")) e.material = v->string(limits::kMaxNameLength);
  if (auto v = r.find("roof_material")) e.roofMaterial = v->string(limits::kMaxNameLength);
  if (auto v = r.find("base")) e.baseZ = v->number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
  if (auto v = r.find("priority")) {
    const std::string p = v->string(64);
    if (p == "maximise_volume") e.priority = Priority::MaximiseVolume;
    else if (p == "minimise_volume") e.priority = Priority::MinimiseVolume;
    else if (p == "manual") e.priority = Priority::Manual;
    else v->fail("expected \"maximise_volume\", \"minimise_volume\" or \"manual\", found \"" + p + "\"");
  }
  std::map<std::string, int> byName;
  for (const JsonReader& pr : r.at("profiles").array(limits::kMaxProfiles)) {
    pr.expectObject();
    for (auto& k : pr.unknownKeys({"name", "points", "tags"})) warnings.push_back(k + ": unknown key kept");
    Profile p;
    const JsonReader nameReader = pr.at("name");
    p.name = nameReader.string(limits::kMaxNameLength);
    if (p.name.empty()) nameReader.fail("a profile needs a name");
    if (!byName.emplace(p.name, static_cast<int>(e.profiles.size())).second)
      nameReader.fail("profile name \"" + p.name + "\" is used twice");
    for (const JsonReader& q : pr.at("points").array(limits::kMaxProfilePoints)) p.points.push_back(q.vec2());
    if (auto t = pr.find("tags"))
      for (const JsonReader& tag : t->array(limits::kMaxProfilePoints)) p.tags.push_back(tag.string(limits::kMaxNameLength));
    e.profiles.push_back(std::move(p));
  }
  const JsonReader plan = r.at("plan");
  plan.expectObject();
  for (auto& k : plan.unknownKeys({"loops", "profile", "edge_profiles", "walls"}))
    warnings.push_back(k + ": unknown key kept");
  auto profileIndex = [&](const JsonReader& nameReader) {
    const std::string n = nameReader.string(limits::kMaxNameLength);
    auto it = byName.find(n);
    if (it == byName.end()) nameReader.fail("no profile named \"" + n + "\" in this object's profiles");
    return it->second;
  };
  int uniform = -1;
  if (auto p = plan.find("profile")) uniform = profileIndex(*p);
  else if (e.profiles.size() == 1) uniform = 0;
  std::size_t totalPoints = 0;
  for (const JsonReader& lr : plan.at("loops").array(limits::kMaxLoops)) {
    PlanLoop loop;
    for (const JsonReader& q : lr.array(limits::kMaxLoopPoints)) loop.points.push_back(q.vec2());
    totalPoints += loop.points.size();
    if (totalPoints > limits::kMaxLoopPoints) lr.fail("the plan has more than " + std::to_string(limits::kMaxLoopPoints) + " corners");
    loop.profile.assign(loop.points.size(), uniform);
    e.loops.push_back(std::move(loop));
  }
  if (auto ep = plan.find("edge_profiles")) {
    const auto lists = ep->array(limits::kMaxLoops);
    if (lists.size() != e.loops.size())
      ep->fail("expected one list per loop (" + std::to_string(e.loops.size()) + "), found " + std::to_string(lists.size()));
    for (std::size_t li = 0; li < lists.size(); ++li) {
      const auto names = lists[li].array(limits::kMaxLoopPoints);
      if (names.size() != e.loops[li].points.size())
        lists[li].fail("expected one profile per edge (" + std::to_string(e.loops[li].points.size()) + "), found " +
                       std::to_string(names.size()));
      for (std::size_t i = 0; i < names.size(); ++i) e.loops[li].profile[i] = profileIndex(names[i]);
    }
  } else if (uniform < 0) {
    plan.fail("name the edges' profile: \"profile\" for all edges or \"edge_profiles\" per edge");
  }
  // Walls: one list of ids per loop; each wall's edges follow each other in one loop.
  if (auto wr = plan.find("walls")) {
    const auto lists = wr->array(limits::kMaxLoops);
    if (lists.size() != e.loops.size())
      wr->fail("expected one list per loop (" + std::to_string(e.loops.size()) + "), found " + std::to_string(lists.size()));
    std::map<int, std::size_t> loopOfWall;
    for (std::size_t li = 0; li < lists.size(); ++li) {
      const auto ids = lists[li].array(limits::kMaxLoopPoints);
      if (ids.size() != e.loops[li].points.size())
        lists[li].fail("expected one wall per edge (" + std::to_string(e.loops[li].points.size()) + "), found " +
                       std::to_string(ids.size()));
      std::vector<int>& walls = e.loops[li].walls;
      for (const JsonReader& id : ids) walls.push_back(static_cast<int>(id.integer(1, 1L << 30)));
      const std::size_t n = walls.size();
      std::size_t runs = 0;
      for (std::size_t i = 0; i < n; ++i) {
        runs += walls[i] != walls[(i + n - 1) % n];
        const auto [it, fresh] = loopOfWall.emplace(walls[i], li);
        if (!fresh && it->second != li)
          ids[i].fail("wall " + std::to_string(walls[i]) + " is in loops " + std::to_string(it->second) + " and " +
                      std::to_string(li) + " (a wall belongs to one loop)");
      }
      std::set<int> distinct(walls.begin(), walls.end());
      if (runs > 0 && runs != distinct.size())
        lists[li].fail("each wall's edges must follow each other (a wall is one run of edges)");
    }
  }
  canonicalWalls(e);
  // Anchors: {loop, edge, fraction | at, height}; the kernel checks that they name real edges.
  auto anchorFrom = [&](const JsonReader& ar, std::set<std::string> extra) {
    ar.expectObject();
    extra.insert({"loop", "edge", "fraction", "at", "height"});
    for (auto& k : ar.unknownKeys(extra)) warnings.push_back(k + ": unknown key kept");
    Anchor a;
    a.loop = static_cast<int>(ar.at("loop").integer(0, static_cast<long>(limits::kMaxLoops)));
    a.edge = static_cast<int>(ar.at("edge").integer(0, static_cast<long>(limits::kMaxLoopPoints)));
    const auto fraction = ar.find("fraction"), at = ar.find("at");
    if (fraction && at) ar.fail("give either \"fraction\" (relative anchor) or \"at\" (absolute anchor), not both");
    if (at) {
      a.absolute = true;
      a.along = at->number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
    } else if (fraction) {
      a.along = fraction->number(0.0, 1.0);
    }
    if (auto h = ar.find("height")) a.height = h->number(0.0, limits::kMaxCoordinate);
    return a;
  };
  // Repeats (Sec. 3.6): {kind: row | grid, along, spacing, height, row_spacing}.
  auto repeatFrom = [&](const JsonReader& rr, const Anchor& a) {
    rr.expectObject();
    for (auto& k : rr.unknownKeys({"kind", "along", "spacing", "height", "row_spacing"}))
      warnings.push_back(k + ": unknown key kept");
    Repeat rep;
    const JsonReader kindReader = rr.at("kind");
    const std::string kind = kindReader.string(32);
    if (kind == "row") rep.kind = RepeatKind::Row;
    else if (kind == "grid") rep.kind = RepeatKind::Grid;
    else kindReader.fail("expected \"row\" or \"grid\", found \"" + kind + "\"");
    rep.along = rr.at("along").number();
    rep.spacing = rr.at("spacing").number();
    if (rep.kind == RepeatKind::Grid) {
      rep.height = rr.at("height").number();
      rep.rowSpacing = rr.at("row_spacing").number();
    }
    if (auto problem = checkRepeat(a, rep)) {
      const auto colon = problem->find(": ");
      rr.at(problem->substr(0, colon)).fail(problem->substr(colon + 2));
    }
    return rep;
  };
  if (auto steps = r.find("steps")) {
    for (const JsonReader& sr : steps->array(limits::kMaxSteps)) {
      sr.expectObject();
      for (auto& k : sr.unknownKeys({"name", "anchor", "shape", "width", "depth", "cant", "front_profile", "side_profile", "points", "repeat"}))
        warnings.push_back(k + ": unknown key kept");
      PlanStep st;
      if (auto v = sr.find("name")) st.name = v->string(limits::kMaxNameLength);
      st.anchor = anchorFrom(sr.at("anchor"), {});
      if (auto v = sr.find("shape")) {
        const std::string shape = v->string(32);
        if (shape == "bay") st.shape = StepShape::Bay;
        else if (shape == "forced") st.shape = StepShape::Forced;
        else if (shape != "rectangle") v->fail("expected \"rectangle\", \"bay\" or \"forced\", found \"" + shape + "\"");
      }
      if (st.shape == StepShape::Forced) {
        for (const JsonReader& q : sr.at("points").array(limits::kMaxProfilePoints)) st.points.push_back(q.vec2());
      } else {
        st.width = sr.at("width").number(0.0, limits::kMaxCoordinate);
        st.depth = sr.at("depth").number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
      }
      if (auto v = sr.find("cant")) st.cant = v->number(0.0, limits::kMaxCoordinate);
      st.frontProfile = profileIndex(sr.at("front_profile"));
      st.sideProfile = sr.find("side_profile") ? profileIndex(sr.at("side_profile")) : st.frontProfile;
      if (auto rep = sr.find("repeat")) st.repeat = repeatFrom(*rep, st.anchor);
      e.steps.push_back(std::move(st));
    }
  }
  if (auto offsets = r.find("offsets")) {
    for (const JsonReader& orr : offsets->array(limits::kMaxSteps)) {
      orr.expectObject();
      for (auto& k : orr.unknownKeys({"height", "side_profile", "edges"})) warnings.push_back(k + ": unknown key kept");
      OffsetEvent o;
      o.height = orr.at("height").number(0.0, limits::kMaxCoordinate);
      o.sideProfile = profileIndex(orr.at("side_profile"));
      for (const JsonReader& tr : orr.at("edges").array(limits::kMaxProfiles)) {
        tr.expectObject();
        for (auto& k : tr.unknownKeys({"profile", "inside", "outside", "inside_profile", "outside_profile"}))
          warnings.push_back(k + ": unknown key kept");
        OffsetEdge t;
        t.profile = profileIndex(tr.at("profile"));
        t.inside = tr.at("inside").number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
        t.outside = tr.at("outside").number(-limits::kMaxCoordinate, limits::kMaxCoordinate);
        t.insideProfile = profileIndex(tr.at("inside_profile"));
        t.outsideProfile = profileIndex(tr.at("outside_profile"));
        o.edges.push_back(t);
      }
      if (o.edges.empty()) orr.at("edges").fail("an offset event needs at least one edge");
      e.offsets.push_back(std::move(o));
    }
  }
  if (auto anchors = r.find("anchors")) {
    for (const JsonReader& ar : anchors->array(limits::kMaxSteps)) {
      MeshAnchor m;
      m.anchor = anchorFrom(ar, {"name", "feature", "size", "repeat"});
      m.name = ar.at("name").string(limits::kMaxNameLength);
      if (auto f = ar.find("feature")) {
        const std::string name = f->string(32);
        const auto kind = featureFromName(name);
        if (!kind)
          f->fail("expected \"none\", \"door\", \"window\", \"roof_window\" or \"chimney_pot\", found \"" + name + "\"");
        m.feature = *kind;
        m.size = defaultFeatureSize(m.feature);
      }
      if (auto sz = ar.find("size")) {
        const auto v = sz->array(3);
        if (v.size() != 3) sz->fail("expected [width, height, depth] in metres");
        double d[3];
        for (std::size_t i = 0; i < 3; ++i) {
          d[i] = v[i].number();
          FeatureSize probe;
          (i == 0 ? probe.width : i == 1 ? probe.height : probe.depth) = d[i];
          if (auto problem = checkFeatureSize(probe)) v[i].fail(problem->substr(problem->find(": ") + 2));
        }
        m.size = {d[0], d[1], d[2]};
      }
      if (m.feature == FeatureKind::None && ar.find("size")) {
        warnings.push_back(ar.path() + ".size: ignored: the anchor has no feature");
        m.size = FeatureSize();
      }
      if (auto rep = ar.find("repeat")) m.repeat = repeatFrom(*rep, m.anchor);
      e.anchors.push_back(std::move(m));
    }
  }
  if (auto problem = checkInstanceCounts(e)) {
    const auto colon = problem->find(": ");
    throw InputError(r.path() + "." + problem->substr(0, colon), problem->substr(colon + 2));
  }
  if (auto m = r.find("masonry")) e.masonry = stoneFromJson(*m, warnings);
  return e;
}

PlanBackground backgroundFromJson(const JsonReader& r, const std::string& folder, std::vector<std::string>& warnings) {
  r.expectObject();
  for (auto& k : r.unknownKeys({"image", "scale", "origin", "opacity"})) warnings.push_back(k + ": unknown key kept");
  PlanBackground b;
  const JsonReader image = r.at("image");
  b.image = image.string(limits::kMaxPathLength);
  if (b.image.empty()) image.fail("the image's path must not be empty");
  if (b.image.find('\0') != std::string::npos) image.fail("a path cannot hold a NUL character");
  if (!folder.empty() && std::filesystem::path(b.image).is_relative())
    b.image = (std::filesystem::path(folder) / b.image).lexically_normal().string();
  if (auto v = r.find("scale")) b.scale = v->number(limits::kMinBackgroundScale, limits::kMaxBackgroundScale);
  if (auto v = r.find("origin")) {
    b.origin = v->vec2();
    if (std::abs(b.origin[0]) > limits::kMaxCoordinate || std::abs(b.origin[1]) > limits::kMaxCoordinate)
      v->fail("must lie within 1e7 m of the origin");
  }
  if (auto v = r.find("opacity")) b.opacity = v->number(0, 1);
  return b;
}

ojson backgroundToJson(const PlanBackground& b, const std::string& folder) {
  ojson j;
  std::string image = b.image;
  if (!folder.empty() && std::filesystem::path(image).is_absolute()) {
    const std::filesystem::path rel = std::filesystem::path(image).lexically_relative(std::filesystem::path(folder).lexically_normal());
    if (!rel.empty()) image = rel.generic_string();
  }
  j["image"] = image;
  j["scale"] = b.scale;
  j["origin"] = vec2(b.origin);
  j["opacity"] = b.opacity;
  return j;
}

std::string absoluteFolderOf(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(path, ec);
  return ec ? std::string() : abs.parent_path().lexically_normal().string();
}

// The unknown keys recorded under `base` (an object's entry, or the root), relative to it and
// in the order they were met; they leave `unknown`.
std::vector<KeptKey> keptUnder(std::vector<UnknownKey>& unknown, const nlohmann::json::json_pointer& base) {
  std::vector<KeptKey> kept;
  const std::string prefix = base.to_string();
  std::erase_if(unknown, [&](const UnknownKey& k) {
    const std::string at = k.pointer.to_string();
    if (at.compare(0, prefix.size(), prefix) != 0 || at.size() == prefix.size() || at[prefix.size()] != '/')
      return false;
    kept.push_back({at.substr(prefix.size()), k.value.dump()});
    return true;
  });
  return kept;
}

// Writes kept keys back into `j` (an object's entry or the root) where their parent still is an
// object without that key; a key whose place is gone with an edit (a profile deleted, say) is
// dropped.
void putKept(ojson& j, const std::vector<KeptKey>& kept) {
  for (const KeptKey& k : kept) {
    const ojson::json_pointer at(k.pointer);
    const ojson::json_pointer parent = at.parent_pointer();
    if (!j.contains(parent)) continue;
    ojson& holder = j[parent];
    if (holder.is_object() && !holder.contains(at.back())) holder[at.back()] = ojson::parse(k.json);
  }
}

// The file's layout: a value goes on one line when that line stays within kLineWidth columns
// (a point, a short list, a small object); otherwise an object takes a line per key and an
// array a line per entry. Scalars are nlohmann's own (shortest round-trip numbers), so only
// whitespace differs from a plain dump.
constexpr std::size_t kLineWidth = 100;

std::string scalarText(const ojson& v) { return v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

std::string flatText(const ojson& v) {
  if (v.is_object()) {
    std::string out = "{";
    for (auto it = v.begin(); it != v.end(); ++it)
      out += (it == v.begin() ? "" : ", ") + scalarText(ojson(it.key())) + ": " + flatText(it.value());
    return out + "}";
  }
  if (v.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + flatText(v[i]);
    return out + "]";
  }
  return scalarText(v);
}

// Writes `v`, which starts `column` columns into its line, at `indent`.
void writeValue(std::string& out, const ojson& v, std::size_t indent, std::size_t column) {
  if ((!v.is_object() && !v.is_array()) || v.empty()) {
    out += v.is_object() ? "{}" : v.is_array() ? "[]" : scalarText(v);
    return;
  }
  if (indent > 0) {  // the root object is always broken into lines
    const std::string flat = flatText(v);
    if (column + flat.size() + 1 <= kLineWidth) {  // + 1 for a comma after it
      out += flat;
      return;
    }
  }
  const std::string inner(indent + 2, ' ');
  out += v.is_object() ? "{\n" : "[\n";
  for (auto it = v.begin(); it != v.end(); ++it) {
    out += inner;
    std::size_t at = inner.size();
    if (v.is_object()) {
      const std::string key = scalarText(ojson(it.key())) + ": ";
      out += key;
      at += key.size();
    }
    writeValue(out, it.value(), indent + 2, at);
    out += std::next(it) == v.end() ? "\n" : ",\n";
  }
  out += std::string(indent, ' ') + (v.is_object() ? "}" : "]");
}

}  // namespace

LoadedProject parseProject(const std::string& text, const std::string& folder) {
  const nlohmann::json root = parseJsonText(text);
  std::vector<UnknownKey> unknown;  // every unknown key the readers below meet, in file order
  JsonReader r(root, "", &unknown);
  if (!root.is_object()) r.fail("a project file must hold a JSON object");
  LoadedProject out;
  const std::string format = r.at("format").string(64);
  if (format != "corbel") r.at("format").fail("expected \"corbel\", found \"" + format + "\"");
  const long version = r.at("version").integer(0, 1L << 30);
  if (version > kProjectVersion)
    r.at("version").fail("this file was written by a newer corbel (format version " + std::to_string(version) +
                         "); this build reads versions up to " + std::to_string(kProjectVersion) +
                         ". Update corbel to open it.");
  if (version < 1) r.at("version").fail("format version must be at least 1");
  for (auto& k : r.unknownKeys({"format", "version", "name", "objects"}))
    out.warnings.push_back(k + ": unknown key kept");

  Document& doc = out.document;
  if (auto n = r.find("name")) doc.name = n->string(limits::kMaxNameLength);
  std::set<ObjectId> ids;
  std::set<std::string> names;
  if (auto objs = r.find("objects")) {
    for (const JsonReader& o : objs->array(limits::kMaxObjects)) {
      o.expectObject();
      DocObject obj;
      const JsonReader idReader = o.at("id");
      obj.id = static_cast<ObjectId>(idReader.integer(1, 0x7fffffff));
      if (!ids.insert(obj.id).second) idReader.fail("id " + std::to_string(obj.id) + " is used twice");
      const JsonReader nameReader = o.at("name");
      obj.name = nameReader.string(limits::kMaxNameLength);
      if (obj.name.empty()) nameReader.fail("name must not be empty");
      if (!names.insert(obj.name).second) nameReader.fail("name \"" + obj.name + "\" is used twice");
      if (auto v = o.find("visible")) obj.visible = v->boolean();
      static const std::set<std::string> specKeys = {"box", "extrusion", "masonry", "kifs", "growth", "unit", "town"};
      int specCount = 0;
      for (const auto& key : specKeys) specCount += o.find(key) ? 1 : 0;
      if (specCount == 0)
        o.fail("no spec: expected one of \"box\", \"extrusion\", \"masonry\", \"kifs\", \"growth\", \"unit\", \"town\"");
      if (specCount > 1) o.fail("more than one spec: an object has exactly one");
      if (auto b = o.find("box")) obj.spec = boxFromJson(*b, out.warnings);
      else if (auto m = o.find("masonry")) obj.spec = masonryFromJson(*m, out.warnings);
      else if (auto k = o.find("kifs")) obj.spec = kifsFromJson(*k, out.warnings);
      else if (auto g = o.find("growth")) obj.spec = growthFromJson(*g, out.warnings);
      else if (auto u = o.find("unit")) obj.spec = unitFromJson(*u, out.warnings);
      else if (auto t = o.find("town")) obj.spec = townFromJson(*t, folder, out.warnings);
      else obj.spec = extrusionFromJson(o.at("extrusion"), out.warnings);
      if (auto bg = o.find("plan_background")) obj.background = backgroundFromJson(*bg, folder, out.warnings);
      // Version 1 had no placements: such an object stands where its kernel builds it. A
      // "placement" or "locked" key in a version-1 file is not corbel's, and kept it would be
      // read as one once saved as version 2: it is dropped, with a warning.
      std::set<std::string> objectKeys = {"id", "name", "visible", "box", "extrusion", "masonry", "kifs", "growth",
                                          "unit", "town", "plan_background", "placement", "locked"};
      if (version >= 2) {
        if (auto v = o.find("locked")) obj.locked = v->boolean();
        if (auto pl = o.find("placement")) obj.placement = placementFromJson(*pl, obj.spec, out.warnings);
      } else {
        for (const char* key : {"placement", "locked"})
          if (o.find(key))
            out.warnings.push_back(o.path() + (o.path().empty() ? "" : ".") + key +
                                   ": not part of format version 1 (this file's); dropped");
      }
      for (auto& k : o.unknownKeys(objectKeys))
        out.warnings.push_back(k + ": unknown key kept");
      obj.kept = keptUnder(unknown, o.pointer());
      doc.objects.push_back(std::move(obj));
    }
  }
  doc.kept = keptUnder(unknown, r.pointer());
  return out;
}

LoadedProject loadProject(const std::string& path) {
  const std::string text = readFile(path, kMaxProjectBytes);
  try {
    return parseProject(text, absoluteFolderOf(path));
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

std::string serializeProject(const Document& doc, const std::string& folder) {
  ojson root;
  root["format"] = "corbel";
  root["version"] = kProjectVersion;
  root["name"] = doc.name;
  ojson objects = ojson::array();
  for (const DocObject& o : doc.objects) {
    ojson j;
    j["id"] = o.id;
    j["name"] = o.name;
    j["visible"] = o.visible;
    if (o.locked) j["locked"] = true;
    if (const auto* b = std::get_if<BoxSpec>(&o.spec)) j["box"] = boxToJson(*b);
    else if (const auto* m = std::get_if<MasonrySpec>(&o.spec)) j["masonry"] = masonryToJson(*m);
    else if (const auto* k = std::get_if<KifsSpec>(&o.spec)) j["kifs"] = kifsToJson(*k);
    else if (const auto* g = std::get_if<GrowthSpec>(&o.spec)) j["growth"] = growthToJson(*g);
    else if (const auto* u = std::get_if<UnitSpec>(&o.spec)) j["unit"] = unitToJson(*u);
    else if (const auto* t = std::get_if<TownSpec>(&o.spec)) j["town"] = townToJson(*t, folder);
    else j["extrusion"] = extrusionToJson(std::get<ExtrusionSpec>(o.spec));
    if (o.background) j["plan_background"] = backgroundToJson(*o.background, folder);
    // An identity placement is left out, unless it holds a key kept from the file (which would
    // be lost with it).
    const bool keptInPlacement = std::any_of(o.kept.begin(), o.kept.end(),
                                             [](const KeptKey& k) { return k.pointer.rfind("/placement/", 0) == 0; });
    if (!o.placement.identity() || keptInPlacement) j["placement"] = placementToJson(o.placement);
    putKept(j, o.kept);
    objects.push_back(std::move(j));
  }
  root["objects"] = std::move(objects);
  putKept(root, doc.kept);
  std::string text;
  writeValue(text, root, 0, 0);
  return text + "\n";
}

void saveProject(const Document& doc, const std::string& path) {
  writeFileAtomic(path, serializeProject(doc, absoluteFolderOf(path)));
}

}  // namespace corbel
