#pragma once
// MeshData: the polygon soup a kernel returns. The Scene turns it into half-edge faces.
#include "core/geometry.h"

#include <string>
#include <vector>

namespace corbel {

struct MeshData {
  std::vector<Vec3> points;
  // Each face is a loop of indices into `points`, counter-clockwise seen from outside.
  std::vector<std::vector<int>> faces;
  // Per face: index into `tags` and into `materials` (both start with "" = none).
  std::vector<int> faceTag;
  std::vector<int> faceMaterial;
  std::vector<std::string> tags{""};
  std::vector<std::string> materials{""};

  int addPoint(const Vec3& p) {
    points.push_back(p);
    return static_cast<int>(points.size()) - 1;
  }
  int addTag(const std::string& name);
  int addMaterial(const std::string& name);
  void addFace(std::vector<int> loop, int tag = 0, int material = 0) {
    faces.push_back(std::move(loop));
    faceTag.push_back(tag);
    faceMaterial.push_back(material);
  }
  // Appends another soup (for repeated or composed objects), re-indexing its tables.
  void append(const MeshData& other);
};

// Gives a vertex one copy per closed fan of faces around it, where it has several (two parts of
// a surface touching at a point, as a face with a hole touching its outer boundary leaves once
// triangulated): the soup is then a 2-manifold that touches itself there. Vertices with an open
// fan are left alone. Returns the number of copies made.
std::size_t splitPinchedVertices(MeshData& mesh);

}  // namespace corbel
