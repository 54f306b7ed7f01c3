// editor/completion_edits.h: a fitted form extruded into the model adds one unit object per unit
// and storey, of kind Unit in the Scene, with the form's floor area times the storeys (measured
// independently, from the shells' volumes), in one undo step that removes exactly them.
#include "editor/completion_edits.h"

#include "core/history.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "growth/completion.h"
#include "growth/form_fit.h"
#include "growth/kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace corbel::editor {
namespace {

Document withSite() {
  Document d;
  d.add("Alpha", GrowthSpec{});
  d.add("Box", BoxSpec{});
  return d;
}

std::set<ObjectId> idsOf(const Document& d) {
  std::set<ObjectId> s;
  for (const DocObject& o : d.objects) s.insert(o.id);
  return s;
}

TEST(CompletionEdits, ExtrudingAFittedFormAddsItsUnitsWithItsFloorAreaInOneUndoStep) {
  growth::FormRequest rq;
  rq.seeds = 4;
  rq.count = 1;
  const growth::FormSet set = growth::generateForms(rq);
  ASSERT_EQ(set.forms.size(), 1u);
  const growth::PlanRect region{20, 10, 44, 28};
  growth::FitOptions fo;
  fo.z0 = 3;  // the second storey
  const growth::FittedForm f = growth::fitForm(set.forms[0].plan, region, {}, fo);
  // The expected floor area from the layout's own rectangles: every sub-unit rectangle, times storeys.
  double subUnitArea = 0;
  for (std::size_t i = 0; i < f.layout.rects.size(); ++i)
    if (f.layout.unit[i] >= 0) subUnitArea += f.layout.rects[i].area();
  const int storeys = 2;

  History history(withSite());
  const Document before = history.current();
  Document d = before;
  UnitExtrusion how;
  how.storeys = storeys;
  how.name = "Alpha form 1";
  const std::vector<ObjectId> ids = extrudeUnits(d, f.units, how);
  history.commit(d, "Extrude Alpha form 1", "");
  ASSERT_EQ(ids.size(), 4u * storeys);

  // Exactly the new objects, each a UnitSpec.
  std::set<ObjectId> added;
  for (ObjectId id : idsOf(history.current()))
    if (!idsOf(before).count(id)) added.insert(id);
  EXPECT_EQ(added, std::set<ObjectId>(ids.begin(), ids.end()));
  for (ObjectId id : ids) EXPECT_TRUE(std::holds_alternative<UnitSpec>(history.current().find(id)->spec));

  // Built by the growth kernel: closed unit shells whose volume is floor area × storey height.
  Scene scene;
  SceneSync sync;
  growth::registerKernel(sync);
  sync.update(history.current(), scene);
  double volume = 0;
  for (ObjectId id : ids) {
    ASSERT_EQ(sync.status().at(id).error, "");
    EXPECT_EQ(scene.objects().at(id).kind, Kind::Unit);
    const ValidityReport r = scene.validate(id);
    EXPECT_TRUE(r.closedManifold()) << ::testing::PrintToString(r.problems());
    EXPECT_EQ(r.components, 1u);
    volume += r.volume;
  }
  EXPECT_NEAR(volume / how.storeyHeight, subUnitArea * storeys, 1e-6 * subUnitArea);
  // The storeys stack from the fitted form's floor (z0 = 3) up.
  double zLo = 1e9, zHi = -1e9;
  for (ObjectId id : ids)
    for (const UnitPart& p : std::get<UnitSpec>(history.current().find(id)->spec).parts)
      zLo = std::min(zLo, p.lo[2]), zHi = std::max(zHi, p.hi[2]);
  EXPECT_DOUBLE_EQ(zLo, 3);
  EXPECT_DOUBLE_EQ(zHi, 3 + storeys * how.storeyHeight);

  // Ctrl+Z removes all of them, Ctrl+Y brings them back.
  const Document after = history.current();
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), before);
  sync.update(history.current(), scene);
  for (ObjectId id : ids) EXPECT_FALSE(scene.hasObject(id));
  EXPECT_TRUE(scene.hasObject(before.objects[1].id));
  ASSERT_TRUE(history.redo());
  EXPECT_EQ(history.current(), after);
  sync.update(history.current(), scene);
  for (ObjectId id : ids) EXPECT_TRUE(scene.hasObject(id));
}

TEST(CompletionEdits, UnitObjectsSurviveSaveAndLoad) {
  Document d;
  growth::Unit u;
  u.id = 2;
  u.parts = {{{0, 0, 0}, {4, 3, 3}}, {{4, 0, 0}, {6, 5, 3}}};
  const auto ids = extrudeUnits(d, {u}, {});
  ASSERT_EQ(ids.size(), 1u);
  EXPECT_EQ(d.find(ids[0])->name, "form unit 2");
  const LoadedProject back = parseProject(serializeProject(d, ""), "");
  EXPECT_EQ(back.document, d);
}

TEST(CompletionEdits, BadStoreysAreRefusedAndEmptyUnitsSkipped) {
  Document d;
  growth::Unit empty;
  empty.id = 1;
  UnitExtrusion bad;
  bad.storeys = 0;
  EXPECT_THROW(extrudeUnits(d, {empty}, bad), std::exception);
  EXPECT_TRUE(extrudeUnits(d, {empty}, {}).empty());
  EXPECT_TRUE(d.objects.empty());
}

}  // namespace
}  // namespace corbel::editor
