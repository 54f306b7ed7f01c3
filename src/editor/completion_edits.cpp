#include "editor/completion_edits.h"

#include "core/error.h"

#include <iterator>

namespace corbel::editor {

namespace {
const char* const kPalette[] = {"brick", "glass",     "grass", "timber",  "slate",
                                "stone", "roof_tile", "metal", "plaster", "concrete"};
}

const char* unitMaterial(int id) { return kPalette[std::size_t(id > 0 ? id - 1 : 0) % std::size(kPalette)]; }

std::vector<ObjectId> extrudeUnits(Document& doc, const std::vector<growth::Unit>& units, const UnitExtrusion& how) {
  if (how.storeys < 1 || how.storeys > 100) throw InputError("storeys", "expected 1 to 100");
  if (!(how.storeyHeight > 0) || how.storeyHeight > 100) throw InputError("storey height", "expected 0 to 100 m");
  std::vector<ObjectId> ids;
  for (const growth::Unit& u : units) {
    if (u.parts.empty()) continue;
    for (int k = 0; k < how.storeys; ++k) {
      UnitSpec spec;
      spec.material = unitMaterial(u.id);
      for (const growth::Box& b : u.parts) {
        UnitPart p{b.lo, b.hi};
        p.lo[2] += k * how.storeyHeight;
        p.hi[2] += k * how.storeyHeight;
        spec.parts.push_back(p);
      }
      if (auto problem = checkUnitSpec(spec)) throw InputError("unit " + std::to_string(u.id), *problem);
      std::string base = how.name + " unit " + std::to_string(u.id);
      if (k > 0) base += " storey " + std::to_string(k + 1);
      ids.push_back(doc.add(base, std::move(spec)));
    }
  }
  return ids;
}

}  // namespace corbel::editor
