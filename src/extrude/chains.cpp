// The chains of a generalized intersection event (Sec. 4.4, Fig. 14): chain construction,
// the intra-chain stage and the inter-chain stage, which relink the active plan at l.
#include "extrude/sweeper.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace corbel::extrude::sweeping {

// Chain construction (Sec. 4.4, Fig. 14a): follow arriving corners from each edge whose
// start did not arrive. A chain is kept as its first and last edge; the edges between are
// interior. Chains of one edge are the edges l splits (splitList_): the inter-chain stage
// splits them and adds them to the list.
void Sweeper::buildChains() {
  const Marks& inK = inK_;
  const std::vector<int>& involved = involvedList_;
  interior_.clear();
  std::vector<Chain>& chains = chains_;
  chains.clear();
  Marks& used = used_;
  used.reset(edges_.size());
  for (int ei : involved) {
    if (used[ei]) continue;
    const Edge& e = edges_[ei];
    if (inK[e.start]) continue;  // not the head of a chain
    if (!inK[e.end]) continue;   // an edge the point splits (a chain of one edge)
    used.set(ei);
    int last = ei;
    for (int cur = ei;;) {
      const int nxt = corners_[edges_[cur].end].next;
      used.set(nxt);
      if (nxt != ei && inK[edges_[nxt].end]) {
        interior_.push_back(nxt);  // interior edge: shrinks to nothing at l
        cur = nxt;
        continue;
      }
      last = nxt;
      break;
    }
    chains.push_back({ei, last});
  }
}

// The intra-chain stage (Fig. 14cd): a chain's interior edges shrank to nothing at l, and a
// closed chain (a whole loop collapsing into the point) leaves the plan.
void Sweeper::intraChain() {
  for (int ei : interior_) edges_[ei].alive = false;
  const std::vector<int>& involved = involvedList_;
  const std::vector<int>& splits = splitList_;
  Marks& used = used_;
  // Closed chains: whole loops that collapse into the point.
  for (int ei : involved) {
    if (used[ei] || splits.end() != std::find(splits.begin(), splits.end(), ei)) continue;
    int cur = ei;
    do {
      used.set(cur);
      edges_[cur].alive = false;
      cur = corners_[edges_[cur].end].next;
    } while (cur != ei && !used[cur]);
  }
}

// The inter-chain stage (Fig. 14de).
bool Sweeper::interChain(int vl, const Vec2& l, double z) {
  std::vector<Chain>& chains = chains_;
  const std::vector<int>& splits = splitList_;
  // Chains of one edge: split it at l.
  for (int ei : splits) {
    Edge piece = edges_[ei];
    piece.start = -1;
    edges_.push_back(piece);
    const int ej = static_cast<int>(edges_.size()) - 1;
    corners_[edges_[ej].end].prev = ej;
    edges_[ei].end = -1;
    chains.push_back({ei, ej});
  }
  if (chains.empty()) return false;

  // Relink: each arriving edge pairs with the leaving edge next to it clockwise around l, so
  // no region between them contains another edge.
  std::vector<Ray>& rays = rays_;
  rays.clear();
  for (int i = 0; i < static_cast<int>(chains.size()); ++i) {
    const Vec2 back = -edges_[chains[i].in].d, fwd = edges_[chains[i].out].d;
    rays.push_back({std::atan2(back[1], back[0]), i, true});
    rays.push_back({std::atan2(fwd[1], fwd[0]), i, false});
  }
  std::vector<int>& newCorners = newCorners_;
  newCorners.clear();
  if (chains.size() == 1) {
    newCorners.push_back(newCorner(chains[0].in, chains[0].out, vl, l, z));
  } else if (chains.size() == 2) {
    // With two chains, linking each to itself would undo the event: they must cross over.
    // (Deciding this by angles fails when the chains are nearly antiparallel.)
    newCorners.push_back(newCorner(chains[0].in, chains[1].out, vl, l, z));
    newCorners.push_back(newCorner(chains[1].in, chains[0].out, vl, l, z));
  } else {
    std::sort(rays.begin(), rays.end(), [](const Ray& a, const Ray& b) {
      return a.angle != b.angle ? a.angle < b.angle : a.incoming < b.incoming;
    });
    const int m = static_cast<int>(rays.size());
    std::vector<char> taken(chains.size(), 0);
    for (int i = 0; i < m; ++i) {
      if (!rays[i].incoming) continue;
      for (int s = 1; s < m; ++s) {
        const Ray& r = rays[(i - s + m) % m];
        if (r.incoming || taken[r.chain]) continue;
        taken[r.chain] = 1;
        newCorners.push_back(newCorner(chains[rays[i].chain].in, chains[r.chain].out, vl, l, z));
        break;
      }
    }
  }
  return true;
}

}  // namespace corbel::extrude::sweeping
