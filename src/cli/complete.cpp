// corbel-cli complete: the form completion engine (Ch. 7, docs/growth.md) from seed units or a
// grown model's gap; one JSON line.
#include "cli/grow.h"
#include "cli/guarded.h"
#include "cli/run.h"
#include "cli/scene_png.h"

#include "core/error.h"
#include "core/export.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "growth/completion.h"
#include "growth/constraints.h"
#include "growth/entrances.h"
#include "growth/form_fit.h"
#include "growth/kernel.h"
#include "growth/sizing.h"
#include "growth/tolerances.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace corbel::cli {

namespace {

// A usage fault of complete, named as the other commands name theirs.
UsageError bad(const std::string& message) { return UsageError("complete: " + message); }

double number(const std::string& flag, const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v)) throw bad(flag + ": expected a number, not '" + s + "'");
  return v;
}

std::vector<std::string> splitOn(const std::string& s, char c) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, c)) out.push_back(part);
  if (!s.empty() && s.back() == c) out.push_back("");
  return out;
}

// Complexity bounds to exact fractions with four decimals.
growth::Fraction fractionOf(double v) { return growth::Fraction::of(std::llround(v * 10000.0), 10000); }

const char* const kPalette[] = {"brick", "glass",     "grass", "timber",  "slate",
                                "stone", "roof_tile", "metal", "plaster", "concrete"};

}  // namespace

int run(const CompleteRequest& r) {
  growth::FormRequest rq;
  rq.count = r.count;
  rq.seed = std::uint64_t(r.seed);
  growth::PlanRect region{0, 0, 24, 16};
  const bool haveRegion = !r.region.empty();
  const std::string& out = r.out;
  const std::string& png = r.render;
  const std::string& from = r.from;
  const std::string& objectName = r.object;
  const int storey = r.storey.value_or(0);
  std::vector<Vec2> doors;  // --entrance points, or the grown model's entrances
  if (r.seeds) rq.seeds = *r.seeds;
  {
    const auto parts = splitOn(r.complexity, ':');
    if (parts.size() != 2) throw bad("--complexity: expected LO:HI, not '" + r.complexity + "'");
    const double lo = number("--complexity", parts[0]), hi = number("--complexity", parts[1]);
    if (lo < 0 || hi < lo) throw bad("--complexity: expected 0 <= LO <= HI, not '" + r.complexity + "'");
    if (hi >= 0.5) throw bad("--complexity: HI must stay below 0.5 (Type I moves approach 1/2, Sec. 7.2.1)");
    rq.lo = fractionOf(lo);
    rq.hi = fractionOf(hi);
  }
  if (haveRegion) {
    const auto parts = splitOn(r.region, ',');
    if (parts.size() != 4) throw bad("--region: expected X0,Y0,X1,Y1, not '" + r.region + "'");
    region = {number("--region", parts[0]), number("--region", parts[1]), number("--region", parts[2]),
              number("--region", parts[3])};
    if (region.x1 - region.x0 < 3 || region.y1 - region.y0 < 3)
      throw bad("--region: expected X1 >= X0 + 3 and Y1 >= Y0 + 3 (meters), not '" + r.region + "'");
  }
  for (const std::string& v : r.entrances) {
    const auto parts = splitOn(v, ',');
    if (parts.size() != 2) throw bad("--entrance: expected X,Y, not '" + v + "'");
    doors.push_back(Vec2(number("--entrance", parts[0]), number("--entrance", parts[1])));
  }
  if (!out.empty()) {
    try {
      exportFormatFor(out);
    } catch (const Error& e) {
      throw bad(e.what());
    }
  }
  if (from.empty()) {
    if (!r.seeds) throw bad("--seeds N (or --from PROJECT) is required");
    if (doors.size() > std::size_t(rq.seeds))
      throw bad("--entrance: " + std::to_string(doors.size()) + " entrances for " + std::to_string(rq.seeds) +
                " seeds (each entrance goes to a different unit)");
  }

  // From a grown model: its growth object grown as the editor grows it, the region (default: the
  // most enclosed gap of the storey, as the editor's completion panel chooses it) and the
  // entrances that open onto the region, one seed each.
  growth::GrownModel model;
  double z0 = 0, storeyHeight = 3.0;
  if (!from.empty()) {
    try {
      const LoadedProject p = loadProject(from);
      for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << from << ": " << w << "\n";
      std::vector<const DocObject*> growths;
      for (const DocObject& o : p.document.objects)
        if (std::holds_alternative<GrowthSpec>(o.spec) && (objectName.empty() || o.name == objectName))
          growths.push_back(&o);
      if (growths.empty())
        throw Error(from + (objectName.empty() ? ": no growth object to complete"
                                               : ": no growth object named \"" + objectName + "\""));
      if (growths.size() > 1) throw Error(from + ": several growth objects; choose one with --object NAME");
      model = growth::grow(growth::growthInputOf(p.document, *growths[0]));
    } catch (const Error& e) {
      std::cerr << "corbel-cli: complete: " << e.what() << "\n";
      return 1;
    }
    const growth::Site& site = model.site;
    if (storey >= site.storeys) {
      std::cerr << "corbel-cli: complete: --storey: the site has storeys 0 to " << site.storeys - 1 << "\n";
      return 2;
    }
    const growth::EntranceOptions eo = growth::storeyOptions(site, storey);
    const std::vector<growth::Box> obstacles = growth::entranceObstacles(site);
    if (!haveRegion) {
      // The gap keeps the clearance the growth keeps from cores and circulation.
      const growth::Box b = site.bounds();
      if (!growth::findGap(model.units, growth::clearanceZones(site), {b.lo[0], b.lo[1], b.hi[0], b.hi[1]}, eo,
                           growth::kGapMinSide, growth::kGapMaxSide, region)) {
        std::cerr << "corbel-cli: complete: no empty region of " << growth::kGapMinSide << " to " << growth::kGapMaxSide
                  << " m on storey " << storey
                  << " of the grown model; give one with --region\n";
        return 1;
      }
    }
    const std::vector<growth::Entrance> entrances = growth::entrancesInRegion(model.units, region, eo, obstacles);
    if (entrances.empty()) {
      std::cerr << "corbel-cli: complete: no grown unit opens onto the region on storey " << storey << "\n";
      return 1;
    }
    for (const growth::Entrance& e : entrances) doors.push_back(e.at);
    rq.seeds = int(doors.size());
    z0 = site.base + storey * site.storeyHeight;
    storeyHeight = site.storeyHeight;
  }

  growth::FormSet set;
  try {
    set = growth::generateForms(rq);
  } catch (const InputError& e) {
    std::cerr << "corbel-cli: complete: " << e.what() << "\n";
    return 2;
  }

  nlohmann::ordered_json j;
  j["seeds"] = rq.seeds;
  j["complexity"] = {rq.lo.value(), rq.hi.value()};
  j["count"] = rq.count;
  j["found"] = set.forms.size();
  j["attempts"] = set.attempts;
  if (!set.note.empty()) j["note"] = set.note;
  j["region"] = {region.x0, region.y0, region.x1, region.y1};

  if (!from.empty()) {
    j["from"] = from;
    j["storey"] = storey;
  }
  if (!doors.empty()) {
    j["entrances"] = nlohmann::ordered_json::array();
    for (const Vec2& d : doors) j["entrances"].push_back({d[0], d[1]});
  }

  // Each form is fitted into the region (in the orientation that suits its entrances best), sized,
  // and its entrances realized. Without a model the forms stand side by side (four to a row) in
  // the scene; with one, the form that meets the most doors stands in its region in the model.
  Scene scene;
  ObjectId id = 1;
  const double w = region.x1 - region.x0, h = region.y1 - region.y0, gap = 0.25 * std::min(w, h);
  j["forms"] = nlohmann::ordered_json::array();
  std::vector<growth::FittedForm> fitted;
  std::vector<bool> fits;  // per form: it obeys the growth rules (always, without a model)
  int best = -1;
  for (std::size_t k = 0; k < set.forms.size(); ++k) {
    const growth::Form& f = set.forms[k];
    const growth::Cartogram c = growth::Cartogram::of(f.plan);
    growth::FitOptions fo;
    fo.z0 = z0;
    fo.storeyHeight = storeyHeight;
    if (!from.empty()) fo.roomWidth = growth::kMinPartWidth;  // among grown units, rooms as growth makes them
    fitted.push_back(growth::fitForm(f.plan, region, doors, fo));
    const growth::FittedForm& fit = fitted.back();
    // Among a grown model the form obeys the growth rules, or it is refused.
    const std::vector<std::string> broken =
        from.empty() ? std::vector<std::string>{} : growth::formViolations(model.site, model.units, fit);
    int met = 0;
    for (const growth::EntranceFit& e : fit.entranceFits) met += e.realized;

    nlohmann::ordered_json fj;
    const growth::Fraction v = f.complexity.value();
    fj["complexity"] = std::to_string(v.num) + "/" + std::to_string(v.den);
    fj["value"] = v.value();
    fj["incidences"] = f.complexity.incidences;
    fj["faces"] = f.complexity.faces;
    fj["moves"] = f.moves;
    fj["sub_units"] = c.subUnits();
    fj["sea_rectangles"] = int(c.rects.size()) - c.subUnits();
    fj["orientation"] = fit.orientation;
    fj["area_error_before"] = fit.sizing.before;
    fj["area_error_after"] = fit.sizing.after;
    fj["sizing_passes"] = fit.sizing.passes;
    if (!doors.empty()) {
      fj["doors_met"] = met;
      fj["area_error_final"] = fit.areaError;
      nlohmann::ordered_json dj = nlohmann::ordered_json::array();
      for (const growth::EntranceFit& e : fit.entranceFits) {
        nlohmann::ordered_json one{{"entrance", e.entrance}, {"unit", e.unit + 1},     {"side", e.side},
                                   {"door", {e.from, e.to}}, {"realized", e.realized}, {"moved", e.moved}};
        if (!e.realized) one["why"] = e.why;
        dj.push_back(one);
      }
      fj["doors"] = dj;
    }
    nlohmann::ordered_json uj = nlohmann::ordered_json::array();
    for (const growth::Unit& u : fit.units)
    {
      double least = INFINITY;  // the narrowest room, which the growth rules keep at 3 m or more
      for (const growth::Box& b : u.parts) least = std::min({least, b.size(0), b.size(1)});
      uj.push_back({{"id", u.id}, {"area", u.floorArea()}, {"parts", u.parts.size()}, {"least_width", least}});
    }
    fj["units"] = uj;
    if (!from.empty()) {
      fj["fits_growth_rules"] = broken.empty();
      if (!broken.empty()) fj["violations"] = broken;
    }
    j["forms"].push_back(fj);
    fits.push_back(broken.empty());
  }
  best = growth::bestFit(fitted, fits);
  if (best >= 0) j["best"] = best + 1;

  auto place = [&](std::vector<growth::Unit> units, std::size_t k, double dx, double dy) {
    for (growth::Unit& u : units) {
      for (growth::Box& b : u.parts) b.lo[0] += dx, b.hi[0] += dx, b.lo[1] += dy, b.hi[1] += dy;
      MeshData m = growth::unitMesh(u);
      const int mat = m.addMaterial(kPalette[std::size_t(u.id - 1) % std::size(kPalette)]);
      for (int& fm : m.faceMaterial) fm = mat;
      scene.replaceObject(id++, Kind::Unit, "form " + std::to_string(k + 1) + " unit " + std::to_string(u.id), m);
    }
  };
  if ((!out.empty() || !png.empty()) && !from.empty() && best >= 0) {
    // The model sliced at the storey's top (Fig. 8.3), so the completed storey shows.
    growth::Site sliced = model.site;
    sliced.storeys = storey + 1;
    sliced.roof.reset();  // a section shows cut tops, not roofs over them
    sliced.openings.reset();
    const double top = sliced.top();
    for (growth::Box& c : sliced.circulation) c.hi[2] = std::min(c.hi[2], top);
    std::vector<growth::Unit> below;
    for (const growth::Unit& u : model.units) {
      growth::Unit b = u;
      b.parts.clear();
      for (growth::Box p : u.parts)
        if (p.lo[2] < top - 1e-9) p.hi[2] = std::min(p.hi[2], top), b.parts.push_back(p);
      if (!b.parts.empty()) below.push_back(b);
    }
    scene = modelScene(sliced, below);
    id = scene.objects().empty() ? 1 : scene.objects().rbegin()->first + 1;
    place(fitted[std::size_t(best)].units, std::size_t(best), 0, 0);
  } else if (!out.empty() || !png.empty()) {
    for (std::size_t k = 0; k < fitted.size(); ++k) {
      const double dx = double(k % 4) * (w + gap), dy = -double(k / 4) * (h + gap);
      place(fitted[k].units, k, dx, dy);
      growth::Unit ground;
      ground.parts = {{{region.x0 + dx, region.y0 + dy, -0.2}, {region.x1 + dx, region.y1 + dy, 0.0}}};
      MeshData g = growth::unitMesh(ground);
      const int mat = g.addMaterial("concrete");
      for (int& fm : g.faceMaterial) fm = mat;
      scene.replaceObject(id++, Kind::Site, "form " + std::to_string(k + 1) + " region", g);
    }
  }
  if (!out.empty() && !set.forms.empty()) {
    exportScene(scene, out);
    j["out"] = out;
  }
  if (!png.empty() && !set.forms.empty()) {
    render::HeadlessContext context;
    writeScenePng(scene, from.empty() ? SceneView{-90, 55, 0.92} : SceneView{-75, 30, 0.95}, png);
    j["render"] = png;
  }
  std::cout << j.dump() << "\n";
  if (set.forms.empty()) {
    std::cerr << "corbel-cli: complete: no form reached the complexity range (" << set.note << ")\n";
    return 1;
  }
  if (!from.empty() && best < 0) {
    std::cerr << "corbel-cli: complete: none of the " << set.forms.size()
              << " forms obeys the growth rules in the region (each form's \"violations\" say why); "
                 "try another --region, --complexity, --seed or a larger --count\n";
    return 1;
  }
  return 0;
}

}  // namespace corbel::cli
