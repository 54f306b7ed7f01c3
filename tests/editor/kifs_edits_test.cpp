// editor/kifs_edits.h: the KIFS panel's edits are the kernel's parameters exactly, refused with
// the field named when the kernel refuses them, and undoable through the History.
#include "editor/kifs_edits.h"

#include "core/error.h"
#include "core/history.h"
#include "kifs/distance.h"
#include "kifs/kernel.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

TEST(WithPreset, GivesThePresetsBuildingAndKeepsMeshAndMaterial) {
  KifsSpec current;
  current.meshResolution = 64;
  current.material = "concrete";
  current.scale = 2.0;
  const KifsSpec s = withPreset(current, "h");
  EXPECT_EQ(s.preset, "h");
  EXPECT_EQ(s.meshResolution, 64);
  EXPECT_EQ(s.material, "concrete");
  // The same building as the preset itself, point by point.
  const kifs::Building fromSpec(kifs::paramsOf(s)), preset(kifs::preset("h"));
  const kifs::Aabb box = preset.worldBounds();
  for (int i = 0; i <= 10; ++i) {
    const glm::dvec3 p = box.lo + (box.hi - box.lo) * (i / 10.0);
    EXPECT_EQ(fromSpec.evaluate(p).bound, preset.evaluate(p).bound);
  }
  EXPECT_THROW(withPreset(current, "no-such-preset"), Error);
}

TEST(SetKifsSpec, CommitsAValidChangeAsOneUndoStep) {
  Document d;
  const ObjectId id = d.add("K", KifsSpec{});
  History history(d);
  Document next = history.current();
  KifsSpec s = std::get<KifsSpec>(next.find(id)->spec);
  s.facade.a1 = 0.4;
  setKifsSpec(next, id, s);
  history.commit(next, "Edit a1");
  EXPECT_EQ(std::get<KifsSpec>(history.current().find(id)->spec).facade.a1, 0.4);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), d);
}

TEST(SetKifsSpec, ARefusedValueNamesTheFieldAndChangesNothing) {
  Document d;
  const ObjectId id = d.add("K", KifsSpec{});
  const Document before = d;
  KifsSpec s;
  s.mass.shell = 40;  // thicker than the building
  try {
    setKifsSpec(d, id, s);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("kifs.mass.shell:", 0), 0u) << e.what();
  }
  EXPECT_EQ(d, before);
  const ObjectId box = d.add("B", BoxSpec{});
  EXPECT_THROW(setKifsSpec(d, box, KifsSpec{}), Error);
}

}  // namespace
}  // namespace corbel::editor
