// posedMesh: the Scene's view of a simulation is the design's faces moved by each block's pose,
// without the removed blocks, with the dropped loads.
#include "sim/posed_mesh.h"

#include <gtest/gtest.h>

namespace corbel::sim {
namespace {

statics::Assembly twoCubes() {
  statics::Assembly as;
  as.blocks = {statics::boxBlock("low", Vec3(0, 0, 0), Vec3(0.3, 0.3, 0.3)),
               statics::boxBlock("high", Vec3(0, 0, 0.3), Vec3(0.3, 0.3, 0.6)),
               statics::boxBlock("ground", Vec3(-2, -2, -1), Vec3(2, 2, 0), 1.0, true)};
  return as;
}

TEST(PosedMesh, DesignStateIsTheDesign) {
  Session s(twoCubes());
  const MeshData mesh = posedMesh(s);
  ASSERT_EQ(mesh.faces.size(), 18u);
  ASSERT_EQ(mesh.points.size(), 24u);
  for (std::size_t b = 0; b < 3; ++b)
    for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(mesh.points[8 * b + v], s.design().blocks[b].vertices[v]);
  EXPECT_EQ(mesh.tags[mesh.faceTag[0]], "block");
  EXPECT_EQ(mesh.tags[mesh.faceTag[17]], "ground");
  EXPECT_EQ(mesh.materials[mesh.faceMaterial[0]], "stone");
}

TEST(PosedMesh, FollowsThePosesLeavesOutRemovedBlocksAndShowsLoads) {
  Session s(twoCubes());
  s.removeBlock(0);
  s.dropLoad(1, 10, 0.1);
  s.runUntil(0.2);
  const MeshData mesh = posedMesh(s, "limestone");
  ASSERT_EQ(mesh.faces.size(), 18u) << "high, ground and the load";
  for (std::size_t v = 0; v < 8; ++v) {
    const Vec3 expected = s.poses()[1].apply(s.design().blocks[1].vertices[v]);
    EXPECT_EQ(mesh.points[v], expected);
  }
  EXPECT_LT(mesh.points[0][2], 0.3 - 0.1) << "the upper cube is falling into the gap";
  EXPECT_EQ(mesh.tags[mesh.faceTag.back()], "load");
  EXPECT_EQ(mesh.materials[mesh.faceMaterial[0]], "limestone");
  // The design itself is untouched.
  EXPECT_EQ(s.design().blocks[1].vertices[0], Vec3(0, 0, 0.3));
}

}  // namespace
}  // namespace corbel::sim
