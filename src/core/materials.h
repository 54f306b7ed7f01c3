#pragma once
// The material palette: names users type in project files, and the colors the renderer and
// exporters use for them. Unknown names get a stable color derived from the name.
#include "core/scene_properties.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace corbel {

using Rgb = std::array<float, 3>;  // linear 0..1

struct MaterialInfo {
  std::string_view name;
  Rgb color;
  float roughness;
};

// Built-in materials, in a fixed order (documented in docs/project-format.md).
const std::vector<MaterialInfo>& builtinMaterials();
bool isBuiltinMaterial(std::string_view name);
// Color of a material; "" falls back to the kind's color.
Rgb materialColor(std::string_view name, Kind kind);
Rgb kindColor(Kind kind);

}  // namespace corbel
