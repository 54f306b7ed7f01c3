#pragma once
// Topology generation (Sec. 7.3.1, Fig. 7.9): from n canonical units, forms whose complexity
// F_q lies in a requested range.
//
// The units start as squares side by side, each shifted against the one before by a third
// or a half of its side (a new arrangement each attempt). A move splits a face at a "split point" (an end
// of one of its contacts, the red points of Fig. 7.9) and advances one piece outward, so
// the new step edge lands on a neighbour (a Type I move, Sec. 7.2.1) or the piece reaches
// one. Only moves that raise F_q without passing the top of the range are taken; among
// them the unit with the fewest faces goes first (balanced shape complexity), the rest is
// chosen by the seeded generator. A form is kept when F_q reaches the range and its
// topology (each unit's cycle of edge labels and the links between units) is new.
#include "growth/complexity.h"
#include "growth/floorplan.h"

#include <cstdint>
#include <string>
#include <vector>

namespace corbel {
class Progress;
}

namespace corbel::growth {

struct FormRequest {
  int seeds = 5;                     // n canonical units (1 .. 12)
  Fraction lo = Fraction::of(1, 4);  // complexity range [lo, hi]
  Fraction hi = Fraction::of(3, 10);
  int count = 4;  // distinct forms wanted (1 .. 64)
  std::uint64_t seed = 1;
  GridCoord unitSize = 12;  // side of a canonical unit in grid cells
  GridCoord minPiece = 3;   // no split leaves a piece, and no advance a step, shorter than this
  int attempts = 200;       // restarts from the canonical units before giving up
};

struct Form {
  Floorplan plan;
  Complexity complexity;
  int moves = 0;
  std::string topology;  // the signature that makes it distinct
};

struct FormSet {
  std::vector<Form> forms;
  int attempts = 0;
  std::string note;  // why fewer than `count` came back, if so
};

// Throws InputError on an unusable request (bad counts, lo > hi, hi ≥ 1). With a progress,
// reports after each attempt and throws Cancelled between attempts once it is cancelled.
FormSet generateForms(const FormRequest& request, Progress* progress = nullptr);

// n canonical squares of side `size` in a row, touching (F_q = (n−1)/(4n)).
Floorplan canonicalRow(int n, GridCoord size);
std::string topologySignature(const Floorplan& plan);

}  // namespace corbel::growth
