#pragma once
// A KIFS spec as JSON: the "kifs" object of a project file (core/project_io.h) and the whole of
// a preset file, assets/kifs/NAME.json (kifs/params.h preset()).
#include "core/json_reader.h"
#include "core/kifs_spec.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace corbel {

// Every key, in a fixed order; numbers round-trip exactly.
nlohmann::ordered_json kifsToJson(const KifsSpec& spec);
// Every key is optional and defaults to core/kifs_spec.h. Types are checked here (InputError
// naming the JSON path), values by kifs::paramsOf. Unknown keys are added to `warnings`.
KifsSpec kifsFromJson(const JsonReader& r, std::vector<std::string>& warnings);

}  // namespace corbel
