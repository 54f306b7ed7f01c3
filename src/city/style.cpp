#include "city/style.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "core/textures.h"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <set>

namespace corbel::city {

namespace {

void rejectUnknown(const JsonReader& r, const std::set<std::string>& known) {
  if (const auto extra = r.unknownKeys(known); !extra.empty()) {
    std::string names;
    for (const auto& k : known) names += (names.empty() ? "" : ", ") + k;
    throw InputError(extra.front(), "unknown key (expected one of: " + names + ")");
  }
}

std::pair<double, double> range(const JsonReader& r, double lo, double hi) {
  const auto v = r.array(2);
  if (v.size() != 2) r.fail("expected [min, max]");
  const double a = v[0].number(lo, hi), b = v[1].number(lo, hi);
  if (a > b) r.fail("min is greater than max");
  return {a, b};
}

extrude::FeatureSize featureSize(const JsonReader& r) {
  const Vec3 v = r.vec3();
  for (int k = 0; k < 3; ++k)
    if (!(v[k] > 0 && v[k] <= 1000)) r.fail("each size must be greater than 0 and at most 1000 m");
  return {v[0], v[1], v[2]};
}

BuildingCondition buildingCondition(const std::optional<JsonReader>& r) {
  BuildingCondition c;
  if (!r) return c;
  r->expectObject();
  rejectUnknown(*r, {"area", "depth", "property"});
  if (auto a = r->find("area")) std::tie(c.minArea, c.maxArea) = range(*a, 0, 1e12);
  if (auto d = r->find("depth")) std::tie(c.minDepth, c.maxDepth) = range(*d, 0, 1e12);
  if (auto p = r->find("property")) {
    p->expectObject();
    for (auto& [key, value] : p->raw().items()) {
      JsonReader v(value, p->path() + "." + key);
      if (value.is_object()) {
        rejectUnknown(v, {"range"});
        c.propertyRange[key] = range(v.at("range"), -1e12, 1e12);
      } else if (value.is_array())
        for (const auto& e : v.array(1000)) c.property[key].push_back(e.raw());
      else
        c.property[key].push_back(value);
    }
  }
  return c;
}

EdgeCondition edgeCondition(const std::optional<JsonReader>& r) {
  EdgeCondition c;
  if (!r) return c;
  r->expectObject();
  rejectUnknown(*r, {"orientation", "length", "angle"});
  if (auto o = r->find("orientation"))
    for (const auto& e : o->array(3)) {
      const auto v = orientationFromName(e.string(16));
      if (!v) e.fail("expected \"street\", \"side\" or \"back\"");
      c.orientation.push_back(*v);
    }
  if (auto l = r->find("length"))
    for (const auto& e : l->array(3)) {
      const auto v = lengthFromName(e.string(16));
      if (!v) e.fail("expected \"short\", \"medium\" or \"long\"");
      c.length.push_back(*v);
    }
  if (auto a = r->find("angle")) std::tie(c.minAngle, c.maxAngle) = range(*a, -180, 180);
  return c;
}

// "name", or {"name": weight, ...}, against a name table.
std::vector<Weighted> weighted(const JsonReader& r, const std::map<std::string, int>& names, const char* what) {
  std::vector<Weighted> out;
  auto lookup = [&](const std::string& name, const JsonReader& at) {
    auto it = names.find(name);
    if (it == names.end()) at.fail(std::string("no ") + what + " named \"" + name + "\"");
    return it->second;
  };
  if (r.raw().is_string()) {
    out.push_back({lookup(r.string(200), r), 1});
  } else {
    r.expectObject();
    for (auto& [key, value] : r.raw().items()) {
      JsonReader w(value, r.path() + "." + key);
      out.push_back({lookup(key, r), w.number(0, 1e9)});
    }
    double total = 0;
    for (const auto& w : out) total += w.weight;
    if (out.empty() || total <= 0) r.fail("expected at least one entry with a weight above 0");
  }
  return out;
}

std::string checkProfile(const extrude::Profile& p) {
  const auto& q = p.points;
  if (q.size() < 2) return "a profile needs at least two points";
  if (q[0] != Vec2(0, 0)) return "a profile starts at [0, 0]";
  for (std::size_t i = 1; i < q.size(); ++i)
    if (q[i][1] < q[i - 1][1]) return "points[" + std::to_string(i) + "]: a profile must not go down";
  if (q[1][1] == q[0][1]) return "the first segment must rise";
  if (q.back()[1] == q[q.size() - 2][1]) return "the last segment must rise";
  if (q.back()[0] < q[q.size() - 2][0]) return "the last segment must not lean outward";
  if (p.tags.size() > q.size() - 1) return "tags: more tags than segments";
  return {};
}

// A tag's texture: "name" or {"texture": "name", "metres": m}, the name one of the built-in
// textures and m the metres of one repeat (default: the texture's own tile).
SurfaceTexture tagTexture(const JsonReader& r) {
  SurfaceTexture t;
  std::optional<JsonReader> name;
  if (r.raw().is_string()) {
    name.emplace(r);
  } else if (r.raw().is_object()) {
    rejectUnknown(r, {"texture", "metres"});
    name.emplace(r.at("texture"));
    if (auto m = r.find("metres")) {
      t.metres = m->number();
      if (!(t.metres > 0 && t.metres <= 1e4))
        m->fail("the metres of one repeat must be greater than 0 and at most 10000");
    }
  } else {
    r.fail("expected a texture name or {\"texture\": name, \"metres\": m}");
  }
  t.name = name->string(200);
  if (!materialTexture(t.name)) {
    std::string known;
    for (std::string_view n : builtinTextureNames()) known += (known.empty() ? "" : ", ") + std::string(n);
    name->fail("no built-in texture named \"" + t.name + "\" (expected one of: " + known + ")");
  }
  return t;
}

void parseInto(Style& s, const nlohmann::json& root, const std::string& folder, int depth) {
  JsonReader r(root, "");
  r.expectObject();
  rejectUnknown(r, {"name", "labels", "use", "profiles", "types", "by_size", "assign", "tag_materials", "tag_textures", "heights"});
  // The styles this one uses first, so its own name and labels win.
  if (auto u = r.find("use")) {
    if (depth > 8) u->fail("styles use each other more than 8 deep (a cycle?)");
    for (const auto& e : u->array(100)) {
      const std::string path = (std::filesystem::path(folder) / e.string(4096)).string();
      try {
        parseInto(s, parseJsonText(readFile(path, std::size_t(1) << 26)),
                  std::filesystem::path(path).parent_path().string(), depth + 1);
      } catch (const InputError& err) {
        throw InputError(e.path() + ": " + path + (err.where.empty() ? "" : ": " + err.where), err.reason);
      } catch (const Error& err) {
        e.fail(err.what());
      }
    }
  }
  if (auto n = r.find("name")) s.name = n->string(200);
  if (auto l = r.find("labels")) {
    l->expectObject();
    rejectUnknown(*l, {"short_below", "long_from", "street_degrees"});
    if (auto v = l->find("short_below")) s.labels.shortBelow = v->number(0, 1000);
    if (auto v = l->find("long_from")) s.labels.longFrom = v->number(0, 1000);
    if (auto v = l->find("street_degrees")) s.labels.streetDegrees = v->number(0, 90);
    if (s.labels.longFrom < s.labels.shortBelow) l->fail("long_from is less than short_below");
  }
  if (auto h = r.find("heights")) {  // replaces the used styles'
    h->expectObject();
    rejectUnknown(*h, {"walls", "levels", "storey"});
    HeightRule rule;
    auto names = [](const JsonReader& v) {
      std::vector<std::string> out;
      if (v.raw().is_string()) out.push_back(v.string(200));
      else
        for (const auto& e : v.array(100)) out.push_back(e.string(200));
      return out;
    };
    if (auto v = h->find("walls")) rule.walls = names(*v);
    if (auto v = h->find("levels")) rule.levels = names(*v);
    if (auto v = h->find("storey")) rule.storey = v->number(1, 100);
    if (rule.walls.empty() && rule.levels.empty()) h->fail("names no attribute: give \"walls\" or \"levels\" (or both)");
    s.heights = rule;
  }
  if (auto m = r.find("tag_materials")) {
    m->expectObject();
    for (auto& [tag, value] : m->raw().items())
      s.tagMaterials[tag] = JsonReader(value, m->path() + "." + tag).string(200);
  }
  if (auto m = r.find("tag_textures")) {
    m->expectObject();
    for (auto& [tag, value] : m->raw().items()) {
      const JsonReader v = *m->find(tag);
      if (tag.empty()) v.fail("the empty tag names no faces (faces without a tag keep their material's texture)");
      s.tagTextures[tag] = tagTexture(v);
    }
  }
  std::map<std::string, int> profileNames, typeNames;
  for (std::size_t i = 0; i < s.profiles.size(); ++i) profileNames[s.profiles[i].name] = static_cast<int>(i);
  for (std::size_t i = 0; i < s.types.size(); ++i) typeNames[s.types[i].name] = static_cast<int>(i);

  if (auto ps = r.find("profiles"))
    for (const auto& pr : ps->array(10000)) {
      pr.expectObject();
      rejectUnknown(pr, {"name", "points", "tags"});
      extrude::Profile p;
      p.name = pr.at("name").string(200);
      for (const auto& q : pr.at("points").array(1000)) p.points.push_back(q.vec2());
      if (auto t = pr.find("tags"))
        for (const auto& e : t->array(1000)) p.tags.push_back(e.string(200));
      if (const std::string why = checkProfile(p); !why.empty()) pr.fail(why);
      if (profileNames.count(p.name)) pr.at("name").fail("a second profile named \"" + p.name + "\"");
      profileNames[p.name] = static_cast<int>(s.profiles.size());
      s.profiles.push_back(std::move(p));
    }

  auto profileIndex = [&](const JsonReader& at) {
    const std::string name = at.string(200);
    auto it = profileNames.find(name);
    if (it == profileNames.end()) at.fail("no profile named \"" + name + "\"");
    return it->second;
  };

  if (auto ts = r.find("types"))
    for (const auto& tr : ts->array(1000)) {
      tr.expectObject();
      rejectUnknown(
          tr, {"name", "when", "weight", "material", "roof_material", "priority", "edges", "windows", "door", "steps",
               "parapet"});
      BuildingType t;
      t.name = tr.at("name").string(200);
      if (typeNames.count(t.name)) tr.at("name").fail("a second building type named \"" + t.name + "\"");
      t.when = buildingCondition(tr.find("when"));
      if (auto w = tr.find("weight")) t.weight = w->number(0, 1e9);
      if (auto m = tr.find("material")) t.material = m->string(200);
      if (auto m = tr.find("roof_material")) t.roofMaterial = m->string(200);
      if (auto p = tr.find("priority")) {
        const std::string name = p->string(100);
        if (name == "maximise_volume") t.priority = Priority::MaximiseVolume;
        else if (name == "minimise_volume") t.priority = Priority::MinimiseVolume;
        else if (name == "manual") t.priority = Priority::Manual;
        else p->fail("expected \"maximise_volume\", \"minimise_volume\" or \"manual\", found \"" + name + "\"");
      }
      const auto edges = tr.at("edges").array(1000);
      if (edges.empty()) tr.at("edges").fail("a building type needs at least one edge rule");
      for (const auto& er : edges) {
        er.expectObject();
        rejectUnknown(er, {"when", "profiles"});
        t.edges.push_back({edgeCondition(er.find("when")), weighted(er.at("profiles"), profileNames, "profile")});
      }
      if (auto ws = tr.find("windows"))
        for (const auto& wr : ws->array(100)) {
          wr.expectObject();
          rejectUnknown(wr, {"when", "min_length", "margin", "spacing", "sill", "floors", "floor_height", "size"});
          WindowRule w;
          w.when = edgeCondition(wr.find("when"));
          if (auto v = wr.find("min_length")) w.minLength = v->number(0, 1e4);
          if (auto v = wr.find("margin")) w.margin = v->number(0, 1e4);
          if (auto v = wr.find("spacing")) w.spacing = v->number(0.1, 1e4);
          if (auto v = wr.find("sill")) w.sill = v->number(0, 1e4);
          if (auto v = wr.find("floors")) w.floors = static_cast<int>(v->integer(1, 200));
          if (auto v = wr.find("floor_height")) w.floorHeight = v->number(0.5, 100);
          if (auto v = wr.find("size")) w.size = featureSize(*v);
          t.windows.push_back(w);
        }
      if (auto d = tr.find("door")) {
        if (d->raw().is_boolean()) {
          if (d->boolean()) t.door = extrude::FeatureSize{1.0, 2.2, 0.15};
        } else {
          t.door = featureSize(*d);
        }
      }
      if (auto ss = tr.find("steps"))
        for (const auto& sr : ss->array(100)) {
          sr.expectObject();
          rejectUnknown(sr, {"when", "chance", "height", "width", "depth", "min_length", "margin", "spacing", "along",
                             "row", "front_profile", "side_profile"});
          StepRule st;
          st.when = edgeCondition(sr.find("when"));
          if (auto v = sr.find("chance")) st.chance = v->number(0, 1);
          st.height = sr.at("height").number(0, 1e4);
          if (auto v = sr.find("width")) st.width = v->number(0.01, 1e3);
          if (auto v = sr.find("depth")) st.depth = v->number(-1e3, 1e3);
          if (auto v = sr.find("min_length")) st.minLength = v->number(0, 1e4);
          if (auto v = sr.find("margin")) st.margin = v->number(0, 1e4);
          if (auto v = sr.find("spacing")) st.spacing = v->number(0.1, 1e4);
          if (auto v = sr.find("along")) st.along = v->number(0, 1);
          if (auto v = sr.find("row")) st.row = v->boolean();
          st.frontProfile = profileIndex(sr.at("front_profile"));
          st.sideProfile = sr.find("side_profile") ? profileIndex(sr.at("side_profile")) : st.frontProfile;
          t.steps.push_back(st);
        }
      if (auto p = tr.find("parapet")) {
        p->expectObject();
        rejectUnknown(*p, {"height", "thickness", "inside_profile"});
        ParapetRule pr;
        pr.height = p->at("height").number(0.01, 1e4);
        if (auto v = p->find("thickness")) pr.thickness = v->number(0.01, 100);
        pr.insideProfile = profileIndex(p->at("inside_profile"));
        t.parapet = pr;
      }
      typeNames[t.name] = static_cast<int>(s.types.size());
      s.types.push_back(std::move(t));
    }

  // The using style's rules replace those of the styles it uses.
  auto rules = [&](const char* key, std::vector<AssignRule>& out) {
    const auto as = r.find(key);
    if (!as) return;
    out.clear();
    for (const auto& ar : as->array(1000)) {
      ar.expectObject();
      rejectUnknown(ar, {"when", "types"});
      out.push_back({buildingCondition(ar.find("when")), weighted(ar.at("types"), typeNames, "building type")});
    }
  };
  rules("by_size", s.bySize);
  rules("assign", s.assign);
}

// A property as a number: a JSON number, or a string that is one, optionally in metres
// ("12.5", "12.5 m", as OpenStreetMap's height tags are written).
std::optional<double> numberOf(const nlohmann::json& v) {
  if (v.is_number()) return v.get<double>();
  if (!v.is_string()) return std::nullopt;
  const std::string& s = v.get_ref<const std::string&>();
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(d)) return std::nullopt;
  std::string rest(end);
  std::erase(rest, ' ');
  if (!rest.empty() && rest != "m") return std::nullopt;
  return d;
}

bool sameValue(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) return a.get<double>() == b.get<double>();
  return a == b;
}


// The net horizontal move of a profile at each height where it has one, m (negative outward);
// consecutive horizontal segments at one height add up, as in the kernel.
std::map<double, double> horizontalMoves(const extrude::Profile& p) {
  std::map<double, double> moves;
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i)
    if (p.points[i + 1][1] == p.points[i][1]) moves[p.points[i][1]] += p.points[i + 1][0] - p.points[i][0];
  std::erase_if(moves, [](const auto& m) { return m.second == 0; });
  return moves;
}

bool movesOutward(const std::map<double, double>& moves) {
  return std::any_of(moves.begin(), moves.end(), [](const auto& m) { return m.second < 0; });
}

std::string decimals(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Takes the overhangs off both edges of every convex corner that the kernel's mitre limit would
// refuse (see styleBuilding), until none is left; each corner so treated gets a warning.
void clipSharpOverhangs(extrude::ExtrusionSpec& spec, std::vector<std::string>& warnings) {
  std::map<int, std::map<double, double>> moves;
  auto movesOf = [&](int p) -> const std::map<double, double>& {
    auto it = moves.find(p);
    if (it == moves.end()) it = moves.emplace(p, horizontalMoves(spec.profiles[p])).first;
    return it->second;
  };
  std::map<int, int> variant;  // profile -> its variant without overhang
  auto plain = [&](int p) {
    if (!movesOutward(movesOf(p))) return p;
    auto it = variant.find(p);
    if (it == variant.end()) {
      spec.profiles.push_back(withoutOverhang(spec.profiles[p]));
      it = variant.emplace(p, static_cast<int>(spec.profiles.size() - 1)).first;
    }
    return it->second;
  };
  for (bool again = true; again;) {
    again = false;
    for (std::size_t li = 0; li < spec.loops.size(); ++li) {
      auto& loop = spec.loops[li];
      const std::size_t n = loop.points.size();
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t ea = (j + n - 1) % n, eb = j;
        const Vec2 da = loop.points[j] - loop.points[ea], db = loop.points[(j + 1) % n] - loop.points[j];
        const auto &ma = movesOf(loop.profile[ea]), &mb = movesOf(loop.profile[eb]);
        std::set<double> heights;
        for (const auto& m : ma) heights.insert(m.first);
        for (const auto& m : mb) heights.insert(m.first);
        for (const double h : heights) {
          const double ka = ma.count(h) ? ma.at(h) : 0.0, kb = mb.count(h) ? mb.at(h) : 0.0;
          if (!(ka < 0 || kb < 0)) continue;
          const double move = std::max(std::abs(ka), std::abs(kb)), pushed = cornerMove(da, db, ka, kb);
          if (pushed <= kMitreLimit * move) continue;
          const double degrees = std::acos(std::clamp(-da.dot(db) / (da.norm() * db.norm()), -1.0, 1.0)) * 180 /
                                 std::numbers::pi;
          const std::string before = spec.profiles[loop.profile[ea]].name, after = spec.profiles[loop.profile[eb]].name;
          loop.profile[ea] = plain(loop.profile[ea]);
          loop.profile[eb] = plain(loop.profile[eb]);
          warnings.push_back("loops[" + std::to_string(li) + "].points[" + std::to_string(j) + "]: at height " +
                             decimals(h, 2) + " m the " + decimals(move, 2) + " m overhang would push this " +
                             decimals(degrees, 1) + "° corner " + decimals(pushed, 1) + " m out, more than the mitre limit of " +
                             decimals(kMitreLimit, 0) + " times the overhang: edges " + std::to_string(ea) + " and " +
                             std::to_string(eb) + " are built without their overhang");
          again = true;
          break;
        }
      }
    }
  }
}

// Fits a repeat within `budget` instances: a grid that would pass it is spread over the same
// span with fewer, wider-spaced columns (all its rows kept), or left with none when not one
// column of its rows fits. Returns how many it has.
std::size_t fitRepeat(const extrude::ExtrusionSpec& spec, const extrude::Anchor& anchor, extrude::Repeat& repeat,
                      std::size_t budget) {
  const RepeatGrid wanted = repeatGrid(spec, anchor, repeat);
  if (wanted.count() <= budget) return wanted.count();
  if (wanted.rows > budget) return 0;
  const std::size_t columns = budget / wanted.rows;
  if (columns <= 1) {
    repeat.along = anchor.along;
  } else {
    repeat.spacing = (repeat.along - anchor.along) / static_cast<double>(columns - 1);
    while (repeatGrid(spec, anchor, repeat).count() > budget) repeat.spacing *= 1 + 1e-9;
  }
  return repeatGrid(spec, anchor, repeat).count();
}

// Keeps the instances of `items` (the spec's mesh anchors or steps) within `limit`: when their
// repeats would make more, each repeat is thinned in proportion (its share of what the single
// items leave is its share of what the repeats wanted, rounded down), so every edge keeps some
// where the limit allows; a repeat left with none is dropped. One warning says how many were
// wanted and how many are left.
template <class Item>
void thinRepeats(const extrude::ExtrusionSpec& spec, std::vector<Item>& items, std::size_t limit, const char* what,
                 std::vector<std::string>& warnings) {
  double repeated = 0;
  std::size_t single = 0;
  for (const Item& it : items) {
    const std::size_t n = repeatGrid(spec, it.anchor, it.repeat).count();
    if (it.repeat.kind == extrude::RepeatKind::None) single += n;
    else repeated += static_cast<double>(n);
  }
  if (static_cast<double>(single) + repeated <= static_cast<double>(limit)) return;
  const double room = static_cast<double>(limit > single ? limit - single : 0);
  std::vector<Item> kept;
  std::size_t left = 0;
  for (Item& it : items) {
    std::size_t n = 1;
    if (it.repeat.kind != extrude::RepeatKind::None) {
      const double share = static_cast<double>(repeatGrid(spec, it.anchor, it.repeat).count()) / repeated;
      n = fitRepeat(spec, it.anchor, it.repeat, static_cast<std::size_t>(std::floor(share * room)));
    }
    if (n > 0 && left + n <= limit) {
      left += n;
      kept.push_back(std::move(it));
    }
  }
  warnings.push_back(std::to_string(static_cast<std::size_t>(repeated) + single) + " " + what + " thinned to " +
                     std::to_string(left) + " (at most " + std::to_string(limit) + " per building)");
  items = std::move(kept);
}

}  // namespace

bool BuildingCondition::matches(const Building& b) const {
  if (b.area < minArea || b.area > maxArea) return false;
  if (b.depth < minDepth || b.depth > maxDepth) return false;
  for (const auto& [key, values] : property) {
    auto it = b.properties.find(key);
    if (it == b.properties.end()) return false;
    bool any = false;
    for (const auto& v : values) any = any || sameValue(*it, v);
    if (!any) return false;
  }
  for (const auto& [key, r] : propertyRange) {
    auto it = b.properties.find(key);
    if (it == b.properties.end()) return false;
    const std::optional<double> v = numberOf(*it);
    if (!v || *v < r.first || *v > r.second) return false;
  }
  return true;
}

bool EdgeCondition::matches(const EdgeLabel& e) const {
  auto in = [](const auto& list, auto v) {
    return list.empty() || std::find(list.begin(), list.end(), v) != list.end();
  };
  return in(orientation, e.orientation) && in(length, e.length_class) && e.angle >= minAngle && e.angle <= maxAngle;
}

void applyTagMaterials(const Style& style, MeshData& mesh) {
  if (style.tagMaterials.empty()) return;
  std::vector<int> remap(mesh.tags.size(), -1);
  for (std::size_t t = 0; t < mesh.tags.size(); ++t)
    if (auto it = style.tagMaterials.find(mesh.tags[t]); it != style.tagMaterials.end())
      remap[t] = mesh.addMaterial(it->second);
  for (std::size_t f = 0; f < mesh.faceTag.size() && f < mesh.faceMaterial.size(); ++f)
    if (const int t = mesh.faceTag[f]; t >= 0 && static_cast<std::size_t>(t) < remap.size() && remap[t] >= 0)
      mesh.faceMaterial[f] = remap[t];
}

TagTextures tagTexturesOf(const Style& style) {
  if (style.tagTextures.empty()) return {};
  const auto* table = &style.tagTextures;
  return [table](ObjectId, const std::string& tag) -> const SurfaceTexture* {
    const auto it = table->find(tag);
    return it == table->end() ? nullptr : &it->second;
  };
}

double cornerMove(const Vec2& daIn, const Vec2& dbIn, double ka, double kb) {
  if (daIn.norm() == 0 || dbIn.norm() == 0) return 0;
  const Vec2 da = daIn / daIn.norm(), db = dbIn / dbIn.norm();
  const double sine = da[0] * db[1] - da[1] * db[0];
  if (sine <= 0 || da.dot(db) > 0) return 0;
  // Where the two moved lines meet: n·v = k for each, n the inward (left) normal.
  const Vec2 na(-da[1], da[0]), nb(-db[1], db[0]);
  const double det = na[0] * nb[1] - na[1] * nb[0];
  return Vec2((ka * nb[1] - kb * na[1]) / det, (na[0] * kb - nb[0] * ka) / det).norm();
}

extrude::Profile withoutOverhang(const extrude::Profile& p) {
  const std::map<double, double> moves = horizontalMoves(p);
  extrude::Profile out;
  out.name = p.name + " (no overhang)";
  if (p.points.empty()) return out;
  out.points.push_back(p.points[0]);
  double shift = 0;
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const Vec2 &a = p.points[i], &b = p.points[i + 1];
    if (b[1] == a[1]) {
      const auto m = moves.find(a[1]);
      if (m != moves.end() && m->second < 0) {
        shift -= b[0] - a[0];
        continue;
      }
    }
    out.points.push_back(b + Vec2(shift, 0));
    if (i < p.tags.size()) out.tags.push_back(p.tags[i]);
  }
  return out;
}

Style parseStyle(const std::string& text, const std::string& folder) {
  Style s;
  parseInto(s, parseJsonText(text), folder, 0);
  if (s.types.empty()) throw InputError("types", "a style needs at least one building type");
  return s;
}

Style loadStyle(const std::string& path) {
  try {
    return parseStyle(readFile(path, std::size_t(1) << 26), std::filesystem::path(path).parent_path().string());
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

BuildingRandom::BuildingRandom(std::uint64_t seed, const std::string& id) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : id) h = (h ^ c) * 1099511628211ULL;
  state_ = seed * 0x9E3779B97F4A7C15ULL ^ h;
}

double BuildingRandom::uniform() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

std::size_t BuildingRandom::pick(const std::vector<Weighted>& choices) {
  double total = 0;
  for (const auto& c : choices) total += c.weight;
  double u = uniform() * total;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (u < choices[i].weight) return i;
    u -= choices[i].weight;
  }
  for (std::size_t i = choices.size(); i-- > 0;)
    if (choices[i].weight > 0) return i;
  return 0;
}

std::optional<std::size_t> assignType(const Style& style, const Building& b, BuildingRandom& random) {
  for (const auto& rule : style.bySize)
    if (rule.when.matches(b)) return static_cast<std::size_t>(rule.types[random.pick(rule.types)].index);
  if (!style.assign.empty()) {
    for (const auto& rule : style.assign)
      if (rule.when.matches(b)) return static_cast<std::size_t>(rule.types[random.pick(rule.types)].index);
    return std::nullopt;
  }
  std::vector<Weighted> candidates;
  for (std::size_t i = 0; i < style.types.size(); ++i)
    if (style.types[i].weight > 0 && style.types[i].when.matches(b))
      candidates.push_back({static_cast<int>(i), style.types[i].weight});
  if (candidates.empty()) return std::nullopt;
  return static_cast<std::size_t>(candidates[random.pick(candidates)].index);
}

double wallTop(const extrude::Profile& p) {
  double top = 0;
  for (std::size_t i = 1; i < p.points.size() && p.points[i][0] == p.points[0][0]; ++i) top = p.points[i][1];
  return top;
}

extrude::Profile withWallHeight(const extrude::Profile& p, double height) {
  std::size_t k = 0;  // the wall's last point
  while (k + 1 < p.points.size() && p.points[k + 1][0] == p.points[0][0]) ++k;
  const double shift = height - p.points[k][1];
  extrude::Profile out;
  out.name = p.name;
  out.points = {p.points[0], Vec2(p.points[0][0], height)};
  auto tag = [&](std::size_t i) { return i < p.tags.size() ? p.tags[i] : std::string(); };
  out.tags.push_back(k == 0 ? std::string("wall") : tag(0));
  for (std::size_t i = k + 1; i < p.points.size(); ++i) {
    out.points.emplace_back(p.points[i][0], p.points[i][1] + shift);
    out.tags.push_back(tag(i - 1));
  }
  while (!out.tags.empty() && out.tags.back().empty()) out.tags.pop_back();
  return out;
}

std::optional<double> wallHeightOf(const Style& style, const Building& b, std::string* warning) {
  if (!style.heights || !b.properties.is_object()) return std::nullopt;
  auto valid = [&](const std::string& key, double v) -> std::optional<double> {
    if (v >= 2 && v <= 1000) return v;
    if (warning) *warning = "\"" + key + "\" gives walls " + decimals(v, 2) + " m tall, outside 2 to 1000 m: ignored";
    return std::nullopt;
  };
  for (const std::string& key : style.heights->walls)
    if (auto it = b.properties.find(key); it != b.properties.end())
      if (const auto v = numberOf(*it)) return valid(key, *v);
  for (const std::string& key : style.heights->levels)
    if (auto it = b.properties.find(key); it != b.properties.end())
      if (const auto v = numberOf(*it)) return valid(key, *v * style.heights->storey);
  return std::nullopt;
}

StyledBuilding styleBuilding(const Style& style, const Building& b, const BuildingLabels& labels, std::uint64_t seed,
                             const BuildingOverride* override) {
  StyledBuilding out;
  BuildingRandom random(seed, b.id);
  auto ti = assignType(style, b, random);
  if (override && override->type) ti = override->type;
  if (!ti) {
    out.problem = "no building type of the style applies (area " + std::to_string(b.area) + " m²)";
    return out;
  }
  const BuildingType& t = style.types[*ti];
  out.type = t.name;
  extrude::ExtrusionSpec& spec = out.spec;
  spec.profiles = style.profiles;
  spec.material = t.material;
  spec.roofMaterial = t.roofMaterial;
  spec.priority = t.priority;
  for (const auto& ring : b.loops) spec.loops.push_back({ring, std::vector<int>(ring.size(), 0)});
  std::set<int> used;
  for (const EdgeLabel& e : labels.edges) {
    const EdgeRule* rule = nullptr;
    for (const auto& er : t.edges)
      if (er.when.matches(e)) {
        rule = &er;
        break;
      }
    if (!rule) {
      out.problem = "loops[" + std::to_string(e.loop) + "] edge " + std::to_string(e.edge) + " (" +
                    std::string(orientationName(e.orientation)) + ", " + std::string(lengthName(e.length_class)) +
                    ", " + std::to_string(static_cast<int>(std::lround(e.angle))) + "°): no edge rule of type \"" +
                    t.name + "\" applies";
      return out;
    }
    int p = rule->profiles[random.pick(rule->profiles)].index;
    if (override) {
      if (auto it = override->profiles.find(e.orientation); it != override->profiles.end()) p = it->second;
      if (auto it = override->edges.find({e.loop, e.edge}); it != override->edges.end()) p = it->second;
    }
    spec.loops[e.loop].profile[e.edge] = p;
  }
  clipSharpOverhangs(spec, out.warnings);
  // Walls as tall as the footprint's attributes say: each edge's profile replaced by a copy with
  // that wall; what stands on the walls (parapet, steps) moves with the tallest wall drawn.
  std::string heightWarning;
  const std::optional<double> wall = wallHeightOf(style, b, &heightWarning);
  if (!heightWarning.empty()) out.warnings.push_back(heightWarning);
  double raise = 0;
  if (wall) {
    std::map<int, int> copies;
    double drawn = 0;
    for (auto& loop : spec.loops)
      for (int& p : loop.profile) {
        auto [it, fresh] = copies.try_emplace(p, static_cast<int>(spec.profiles.size()));
        if (fresh) {
          drawn = std::max(drawn, wallTop(spec.profiles[p]));
          extrude::Profile copy = withWallHeight(spec.profiles[p], *wall);
          copy.name += " (walls " + decimals(*wall, 2) + " m)";
          spec.profiles.push_back(std::move(copy));
        }
        p = it->second;
      }
    raise = *wall - drawn;
  }
  for (const auto& loop : spec.loops) used.insert(loop.profile.begin(), loop.profile.end());
  if (t.parapet) {
    extrude::OffsetEvent ev;
    ev.height = std::max(0.01, t.parapet->height + raise);
    ev.sideProfile = t.parapet->insideProfile;
    for (int p : used)
      ev.edges.push_back({p, -t.parapet->thickness, -1000.0, t.parapet->insideProfile, t.parapet->insideProfile});
    spec.offsets.push_back(ev);
  }

  // The door: on the building's main front, near its start.
  const EdgeLabel* doorEdge = nullptr;
  double doorEnd = 0;
  if (t.door && !labels.edges.empty()) {
    const EdgeLabel& e = labels.edges[labels.longestStreetEdge];
    if (e.length >= t.door->width + 1.0) {
      doorEdge = &e;
      const double at = std::min(1.0 + t.door->width / 2, e.length / 2);
      doorEnd = at + t.door->width / 2;
      spec.anchors.emplace_back("door", extrude::Anchor{e.loop, e.edge, true, at, 0.0}, extrude::FeatureKind::Door,
                                *t.door);
    }
  }
  for (std::size_t wi = 0; wi < t.windows.size(); ++wi) {
    const WindowRule& w = t.windows[wi];
    for (const EdgeLabel& e : labels.edges) {
      if (!w.when.matches(e) || e.length < w.minLength) continue;
      double first = w.margin, last = e.length - w.margin;
      if (&e == doorEdge) first = std::max(first, doorEnd + w.spacing / 2 + w.size.width / 2);
      if (last < first) {
        if (&e == doorEdge) continue;
        first = last = e.length / 2;
      }
      // Given walls: as many rows as fit under the eaves (the shipped styles' floors on their
      // own walls), at least one.
      const int floors = wall ? std::max(1, static_cast<int>(std::floor((*wall - w.sill - w.size.height) /
                                                                         w.floorHeight)) + 1)
                              : w.floors;
      extrude::Repeat rep;
      rep.kind = floors > 1 ? extrude::RepeatKind::Grid : extrude::RepeatKind::Row;
      rep.along = last;
      rep.spacing = w.spacing;
      rep.height = w.sill + (floors - 1) * w.floorHeight;
      rep.rowSpacing = w.floorHeight;
      if (last == first && floors == 1) rep.kind = extrude::RepeatKind::None;
      spec.anchors.emplace_back("windows " + std::to_string(wi) + " on edge " + std::to_string(e.edge),
                                extrude::Anchor{e.loop, e.edge, true, first, w.sill}, extrude::FeatureKind::Window,
                                w.size, rep);
    }
  }
  for (std::size_t si = 0; si < t.steps.size(); ++si) {
    const StepRule& st = t.steps[si];
    if (random.uniform() >= st.chance) continue;
    const EdgeLabel* longest = nullptr;
    for (const EdgeLabel& e : labels.edges) {
      if (!st.when.matches(e) || e.length < st.minLength || e.loop != 0) continue;
      if (st.row) {
        extrude::PlanStep step;
        step.name = "step " + std::to_string(si) + " on edge " + std::to_string(e.edge);
        step.anchor = {e.loop, e.edge, true, st.margin, std::max(0.0, st.height + raise)};
        step.width = st.width;
        step.depth = st.depth;
        step.frontProfile = st.frontProfile;
        step.sideProfile = st.sideProfile;
        if (e.length - 2 * st.margin > st.spacing)
          step.repeat = {extrude::RepeatKind::Row, e.length - st.margin, 0, st.spacing, 3};
        else
          step.anchor = {e.loop, e.edge, false, 0.5, std::max(0.0, st.height + raise)};
        spec.steps.push_back(step);
      } else if (!longest || e.length > longest->length) {
        longest = &e;
      }
    }
    if (longest) {
      extrude::PlanStep step;
      step.name = "step " + std::to_string(si);
      step.anchor = {longest->loop, longest->edge, false, st.along, std::max(0.0, st.height + raise)};
      step.width = st.width;
      step.depth = st.depth;
      step.frontProfile = st.frontProfile;
      step.sideProfile = st.sideProfile;
      spec.steps.push_back(step);
    }
  }
  thinRepeats(spec, spec.anchors, kMaxFeatureInstances, "feature instances (windows, doors)", out.warnings);
  thinRepeats(spec, spec.steps, kMaxStepInstances, "steps (dormers, chimneys)", out.warnings);
  return out;
}

}  // namespace corbel::city
