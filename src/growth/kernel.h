#pragma once
// Growth sites in the Document (core/growth_spec.h) become grown units in the Scene.
#include "core/growth_spec.h"
#include "core/scene_sync.h"
#include "core/unit_spec.h"
#include "growth/site.h"
#include "growth/unit.h"
#include "growth/view_map.h"

#include <functional>
#include <memory>

namespace corbel::growth {

// The growth object's builder: parses the spec's site (a fault throws InputError at
// "growth.site.<path>"), grows it from the spec's seed for spec.steps steps (or until every unit
// stops), one step per progress report and cancellable between steps, on the exact CPU view
// mapper. The object's faces are every unit (kind Unit, material plaster), the cores (concrete)
// and the circulation (slate), each a closed box complex, and what finishMesh adds (roofs,
// doors, windows) when the site asks for it. When every unit has stopped it says
// so in the build's warnings ("every unit stopped after N steps"), which the editor's Run reads.
// Unit objects (core/unit_spec.h) are built the same way: one closed shell of their parts, of
// kind Unit, in the spec's material.
void registerKernel(SceneSync& sync);
// The same, but each growth build asks `mappers` for the view mapper to grow on (null: the exact
// CPU one); the editor's GL view maps come this way. Builds run on any thread, so the source and
// the mappers it gives must be safe to call from one.
using MapperSource = std::function<std::shared_ptr<ViewMapper>()>;
void registerKernelWith(SceneSync& sync, MapperSource mappers);

// What a growth object's build grows: the parsed site, and the units after the spec's steps
// (or once every unit stopped). The builder and the editor's form completion share it, so the
// completion sees the model the 3D view shows.
struct GrownModel {
  Site site;
  std::vector<Unit> units;
  int steps = 0;
  bool stopped = false;  // every unit stopped
};
// `mapper` (may be null: the exact CPU mapper) renders the engine's view maps.
GrownModel grow(const GrowthSpec& spec, Progress* progress = nullptr, ViewMapper* mapper = nullptr);

// What finishes a grown model, as the site asks (Site::roof, Site::openings): the roofs
// (growth/roofs.h; a region the kernel cannot roof adds a warning) and the doors and windows
// (growth/openings.h, on exact view maps). Empty when the site asks for neither.
MeshData finishMesh(const Site& site, const std::vector<Unit>& units, std::vector<std::string>& warnings);

// The words of that note, for the editor: the steps after which every unit stopped, or -1.
int stoppedAfter(const std::vector<std::string>& warnings);

}  // namespace corbel::growth
