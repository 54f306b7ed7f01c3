#pragma once
// Growth sites in the Document (core/growth_spec.h) become grown units in the Scene.
#include "core/growth_spec.h"
#include "core/scene_sync.h"

namespace corbel::growth {

// The growth object's builder: parses the spec's site (a fault throws InputError at
// "growth.site.<path>"), grows it from the spec's seed for spec.steps steps (or until every unit
// stops), one step per progress report and cancellable between steps, on the exact CPU view
// mapper. The object's faces are every unit (kind Unit, material plaster), the cores (concrete)
// and the circulation (slate), each a closed box complex. When every unit has stopped it says
// so in the build's warnings ("every unit stopped after N steps"), which the editor's Run reads.
void registerKernel(SceneSync& sync);

// The words of that note, for the editor: the steps after which every unit stopped, or -1.
int stoppedAfter(const std::vector<std::string>& warnings);

}  // namespace corbel::growth
