#pragma once
// View maps (Sec. 5.2). The view of a vertical face is the part of it seen from outside the
// site along its normal under orthographic projection; a unit's view is the sum over its
// faces. Faces are axis-aligned, so four projections cover every face: the directions ±x and
// ±y (the paper's ±x and ±z; corbel is Z up).
//
// A ViewMap is one projection as a grid of cells, each holding the id of the box seen first
// there and that face's depth. The grid's edges may be uniform (pixels: a rasterizer, GL) or
// every box's projected coordinates (ExactViewMapper: then cell areas are exact). Ids are
// 32-bit (unit ids ≥ 1; 0 is empty; kObstacleId is a core or circulation), so any number of
// units fits. The ViewMapper interface is what the growth engine calls; src/render may
// implement it with GL, and tests hold every implementation against ExactViewMapper.
#include "growth/box.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace corbel::growth {

enum class ViewDirection { PosX = 0, NegX = 1, PosY = 2, NegY = 3 };  // outward normal of the faces seen
inline constexpr std::array<ViewDirection, 4> kViewDirections{ViewDirection::PosX, ViewDirection::NegX,
                                                              ViewDirection::PosY, ViewDirection::NegY};
inline constexpr std::uint32_t kEmptyId = 0;
inline constexpr std::uint32_t kObstacleId = 0xFFFFFFFFu;

struct ViewBox {
  Box box;
  std::uint32_t id = kEmptyId;
};

// Where a box lands in projection d: plane coordinates (u = the other horizontal axis,
// v = z) and the depth of its face toward the viewer (larger is nearer).
Rect projectBox(const Box& b, ViewDirection d);
double frontDepth(const Box& b, ViewDirection d);
// The window a view map covers in projection d, from the site's bounds.
Rect projectFrame(const Box& frame, ViewDirection d);

// The view a new piece of surface would add to its unit, and what it would take from others.
struct ViewGain {
  double gain = 0;
  std::map<std::uint32_t, double> taken;  // unit id → area it would lose
  void add(const ViewGain& g);
};

class ViewMap {
 public:
  ViewMap() = default;
  // Empty cells between consecutive edges (both increasing, at least two each).
  ViewMap(std::vector<double> uEdges, std::vector<double> vEdges);
  // A uniform grid of `columns` × `rows` cells over `frame`.
  static ViewMap uniform(const Rect& frame, int columns, int rows);

  int columns() const { return int(u_.size()) - 1; }
  int rows() const { return int(v_.size()) - 1; }
  const std::vector<double>& uEdges() const { return u_; }
  const std::vector<double>& vEdges() const { return v_; }
  std::uint32_t id(int i, int j) const { return id_[index(i, j)]; }
  double depth(int i, int j) const { return depth_[index(i, j)]; }
  // Keeps the nearer of what the cell holds and (id, depth).
  void offer(int i, int j, std::uint32_t id, double depth);
  // Sums the cell areas per id; call after the last offer.
  void finish();

  double area(std::uint32_t id) const;
  const std::map<std::uint32_t, double>& areas() const { return areas_; }
  // A face at `depth` covering r, belonging to `self`: the area where it would be seen first
  // and that `self` does not already see there (gain), and per other unit what it hides.
  ViewGain gain(const Rect& r, double depth, std::uint32_t self) const;

 private:
  std::size_t index(int i, int j) const { return std::size_t(j) * columns() + i; }
  std::vector<double> u_, v_;
  std::vector<std::uint32_t> id_;
  std::vector<double> depth_;
  std::map<std::uint32_t, double> areas_;
};

struct ViewMaps {
  std::array<ViewMap, 4> maps;  // by ViewDirection
  const ViewMap& operator[](ViewDirection d) const { return maps[static_cast<int>(d)]; }
  ViewMap& operator[](ViewDirection d) { return maps[static_cast<int>(d)]; }
  double view(std::uint32_t id) const;
  double view(std::uint32_t id, ViewDirection d) const { return (*this)[d].area(id); }
  // Gain in view (Sec. 5.2) of adding the box `added` to unit `self`: every vertical side of
  // the added region, in its own projection, against the current maps.
  ViewGain gain(const Box& added, std::uint32_t self) const;
};

class ViewMapper {
 public:
  virtual ~ViewMapper() = default;
  // The four projections of `boxes`; `frame` bounds them all (the site).
  virtual ViewMaps render(const std::vector<ViewBox>& boxes, const Box& frame) = 0;
};

// Exact visible areas: the grid's edges are every projected box coordinate, so each cell is
// covered by a box entirely or not at all.
class ExactViewMapper : public ViewMapper {
 public:
  ViewMaps render(const std::vector<ViewBox>& boxes, const Box& frame) override;
};

// A CPU rasterizer with square pixels of `pixelSize` meters: a pixel shows the nearest box
// whose projection holds the pixel's centre (half-open on the high sides, like GL's rule).
class RasterViewMapper : public ViewMapper {
 public:
  explicit RasterViewMapper(double pixelSize) : pixel_(pixelSize) {}
  ViewMaps render(const std::vector<ViewBox>& boxes, const Box& frame) override;

 private:
  double pixel_;
};

// The pixel range [first, last) whose centres lie in [a, b) on a grid starting at `origin`.
std::pair<int, int> pixelSpan(double a, double b, double origin, double pixel, int count);

}  // namespace corbel::growth
