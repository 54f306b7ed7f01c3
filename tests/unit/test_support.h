#pragma once
// Small helpers shared by the unit tests (temporary folders, files, hand-built meshes).
#include "core/mesh_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace corbel::test {

// A fresh folder under $TMPDIR (or /tmp), removed with everything in it on destruction.
class TempDir {
 public:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/corbel-test-XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data())) ADD_FAILURE() << "mkdtemp failed";
    path_ = buf.data();
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  // Names of the entries in the folder, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::string path_;
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

inline std::string sourcePath(const std::string& relative) { return std::string(CORBEL_SOURCE_DIR) + "/" + relative; }

// Every *.corbel file under assets/examples/, sorted.
inline std::vector<std::string> exampleProjects() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(sourcePath("assets/examples")))
    if (e.path().extension() == ".corbel") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// An axis-aligned box [lo, hi] written out by hand: 8 points, 6 quads counter-clockwise seen
// from outside (independent of the massing kernel).
inline MeshData handBox(const Vec3& lo, const Vec3& hi, const std::string& material = "",
                        const std::string& sideTag = "side") {
  MeshData m;
  const int tag = m.addTag(sideTag), top = m.addTag("top"), bottom = m.addTag("bottom");
  const int mat = m.addMaterial(material);
  int v[2][2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        v[i][j][k] = m.addPoint(Vec3(i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]));
  m.addFace({v[0][0][0], v[0][1][0], v[1][1][0], v[1][0][0]}, bottom, mat);  // z = lo, normal -Z
  m.addFace({v[0][0][1], v[1][0][1], v[1][1][1], v[0][1][1]}, top, mat);     // z = hi, normal +Z
  m.addFace({v[0][0][0], v[1][0][0], v[1][0][1], v[0][0][1]}, tag, mat);     // y = lo, normal -Y
  m.addFace({v[0][1][0], v[0][1][1], v[1][1][1], v[1][1][0]}, tag, mat);     // y = hi, normal +Y
  m.addFace({v[0][0][0], v[0][0][1], v[0][1][1], v[0][1][0]}, tag, mat);     // x = lo, normal -X
  m.addFace({v[1][0][0], v[1][1][0], v[1][1][1], v[1][0][1]}, tag, mat);     // x = hi, normal +X
  return m;
}

}  // namespace corbel::test
