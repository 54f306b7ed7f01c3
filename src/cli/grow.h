#pragma once
// The Scene of a grown model, shared by corbel-cli grow and complete (docs/growth.md).

#include "core/scene.h"
#include "growth/site.h"
#include "growth/unit.h"

#include <vector>

namespace corbel::cli {

// Units (kind unit), cores and circulation (kind mass) as Scene objects, ids from 1.
Scene modelScene(const growth::Site& site, const std::vector<growth::Unit>& units);

}  // namespace corbel::cli
