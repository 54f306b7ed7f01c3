#include "sim/posed_mesh.h"

namespace corbel::sim {
namespace {

void addBlock(MeshData& mesh, const statics::Block& block, const Pose& pose, int tag, int material) {
  const int first = int(mesh.points.size());
  for (const Vec3& v : block.vertices) mesh.addPoint(pose.apply(v));
  for (const auto& f : block.faces) {
    std::vector<int> loop;
    loop.reserve(f.size());
    for (int v : f) loop.push_back(first + v);
    mesh.addFace(std::move(loop), tag, material);
  }
}

}  // namespace

MeshData posedMesh(const Session& session, const std::string& material) {
  MeshData mesh;
  const int stone = mesh.addMaterial(material);
  const int block = mesh.addTag("block"), ground = mesh.addTag("ground"), load = mesh.addTag("load");
  const auto& blocks = session.design().blocks;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!session.removed(int(i)))
      addBlock(mesh, blocks[i], session.poses()[i], blocks[i].fixed ? ground : block, stone);
  for (std::size_t k = 0; k < session.pieces().size(); ++k) {
    const statics::Block& whole = blocks[session.pieces()[k].block];
    addBlock(mesh, session.pieces()[k].shape, session.piecePoses()[k], whole.fixed ? ground : block, stone);
  }
  for (std::size_t k = 0; k < session.loads().size(); ++k)
    addBlock(mesh, session.loads()[k].cube, session.loadPoses()[k], load, stone);
  return mesh;
}

}  // namespace corbel::sim
