// The ShapeTree (Ch. 6). See shapetree.h.
#include "growth/shapetree.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace corbel::growth {

namespace {

void say(std::string* why, const std::string& s) {
  if (why) *why = s;
}

GridCoord dot(GridPoint a, GridPoint b) { return a.x * b.x + a.y * b.y; }
GridPoint add(GridPoint a, GridPoint b, GridCoord k = 1) { return {a.x + k * b.x, a.y + k * b.y}; }

// Closed axis-aligned segments meet?
bool segmentsMeet(GridPoint a0, GridPoint a1, GridPoint b0, GridPoint b1) {
  const GridCoord ax0 = std::min(a0.x, a1.x), ax1 = std::max(a0.x, a1.x);
  const GridCoord ay0 = std::min(a0.y, a1.y), ay1 = std::max(a0.y, a1.y);
  const GridCoord bx0 = std::min(b0.x, b1.x), bx1 = std::max(b0.x, b1.x);
  const GridCoord by0 = std::min(b0.y, b1.y), by1 = std::max(b0.y, b1.y);
  return ax0 <= bx1 && bx0 <= ax1 && ay0 <= by1 && by0 <= ay1;
}

// Point strictly inside a simple rectilinear polygon (crossing count on a ray to +x,
// the point being off every edge).
bool strictlyInside(const std::vector<GridPoint>& poly, double px, double py) {
  bool in = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const GridPoint a = poly[i], b = poly[(i + 1) % poly.size()];
    if (a.x != b.x) continue;  // horizontal edges never cross a horizontal ray at a non-grid y
    const double y0 = double(std::min(a.y, b.y)), y1 = double(std::max(a.y, b.y));
    if (py > y0 && py<y1&& double(a.x)> px) in = !in;
  }
  return in;
}

}  // namespace

bool interiorsMeet(const GridRect& a, const GridRect& b) {
  return std::min(a.x1, b.x1) > std::max(a.x0, b.x0) && std::min(a.y1, b.y1) > std::max(a.y0, b.y0);
}

std::vector<GridRect> subtractRect(const GridRect& a, const GridRect& b) {
  if (!interiorsMeet(a, b)) return {a};
  std::vector<GridRect> out;
  const GridCoord cx0 = std::max(a.x0, b.x0), cx1 = std::min(a.x1, b.x1);
  if (a.x0 < cx0) out.push_back({a.x0, a.y0, cx0, a.y1});
  if (cx1 < a.x1) out.push_back({cx1, a.y0, a.x1, a.y1});
  if (a.y0 < b.y0) out.push_back({cx0, a.y0, cx1, b.y0});
  if (b.y1 < a.y1) out.push_back({cx0, b.y1, cx1, a.y1});
  return out;
}

char facingLetter(Facing f) { return f == Facing::None ? '?' : char('a' + int(f)); }

Facing oppositeFacing(Facing f) { return f == Facing::None ? f : Facing((int(f) + 2) % 4); }

// Indexed by Facing: the clockwise travel direction and the outward normal.
constexpr GridPoint kTravel[4] = {{1, 0}, {0, -1}, {-1, 0}, {0, 1}};
constexpr GridPoint kNormal[4] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};

GridPoint travelOf(Facing f) { return f == Facing::None ? GridPoint{0, 0} : kTravel[int(f)]; }

GridPoint normalOf(Facing f) { return f == Facing::None ? GridPoint{0, 0} : kNormal[int(f)]; }

// The facing whose travel direction is the unit vector d.
static Facing facingTravelling(GridPoint d) {
  for (Facing f : {Facing::North, Facing::East, Facing::South, Facing::West})
    if (travelOf(f) == d) return f;
  return Facing::None;
}

GridCoord ShapeEdge::lo() const {
  return facing == Facing::North || facing == Facing::South ? std::min(from.x, to.x) : std::min(from.y, to.y);
}
GridCoord ShapeEdge::hi() const {
  return facing == Facing::North || facing == Facing::South ? std::max(from.x, to.x) : std::max(from.y, to.y);
}

GridCoord signedArea2(const std::vector<GridPoint>& c) {
  GridCoord s = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const GridPoint a = c[i], b = c[(i + 1) % c.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return s;
}

std::vector<GridPoint> cleanOutline(std::vector<GridPoint> c) {
  bool changed = true;
  while (changed && c.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < c.size() && c.size() >= 3; ++i) {
      const std::size_t n = c.size();
      const GridPoint p = c[(i + n - 1) % n], q = c[i], r = c[(i + 1) % n];
      const bool repeated = q == r;
      const bool collinear = (p.x == q.x && q.x == r.x) || (p.y == q.y && q.y == r.y);
      if (repeated || collinear) {
        c.erase(c.begin() + std::ptrdiff_t(i));
        changed = true;
        break;
      }
    }
  }
  return c;
}

bool simpleRectilinear(const std::vector<GridPoint>& c, std::string* why) {
  const std::size_t n = c.size();
  if (n < 4 || n % 2) return say(why, "fewer than four corners or an odd count"), false;
  for (std::size_t i = 0; i < n; ++i) {
    const GridPoint a = c[i], b = c[(i + 1) % n], d = c[(i + 2) % n];
    if (a == b) return say(why, "a zero-length edge"), false;
    if (a.x != b.x && a.y != b.y) return say(why, "an edge that is not axis-aligned"), false;
    const bool h1 = a.y == b.y, h2 = b.y == d.y;
    if (h1 == h2) return say(why, "two consecutive edges are parallel"), false;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segmentsMeet(c[i], c[(i + 1) % n], c[j], c[(j + 1) % n]))
        return say(why, "the outline touches or crosses itself"), false;
    }
  if (signedArea2(c) >= 0) return say(why, "the outline is not clockwise"), false;
  return true;
}

ShapeTree ShapeTree::canonical(GridPoint lo, GridCoord w, GridCoord h) {
  ShapeTree t;
  const GridCoord len[4] = {w, h, w, h};
  for (int i = 0; i < 4; ++i) {
    ShapeNode n;
    n.facing = Facing(i);
    n.weight = len[i];
    t.nodes_.push_back(n);
    t.roots_.push_back(i);
  }
  t.anchor_ = {lo.x, lo.y + h};  // the north edge starts at the north-west corner
  t.boxes_ = {{lo.x, lo.y, lo.x + w, lo.y + h}};
  t.boxOwner_ = {-1};
  return t;
}

void ShapeTree::collectLeaves(int n, bool withVirtual, std::vector<int>& out) const {
  const ShapeNode& node = nodes_[std::size_t(n)];
  if (node.isLeaf()) {
    if (withVirtual || !node.isVirtual()) out.push_back(n);
    return;
  }
  for (int c : node.children) collectLeaves(c, withVirtual, out);
}

std::vector<int> ShapeTree::leaves(bool withVirtual) const {
  std::vector<int> out;
  for (int r : roots_) collectLeaves(r, withVirtual, out);
  return out;
}

std::vector<ShapeEdge> ShapeTree::edges() const {
  std::vector<ShapeEdge> out;
  GridPoint at = anchor_;
  for (int l : leaves(true)) {
    const ShapeNode& n = nodes_[std::size_t(l)];
    const GridPoint to = add(at, travelOf(n.facing), n.weight);
    if (!n.isVirtual()) out.push_back({l, n.facing, at, to});
    at = to;
  }
  return out;
}

int ShapeTree::faceCount() const { return int(leaves(false).size()); }

std::vector<GridPoint> ShapeTree::outline() const {
  std::vector<GridPoint> c;
  for (const ShapeEdge& e : edges()) c.push_back(e.from);
  return cleanOutline(c);
}

GridCoord ShapeTree::area() const { return -signedArea2(outline()) / 2; }

GridRect ShapeTree::bounds() const {
  const auto c = outline();
  GridRect r{c[0].x, c[0].y, c[0].x, c[0].y};
  for (GridPoint p : c) {
    r.x0 = std::min(r.x0, p.x), r.x1 = std::max(r.x1, p.x);
    r.y0 = std::min(r.y0, p.y), r.y1 = std::max(r.y1, p.y);
  }
  return r;
}

ShapeEdge ShapeTree::edgeOf(int leaf) const {
  for (const ShapeEdge& e : edges())
    if (e.node == leaf) return e;
  return {};
}

ShapeComponent ShapeTree::component(int node) const {
  ShapeComponent c;
  collectLeaves(node, false, c.leaves);
  const std::vector<int> all = leaves(false);
  if (c.leaves.empty()) return c;
  const auto it = std::find(all.begin(), all.end(), c.leaves.back());
  c.closing = all[std::size_t((it - all.begin() + 1) % std::ptrdiff_t(all.size()))];
  return c;
}

SplitNodes ShapeTree::faceSplit(int leaf, GridCoord at, std::string* why) {
  if (leaf < 0 || std::size_t(leaf) >= nodes_.size() || !nodes_[std::size_t(leaf)].isLeaf() ||
      nodes_[std::size_t(leaf)].isVirtual())
    return say(why, "Face Split needs a real leaf"), SplitNodes{};
  const ShapeNode v = nodes_[std::size_t(leaf)];
  if (at <= 0 || at >= v.weight) return say(why, "the split point must lie strictly inside the edge"), SplitNodes{};
  for (int a = leaf; a >= 0; a = nodes_[std::size_t(a)].parent) {
    const int cap = nodes_[std::size_t(a)].splitLimit;
    if (cap >= 0 && splitCount(a) + 1 > cap)
      return say(why,
                 "the subtree at node " + std::to_string(a) + " allows " + std::to_string(cap) + " splits (Eq. 6.1)"),
             SplitNodes{};
  }
  history_.push_back(save());
  const int op = int(history_.size()) - 1;
  SplitNodes s;
  const GridCoord w[3] = {at, 0, v.weight - at};
  int* ids[3] = {&s.first, &s.virtualNode, &s.second};
  for (int k = 0; k < 3; ++k) {
    ShapeNode c;
    c.facing = k == 1 ? Facing::None : v.facing;
    c.weight = w[k];
    c.parent = leaf;
    c.createdBy = op;
    *ids[k] = int(nodes_.size());
    nodes_[std::size_t(leaf)].children.push_back(*ids[k]);
    nodes_.push_back(c);
  }
  return s;
}

bool ShapeTree::faceAdvance(int leaf, GridCoord alpha, std::string* why) {
  if (leaf < 0 || std::size_t(leaf) >= nodes_.size() || !nodes_[std::size_t(leaf)].isLeaf() ||
      nodes_[std::size_t(leaf)].isVirtual())
    return say(why, "Face Advance needs a real leaf"), false;
  if (alpha == 0) return say(why, "Face Advance by 0"), false;
  const std::vector<int> order = leaves(true);
  const std::size_t n = order.size();
  const std::size_t i = std::size_t(std::find(order.begin(), order.end(), leaf) - order.begin());
  const int prev = order[(i + n - 1) % n], next = order[(i + 1) % n];
  const ShapeEdge moved = edgeOf(leaf);
  const GridPoint nrm = normalOf(nodes_[std::size_t(leaf)].facing);
  const GridCoord oldArea = area();
  Saved before = save();

  // The neighbour before gains α·n̂ on its vector, the one after loses it.
  auto reshape = [&](int u, GridCoord sign) -> bool {
    ShapeNode& node = nodes_[std::size_t(u)];
    const GridCoord k = sign * alpha;
    if (node.isVirtual()) {
      node.facing = facingTravelling({k > 0 ? nrm.x : -nrm.x, k > 0 ? nrm.y : -nrm.y});
      node.weight = std::llabs(k);
      if (node.createdBy < 0) node.createdBy = int(history_.size());
      return true;
    }
    const GridCoord w = node.weight + k * dot(nrm, travelOf(node.facing));
    if (w < 0) return false;
    node.weight = w;
    if (w == 0) node.facing = Facing::None;
    return true;
  };
  if (!reshape(prev, 1) || !reshape(next, -1)) {
    restore(std::move(before));
    return say(why, "a neighbouring edge would get a negative length"), false;
  }
  if (i == 0 || i == n - 1) anchor_ = add(anchor_, nrm, alpha);

  // The swept rectangle joins the boxes (outward) or leaves them (inward).
  const GridPoint far0 = add(moved.from, nrm, alpha), far1 = add(moved.to, nrm, alpha);
  const GridRect swept{
      std::min({moved.from.x, moved.to.x, far0.x, far1.x}), std::min({moved.from.y, moved.to.y, far0.y, far1.y}),
      std::max({moved.from.x, moved.to.x, far0.x, far1.x}), std::max({moved.from.y, moved.to.y, far0.y, far1.y})};
  if (alpha > 0) {
    bool merged = false;
    if (!boxes_.empty() && boxOwner_.back() == leaf) {
      GridRect& last = boxes_.back();
      GridRect joined{std::min(last.x0, swept.x0), std::min(last.y0, swept.y0), std::max(last.x1, swept.x1),
                      std::max(last.y1, swept.y1)};
      if (joined.area() == last.area() + swept.area()) last = joined, merged = true;
    }
    if (!merged) {
      boxes_.push_back(swept);
      boxOwner_.push_back(leaf);
    }
  } else {
    std::vector<GridRect> kept;
    std::vector<int> owners;
    for (std::size_t b = 0; b < boxes_.size(); ++b)
      for (const GridRect& r : subtractRect(boxes_[b], swept)) kept.push_back(r), owners.push_back(boxOwner_[b]);
    boxes_ = std::move(kept);
    boxOwner_ = std::move(owners);
  }

  std::string reason;
  const auto out = outline();
  if (!simpleRectilinear(out, &reason) || area() != oldArea + alpha * nodes_[std::size_t(leaf)].weight) {
    restore(std::move(before));
    return say(why, "the footprint would stop being a simple polygon (" +
                        (reason.empty() ? "it overlaps itself" : reason) + ")"),
           false;
  }
  history_.push_back(std::move(before));
  return true;
}

int ShapeTree::splitCount(int node) const {
  const ShapeNode& n = nodes_[std::size_t(node)];
  if (n.isLeaf()) return 0;
  int count = 1;
  for (int c : n.children) count += splitCount(c);
  return count;
}

bool ShapeTree::setSplitLimit(int node, int limit, std::string* why) {
  if (node < 0 || std::size_t(node) >= nodes_.size()) return say(why, "no such node"), false;
  if (limit >= 0 && splitCount(node) > limit) return say(why, "the subtree already has more splits"), false;
  // The node's children's caps against its own, and its caps against its parent's.
  auto childrenFit = [&](int n, int cap) {
    if (cap < 0) return true;
    int sum = 0;
    for (int c : nodes_[std::size_t(n)].children)
      sum += std::max(0, c == node ? limit : nodes_[std::size_t(c)].splitLimit);
    return sum <= cap;
  };
  const int parent = nodes_[std::size_t(node)].parent;
  if (!childrenFit(node, limit) || (parent >= 0 && !childrenFit(parent, nodes_[std::size_t(parent)].splitLimit)))
    return say(why, "the children's split counts would exceed the parent's (Eq. 6.1)"), false;
  nodes_[std::size_t(node)].splitLimit = limit;
  return true;
}

void ShapeTree::restore(Saved s) {
  nodes_ = std::move(s.nodes);
  anchor_ = s.anchor;
  boxes_ = std::move(s.boxes);
  boxOwner_ = std::move(s.boxOwner);
}

bool ShapeTree::undo() {
  if (history_.empty()) return false;
  // Split caps are settings, not ops: they survive undo on the nodes that remain.
  Saved& back = history_.back();
  for (std::size_t i = 0; i < back.nodes.size() && i < nodes_.size(); ++i)
    back.nodes[i].splitLimit = nodes_[i].splitLimit;
  restore(std::move(back));
  history_.pop_back();
  return true;
}

bool ShapeTree::valid(std::string* why) const {
  const auto out = outline();
  if (!simpleRectilinear(out, why)) return false;
  for (const ShapeEdge& e : edges()) {
    const GridPoint d{e.to.x - e.from.x, e.to.y - e.from.y};
    const GridCoord len = nodes_[std::size_t(e.node)].weight;
    if (d.x != travelOf(e.facing).x * len || d.y != travelOf(e.facing).y * len)
      return say(why, std::string("edge ") + std::to_string(e.node) + " runs against its label"), false;
  }
  GridCoord sum = 0;
  for (std::size_t a = 0; a < boxes_.size(); ++a) {
    sum += boxes_[a].area();
    if (boxes_[a].area() <= 0) return say(why, "an empty box"), false;
    const GridRect& b = boxes_[a];
    if (!strictlyInside(out, double(b.x0) + 0.5, double(b.y0) + 0.5))  // its first cell
      return say(why, "a box lies outside the footprint"), false;
    for (std::size_t c = a + 1; c < boxes_.size(); ++c)
      if (interiorsMeet(boxes_[a], boxes_[c])) return say(why, "two boxes overlap"), false;
  }
  if (sum != area()) return say(why, "the boxes do not tile the footprint"), false;
  return true;
}

}  // namespace corbel::growth
