// The site file of docs/growth.md → Site.
#include "core/atomic_file.h"
#include "core/json_reader.h"
#include "growth/seeding.h"
#include "growth/site.h"

namespace corbel::growth {

namespace {

void warnUnknown(const JsonReader& r, const std::set<std::string>& known, std::vector<std::string>* warnings) {
  if (!warnings) return;
  for (auto& k : r.unknownKeys(known)) warnings->push_back(k + ": unknown key ignored");
}

Vec2 positiveSize(const JsonReader& r) {
  const Vec2 v = r.vec2();
  if (!(v[0] > 0 && v[1] > 0)) r.fail("sizes must be positive");
  return v;
}

SeedControls readControls(const JsonReader& g, std::vector<std::string>* warnings) {
  warnUnknown(g, {"count", "size", "spacing", "target_area", "storeys", "seed", "behaviour"}, warnings);
  SeedControls c;
  c.count = int(g.at("count").integer(0, 100000));
  if (auto z = g.find("size")) c.size = positiveSize(*z);
  if (auto sp = g.find("spacing")) c.spacing = sp->number(0, 1e4);
  if (auto t = g.find("target_area")) {
    const Vec2 range = t->vec2();
    c.areaLo = range[0];
    c.areaHi = range[1];
  }
  if (auto st = g.find("storeys"))
    for (const JsonReader& k : st->array(1000)) c.storeys.push_back(int(k.integer(0, 999)));
  if (auto sd = g.find("seed")) c.seed = unsigned(sd->integer(0, 4294967295LL));
  if (auto b = g.find("behaviour")) c.behaviour = b->string(64);
  return c;
}

FeatureSize featureSize(const JsonReader& r) {
  const Vec3 v = r.vec3();
  if (!(v[0] > 0 && v[1] > 0 && v[2] > 0)) r.fail("width, height and depth must be positive");
  if (!(v[0] <= 100 && v[1] <= 100 && v[2] <= 10)) r.fail("too large for a door or a window");
  return {v[0], v[1], v[2]};
}

RoofSettings readRoof(const JsonReader& r, std::vector<std::string>* warnings) {
  r.expectObject();
  warnUnknown(r, {"profile", "pitch", "parapet", "parapet_thickness", "slab", "material", "wall_material"}, warnings);
  RoofSettings roof;
  if (auto p = r.find("profile")) {
    const std::string name = p->string(16);
    if (name == "flat") roof.profile = RoofProfile::Flat;
    else if (name == "shed") roof.profile = RoofProfile::Shed;
    else if (name == "gable") roof.profile = RoofProfile::Gable;
    else if (name == "hip") roof.profile = RoofProfile::Hip;
    else p->fail("expected one of flat, shed, gable, hip");
  }
  if (auto p = r.find("pitch")) roof.pitch = p->number(5, 75);
  if (auto p = r.find("parapet")) roof.parapet = p->number(0.1, 5);
  if (auto p = r.find("parapet_thickness")) roof.parapetThickness = p->number(0.05, 1);
  if (auto p = r.find("slab")) roof.slab = p->number(0.05, 2);
  if (auto p = r.find("material")) roof.material = p->string(64);
  if (auto p = r.find("wall_material")) roof.wallMaterial = p->string(64);
  return roof;
}

OpeningSettings readOpenings(const JsonReader& r, std::vector<std::string>* warnings) {
  r.expectObject();
  warnUnknown(r, {"door", "window", "sill", "spacing"}, warnings);
  OpeningSettings o;
  if (auto p = r.find("door")) o.door = featureSize(*p);
  if (auto p = r.find("window")) o.window = featureSize(*p);
  if (auto p = r.find("sill")) o.sill = p->number(0, 10);
  if (auto p = r.find("spacing")) o.spacing = p->number(0.5, 100);
  if (o.spacing < o.window.width) {
    if (auto p = r.find("spacing")) p->fail("must be at least the window's width");
    r.at("window").fail("wider than the spacing of windows");
  }
  return o;
}

GrowthSettings readGrowth(const JsonReader& r, std::vector<std::string>* warnings) {
  r.expectObject();
  warnUnknown(r,
              {"tau", "intrusion_penalty", "view_goal_ratio", "aspect_chance", "double_volume_chance", "max_aspect",
               "patience", "sub_units"},
              warnings);
  GrowthSettings g;
  if (auto p = r.find("tau")) g.tau = p->number(0, 1);
  if (auto p = r.find("intrusion_penalty")) g.intrusionPenalty = p->number(0, 1000);
  if (auto p = r.find("view_goal_ratio")) g.viewGoalRatio = p->number(0, 10);
  if (auto p = r.find("aspect_chance")) g.aspectChance = p->number(0, 1);
  if (auto p = r.find("double_volume_chance")) g.doubleVolumeChance = p->number(0, 1);
  if (auto p = r.find("max_aspect")) g.maxAspect = p->number(1, 100);
  if (auto p = r.find("patience")) g.patience = int(p->integer(1, 1000));
  if (auto p = r.find("sub_units")) {
    const auto range = p->array(2);
    if (range.size() != 2) p->fail("expected [least, most]");
    g.minSubUnits = int(range[0].integer(1, 8));
    g.maxSubUnits = int(range[1].integer(1, 8));
    if (g.maxSubUnits < g.minSubUnits) p->fail("the most is less than the least");
  }
  return g;
}

}  // namespace

const char* roofProfileName(RoofProfile p) {
  switch (p) {
    case RoofProfile::Flat: return "flat";
    case RoofProfile::Shed: return "shed";
    case RoofProfile::Gable: return "gable";
    case RoofProfile::Hip: return "hip";
  }
  return "flat";
}

std::optional<SeedControls> seedControlsOf(const std::string& jsonText) {
  const nlohmann::json j = parseJsonText(jsonText);
  const JsonReader root(j, "");
  root.expectObject();
  if (auto g = root.find("generate_seeds")) return readControls(*g, nullptr);
  return std::nullopt;
}

Site parseSite(const std::string& jsonText, std::vector<std::string>* warnings) {
  const nlohmann::json j = parseJsonText(jsonText);
  const JsonReader root(j, "");
  root.expectObject();
  warnUnknown(root,
              {"format", "version", "envelope", "base", "storeys", "storey_height", "alpha", "cantilever", "clearance",
               "cores", "circulation", "seeds", "generate_seeds", "growth", "roof", "openings", "name"},
              warnings);
  if (auto f = root.find("format"); f && f->string(64) != "corbel-growth-site")
    f->fail("expected \"corbel-growth-site\"");
  if (auto v = root.find("version"); v && v->integer(1, 1000) > 1) v->fail("this build reads version 1 site files");

  Site site;
  const JsonReader env = root.at("envelope");
  warnUnknown(env, {"origin", "size", "polygon"}, warnings);
  if (auto poly = env.find("polygon")) {
    for (const JsonReader& p : poly->array(10000)) site.plan.push_back(p.vec2());
    if (site.plan.size() < 3) poly->fail("needs at least 3 corners");
  } else {
    const Vec2 o = env.find("origin") ? env.at("origin").vec2() : Vec2(0.0);
    const Vec2 s = positiveSize(env.at("size"));
    site.plan = rectanglePlan(o[0], o[1], o[0] + s[0], o[1] + s[1]);
  }
  if (auto b = root.find("base")) site.base = b->number();
  site.storeys = int(root.at("storeys").integer(1, 1000));
  if (auto h = root.find("storey_height")) site.storeyHeight = h->number(1e-3, 100);
  if (auto a = root.find("alpha")) site.alpha = a->number();
  if (auto c = root.find("cantilever")) site.cantilever = c->number();
  if (auto c = root.find("clearance")) {
    warnUnknown(*c, {"core", "circulation"}, warnings);
    if (auto k = c->find("core")) site.coreClearance = k->number();
    if (auto k = c->find("circulation")) site.circulationClearance = k->number();
  }
  if (auto g = root.find("growth")) site.growth = readGrowth(*g, warnings);
  if (auto r = root.find("roof")) site.roof = readRoof(*r, warnings);
  if (auto o = root.find("openings")) site.openings = readOpenings(*o, warnings);
  if (auto cores = root.find("cores"))
    for (const JsonReader& c : cores->array(100000)) {
      warnUnknown(c, {"at", "size", "name"}, warnings);
      const Vec2 at = c.at("at").vec2();
      const Vec2 size = positiveSize(c.at("size"));
      site.cores.push_back({at[0], at[1], at[0] + size[0], at[1] + size[1]});
    }
  if (auto circ = root.find("circulation"))
    for (const JsonReader& c : circ->array(100000)) {
      warnUnknown(c, {"at", "size", "name"}, warnings);
      const Vec3 at = c.at("at").vec3();
      const Vec3 size = c.at("size").vec3();
      if (!(size[0] > 0 && size[1] > 0 && size[2] > 0)) c.at("size").fail("sizes must be positive");
      site.circulation.push_back({at, at + size});
    }
  const auto generate = root.find("generate_seeds");
  if (!generate && !root.find("seeds")) root.at("seeds");  // names the missing key
  if (auto list = root.find("seeds"))
  for (const JsonReader& s : list->array(100000)) {
    warnUnknown(s, {"at", "size", "storey", "target_area", "target_volume", "locked", "behaviour", "name"}, warnings);
    Seed seed;
    seed.at = s.at("at").vec2();
    if (auto z = s.find("size")) seed.size = positiveSize(*z);
    if (auto k = s.find("storey")) seed.storey = int(k->integer(0, 999));
    if (auto a = s.find("target_area")) seed.targetArea = a->number(1e-6, 1e9);
    if (auto v = s.find("target_volume")) seed.targetVolume = v->number(1e-6, 1e9);
    if (auto l = s.find("locked"))
      for (const JsonReader& name : l->array(6)) {
        Side side;
        if (!sideFromName(name.string(16), side)) name.fail("expected one of -x, +x, -y, +y, bottom, top");
        seed.locked[static_cast<int>(side)] = true;
      }
    if (auto b = s.find("behaviour")) seed.behaviour = b->string(64);
    site.seeds.push_back(seed);
  }
  // Seeds at exits along the circulation, within these controls (growth/seeding.h); the
  // hand-placed ones above are kept and the generated ones placed clear of them.
  if (generate) generateSeeds(site, readControls(*generate, warnings));
  validateSite(site);
  return site;
}

Site loadSite(const std::string& path, std::vector<std::string>* warnings) {
  const std::string text = readFile(path, std::size_t(64) << 20);
  try {
    return parseSite(text, warnings);
  } catch (const InputError& e) {
    throw InputError(e.where.empty() ? path : path + ": " + e.where, e.reason);
  }
}

}  // namespace corbel::growth
