#include "editor/growth_edits.h"

#include "core/error.h"
#include "growth/engine.h"
#include "growth/seeding.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace corbel::editor {

std::optional<GrowthSpec> nextStep(const GrowthSpec& spec, int stoppedAfter) {
  if (spec.steps < 0 || (stoppedAfter >= 0 && stoppedAfter <= spec.steps) || spec.steps >= limits::kMaxGrowthSteps)
    return std::nullopt;
  GrowthSpec next = spec;
  ++next.steps;
  return next;
}

namespace {

using nlohmann::json;

const char* listKey(SiteItem item) {
  switch (item) {
    case SiteItem::Core:
      return "cores";
    case SiteItem::Circulation:
      return "circulation";
    case SiteItem::Seed:
      return "seeds";
  }
  return "";
}

std::string where(SiteItem item, int index) { return std::string(listKey(item)) + "[" + std::to_string(index) + "]"; }

json pair(double a, double b) { return json::array({a, b}); }

// The site file as JSON with `edit` applied (it returns "" or why not); the edited site is
// checked and the spec returned with its compact text (keys sorted, as a project written and
// read back has it).
template <class Edit>
SiteEditResult editSite(const GrowthSpec& spec, Edit edit) {
  SiteEditResult r;
  json site;
  try {
    site = json::parse(spec.site);
  } catch (const json::exception&) {
    r.error = "growth.site: is not JSON";
    return r;
  }
  if (!site.is_object()) {
    r.error = "growth.site: must be an object";
    return r;
  }
  r.error = edit(site);
  if (!r.error.empty()) return r;
  GrowthSpec next = spec;
  next.site = site.dump();
  r.error = checkSite(next.site);
  if (r.error.empty()) r.spec = std::move(next);
  return r;
}

// editSite with `edit` applied to the list of `item` (created when missing).
template <class Edit>
SiteEditResult editList(const GrowthSpec& spec, SiteItem item, int index, bool appendAllowed, Edit edit) {
  return editSite(spec, [&](json& site) -> std::string {
    json& list = site[listKey(item)];
    if (list.is_null()) list = json::array();
    if (!list.is_array()) return "growth.site." + std::string(listKey(item)) + ": must be a list";
    const int size = static_cast<int>(list.size());
    if (index < 0 || index > size || (index == size && !appendAllowed))
      return "growth.site." + where(item, index) + ": no such entry";
    if (index == size) list.push_back(json::object());
    edit(list, index);
    if (list.empty()) site.erase(listKey(item));
    return "";
  });
}

bool finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

int itemCount(const HandPlaced& h, SiteItem k) {
  switch (k) {
    case SiteItem::Core:
      return int(h.cores.size());
    case SiteItem::Circulation:
      return int(h.circulation.size());
    case SiteItem::Seed:
      return int(h.seeds.size());
  }
  return 0;
}

HandPlaced handPlaced(const std::string& siteText) {
  // Only the file's own lists: parse the text without generating seeds.
  json site = json::parse(siteText, nullptr, false);
  if (site.is_object()) site.erase("generate_seeds");
  HandPlaced out;
  if (!site.is_object()) return out;
  if (!site.contains("seeds")) site["seeds"] = json::array();
  growth::Site parsed;
  try {
    parsed = growth::parseSite(site.dump());
  } catch (const InputError&) {
    return out;  // the build names the fault
  }
  out.cores = parsed.cores;
  out.circulation = parsed.circulation;
  out.seeds = parsed.seeds;
  return out;
}

std::string checkSite(const std::string& siteText) {
  try {
    const growth::Site site = growth::parseSite(siteText);
    growth::GrowthEngine engine(site);  // unknown behaviours, unsupported seeds
  } catch (const InputError& e) {
    return e.where.empty() ? "growth.site: " + e.reason : "growth.site." + e.where + ": " + e.reason;
  } catch (const std::exception& e) {
    return std::string("growth.site: ") + e.what();
  }
  return {};
}

SiteEditResult setCore(const GrowthSpec& spec, int index, const growth::Rect& c) {
  if (!finite({c.u0, c.v0, c.u1, c.v1}))
    return {std::nullopt, "growth.site." + where(SiteItem::Core, index) + ": is not a finite number"};
  if (!(c.u1 > c.u0 && c.v1 > c.v0))
    return {std::nullopt, "growth.site." + where(SiteItem::Core, index) + ".size: must be positive"};
  return editList(spec, SiteItem::Core, index, true, [&](json& list, int i) {
    json& e = list[i];
    if (!e.contains("name")) e["name"] = "core " + std::to_string(i + 1);
    e["at"] = pair(c.u0, c.v0);
    e["size"] = pair(c.u1 - c.u0, c.v1 - c.v0);
  });
}

SiteEditResult setCirculation(const GrowthSpec& spec, int index, const growth::Box& b) {
  if (!finite({b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]}))
    return {std::nullopt, "growth.site." + where(SiteItem::Circulation, index) + ": is not a finite number"};
  if (!(b.size(0) > 0 && b.size(1) > 0 && b.size(2) > 0))
    return {std::nullopt, "growth.site." + where(SiteItem::Circulation, index) + ".size: sizes must be positive"};
  return editList(spec, SiteItem::Circulation, index, true, [&](json& list, int i) {
    json& e = list[i];
    if (!e.contains("name")) e["name"] = "circulation " + std::to_string(i + 1);
    e["at"] = json::array({b.lo[0], b.lo[1], b.lo[2]});
    e["size"] = json::array({b.size(0), b.size(1), b.size(2)});
  });
}

SiteEditResult setSeed(const GrowthSpec& spec, int index, const growth::Seed& s) {
  const std::string at = "growth.site." + where(SiteItem::Seed, index);
  if (!finite({s.at[0], s.at[1]})) return {std::nullopt, at + ".at: is not a finite number"};
  if (!finite({s.size[0], s.size[1]}) || !(s.size[0] > 0 && s.size[1] > 0))
    return {std::nullopt, at + ".size: sizes must be positive"};
  if (!finite({s.targetArea, s.targetVolume}) || s.targetArea < 0 || s.targetVolume < 0 ||
      (s.targetArea > 0) == (s.targetVolume > 0))
    return {std::nullopt, at + ": needs exactly one of target_area and target_volume"};
  if (s.behaviour.empty()) return {std::nullopt, at + ".behaviour: must not be empty"};
  return editList(spec, SiteItem::Seed, index, true, [&](json& list, int i) {
    json& e = list[i];
    e["at"] = pair(s.at[0], s.at[1]);
    e["size"] = pair(s.size[0], s.size[1]);
    e["storey"] = s.storey;
    e.erase("target_area");
    e.erase("target_volume");
    if (s.targetArea > 0)
      e["target_area"] = s.targetArea;
    else
      e["target_volume"] = s.targetVolume;
    json locked = json::array();
    for (growth::Side side : growth::kAllSides)
      if (s.locked[static_cast<int>(side)]) locked.push_back(std::string(growth::sideName(side)));
    if (locked.empty())
      e.erase("locked");
    else
      e["locked"] = locked;
    e["behaviour"] = s.behaviour;
  });
}

SiteEditResult removeItem(const GrowthSpec& spec, SiteItem item, int index) {
  return editList(spec, item, index, false, [](json& list, int i) { list.erase(list.begin() + i); });
}

SiteFrame siteFrame(const std::string& siteText) {
  SiteFrame f;
  const json site = json::parse(siteText, nullptr, false);
  if (!site.is_object()) return f;
  try {
    const growth::Site parsed = growth::parseSite(siteText);
    f.plan = parsed.plan;
    f.storeys = parsed.storeys;
    f.storeyHeight = parsed.storeyHeight;
    f.box = !(site.contains("envelope") && site["envelope"].contains("polygon"));
    f.controls = growth::seedControlsOf(siteText);
    f.growth = parsed.growth;
    f.valid = true;
  } catch (const std::exception&) {
  }
  return f;
}

SiteEditResult setEnvelopeBox(const GrowthSpec& spec, Vec2 origin, Vec2 size) {
  if (!finite({origin[0], origin[1]})) return {std::nullopt, "growth.site.envelope.origin: is not a finite number"};
  if (!finite({size[0], size[1]}) || !(size[0] > 0 && size[1] > 0))
    return {std::nullopt, "growth.site.envelope.size: sizes must be positive"};
  return editSite(spec, [&](json& site) -> std::string {
    json& e = site["envelope"];
    e = json::object();  // a box replaces a polygon
    e["origin"] = pair(origin[0], origin[1]);
    e["size"] = pair(size[0], size[1]);
    return "";
  });
}

SiteEditResult setEnvelopePolygon(const GrowthSpec& spec, const std::vector<Vec2>& corners) {
  if (corners.size() < 3) return {std::nullopt, "growth.site.envelope.polygon: needs at least 3 corners"};
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (!finite({corners[i][0], corners[i][1]}))
      return {std::nullopt, "growth.site.envelope.polygon[" + std::to_string(i) + "]: is not a finite number"};
  return editSite(spec, [&](json& site) -> std::string {
    json poly = json::array();
    for (const Vec2& c : corners) poly.push_back(pair(c[0], c[1]));
    site["envelope"] = json{{"polygon", poly}};
    return "";
  });
}

namespace {
// The envelope's corners as the site file gives them, or nullopt when the site does not parse.
std::optional<std::vector<Vec2>> envelopePlan(const GrowthSpec& spec) {
  const SiteFrame f = siteFrame(spec.site);
  if (!f.valid) return std::nullopt;
  return f.plan;
}
std::string noCorner(int i) { return "growth.site.envelope.polygon[" + std::to_string(i) + "]: no such corner"; }
const char* kUnparsed = "growth.site: the site does not parse (its build names the fault)";
}  // namespace

SiteEditResult insertEnvelopeCorner(const GrowthSpec& spec, int edge) {
  auto plan = envelopePlan(spec);
  if (!plan) return {std::nullopt, kUnparsed};
  const int n = int(plan->size());
  if (edge < 0 || edge >= n) return {std::nullopt, noCorner(edge)};
  const Vec2 mid = ((*plan)[edge] + (*plan)[(edge + 1) % n]) * 0.5;
  plan->insert(plan->begin() + edge + 1, mid);
  return setEnvelopePolygon(spec, *plan);
}

SiteEditResult removeEnvelopeCorner(const GrowthSpec& spec, int corner) {
  auto plan = envelopePlan(spec);
  if (!plan) return {std::nullopt, kUnparsed};
  if (corner < 0 || corner >= int(plan->size())) return {std::nullopt, noCorner(corner)};
  if (plan->size() <= 3) return {std::nullopt, "growth.site.envelope.polygon: needs at least 3 corners"};
  plan->erase(plan->begin() + corner);
  return setEnvelopePolygon(spec, *plan);
}

SiteEditResult moveEnvelopeCorner(const GrowthSpec& spec, int corner, Vec2 to) {
  auto plan = envelopePlan(spec);
  if (!plan) return {std::nullopt, kUnparsed};
  if (corner < 0 || corner >= int(plan->size())) return {std::nullopt, noCorner(corner)};
  (*plan)[corner] = to;
  return setEnvelopePolygon(spec, *plan);
}

std::optional<SiteEditResult> dragEnvelopeCorner(const GrowthSpec& spec, const std::vector<Vec2>& from,
                                                 const std::vector<Vec2>& now, int corner, double dx, double dy) {
  dx = std::round(dx * 2) / 2;
  dy = std::round(dy * 2) / 2;
  if (corner < 0 || corner >= int(from.size()) || corner >= int(now.size())) return std::nullopt;
  const Vec2 to(from[corner][0] + dx, from[corner][1] + dy);
  if (to == now[corner]) return std::nullopt;
  return moveEnvelopeCorner(spec, corner, to);
}

std::optional<int> pickEnvelopeCorner(const std::vector<Vec2>& plan, double x, double y, double radius) {
  std::optional<int> best;
  double bestD = radius;
  for (int i = 0; i < int(plan.size()); ++i) {
    const double d = std::hypot(plan[i][0] - x, plan[i][1] - y);
    if (d <= bestD) best = i, bestD = d;
  }
  return best;
}

SiteEditResult setStoreys(const GrowthSpec& spec, int storeys, double storeyHeight) {
  if (storeys < 1 || storeys > 1000) return {std::nullopt, "growth.site.storeys: must lie in 1..1000"};
  if (!std::isfinite(storeyHeight) || !(storeyHeight > 0))
    return {std::nullopt, "growth.site.storey_height: must be positive"};
  return editSite(spec, [&](json& site) -> std::string {
    site["storeys"] = storeys;
    site["storey_height"] = storeyHeight;
    return "";
  });
}

SiteEditResult setGrowthSettings(const GrowthSpec& spec, const growth::GrowthSettings& g) {
  const growth::GrowthSettings d;
  for (double v : {g.tau, g.intrusionPenalty, g.viewGoalRatio, g.aspectChance, g.doubleVolumeChance, g.maxAspect})
    if (!std::isfinite(v)) return {std::nullopt, "growth.site.growth: a setting is not a finite number"};
  return editSite(spec, [&](json& site) -> std::string {
    json out = json::object();
    if (g.tau != d.tau) out["tau"] = g.tau;
    if (g.intrusionPenalty != d.intrusionPenalty) out["intrusion_penalty"] = g.intrusionPenalty;
    if (g.viewGoalRatio != d.viewGoalRatio) out["view_goal_ratio"] = g.viewGoalRatio;
    if (g.aspectChance != d.aspectChance) out["aspect_chance"] = g.aspectChance;
    if (g.doubleVolumeChance != d.doubleVolumeChance) out["double_volume_chance"] = g.doubleVolumeChance;
    if (g.maxAspect != d.maxAspect) out["max_aspect"] = g.maxAspect;
    if (g.patience != d.patience) out["patience"] = g.patience;
    if (g.minSubUnits != d.minSubUnits || g.maxSubUnits != d.maxSubUnits)
      out["sub_units"] = json::array({g.minSubUnits, g.maxSubUnits});
    if (out.empty())
      site.erase("growth");
    else
      site["growth"] = std::move(out);
    return "";
  });
}

SiteEditResult setSeedControls(const GrowthSpec& spec, const std::optional<growth::SeedControls>& c) {
  if (c) {
    if (!finite({c->size[0], c->size[1]}) || !(c->size[0] > 0 && c->size[1] > 0))
      return {std::nullopt, "growth.site.generate_seeds.size: sizes must be positive"};
    if (!std::isfinite(c->spacing)) return {std::nullopt, "growth.site.generate_seeds.spacing: is not a finite number"};
    if (!finite({c->areaLo, c->areaHi}))
      return {std::nullopt, "growth.site.generate_seeds.target_area: is not a finite number"};
    if (c->behaviour.empty()) return {std::nullopt, "growth.site.generate_seeds.behaviour: must not be empty"};
  }
  return editSite(spec, [&](json& site) -> std::string {
    if (!c) {
      site.erase("generate_seeds");
      // A site needs seeds or generate_seeds: without either it keeps an empty seed list.
      if (!site.contains("seeds")) site["seeds"] = json::array();
      return "";
    }
    json g = json::object();
    g["count"] = c->count;
    g["size"] = pair(c->size[0], c->size[1]);
    g["spacing"] = c->spacing;
    g["target_area"] = pair(c->areaLo, c->areaHi);
    if (!c->storeys.empty()) g["storeys"] = c->storeys;
    g["seed"] = c->seed;
    g["behaviour"] = c->behaviour;
    site["generate_seeds"] = g;
    return "";
  });
}

std::optional<SiteEditResult> dragItem(const GrowthSpec& spec, const HandPlaced& from, const HandPlaced& now,
                                       SiteItem item, int index, double dx, double dy) {
  dx = std::round(dx * 2) / 2;
  dy = std::round(dy * 2) / 2;
  if (index < 0 || index >= itemCount(from, item) || index >= itemCount(now, item)) return std::nullopt;
  switch (item) {
    case SiteItem::Core: {
      const growth::Rect& c = from.cores[index];
      const growth::Rect to{c.u0 + dx, c.v0 + dy, c.u1 + dx, c.v1 + dy};
      if (to == now.cores[index]) return std::nullopt;
      return setCore(spec, index, to);
    }
    case SiteItem::Circulation: {
      growth::Box to = from.circulation[index];
      to.lo[0] += dx, to.hi[0] += dx, to.lo[1] += dy, to.hi[1] += dy;
      if (to == now.circulation[index]) return std::nullopt;
      return setCirculation(spec, index, to);
    }
    case SiteItem::Seed: {
      growth::Seed to = from.seeds[index];
      to.at = Vec2(to.at[0] + dx, to.at[1] + dy);
      if (to.at == now.seeds[index].at) return std::nullopt;
      return setSeed(spec, index, to);
    }
  }
  return std::nullopt;
}

namespace {
// The ray parameter at which the ray enters box [lo, hi] (0 when it starts inside), or nullopt.
std::optional<double> rayEntry(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (o[k] < lo[k] || o[k] > hi[k]) return std::nullopt;
      continue;
    }
    double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1 ? std::optional<double>(t0) : std::nullopt;
}
}  // namespace

std::optional<Vec2> rayOnPlane(const Vec3& origin, const Vec3& dir, double z) {
  if (std::abs(dir[2]) < 1e-9) return std::nullopt;
  const double t = (z - origin[2]) / dir[2];
  if (!(t > 0) || t > 1e4) return std::nullopt;
  return Vec2(origin[0] + t * dir[0], origin[1] + t * dir[1]);
}

std::optional<SiteGrab> grabInView(const HandPlaced& h, const growth::Site& site, const Vec3& origin, const Vec3& dir) {
  std::optional<SiteGrab> best;
  double bestT = std::numeric_limits<double>::infinity();
  auto consider = [&](std::optional<SiteItem> item, int index, const Vec3& lo, const Vec3& hi) {
    const auto t = rayEntry(origin, dir, lo, hi);
    if (!t || *t >= bestT) return;
    bestT = *t;
    const Vec3 p = origin + dir * *t;
    best = SiteGrab{item, index, p[2], Vec2(p[0], p[1])};
  };
  for (int i = 0; i < int(h.seeds.size()); ++i) {
    const growth::Seed& s = h.seeds[i];
    const double z = site.base + s.storey * site.storeyHeight;
    consider(SiteItem::Seed, i, Vec3(s.at[0], s.at[1], z),
             Vec3(s.at[0] + s.size[0], s.at[1] + s.size[1], z + site.storeyHeight));
  }
  for (int i = 0; i < int(h.circulation.size()); ++i) {
    const growth::Box& c = h.circulation[i];
    consider(SiteItem::Circulation, i, Vec3(c.lo[0], c.lo[1], c.lo[2]), Vec3(c.hi[0], c.hi[1], c.hi[2]));
  }
  for (int i = 0; i < int(h.cores.size()); ++i) {
    const growth::Rect& c = h.cores[i];
    consider(SiteItem::Core, i, Vec3(c.u0, c.v0, site.base), Vec3(c.u1, c.v1, site.top()));
  }
  // The envelope's corners: the closest approach of the ray to each vertical edge [base, top].
  for (int i = 0; i < int(site.plan.size()); ++i) {
    const Vec3 a(site.plan[i][0], site.plan[i][1], site.base);
    const Vec3 up(0, 0, 1);
    const double len = site.top() - site.base;
    // Lines origin + t dir and a + u up: minimise |origin + t dir - a - u up|.
    const Vec3 w = origin - a;
    const double b = dir | up, dd = dir | w, e = up | w, den = 1 - b * b;
    if (den < 1e-12) continue;  // looking straight down the edge
    const double u = std::clamp((e - b * dd) / den, 0.0, len);
    const double t = std::max(0.0, (a + up * u - origin) | dir);  // the ray's point nearest that one
    const Vec3 p = origin + dir * t, q = a + up * u;
    if ((p - q).norm() > std::max(0.3, 0.015 * t) || t >= bestT) continue;
    bestT = t;
    best = SiteGrab{std::nullopt, i, q[2], Vec2(q[0], q[1])};
  }
  return best;
}

std::optional<std::pair<SiteItem, int>> pickItem(const HandPlaced& h, const growth::Site& site, int storey, double x,
                                                 double y) {
  auto inside = [&](double x0, double y0, double x1, double y1) { return x >= x0 && x <= x1 && y >= y0 && y <= y1; };
  for (int i = 0; i < int(h.seeds.size()); ++i) {
    const growth::Seed& s = h.seeds[i];
    if (s.storey == storey && inside(s.at[0], s.at[1], s.at[0] + s.size[0], s.at[1] + s.size[1]))
      return std::pair{SiteItem::Seed, i};
  }
  const double z0 = site.base + storey * site.storeyHeight, z1 = z0 + site.storeyHeight;
  for (int i = 0; i < int(h.circulation.size()); ++i) {
    const growth::Box& c = h.circulation[i];
    if (c.lo[2] < z1 - 1e-9 && c.hi[2] > z0 + 1e-9 && inside(c.lo[0], c.lo[1], c.hi[0], c.hi[1]))
      return std::pair{SiteItem::Circulation, i};
  }
  for (int i = 0; i < int(h.cores.size()); ++i) {
    const growth::Rect& c = h.cores[i];
    if (inside(c.u0, c.v0, c.u1, c.v1)) return std::pair{SiteItem::Core, i};
  }
  return std::nullopt;
}

std::optional<growth::Rect> freeCoreSpot(const growth::Site& site, Vec2 size) {
  const growth::Box b = site.bounds();
  growth::Site trial = site;
  trial.cores.push_back({});
  for (double y = std::floor(b.lo[1]); y + size[1] <= b.hi[1]; y += 1.0)
    for (double x = std::floor(b.lo[0]); x + size[0] <= b.hi[0]; x += 1.0) {
      trial.cores.back() = {x, y, x + size[0], y + size[1]};
      try {
        growth::validateSite(trial);  // inside the envelope, clear of cores, circulation and seeds
        return trial.cores.back();
      } catch (const InputError&) {
      }
    }
  return std::nullopt;
}

std::optional<growth::Seed> freeSeedSpot(const growth::Site& site, const growth::Seed& like) {
  const growth::Box b = site.bounds();
  growth::Site trial = site;
  trial.seeds.push_back(like);
  for (double y = std::floor(b.lo[1]); y + like.size[1] <= b.hi[1]; y += 1.0)
    for (double x = std::floor(b.lo[0]); x + like.size[0] <= b.hi[0]; x += 1.0) {
      trial.seeds.back().at = Vec2(x, y);
      try {
        growth::validateSite(trial);
        growth::GrowthEngine engine(trial);  // held up by something
        return trial.seeds.back();
      } catch (const InputError&) {
      }
    }
  return std::nullopt;
}

Document freezeGrowth(const Document& doc, ObjectId id, const growth::GrownModel& grown, std::vector<ObjectId>* added) {
  const DocObject* o = doc.find(id);
  const auto* spec = o ? std::get_if<GrowthSpec>(&o->spec) : nullptr;
  if (!spec) throw InputError("freeze", "the object is not a growth site");
  json site = json::parse(spec->site, nullptr, false);
  if (!site.is_object()) throw InputError("growth.site", "must be an object");
  Document out = doc;
  std::vector<ObjectId> ids;
  const int grownCount = int(grown.site.seeds.size());
  for (const growth::Unit& u : grown.units) {
    if (u.id > grownCount || u.parts.empty()) continue;  // a unit already there stays as it is
    UnitSpec unit;
    for (const growth::Box& b : u.parts) unit.parts.push_back({b.lo, b.hi});
    if (auto problem = checkUnitSpec(unit)) throw InputError("unit " + std::to_string(u.id), *problem);
    const ObjectId unitId = out.add(o->name + " unit " + std::to_string(u.id), std::move(unit));
    out.find(unitId)->placement = o->placement;
    ids.push_back(unitId);
  }
  if (ids.empty()) throw InputError("freeze", "the site has grown no units to freeze");
  site["seeds"] = json::array();
  site.erase("generate_seeds");
  auto& g = std::get<GrowthSpec>(out.find(id)->spec);
  g.site = site.dump();
  g.aroundUnits = true;
  if (added) *added = std::move(ids);
  return out;
}

}  // namespace corbel::editor
