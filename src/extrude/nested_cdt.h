#pragma once
// Plan loops triangulated with CGAL's constrained Delaunay triangulation, each face knowing its
// nesting level: a flood fill across the constrained edges from the infinite face (the CGAL
// manual's polygon-with-holes recipe). Odd levels are inside (a face, a footprint), even ones
// outside or in a hole. Each vertex carries an int, the caller's index of the point. Used for
// the kernel's faces with holes (mesh_output.cpp) and the town's plain blocks (city/blocks.cpp).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <utility>
#include <vector>

namespace corbel::extrude::nested {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;
  bool inDomain() const { return nesting % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Sets every face's nesting level (call after the constraints are in).
inline void markNesting(CDT& cdt) {
  for (auto f : cdt.all_face_handles()) f->info().nesting = -1;
  std::vector<CDT::Face_handle> border{cdt.infinite_face()};
  for (int level = 0; !border.empty(); ++level) {
    std::vector<CDT::Face_handle> next;
    for (auto start : border) {
      if (start->info().nesting != -1) continue;
      std::vector<CDT::Face_handle> stack{start};
      while (!stack.empty()) {
        auto f = stack.back();
        stack.pop_back();
        if (f->info().nesting != -1) continue;
        f->info().nesting = level;
        for (int i = 0; i < 3; ++i) {
          auto n = f->neighbor(i);
          if (n->info().nesting != -1) continue;
          (cdt.is_constrained(CDT::Edge(f, i)) ? next : stack).push_back(n);
        }
      }
    }
    border = std::move(next);
  }
}

}  // namespace corbel::extrude::nested
