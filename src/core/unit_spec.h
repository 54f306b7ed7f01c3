#pragma once
// A housing unit in the Document (Ng, Sec. 5.1): the axis-aligned boxes it is made of, as
// growth/unit.h represents a unit (interior-disjoint parts whose union is the unit). A form
// completed into a region of a grown model (Ch. 7, Fig. 8.6) is extruded into such objects,
// one per unit and storey; the growth kernel builds each as a closed shell of kind Unit.
#include "core/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel {

struct UnitPart {
  Vec3 lo{0.0}, hi{0.0};  // meters, lo < hi on every axis
  bool operator==(const UnitPart&) const = default;
};

struct UnitSpec {
  std::vector<UnitPart> parts;
  std::string material = "plaster";
  bool operator==(const UnitSpec&) const = default;
};

namespace limits {
inline constexpr std::size_t kMaxUnitParts = 10000;
}

// "parts: ...", "parts[2]: ..." or "material: ..." for a bad spec; nullopt when it is fine.
std::optional<std::string> checkUnitSpec(const UnitSpec& spec);

}  // namespace corbel
