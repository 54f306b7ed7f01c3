// statics/kernel.h: masonry objects of a Document become blocks in the Scene through SceneSync.
#include "statics/kernel.h"

#include "core/document.h"
#include "core/error.h"
#include "core/scene.h"
#include "statics/examples.h"
#include "statics/tolerances.h"

#include <gtest/gtest.h>

namespace corbel::statics {
namespace {

// One masonry object synced into a Scene by the statics kernel alone.
struct Synced {
  Scene scene;
  SceneSync sync;
  ObjectId id = 0;
  explicit Synced(const MasonrySpec& spec) {
    Document d;
    id = d.add("m", spec);
    registerKernel(sync);
    sync.update(d, scene);
  }
  const std::string& error() const { return sync.status().at(id).error; }
};

// Every block's volume, the ground's included, from the statics model's own mass properties.
double volumeOf(const Assembly& as) {
  BBox box;
  for (const Block& b : as.blocks)
    for (const Vec3& v : b.vertices) box.add(v);
  double all = 0;
  for (const BlockProperties& p : validateAssembly(as, lengthTolerance(box))) all += p.volume;
  return all;
}

// The arch on columns with a set thickness: one closed polyhedron per block, of kind Block,
// the free blocks' volume (as the Scene measures it, from the mesh) equal to the statics
// model's own (from its blocks), and the thickness really applied.
TEST(StaticsKernel, AMasonryObjectBecomesItsModelsBlocks) {
  MasonrySpec spec;
  spec.model = "arch-on-columns";
  spec.parameters = {{"thickness", 0.21}};
  const Synced s(spec);
  ASSERT_TRUE(s.error().empty()) << s.error();
  const ValidityReport r = s.scene.validate(s.id);
  EXPECT_TRUE(r.closedManifold());

  ParametricModel model = exampleByName("arch-on-columns");
  model.parameters.set("thickness", 0.21);
  const Assembly as = model.build(model.parameters);
  EXPECT_EQ(r.components, as.blocks.size()) << "one closed piece per block, the ground included";
  const double all = volumeOf(as);
  EXPECT_NEAR(r.volume, all, 1e-9 * all);

  // A different thickness changes the blocks (the parameter is not ignored).
  model.parameters.set("thickness", 0.3);
  EXPECT_GT(std::abs(volumeOf(model.build(model.parameters)) - r.volume), 1e-3 * all);
}

TEST(StaticsKernel, AWrongModelOrParameterIsReportedOnTheObject) {
  MasonrySpec bad;
  bad.model = "pyramid";
  try {
    modelOf(bad);
    ADD_FAILURE() << "an unknown model was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "masonry.model");
    EXPECT_NE(e.reason.find("arch-on-columns"), std::string::npos) << "the known models are listed: " << e.what();
  }
  MasonrySpec typo;
  typo.parameters = {{"thicknes", 0.2}};
  try {
    modelOf(typo);
    ADD_FAILURE() << "an unknown parameter was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "masonry.parameters.thicknes");
  }
  // Through SceneSync: the object fails with that message, and the Scene gets nothing.
  const Synced s(typo);
  EXPECT_NE(s.error().find("masonry.parameters.thicknes"), std::string::npos);
  EXPECT_FALSE(s.scene.hasObject(s.id));
}

}  // namespace
}  // namespace corbel::statics
