#include "core/materials.h"

#include <cstdint>

namespace corbel {

const std::vector<MaterialInfo>& builtinMaterials() {
  static const std::vector<MaterialInfo> table = {
      {"plaster", {0.86f, 0.82f, 0.74f}, 0.9f},  {"stone", {0.72f, 0.68f, 0.60f}, 0.85f},
      {"brick", {0.66f, 0.33f, 0.24f}, 0.9f},    {"roof_tile", {0.58f, 0.24f, 0.18f}, 0.8f},
      {"slate", {0.34f, 0.37f, 0.42f}, 0.7f},    {"concrete", {0.62f, 0.62f, 0.60f}, 0.95f},
      {"timber", {0.55f, 0.40f, 0.25f}, 0.8f},   {"glass", {0.45f, 0.62f, 0.75f}, 0.1f},
      {"metal", {0.55f, 0.58f, 0.62f}, 0.35f},   {"grass", {0.42f, 0.58f, 0.30f}, 1.0f},
  };
  return table;
}

bool isBuiltinMaterial(std::string_view name) {
  for (const auto& m : builtinMaterials())
    if (m.name == name) return true;
  return false;
}

Rgb kindColor(Kind kind) {
  switch (kind) {
    case Kind::Mass: return {0.80f, 0.78f, 0.72f};
    case Kind::Shell: return {0.86f, 0.82f, 0.74f};
    case Kind::Block: return {0.74f, 0.69f, 0.60f};
    case Kind::Unit: return {0.90f, 0.88f, 0.84f};
    case Kind::Ornament: return {0.78f, 0.72f, 0.62f};
    case Kind::Site: return {0.50f, 0.60f, 0.42f};
    case Kind::Feature: return {0.45f, 0.40f, 0.36f};
  }
  return {0.8f, 0.8f, 0.8f};
}

Rgb materialColor(std::string_view name, Kind kind) {
  if (name.empty()) return kindColor(kind);
  for (const auto& m : builtinMaterials())
    if (m.name == name) return m.color;
  // FNV-1a of the name picks a muted, stable hue.
  std::uint32_t h = 2166136261u;
  for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  auto channel = [&](int shift) { return 0.35f + 0.5f * static_cast<float>((h >> shift) & 0xff) / 255.0f; };
  return {channel(0), channel(8), channel(16)};
}

}  // namespace corbel
