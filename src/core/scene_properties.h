#pragma once
// The named per-face properties of the Scene: the contract between kernels, exporters and
// the renderer. Each name is documented here once; new kernels add theirs here.
#include <cstdint>
#include <optional>
#include <string_view>

namespace corbel {

using ObjectId = std::uint32_t;

// What an object is. Stored per face as "corbel:kind" (uint8).
enum class Kind : std::uint8_t {
  Mass = 0,      // simple mass-model volume (box specs)
  Shell = 1,     // procedural extrusion: walls and roof of one building
  Block = 2,     // masonry block (statics)
  Unit = 3,      // grown housing unit
  Ornament = 4,  // KIFS ornament mesh
  Site = 5,      // ground, plots, site envelope
  Feature = 6,   // instanced feature mesh (door, window, chimney pot)
};
inline constexpr int kKindCount = 7;

std::string_view kindName(Kind kind);
std::optional<Kind> kindFromName(std::string_view name);

namespace prop {
// ObjectId (int32 in OpenMesh, ≥ 1): the Document object a face belongs to. Objects never
// share vertices, so every connected piece of the mesh belongs to exactly one object.
inline constexpr const char* kObject = "corbel:object";
// Kind (uint8): see enum Kind.
inline constexpr const char* kKind = "corbel:kind";
// int32 index into Scene::tagName(): the semantic tag a kernel gave the face ("wall",
// "roof", "base", profile segment tags, ...). 0 is the empty tag.
inline constexpr const char* kTag = "corbel:tag";
// int32 index into Scene::materialName(): the face's material name. 0 means "by kind".
inline constexpr const char* kMaterial = "corbel:material";
}  // namespace prop

}  // namespace corbel
