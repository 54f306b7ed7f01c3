// corbel-cli complete --seeds N --complexity LO:HI [--count K] [--region X0,Y0,X1,Y1]
//                     [--seed S] [--out FILE] [--render PNG]
#include "cli/complete.h"

#include "cli/scene_png.h"

#include "core/error.h"
#include "core/export.h"
#include "core/scene.h"
#include "growth/completion.h"
#include "growth/sizing.h"
#include "render/headless_context.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace corbel::cli {

namespace {

constexpr const char* kCompleteUsage =
    "usage: corbel-cli complete --seeds N --complexity LO:HI [--count K] [--region X0,Y0,X1,Y1] [--seed S] "
    "[--out FILE.{obj,ply,off,glb}] [--render PNG]\n";

struct BadArgument {
  std::string message;
};

double number(const std::string& flag, const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v)) throw BadArgument{flag + ": expected a number, not '" + s + "'"};
  return v;
}

long long whole(const std::string& flag, const std::string& s, long long lo, long long hi) {
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || v < lo || v > hi)
    throw BadArgument{flag + ": expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                      "], not '" + s + "'"};
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

int complete(int argc, char** argv) {
  growth::FormRequest rq;
  rq.count = 4;
  bool haveSeeds = false, haveRange = false;
  growth::PlanRect region{0, 0, 24, 16};
  std::string out, png;
  try {
    for (int i = 2; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw BadArgument{a + " needs a value"};
        return argv[++i];
      };
      if (a == "--seeds") {
        rq.seeds = int(whole(a, value(), 1, 12));
        haveSeeds = true;
      } else if (a == "--count") {
        rq.count = int(whole(a, value(), 1, 64));
      } else if (a == "--seed") {
        rq.seed = std::uint64_t(whole(a, value(), 0, 1ll << 62));
      } else if (a == "--complexity") {
        const std::string v = value();
        const auto parts = splitOn(v, ':');
        if (parts.size() != 2) throw BadArgument{"--complexity: expected LO:HI, not '" + v + "'"};
        const double lo = number("--complexity", parts[0]), hi = number("--complexity", parts[1]);
        if (lo < 0 || hi < lo) throw BadArgument{"--complexity: expected 0 <= LO <= HI, not '" + v + "'"};
        if (hi >= 0.5)
          throw BadArgument{"--complexity: HI must stay below 0.5 (Type I moves approach 1/2, Sec. 7.2.1)"};
        rq.lo = fractionOf(lo);
        rq.hi = fractionOf(hi);
        haveRange = true;
      } else if (a == "--region") {
        const std::string v = value();
        const auto parts = splitOn(v, ',');
        if (parts.size() != 4) throw BadArgument{"--region: expected X0,Y0,X1,Y1, not '" + v + "'"};
        region = {number("--region", parts[0]), number("--region", parts[1]), number("--region", parts[2]),
                  number("--region", parts[3])};
        if (region.x1 - region.x0 < 3 || region.y1 - region.y0 < 3)
          throw BadArgument{"--region: expected X1 >= X0 + 3 and Y1 >= Y0 + 3 (meters), not '" + v + "'"};
      } else if (a == "--out") {
        out = value();
        exportFormatFor(out);
      } else if (a == "--render") {
        png = value();
      } else {
        throw BadArgument{"unexpected argument " + a};
      }
    }
    if (!haveSeeds) throw BadArgument{"--seeds N is required"};
    if (!haveRange) throw BadArgument{"--complexity LO:HI is required"};
  } catch (const BadArgument& e) {
    std::cerr << "corbel-cli: complete: " << e.message << "\n" << kCompleteUsage;
    return 2;
  } catch (const Error& e) {
    std::cerr << "corbel-cli: complete: " << e.what() << "\n";
    return 2;
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

  // Each form is fitted into the region and sized; side by side (four to a row) in the scene.
  Scene scene;
  ObjectId id = 1;
  const double w = region.x1 - region.x0, h = region.y1 - region.y0, gap = 0.25 * std::min(w, h);
  j["forms"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < set.forms.size(); ++k) {
    const growth::Form& f = set.forms[k];
    growth::Cartogram c = growth::Cartogram::of(f.plan);
    growth::fitToRegion(c, region);
    growth::SizingOptions so;
    so.minWidth = std::min(0.5, 0.05 * std::min(w, h));
    growth::Layout layout = growth::Layout::of(c);
    const growth::SizingResult sized = growth::sizeGeometry(layout, so);
    const int n = int(f.plan.units().size());
    std::vector<growth::Unit> units = growth::sizedUnits(layout, n, 0.0, 3.0);

    nlohmann::ordered_json fj;
    const growth::Fraction v = f.complexity.value();
    fj["complexity"] = std::to_string(v.num) + "/" + std::to_string(v.den);
    fj["value"] = v.value();
    fj["incidences"] = f.complexity.incidences;
    fj["faces"] = f.complexity.faces;
    fj["moves"] = f.moves;
    fj["sub_units"] = c.subUnits();
    fj["sea_rectangles"] = int(c.rects.size()) - c.subUnits();
    fj["area_error_before"] = sized.before;
    fj["area_error_after"] = sized.after;
    fj["sizing_passes"] = sized.passes;
    nlohmann::ordered_json uj = nlohmann::ordered_json::array();
    for (const growth::Unit& u : units)
      uj.push_back({{"id", u.id}, {"area", u.floorArea()}, {"parts", u.parts.size()}});
    fj["units"] = uj;
    j["forms"].push_back(fj);

    if (out.empty() && png.empty()) continue;
    const double dx = double(k % 4) * (w + gap), dy = -double(k / 4) * (h + gap);
    for (growth::Unit& u : units) {
      for (growth::Box& b : u.parts) b.lo[0] += dx, b.hi[0] += dx, b.lo[1] += dy, b.hi[1] += dy;
      MeshData m = growth::unitMesh(u);
      const int mat = m.addMaterial(kPalette[std::size_t(u.id - 1) % std::size(kPalette)]);
      for (int& fm : m.faceMaterial) fm = mat;
      scene.replaceObject(id++, Kind::Unit, "form " + std::to_string(k + 1) + " unit " + std::to_string(u.id), m);
    }
    growth::Unit ground;
    ground.parts = {{{region.x0 + dx, region.y0 + dy, -0.2}, {region.x1 + dx, region.y1 + dy, 0.0}}};
    MeshData g = growth::unitMesh(ground);
    const int mat = g.addMaterial("concrete");
    for (int& fm : g.faceMaterial) fm = mat;
    scene.replaceObject(id++, Kind::Site, "form " + std::to_string(k + 1) + " region", g);
  }
  if (!out.empty() && !set.forms.empty()) {
    exportScene(scene, out);
    j["out"] = out;
  }
  if (!png.empty() && !set.forms.empty()) {
    render::HeadlessContext context;
    writeScenePng(scene, {-90, 55, 0.92}, png);
    j["render"] = png;
  }
  std::cout << j.dump() << "\n";
  if (set.forms.empty()) {
    std::cerr << "corbel-cli: complete: no form reached the complexity range (" << set.note << ")\n";
    return 1;
  }
  return 0;
}

}  // namespace corbel::cli
