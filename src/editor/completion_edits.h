#pragma once
// The completion panel's change to the Document (Ng, Fig. 8.6: a completed form integrated into
// the model): its fitted units become unit objects (core/unit_spec.h), one per unit and storey,
// added in one commit so one undo removes them all.
#include "core/document.h"
#include "growth/unit.h"

#include <string>
#include <vector>

namespace corbel::editor {

struct UnitExtrusion {
  int storeys = 1;            // the units repeated this many storeys up
  double storeyHeight = 3.0;  // each storey's height; storey k's parts start k heights above the units'
  std::string name = "form";  // objects are named "<name> unit <id>" (and " storey <k>" above the first)
};

// Adds the objects to `doc` and returns their ids, in order (unit by unit, storey by storey).
// Units without parts are skipped. Each unit gets a material of its own (by id).
std::vector<ObjectId> extrudeUnits(Document& doc, const std::vector<growth::Unit>& units, const UnitExtrusion& how);

// The material a completed unit of this id is drawn in (the thumbnails use the same order).
const char* unitMaterial(int id);

}  // namespace corbel::editor
