// editor/new_objects.h: what Object > Add makes builds in its kernel, where the user sees it.
#include "editor/new_objects.h"

#include "core/scene.h"
#include "core/scene_sync.h"
#include "growth/kernel.h"
#include "statics/examples.h"
#include "statics/kernel.h"

#include "statics/template_models.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace corbel::editor {
namespace {

TEST(NewObjects, BesideTheSceneIsFourMetresRightAndCentred) {
  BBox scene;
  scene.add(Vec3(-5, 0, 0));
  scene.add(Vec3(10, 20, 6));
  const Vec2 at = besideScene(scene, 8);
  EXPECT_DOUBLE_EQ(at[0], 14);  // 10 + 4
  EXPECT_DOUBLE_EQ(at[1], 6);   // centre 10 − 8 / 2
  EXPECT_DOUBLE_EQ(besideScene(BBox(), 8)[0], 0);
}

TEST(NewObjects, TheStarterGrowthSiteGrowsInsideItsEnvelope) {
  SceneSync sync;
  growth::registerKernelWith(sync, [] { return std::shared_ptr<growth::ViewMapper>(); });
  Document doc;
  const ObjectId id = doc.add("Site", starterGrowthSite(Vec2(100, 50)));
  Scene scene;
  sync.update(doc, scene);
  const auto it = sync.status().find(id);
  ASSERT_TRUE(it == sync.status().end() || it->second.error.empty()) << it->second.error;
  const BBox b = scene.bounds(id);
  ASSERT_FALSE(b.empty());
  // Units grow within the 30 × 20 m envelope at (100, 50), up to 3 storeys of 3 m (to the
  // micrometre: the kernel's arithmetic leaves units a rounding error past the envelope).
  EXPECT_GE(b.lo[0], 100 - 1e-6);
  EXPECT_LE(b.hi[0], 130 + 1e-6);
  EXPECT_GE(b.lo[1], 50 - 1e-6);
  EXPECT_LE(b.hi[1], 70 + 1e-6);
  EXPECT_LE(b.hi[2], 9 + 1e-6);
  EXPECT_GT(b.hi[2], 0);
}

TEST(NewObjects, EveryMasonryTemplateIsOffered) {
  const auto t = masonryTemplates();
  ASSERT_EQ(t.size(), statics::exampleNames().size() + statics::templateModelNames().size());
  std::size_t examples = 0;
  for (const MasonryTemplate& m : t) {
    const auto& names = statics::exampleNames();
    EXPECT_EQ(m.example, std::find(names.begin(), names.end(), m.model) != names.end()) << m.model;
    examples += m.example;
    EXPECT_NE(m.label, m.model) << "a label in words for " << m.model;
    EXPECT_NO_THROW(statics::modelOf(masonryObject(m.model))) << m.model;
  }
  EXPECT_EQ(examples, statics::exampleNames().size());
  EXPECT_FALSE(t.front().example) << "the templates alone come first";
}

}  // namespace
}  // namespace corbel::editor
