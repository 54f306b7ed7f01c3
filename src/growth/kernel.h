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
// A growth object with `aroundUnits` grows around the Document's unit objects (SceneSync
// inputs; `unitsAround`): they are its site's fixed units, finished with roofs, doors and windows
// by it but meshed by their own objects.
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
  std::vector<Unit> units;  // the grown ones (ids 1..seeds), then the site's fixed ones
  int steps = 0;
  bool stopped = false;  // every unit stopped
};
// What a growth object's build grows from: its spec and the units already there (Site::fixed,
// for a spec with aroundUnits; growthInputOf).
struct GrowthInput {
  GrowthInput() = default;
  GrowthInput(GrowthSpec s, std::vector<Site::FixedUnit> f = {}) : spec(std::move(s)), fixed(std::move(f)) {}  // NOLINT: a spec alone grows around nothing
  GrowthSpec spec;
  std::vector<Site::FixedUnit> fixed;
  bool operator==(const GrowthInput&) const = default;
};
// `mapper` (may be null: the exact CPU mapper) renders the engine's view maps. The fixed units
// that reach into the envelope's bounds become the site's (Site::fixed).
GrownModel grow(const GrowthInput& input, Progress* progress = nullptr, ViewMapper* mapper = nullptr);
inline GrownModel grow(const GrowthSpec& spec, Progress* progress = nullptr, ViewMapper* mapper = nullptr) {
  return grow(GrowthInput{spec, {}}, progress, mapper);
}
// Adds to the site those of `fixed` that reach into its envelope's bounds.
void placeFixedUnits(Site& site, std::vector<Site::FixedUnit> fixed);

// The unit objects a growth object with aroundUnits grows around: every unit object of `others`
// (visible or not), its parts brought into the growth object's frame. A unit turned against the
// site by other than a quarter turn, or scaled differently, cannot stay axis-aligned: it is left
// out and `warnings` says so.
std::vector<Site::FixedUnit> unitsAround(const DocObject& growthObject, const std::vector<DocObject>& others,
                                         std::vector<std::string>* warnings = nullptr);
// The Document's objects a growth object reads (SceneSync inputs): its unit objects when the
// spec has aroundUnits, else none.
std::vector<DocObject> unitObjectsFor(const Document& doc, const DocObject& growthObject);
// What the growth object (a GrowthSpec's) grows from in `doc`, as its build sees it.
GrowthInput growthInputOf(const Document& doc, const DocObject& growthObject);

// What finishes a grown model, as the site asks (Site::roof, Site::openings): the roofs
// (growth/roofs.h; a region the kernel cannot roof adds a warning) and the doors and windows
// (growth/openings.h, on exact view maps). Empty when the site asks for neither.
MeshData finishMesh(const Site& site, const std::vector<Unit>& units, std::vector<std::string>& warnings);

// The words of that note, for the editor: the steps after which every unit stopped, or -1.
int stoppedAfter(const std::vector<std::string>& warnings);

}  // namespace corbel::growth
