#pragma once
// The KIFS panel's changes to a KIFS object (core/kifs_spec.h), as pure functions on a Document
// that the panel commits (one undo step each). The kifs kernel checks every value
// (kifs::paramsOf); a refused one throws corbel::Error naming the field and changes nothing.
#include "core/document.h"

#include <string>

namespace corbel::editor {

// Replaces the object's KIFS spec with `spec`; throws corbel::Error when there is no such KIFS
// object or the kernel refuses a value.
void setKifsSpec(Document& doc, ObjectId id, const KifsSpec& spec);

// `current` with every parameter of preset `name` (kifs::preset), keeping what is not the
// building's shape: its mesh resolution and material. Throws for an unknown preset, listing them.
KifsSpec withPreset(const KifsSpec& current, const std::string& name);

}  // namespace corbel::editor
