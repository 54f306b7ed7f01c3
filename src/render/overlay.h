#pragma once
// Overlay geometry drawn over the scene: lines and arrows (force vectors, anchors, guides).
#include "core/geometry.h"
#include "core/placement.h"

#include <array>
#include <vector>

namespace corbel::render {

using Rgba = std::array<float, 4>;

class Overlay {
 public:
  void clear();
  void line(const Vec3& a, const Vec3& b, const Rgba& color);
  // A shaft and a four-sided cone head (head length = headFraction of the arrow).
  void arrow(const Vec3& from, const Vec3& to, const Rgba& color, double headFraction = 0.2);
  // A filled convex polygon (a fan of triangles), lit by its Newell normal. Drawn over a Scene
  // face it covers, it wins the depth test (the Scene's faces are pushed back by a polygon
  // offset), so it can recolour a face, e.g. a masonry block by its tension.
  void polygon(const std::vector<Vec3>& corners, const Rgba& color);

  // Interleaved [x y z r g b a] vertices.
  const std::vector<float>& lineVertices() const { return lines_; }
  // Interleaved [x y z nx ny nz r g b] triangle vertices (arrow heads).
  const std::vector<float>& triangleVertices() const { return triangles_; }
  bool empty() const { return lines_.empty() && triangles_.empty(); }

  // What has been added so far; placeSince moves what was added after it by a placement
  // (an object's panel draws in the object's own frame; the view shows it placed).
  struct Mark {
    std::size_t lines = 0, triangles = 0;
  };
  Mark mark() const { return {lines_.size(), triangles_.size()}; }
  void placeSince(const Mark& mark, const Placement& placement);

 private:
  std::vector<float> lines_;
  std::vector<float> triangles_;
};

}  // namespace corbel::render
