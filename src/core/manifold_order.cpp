#include "core/manifold_order.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace corbel {

namespace {

// An open-addressing map from edge keys (two vertex indices, never all ones) to ints, sized
// once for the soup: the standard unordered_map allocated a node per edge, which at town scale
// (a validation mesh and a Scene insertion per building) was a fifth of the batch's time.
class EdgeMap {
 public:
  explicit EdgeMap(std::size_t expected) {
    std::size_t cap = 16;
    while (cap < 2 * expected) cap *= 2;
    keys_.assign(cap, kEmpty);
    values_.resize(cap);
  }
  const int* find(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  int& operator[](std::uint64_t key) {  // inserted as 0 when absent
    for (std::size_t i = slot(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == kEmpty) {
        keys_[i] = key;
        values_[i] = 0;
        return values_[i];
      }
    }
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
  std::size_t slot(std::uint64_t key) const {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return static_cast<std::size_t>(key) & (keys_.size() - 1);
  }
  std::vector<std::uint64_t> keys_;
  std::vector<int> values_;
};

}  // namespace

std::vector<int> manifoldFaceOrder(const MeshData& data, std::size_t& rejected) {
  const int nf = static_cast<int>(data.faces.size());
  const int nv = static_cast<int>(data.points.size());
  std::vector<char> ok(nf, 1);
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  std::size_t corners = 0;
  for (const auto& loop : data.faces) corners += loop.size();
  EdgeMap directed(corners);    // (u, v) → face
  EdgeMap undirected(corners);  // (min, max) → use count
  for (int f = 0; f < nf; ++f) {
    const auto& loop = data.faces[f];
    bool good = loop.size() >= 3;
    for (std::size_t i = 0; good && i < loop.size(); ++i) {
      const int u = loop[i], v = loop[(i + 1) % loop.size()];
      if (u < 0 || v < 0 || u >= nv || v >= nv || u == v) good = false;
      for (std::size_t j = i + 1; good && j < loop.size(); ++j) good = loop[j] != u;  // a vertex once per face
    }
    for (std::size_t i = 0; good && i < loop.size(); ++i) {
      const int u = loop[i], v = loop[(i + 1) % loop.size()];
      if (directed.find(key(u, v))) good = false;
      const int* un = undirected.find(key(std::min(u, v), std::max(u, v)));
      if (un && *un >= 2) good = false;
    }
    if (!good) {
      ok[f] = 0;
      continue;
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int u = loop[i], v = loop[(i + 1) % loop.size()];
      directed[key(u, v)] = f;
      ++undirected[key(std::min(u, v), std::max(u, v))];
    }
  }
  // One fan per vertex: wedges (corners of faces at the vertex) joined across shared edges.
  // The wedges of vertex v are wedge[start[v] .. start[v + 1]), in face order.
  std::vector<int> start(nv + 1, 0);
  for (int f = 0; f < nf; ++f)
    if (ok[f])
      for (int u : data.faces[f]) ++start[u + 1];
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, int>> wedge(start[nv]);  // (face, corner index)
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int f = 0; f < nf; ++f)
      if (ok[f])
        for (int i = 0; i < static_cast<int>(data.faces[f].size()); ++i) wedge[fill[data.faces[f][i]]++] = {f, i};
  }
  std::vector<int> parent, count;
  std::vector<std::pair<int, int>> byNeighbour;  // other end of an edge at v → wedge
  for (int v = 0; v < nv; ++v) {
    const std::pair<int, int>* w = wedge.data() + start[v];
    const int n = start[v + 1] - start[v];
    if (n < 2) continue;
    parent.resize(n);
    for (int i = 0; i < n; ++i) parent[i] = i;
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    // The first wedge to reach each neighbour; a list for the few wedges of most vertices, a
    // hash map for a vertex many faces meet at.
    byNeighbour.clear();
    std::unordered_map<int, int> manyNeighbours;
    for (int i = 0; i < n; ++i) {
      const auto& loop = data.faces[w[i].first];
      const int m = static_cast<int>(loop.size());
      for (int other : {loop[(w[i].second + 1) % m], loop[(w[i].second + m - 1) % m]}) {
        int first = -1;
        if (n > 32) {
          auto [it, fresh] = manyNeighbours.try_emplace(other, i);
          if (!fresh) first = it->second;
        } else {
          auto it =
              std::find_if(byNeighbour.begin(), byNeighbour.end(), [&](const auto& e) { return e.first == other; });
          if (it == byNeighbour.end())
            byNeighbour.push_back({other, i});
          else
            first = it->second;
        }
        if (first >= 0) parent[find(i)] = find(first);
      }
    }
    // The largest fan stays (the lowest root among equals); the others' faces are refused.
    count.assign(n, 0);
    for (int i = 0; i < n; ++i) ++count[find(i)];
    int best = 0;
    for (int root = 1; root < n; ++root)
      if (count[root] > count[best]) best = root;
    for (int i = 0; i < n; ++i)
      if (find(i) != best) ok[w[i].first] = 0;
  }
  // Growth order across shared edges.
  std::vector<int> order;
  order.reserve(nf);
  std::vector<char> queued(nf, 0);
  for (int seed = 0; seed < nf; ++seed) {
    if (!ok[seed] || queued[seed]) continue;
    queued[seed] = 1;
    std::size_t head = order.size();
    order.push_back(seed);
    while (head < order.size()) {
      const int f = order[head++];
      const auto& loop = data.faces[f];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int u = loop[i], v = loop[(i + 1) % loop.size()];
        const int* it = directed.find(key(v, u));
        if (it && ok[*it] && !queued[*it]) {
          queued[*it] = 1;
          order.push_back(*it);
        }
      }
    }
  }
  rejected = 0;
  for (int f = 0; f < nf; ++f) rejected += ok[f] ? 0 : 1;
  return order;
}

}  // namespace corbel
