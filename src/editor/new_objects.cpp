#include "editor/new_objects.h"

#include "statics/examples.h"
#include "statics/kernel.h"
#include "statics/template_models.h"

#include <nlohmann/json.hpp>

namespace corbel::editor {

Vec2 besideScene(const BBox& scene, double depth) {
  if (scene.empty()) return Vec2(0, 0);
  return Vec2(scene.hi[0] + 4.0, scene.center()[1] - depth / 2);
}

GrowthSpec starterGrowthSite(Vec2 at) {
  const double x = at[0], y = at[1];
  nlohmann::json site = {{"format", "corbel-growth-site"},
                         {"version", 1},
                         {"envelope", {{"origin", {x, y}}, {"size", {30, 20}}}},
                         {"storeys", 3},
                         {"storey_height", 3},
                         {"alpha", 0.3},
                         {"cantilever", 6},
                         {"clearance", {{"core", 1}, {"circulation", 0}}},
                         {"cores", {{{"name", "core"}, {"at", {x + 13, y + 8}}, {"size", {4, 4}}}}}};
  nlohmann::json landings = nlohmann::json::array();
  for (int storey = 0; storey < 3; ++storey) {
    landings.push_back({{"name", "landing N" + std::to_string(storey)},
                        {"at", {x + 13.5, y + 12, 3.0 * storey}},
                        {"size", {3, 4, 3}}});
    landings.push_back({{"name", "landing S" + std::to_string(storey)},
                        {"at", {x + 13.5, y + 4, 3.0 * storey}},
                        {"size", {3, 4, 3}}});
  }
  site["circulation"] = landings;
  site["generate_seeds"] = {{"count", 8}, {"size", {3, 3}}, {"target_area", {40, 80}}, {"seed", 1}};
  GrowthSpec g;
  g.site = site.dump();
  g.seed = 1;
  g.steps = -1;
  return g;
}

std::vector<MasonryTemplate> masonryTemplates() {
  const std::pair<const char*, const char*> words[] = {
      {"arch-on-columns", "Arch on Columns (Fig. 8)"},
      {"bezier-arch", "Bezier Arch (Fig. 12)"},
      {"tower", "Stacked Tower (Fig. 11)"},
      {"barrel-vault", "Barrel Vault on Buttressed Walls (Fig. 13)"},
      {"flying-buttresses", "Vault with Flying Buttresses (Fig. 13)"},
      {"groin-vault", "Groin Vault on Piers"},
      {"chapel", "Chapel (Fig. 9)"},
      {"abbey", "Abbey Nave (Fig. 1)"},
      {"mosque", "Dome on a Drum with Flyers (Fig. 10)"},
      {"mosque-hall", "Dome over a Square Hall (Fig. 10)"},
      {"semicircular-arch", "Semicircular Arch"},
      {"pointed-arch", "Pointed Arch"},
      {"column", "Column of Drums"},
      {"wall", "Wall with Windows (Fig. 3)"},
      {"buttress", "Buttress"},
      {"dome", "Dome"},
      {"dome-on-drum", "Dome on a Drum"},
  };
  std::vector<MasonryTemplate> out;
  // The templates alone first, then the composed examples.
  const std::vector<std::string> templates = statics::templateModelNames(), examples = statics::exampleNames();
  for (const auto* names : {&templates, &examples})
    for (const std::string& name : *names) {
      std::string label = name;
      for (const auto& [n, l] : words)
        if (name == n) label = l;
      out.push_back({name, label, names == &examples});
    }
  return out;
}

MasonrySpec masonryObject(const std::string& model) {
  MasonrySpec m;
  m.model = model;
  return m;
}

BBox masonryBounds(const MasonrySpec& spec) {
  const statics::ParametricModel model = statics::modelOf(spec);
  BBox box;
  for (const statics::Block& b : model.build(model.parameters).blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  return box;
}

}  // namespace corbel::editor
