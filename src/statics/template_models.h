#pragma once
// Each masonry template of Whiting et al. 2009 (Sec. 2, Fig. 3 and 4) alone on the ground, as a
// parametric model an artist adds and edits as an object of its own kind: the semicircular and
// pointed arches, a column of drums, a wall with windows under lintels, a buttress, a dome and
// a dome on a drum. The composed examples (statics/examples.h) put templates together.
#include "statics/parameters.h"

#include <optional>
#include <string>
#include <vector>

namespace corbel::statics {

std::vector<std::string> templateModelNames();
// The model of that name, or nullopt when it is not a template (exampleByName reports the
// unknown name, listing both kinds).
std::optional<ParametricModel> templateModelByName(const std::string& name);

}  // namespace corbel::statics
