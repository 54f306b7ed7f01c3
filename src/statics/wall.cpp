#include "statics/wall.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace corbel::statics {
namespace {

struct Span {
  double lo, hi;
};

}  // namespace

std::vector<Block> wallBlocks(const WallSpec& spec) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(spec.length) || !positive(spec.thickness) || !positive(spec.height))
    throw Error("wall: length, thickness and height must be positive numbers");
  if (spec.courses < 1 || spec.courses > 10000) throw Error("wall: the number of courses must be in 1..10000");
  if (!positive(spec.blockLength)) throw Error("wall: the block length must be a positive number");
  if (spec.length / spec.blockLength > 100000) throw Error("wall: too many blocks per course");
  if (!positive(spec.density)) throw Error("wall: the density must be a positive number");
  const double bearing = spec.blockLength / 2, sliver = spec.blockLength / 4;
  std::vector<Span> lintels;
  for (std::size_t i = 0; i < spec.windows.size(); ++i) {
    const WindowSpec& w = spec.windows[i];
    const std::string who = "wall: window " + std::to_string(i);
    if (!std::isfinite(w.x) || !positive(w.width)) throw Error(who + ": x and width must be numbers, the width positive");
    if (w.sill < 0 || w.head <= w.sill || w.head >= spec.courses)
      throw Error(who + ": needs 0 ≤ sill < head < courses (the head course holds the lintel)");
    const Span l{w.x - bearing, w.x + w.width + bearing};
    if (l.lo < 0 || l.hi > spec.length) throw Error(who + ": the opening and its lintel's bearings leave the wall");
    for (std::size_t j = 0; j < lintels.size(); ++j)
      if (l.lo < lintels[j].hi && lintels[j].lo < l.hi)
        throw Error(who + " overlaps window " + std::to_string(j) + " (with their lintels)");
    lintels.push_back(l);
  }
  std::vector<Block> out;
  for (int c = 0; c < spec.courses; ++c) {
    std::vector<double> fixedCuts = {0.0, spec.length};
    std::vector<Span> open, whole;
    for (std::size_t i = 0; i < spec.windows.size(); ++i) {
      const WindowSpec& w = spec.windows[i];
      if (c >= w.sill && c < w.head) {
        open.push_back({w.x, w.x + w.width});
        fixedCuts.push_back(w.x);
        fixedCuts.push_back(w.x + w.width);
      } else if (c == w.head) {
        whole.push_back(lintels[i]);
        fixedCuts.push_back(lintels[i].lo);
        fixedCuts.push_back(lintels[i].hi);
      }
    }
    std::vector<double> cuts = fixedCuts;
    // Bond joints: k·b on even courses, (k + ½)·b on odd ones.
    for (int k = (c % 2) ? 0 : 1;; ++k) {
      const double x = (k + ((c % 2) ? 0.5 : 0.0)) * spec.blockLength;
      if (x >= spec.length) break;
      bool keep = true;
      for (double f : fixedCuts) keep = keep && std::abs(x - f) >= sliver;
      for (const Span& s : whole) keep = keep && !(x > s.lo && x < s.hi);
      for (const Span& s : open) keep = keep && !(x > s.lo && x < s.hi);
      if (keep) cuts.push_back(x);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const double z0 = spec.height * c / spec.courses, z1 = spec.height * (c + 1) / spec.courses;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double mid = 0.5 * (cuts[k] + cuts[k + 1]);
      bool inOpening = false;
      for (const Span& s : open) inOpening = inOpening || (mid > s.lo && mid < s.hi);
      if (inOpening) continue;
      out.push_back(boxBlock("course " + std::to_string(c) + " block " + std::to_string(out.size()),
                             Vec3(cuts[k], 0.0, z0), Vec3(cuts[k + 1], spec.thickness, z1), spec.density));
    }
  }
  return out;
}

}  // namespace corbel::statics
