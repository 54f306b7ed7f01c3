#pragma once
// The shell's directed edges, each with the face loop it lies on: the index the output
// clean-up passes that move corners between faces work on (spurs.cpp, folds.cpp).
#include "extrude/sweep.h"

#include <cstdint>
#include <unordered_map>

namespace corbel::extrude {

// A directed edge u → v as one word.
inline std::uint64_t edgeKey(int u, int v) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(v);
}

// Where a directed edge of the shell lies: its face and loop.
struct EdgePlace {
  int face = -1;
  int loop = -1;
};

using EdgeIndex = std::unordered_map<std::uint64_t, EdgePlace>;

// Every directed edge of the shell once, into `edges`; false where the shell is not a closed
// 2-manifold (an edge twice, or without its partner), when which face lies across an edge is
// not known.
inline bool indexEdges(const SweepOutput& shell, EdgeIndex& edges) {
  for (std::size_t fi = 0; fi < shell.faces.size(); ++fi)
    for (std::size_t li = 0; li < shell.faces[fi].loops.size(); ++li) {
      const auto& l = shell.faces[fi].loops[li];
      for (std::size_t i = 0; i < l.size(); ++i)
        if (!edges.emplace(edgeKey(l[i], l[(i + 1) % l.size()]), EdgePlace{static_cast<int>(fi), static_cast<int>(li)})
                 .second)
          return false;
    }
  for (const auto& [k, p] : edges)
    if (!edges.count((k << 32) | (k >> 32))) return false;
  return true;
}

}  // namespace corbel::extrude
