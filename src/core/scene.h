#pragma once
// Scene: one OpenMesh half-edge mesh shared by every kernel (see scene_properties.h).
#include "core/geometry.h"
#include "core/mesh_data.h"
#include "core/scene_properties.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace corbel {

struct SceneTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<SceneTraits>;

// What Scene::validate says about one object's surface.
struct ValidityReport {
  std::size_t faces = 0;
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t components = 0;
  long euler = 0;                        // V − E + F
  std::size_t boundary_edges = 0;        // edges with a face on one side only
  std::size_t non_manifold_vertices = 0; // vertices whose faces form more than one fan
  std::size_t rejected_faces = 0;        // faces the kernel gave that would break manifoldness
  std::size_t degenerate_faces = 0;      // faces with (near) zero area
  std::size_t non_finite_points = 0;     // NaN or infinite coordinates
  double area = 0.0;
  double volume = 0.0;                   // signed (divergence theorem); > 0 when outward
  bool watertight() const { return boundary_edges == 0 && rejected_faces == 0; }
  bool manifold() const { return non_manifold_vertices == 0 && rejected_faces == 0; }
  // Self-consistent: finite points, no degenerate faces, and a closed surface encloses a
  // positive volume (outward orientation).
  bool consistent() const {
    return non_finite_points == 0 && degenerate_faces == 0 && (!watertight() || volume > 0);
  }
  bool closedManifold() const { return watertight() && manifold() && consistent(); }
  // One sentence per problem, for logs and the CLI.
  std::vector<std::string> problems() const;
};

class Scene {
 public:
  Scene();
  Scene(const Scene&);
  Scene& operator=(const Scene&);

  struct ObjectInfo {
    Kind kind = Kind::Mass;
    std::string name;
    std::size_t rejected_faces = 0;
  };

  // Replaces every face of `id` with `data` (objects never share vertices). Faces that
  // OpenMesh cannot add without breaking manifoldness are counted, not added.
  void replaceObject(ObjectId id, Kind kind, const std::string& name, const MeshData& data);
  void removeObject(ObjectId id);
  void setObjectName(ObjectId id, const std::string& name);
  void clear();

  bool hasObject(ObjectId id) const { return objects_.count(id) != 0; }
  const std::map<ObjectId, ObjectInfo>& objects() const { return objects_; }
  std::vector<PolyMesh::FaceHandle> faces(ObjectId id) const;  // one scan of the mesh
  // Every object's faces in one scan (exporters of large scenes).
  std::map<ObjectId, std::vector<PolyMesh::FaceHandle>> facesByObject() const;

  BBox bounds(ObjectId id) const;
  BBox bounds() const;
  ValidityReport validate(ObjectId id) const;

  const PolyMesh& mesh() const { return mesh_; }
  ObjectId faceObject(PolyMesh::FaceHandle f) const { return static_cast<ObjectId>(mesh_.property(object_, f)); }
  Kind faceKind(PolyMesh::FaceHandle f) const { return static_cast<Kind>(mesh_.property(kind_, f)); }
  const std::string& faceTag(PolyMesh::FaceHandle f) const { return tags_[mesh_.property(tag_, f)]; }
  const std::string& faceMaterial(PolyMesh::FaceHandle f) const {
    return materials_[mesh_.property(material_, f)];
  }
  int faceMaterialIndex(PolyMesh::FaceHandle f) const { return mesh_.property(material_, f); }
  const std::vector<std::string>& materialNames() const { return materials_; }
  const std::vector<std::string>& tagNames() const { return tags_; }

  // A number no other state of any Scene had: it changes on every change (copies included),
  // so the renderer and exporters can cache derived buffers by it.
  std::uint64_t revision() const { return revision_; }

 private:
  void bindProperties();
  int internTag(const std::string& name);
  int internMaterial(const std::string& name);
  void collectGarbage();
  void touch();

  PolyMesh mesh_;
  OpenMesh::FPropHandleT<std::int32_t> object_;
  OpenMesh::FPropHandleT<std::uint8_t> kind_;
  OpenMesh::FPropHandleT<std::int32_t> tag_;
  OpenMesh::FPropHandleT<std::int32_t> material_;
  std::map<ObjectId, ObjectInfo> objects_;
  std::vector<std::string> tags_{""};
  std::vector<std::string> materials_{""};
  std::unordered_map<std::string, int> tagIndex_{{"", 0}};
  std::unordered_map<std::string, int> materialIndex_{{"", 0}};
  std::uint64_t revision_ = 0;  // set by touch()
};

}  // namespace corbel
