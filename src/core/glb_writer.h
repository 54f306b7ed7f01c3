#pragma once
// A glb written object by object (docs/export.md): each object's faces are laid out in glTF's
// buffers as it is added, so that a caller with many objects (a town) needs no Scene to hold
// them first. exportScene's glb is this writer over the Scene's objects.
#include "core/export.h"
#include "core/instances.h"
#include "core/mesh_data.h"

#include <memory>
#include <string>

namespace corbel {

class GlbWriter {
 public:
  // `options` as exportScene takes them for a glb; options.instances is read by write().
  explicit GlbWriter(const ExportOptions& options);
  ~GlbWriter();
  GlbWriter(const GlbWriter&) = delete;
  GlbWriter& operator=(const GlbWriter&) = delete;

  // An object as Scene::replaceObject(id, kind, name, mesh) would hold it: the faces a Scene
  // takes, in the order it keeps them. Objects are written in the order they are added (a
  // Scene's in the order of their ids).
  void add(ObjectId id, Kind kind, const std::string& name, const MeshData& mesh);

  // A copy of options.instances' mesh number `mesh`, which the caller need not keep: it is
  // written at once to a temporary file (SpillStreams) and read back by write(), where a mesh's
  // copies are its own `placements` and then these, in the order given. The mesh need not be in
  // options.instances yet, only by write(). Throws corbel::Error when the temporary file fails.
  void place(std::size_t mesh, const RigidPlacement& placement);

  // The instanced meshes, the scene and its georeference, written atomically to `path`; once.
  // Throws corbel::Error.
  void write(const std::string& path);

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace corbel
