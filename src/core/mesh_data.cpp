#include "core/mesh_data.h"

#include <algorithm>

namespace corbel {

namespace {
int intern(std::vector<std::string>& table, const std::string& name) {
  auto it = std::find(table.begin(), table.end(), name);
  if (it != table.end()) return static_cast<int>(it - table.begin());
  table.push_back(name);
  return static_cast<int>(table.size()) - 1;
}
}  // namespace

int MeshData::addTag(const std::string& name) { return intern(tags, name); }
int MeshData::addMaterial(const std::string& name) { return intern(materials, name); }

void MeshData::append(const MeshData& other) {
  const int base = static_cast<int>(points.size());
  points.insert(points.end(), other.points.begin(), other.points.end());
  for (size_t f = 0; f < other.faces.size(); ++f) {
    std::vector<int> loop = other.faces[f];
    for (int& i : loop) i += base;
    const int tag = f < other.faceTag.size() ? addTag(other.tags[other.faceTag[f]]) : 0;
    const int mat =
        f < other.faceMaterial.size() ? addMaterial(other.materials[other.faceMaterial[f]]) : 0;
    addFace(std::move(loop), tag, mat);
  }
}

std::size_t splitPinchedVertices(MeshData& mesh) {
  struct Corner {
    int prev, next, face, index;
  };
  std::vector<std::vector<Corner>> corners(mesh.points.size());
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const auto& loop = mesh.faces[f];
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i)
      if (loop[i] >= 0 && static_cast<std::size_t>(loop[i]) < corners.size())
        corners[loop[i]].push_back({loop[(i + n - 1) % n], loop[(i + 1) % n], f, i});
  }
  std::size_t copies = 0;
  for (std::size_t v = 0; v < corners.size(); ++v) {
    auto& c = corners[v];
    if (c.size() < 6) continue;  // two closed fans need at least three faces each
    std::sort(c.begin(), c.end(), [](const Corner& a, const Corner& b) { return a.prev < b.prev; });
    auto after = [&](int next) -> int {  // the corner whose previous vertex is `next`
      const auto it = std::lower_bound(c.begin(), c.end(), next, [](const Corner& a, int p) { return a.prev < p; });
      if (it == c.end() || it->prev != next || (it + 1 != c.end() && (it + 1)->prev == next)) return -1;
      return static_cast<int>(it - c.begin());
    };
    std::vector<int> fan(c.size(), -1);
    int fans = 0;
    bool closed = true;
    for (std::size_t s = 0; s < c.size() && closed; ++s) {
      if (fan[s] >= 0) continue;
      int k = static_cast<int>(s);
      while (k >= 0 && fan[k] < 0) {
        fan[k] = fans;
        k = after(c[k].next);
      }
      closed = k == static_cast<int>(s);
      ++fans;
    }
    if (!closed || fans < 2) continue;
    for (int extra = 1; extra < fans; ++extra) {
      const int copy = mesh.addPoint(mesh.points[v]);
      for (std::size_t k = 0; k < c.size(); ++k)
        if (fan[k] == extra) mesh.faces[c[k].face][c[k].index] = copy;
      ++copies;
    }
  }
  return copies;
}

}  // namespace corbel
