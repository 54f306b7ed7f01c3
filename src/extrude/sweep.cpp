// The sweep-plane algorithm of Kelly & Wonka, Sec. 4.2–4.5 and 4.8.
//
// Active plan: loops of corners and edges. Edge e lies at height z on the line
// n_e·x = c_e + k_e·z (n_e its inward normal, k_e = tan θ_e), i.e. on its direction plane.
// A corner is where its two edges' lines meet, so its position is always recomputed from the
// lines (no drift). Every face of the output is traced by one edge between two events.
#include "extrude/sweep.h"

#include "core/error.h"

#include <algorithm>
#include <type_traits>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <queue>
#include <sstream>
#include <unordered_map>

namespace corbel::extrude {

namespace {

// CORBEL_SWEEP_TRACE=1 prints every event to stderr (for debugging kernels, never in tests).
bool traceOn() {
  static const bool on = [] {
    const char* v = std::getenv("CORBEL_SWEEP_TRACE");
    return v && *v == '1';
  }();
  return on;
}
#define SWEEP_TRACE(...)                  \
  do {                                    \
    if (traceOn()) {                      \
      std::fprintf(stderr, __VA_ARGS__);  \
      std::fputc('\n', stderr);           \
    }                                     \
  } while (0)

double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
Vec2 leftOf(const Vec2& d) { return Vec2(-d[1], d[0]); }

struct Edge {
  Vec2 d;         // unit direction
  Vec2 n;         // inward unit normal (left of d)
  double k = 0;   // tan θ
  double c = 0;   // n·x = c + k z
  int face = -1;
  int src = -1;   // index into the flat input edge list
  int step = 0;   // current angle step of the input edge
  int start = -1, end = -1;
  bool alive = true;
};

struct Corner {
  int prev = -1, next = -1;  // the edge ending here and the edge starting here
  int vertex = -1;           // output vertex where the corner was created
  // Fallback motion for parallel neighbours: position p0 + v (z − z0).
  Vec2 p0;
  double z0 = 0;
  Vec2 v;
  // Where the corner's lines meet at z0 and |v|: together they bound where it can be at any
  // height without touching its edges (a cheap rejection in event scans).
  Vec2 base;
  double baseNorm = 0;  // |base|, for the rounding margin of those rejections
  double speed = 0;
  bool parallel = false;
  bool alive = true;
  // Made by an edge direction event (or resolving one): nothing at its point has been met
  // yet, since direction events come before intersection events at their height.
  bool turned = false;
};

struct FaceBuild {
  std::vector<std::pair<int, int>> segments;  // directed boundary pieces (vertex ids)
  int src = -1;
  int segment = -1;
  double angle = 0;
  Vec3 normal;
  bool base = false;
};


// Flags over corner or edge ids, cleared in O(1) by moving to a new generation.
class Marks {
 public:
  void reserve(std::size_t n) { v_.reserve(n); }
  void reset(std::size_t n) {
    if (v_.size() < n) v_.resize(n, 0);
    ++gen_;
  }
  bool operator[](int i) const { return static_cast<std::size_t>(i) < v_.size() && v_[i] == gen_; }
  void set(int i) {
    if (static_cast<std::size_t>(i) >= v_.size()) v_.resize(i + 1, 0);
    v_[i] = gen_;
  }

 private:
  std::vector<unsigned> v_;
  unsigned gen_ = 0;
};

struct Candidate {
  double z;
  Vec2 p;
  int corner;  // the corner whose motion predicted it (a cheap staleness test)
  unsigned id = 0;
  bool operator>(const Candidate& o) const { return z > o.z; }
};

// A chain of an event (Sec. 4.4): the edge arriving at its point and the edge leaving it.
struct Chain {
  int in, out;
};

// A chain's arriving or leaving edge as a direction out of the event point.
struct Ray {
  double angle;
  int chain;
  bool incoming;
};

// A corner's path x(z) = q + v z, and the heights between which its predictions count.
struct CornerPath {
  Vec2 v, q;
  double lo, hi;
};

class Sweeper {
 public:
  Sweeper(const SweepInput& in, const Tolerances& tol, Progress* progress)
      : in_(in), tol_(tol), progress_(progress), stopZ_(in.stopZ) {}

  SweepOutput run();

 private:
  // Geometry.
  Vec2 cornerAt(int c, double z) const;
  Vec2 liveAt(int c, double z) const;  // at z, or where it was made if that is above z
  double settle(const Corner& c) const;
  double lastUseful(const Corner& c) const;
  Vec2 nearestOnPath(int c, const Vec2& p, double z) const;
  void setCornerMotion(int c, const Vec2& at, double z);
  void setEdgePlane(Edge& e, const Vec2& d, const Vec2& pointOnLine, double z, double angle);
  int addVertex(const Vec2& p, double z);
  int addFace(int src, int segment, double angle, const Edge& e);

  // Topology.
  int newCorner(int prev, int next, int vertex, const Vec2& at, double z);
  void arc(int corner, int topVertex);
  void killCorner(int c, int topVertex);
  void resolveCorner(int c, double z, int depth = 0);
  void zipSpike(int c, double z, int depth);
  // Edges A (arriving) and B (leaving) of a closed corner meet along vl–v: their faces' tops.
  void shareTop(int A, int B, int vl, int v);
  // A corner that replaces closed ones: made, resolved and, if it lives, predicted.
  void relink(int prev, int next, int vertex, const Vec2& at, double z, int depth);
  void mergeColinear(int c, double z, int depth);
  bool samePiece(int A, int B) const;
  // Post inter-chain validation (Sec. 4.4): do the corners an event made at l keep the active
  // plan simple up to maxRise above it? False where their wedges overlap or their edges cross.
  bool locallySimple(const std::vector<int>& made, const Vec2& l, double z, double maxRise) const;

  // Events.
  void predict(int corner);
  void predictAgainst(const std::vector<int>& planes);
  bool handleIntersection(const Candidate& cand);
  void handleDirectionChanges(double h);
  // Closes every loop still open at z: with a flat cap (and a warning) when the sweep ran out
  // of events, or, at a stop height, by handing the loops back as the active plan.
  void capRemaining(double z, std::vector<std::vector<PlanCorner>>* plan = nullptr);
  void refuseStandingLoop(const std::vector<int>& loop) const;
  void buildFaces(SweepOutput& out);
  // The active plan at height z (between events), for SweepInput::probes.
  std::vector<std::vector<PlanCorner>> snapshot(double z) const;

  const SweepInput& in_;
  const Tolerances& tol_;
  Progress* progress_;
  std::vector<const SweepEdge*> inputs_;
  std::vector<Edge> edges_;
  std::vector<Corner> corners_;
  std::vector<FaceBuild> faces_;
  std::vector<Vec3> points_;
  // Predictions are kept per corner (a min-heap each); the global queue holds each corner's
  // earliest, so it stays as small as the plan and pops in the same height order as one queue
  // of every prediction would.
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
  std::vector<std::vector<Candidate>> pending_;
  std::vector<CornerPath> paths_;  // predictAgainst's scratch, kept to save the allocations
  std::vector<int> arriving_, involvedList_, splitList_;  // handleIntersection's, likewise
  std::vector<int> signature_, newCorners_, made_;
  std::vector<Chain> chains_;
  std::vector<Ray> rays_;
  // Live corners and edges in id order (dead ones dropped when met), so an event scans the
  // plan as it is, not everything it ever was.
  std::vector<int> liveCorners_, liveEdges_;
  std::size_t syncedCorners_ = 0, syncedEdges_ = 0;
  Marks inK_, involved_, used_;
  void syncLive();
  unsigned nextId_ = 0;
  bool diverged_ = false;
  void push(Candidate c);
  bool nextCandidate(Candidate& out);
  std::vector<double> directionHeights_;
  // SweepInput::timeLimitSeconds, checked wherever the work grows with the plan (predictions
  // are n per corner: a 20,000-corner circle makes 4e8 of them before its first event).
  std::chrono::steady_clock::time_point started_;
  void checkClock() const;
  bool turning_ = false;  // inside handleDirectionChanges: new corners are `turned`
  // Turned corners that lie on another edge at the height they were made: candidates there.
  void meetAtTurn(const std::vector<int>& corners, double h);
  std::vector<std::string> warnings_;
  double z_ = 0;
  std::size_t events_ = 0;
  std::vector<int> recent_;  // vertices made at height recentZ_
  // The same, bucketed on a grid of cell δ2 once there are many (a plan of 100,000 corners
  // welds its base in linear time: scanning the list for each made it quadratic, 10 s and more
  // before the first clock check). Keyed by the cell's two indices mixed into one word.
  std::unordered_map<std::uint64_t, std::vector<int>> recentGrid_;
  bool cellOf(const Vec2& p, std::int64_t& ix, std::int64_t& iy) const;
  Vec2 lastEventPoint_{std::numeric_limits<double>::infinity(), 0.0};
  double lastEventZ_ = 0;
  int repeats_ = 0;
  // The edges of the last two events, sorted: two chains that swap back and forth between
  // the same four edges (a plan that overlaps itself along a line) repeat them alternately.
  std::vector<int> lastInvolved_[2];
  double lastInvolvedZ_[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  int swaps_ = 0;
  double burstZ_ = -std::numeric_limits<double>::infinity();  // where the current burst of events began
  std::size_t burst_ = 0;                                     // events since then
  double recentZ_ = std::numeric_limits<double>::quiet_NaN();
  std::size_t overlaps_ = 0;  // events after which the plan overlapped itself
  Vec3 firstOverlap_;
  // The height the sweep stops at: SweepInput::stopZ, or lower where the plan overlapped
  // itself and SweepInput::stopAtOverlap hands it back for the winding rule.
  double stopZ_;
  bool stoppedAtOverlap_ = false;
};

// ------------------------------------------------------------------ geometry

void Sweeper::setEdgePlane(Edge& e, const Vec2& d, const Vec2& p, double z, double angle) {
  e.d = d;
  e.n = leftOf(d);
  e.k = std::tan(angle);
  e.c = OpenMesh::dot(e.n, p) - e.k * z;
}

Vec2 Sweeper::cornerAt(int ci, double z) const {
  const Corner& c = corners_[ci];
  if (c.parallel) return c.p0 + c.v * (z - c.z0);
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double det = cross2(a.n, b.n);
  const double ra = a.c + a.k * z, rb = b.c + b.k * z;
  return Vec2((ra * b.n[1] - rb * a.n[1]) / det, (a.n[0] * rb - b.n[0] * ra) / det);
}

Vec2 Sweeper::liveAt(int ci, double z) const { return cornerAt(ci, std::max(z, corners_[ci].z0)); }

// Events within δ1 of height are one event (Sec. 4.4), so a corner arrives at p if its path
// passes within δ2 of p somewhere within δ1 of z. For most corners this is where it is at z;
// a corner racing along a near-flat ridge (between almost antiparallel edges) moves thousands
// of metres per metre of rise, and the rounding of two predictions of one event in height
// alone would put it microns away.
constexpr double kRaceReach = 100;

Vec2 Sweeper::nearestOnPath(int ci, const Vec2& p, double z) const {
  // A corner does not exist below the height it was made at: events clustered within δ1 may
  // come a little below an event already handled, and a racing corner made there, taken back
  // along its path, would sweep the whole ridge it is about to zip in no height at all.
  const double z0 = corners_[ci].z0;
  z = std::max(z, z0);
  const Vec2 at = cornerAt(ci, z);
  const Vec2& v = corners_[ci].v;
  const double vv = OpenMesh::dot(v, v);
  // Slower corners move less than δ2 in δ1 of height: their place at z decides, so the
  // clustering of ordinary events stays exactly δ2.
  if (!(vv * tol_.height * tol_.height > tol_.cluster * tol_.cluster)) return at;
  // ... but never further along its path than kRaceReach δ2, so a corner racing at 1e8 m/m
  // cannot skip past the ends of its own edges into an unrelated event on its line.
  const double window = std::min(tol_.height, kRaceReach * tol_.cluster / std::sqrt(vv));
  const double t = std::clamp(OpenMesh::dot(v, p - at) / vv, std::max(-window, z0 - z), window);
  return at + v * t;
}

void Sweeper::setCornerMotion(int ci, const Vec2& at, double z) {
  Corner& c = corners_[ci];
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double det = cross2(a.n, b.n);
  c.p0 = at;
  c.z0 = z;
  // Neighbours on almost one line in one direction with one angle: their lines may meet
  // metres from the corner (two walls 2e-8 rad apart whose offsets differ by 1e-7 m meet 5 m
  // away), and the corner, which sits where the event made it, would jump there. It moves
  // with the edges instead, as between parallel ones.
  const bool straight = OpenMesh::dot(a.d, b.d) > 0 && std::abs(det) <= tol_.mergeSine && a.k == b.k &&
                        (cornerAt(ci, z) - at).norm() > tol_.cluster;
  if (std::abs(det) > tol_.parallelSine && !straight) {
    c.parallel = false;
    c.v = Vec2((a.k * b.n[1] - b.k * a.n[1]) / det, (a.n[0] * b.k - b.n[0] * a.k) / det);
    c.speed = c.v.norm();
    if (c.speed * tol_.height > tol_.cluster) {
      // A racing corner (see nearestOnPath): its lines meet so obliquely that the rounding of
      // the event's height (1e-9 relative) moves their meeting point by decimetres along the
      // ridge. It is made where its lines pass through the event point, which may be a little
      // above the event; below that it does not exist yet (liveAt), and cannot reach back
      // along its ridge into events below. "A little" is δ1, or more where both lines pass
      // within δ2 of the point (as every line of the event does): a split by a wall 6e-8 rad
      // off antiparallel puts their meeting point 0.4 m back along the ridge, 1.3 δ1 below,
      // and a corner made there crossed the event point again and undid the split.
      const double later = OpenMesh::dot(c.v, at - cornerAt(ci, z)) / (c.speed * c.speed);
      const double offA = std::abs(OpenMesh::dot(a.n, at) - (a.c + a.k * z));
      const double offB = std::abs(OpenMesh::dot(b.n, at) - (b.c + b.k * z));
      if (later > 0 && (later <= tol_.height || std::max(offA, offB) <= tol_.cluster)) c.z0 = z + later;
    }
    c.base = cornerAt(ci, c.z0);
    c.baseNorm = c.base.norm();
    return;
  }
  // Parallel neighbours: colinear edges of one plane move the corner with them; an
  // antiparallel spike is zipped before it moves (resolveCorner).
  c.parallel = true;
  c.v = OpenMesh::dot(a.d, b.d) > 0 ? a.n * a.k : Vec2(0.0, 0.0);
  c.speed = c.v.norm();
  c.base = at;
  c.baseNorm = at.norm();
}

// Points made at one event height that coincide are one vertex: several corners and zips of
// one event (or of events clustered at one height) meet there, and the shell must share it.
bool Sweeper::cellOf(const Vec2& p, std::int64_t& ix, std::int64_t& iy) const {
  const double x = std::floor(p[0] / tol_.cluster), y = std::floor(p[1] / tol_.cluster);
  if (!(std::abs(x) < 1e15 && std::abs(y) < 1e15)) return false;  // also NaN
  ix = static_cast<std::int64_t>(x);
  iy = static_cast<std::int64_t>(y);
  return true;
}

namespace {
std::uint64_t cellKey(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(iy);
}
}  // namespace

int Sweeper::addVertex(const Vec2& p, double z) {
  constexpr std::size_t kGridFrom = 64;  // below this many, a scan of the list is cheaper
  if (recentZ_ != z) {
    if (std::abs(recentZ_ - z) > tol_.height) {
      recent_.clear();
      if (!recentGrid_.empty()) recentGrid_.clear();
    }
    recentZ_ = z;
  }
  auto near = [&](int v) {
    return std::abs(points_[v][0] - p[0]) <= tol_.cluster && std::abs(points_[v][1] - p[1]) <= tol_.cluster;
  };
  std::int64_t ix = 0, iy = 0;
  const bool gridded = recent_.size() >= kGridFrom && cellOf(p, ix, iy);
  if (recent_.size() == kGridFrom) {
    // Switching to the grid: the list so far goes in (points no cell holds stay in the list).
    for (int v : recent_) {
      std::int64_t vx, vy;
      if (cellOf(Vec2(points_[v][0], points_[v][1]), vx, vy)) recentGrid_[cellKey(vx, vy)].push_back(v);
    }
  }
  if (gridded) {
    // The first vertex made within δ2 (the least index), as the scan of the list found it.
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = recentGrid_.find(cellKey(ix + dx, iy + dy));
        if (it == recentGrid_.end()) continue;
        for (int v : it->second)
          if ((found < 0 || v < found) && near(v)) found = v;
      }
    if (found >= 0) return found;
  } else {
    for (int v : recent_)
      if (near(v)) return v;
  }
  points_.emplace_back(p[0], p[1], z);
  const int v = static_cast<int>(points_.size()) - 1;
  recent_.push_back(v);
  if (recent_.size() > kGridFrom && cellOf(p, ix, iy)) recentGrid_[cellKey(ix, iy)].push_back(v);
  return v;
}

int Sweeper::addFace(int src, int segment, double angle, const Edge& e) {
  FaceBuild f;
  f.src = src;
  f.segment = segment;
  f.angle = angle;
  // Outward normal of the direction plane n·x − k z = c is −(n, −k), normalised.
  f.normal = Vec3(-e.n[0], -e.n[1], e.k);
  f.normal.normalize();
  f.segments.reserve(4);  // its bottom, two sides and a top, in the common case
  faces_.push_back(std::move(f));
  return static_cast<int>(faces_.size()) - 1;
}

// ------------------------------------------------------------------ topology

int Sweeper::newCorner(int prev, int next, int vertex, const Vec2& at, double z) {
  SWEEP_TRACE("  new corner %zu: edges %d -> %d at v%d (%g, %g, %g)", corners_.size(), prev, next, vertex, at[0], at[1], z);
  Corner c;
  c.prev = prev;
  c.next = next;
  c.vertex = vertex;
  c.turned = turning_;
  corners_.push_back(c);
  pending_.emplace_back();
  const int ci = static_cast<int>(corners_.size()) - 1;
  edges_[prev].end = ci;
  edges_[next].start = ci;
  setCornerMotion(ci, at, z);
  SWEEP_TRACE("    v=(%g, %g), sine %g", corners_[ci].v[0], corners_[ci].v[1], cross2(edges_[prev].n, edges_[next].n));
  return ci;
}

// The corner's path from where it was created to topVertex is an arc shared by the faces of
// its two edges: the edge ending here sees it going up, the edge starting here going down.
void Sweeper::arc(int ci, int top) {
  const Corner& c = corners_[ci];
  if (c.vertex == top) return;
  faces_[edges_[c.prev].face].segments.emplace_back(c.vertex, top);
  faces_[edges_[c.next].face].segments.emplace_back(top, c.vertex);
}

void Sweeper::killCorner(int ci, int top) {
  arc(ci, top);
  corners_[ci].alive = false;
}

void Sweeper::resolveCorner(int ci, double z, int depth) {
  if (!corners_[ci].alive) return;
  if (depth > 64) {
    warnings_.push_back("unresolved degenerate corner cascade at height " + std::to_string(z));
    return;
  }
  const Corner& c = corners_[ci];
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double sine = std::abs(cross2(a.d, b.d));
  if (sine > std::max(tol_.mergeSine, tol_.ridgeMaxSine)) return;  // an ordinary corner
  if (OpenMesh::dot(a.d, b.d) < 0) {
    // Almost antiparallel: one line (a ridge) when they are within ridgeSine, or, up to
    // ridgeMaxSine, when the sliver between them is too small to matter (sine · L² of the
    // shorter edge under ridgeArea). Otherwise the corner races along the ridge exactly.
    // A loop of these two edges alone has no area to keep (both corners are where the lines
    // meet): it always closes along the ridge.
    if (sine > tol_.ridgeSine && a.start != b.end) {
      const Vec2 l = liveAt(ci, z);
      const double shorter = std::min((l - liveAt(a.start, z)).norm(), (liveAt(b.end, z) - l).norm());
      if (sine * shorter * shorter > tol_.ridgeArea) return;
    }
    zipSpike(ci, z, depth);
  } else if (sine <= tol_.mergeSine && (std::abs(a.k - b.k) > 1e-12 * (1.0 + std::abs(a.k) + std::abs(b.k)) ||
                                        samePiece(c.prev, c.next))) {
    mergeColinear(ci, z, depth);
  }
}

// Two pieces of one input edge (a step split it) whose profiles go on alike from here: once
// the step between them has closed and they lie in one line, they are one edge again (Sec.
// 4.8 merges all consecutive colinear edges of an ambiguous event into one). Merging them
// moves no plane; it keeps the edge whole for what comes later, such as an anchor placed by
// a fraction of its length (the terrace's dormers).
// (Two edges of one input, as a split event leaves them, stay apart: where the corner between
// them runs decides later events, and merging them moved random80914's roof by 3 %.)
bool Sweeper::samePiece(int A, int B) const {
  if (edges_[A].src == edges_[B].src) return false;
  const SweepEdge &a = *inputs_[edges_[A].src], &b = *inputs_[edges_[B].src];
  if (a.sourceLoop != b.sourceLoop || a.sourceEdge != b.sourceEdge || a.profile != b.profile || a.step != b.step)
    return false;
  const int sa = edges_[A].step, sb = edges_[B].step;
  if (a.steps.size() - sa != b.steps.size() - sb) return false;
  for (std::size_t k = 1; sa + k < a.steps.size(); ++k) {
    const SweepEdge::Step &x = a.steps[sa + k], &y = b.steps[sb + k];
    if (x.z != y.z || x.angle != y.angle || x.segment != y.segment || x.priority != y.priority) return false;
  }
  const SweepEdge::Step &x = a.steps[sa], &y = b.steps[sb];
  return x.angle == y.angle && x.segment == y.segment && x.priority == y.priority;
}

void Sweeper::shareTop(int A, int B, int vl, int v) {
  faces_[edges_[A].face].segments.emplace_back(vl, v);
  faces_[edges_[B].face].segments.emplace_back(v, vl);
}

void Sweeper::relink(int prev, int next, int vertex, const Vec2& at, double z, int depth) {
  const int n = newCorner(prev, next, vertex, at, z);
  resolveCorner(n, z, depth + 1);
  if (corners_[n].alive) predict(n);
}

// Two antiparallel edges meeting at a corner lie on one line: above this height they would
// cross. They meet along their overlap (a ridge); the longer one goes on (Sec. 4.4, the
// degenerate chains of two parallel edges). Corners are taken where they live (liveAt): a
// racing corner made a little above z would, taken back to z along its path, sit decimetres
// to metres along the ridge from its event (taking them at z: 265 random failures, not 131).
void Sweeper::zipSpike(int ci, double z, int depth) {
  Corner& c = corners_[ci];
  const int A = c.prev, B = c.next;
  const int a0 = edges_[A].start, b1 = edges_[B].end;
  const Vec2 l = liveAt(ci, z);
  const int vl = c.vertex;
  c.alive = false;
  SWEEP_TRACE("zip corner %d (edges %d, %d) at (%g, %g, %g)", ci, A, B, l[0], l[1], z);
  if (a0 == b1) {
    // A loop of two edges: it closes along the ridge.
    const Vec2 pa = liveAt(a0, z);
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    edges_[A].alive = edges_[B].alive = false;
    return;
  }
  const Vec2 pa = liveAt(a0, z), pb = liveAt(b1, z);
  const double la = OpenMesh::dot(edges_[A].d, l - pa);
  const double lb = OpenMesh::dot(edges_[B].d, pb - l);
  const int aPrev = corners_[a0].prev, bNext = corners_[b1].next;
  if (std::abs(la - lb) <= tol_.cluster) {
    const int v = addVertex((pa + pb) * 0.5, z);
    killCorner(a0, v);
    killCorner(b1, v);
    shareTop(A, B, vl, v);
    edges_[A].alive = edges_[B].alive = false;
    if (aPrev == bNext) {
      // A loop of three edges closing at once: the third edge's face ends at v too.
      edges_[aPrev].alive = false;
      return;
    }
    relink(aPrev, bNext, v, (pa + pb) * 0.5, z, depth);
  } else if (la < lb) {
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    edges_[A].alive = false;
    relink(aPrev, B, va, pa, z, depth);
  } else {
    const int vb = addVertex(pb, z);
    killCorner(b1, vb);
    shareTop(A, B, vl, vb);
    edges_[B].alive = false;
    relink(A, bNext, vb, pb, z, depth);
  }
}

// Colinear neighbours with different angles: the ambiguous case of Sec. 4.8. The edge of
// higher priority takes over the other's extent; the other's face ends here.
void Sweeper::mergeColinear(int ci, double z, int depth) {
  Corner& c = corners_[ci];
  const int A = c.prev, B = c.next;
  const int vl = c.vertex;
  // Each edge's priority is its segment's at this height (edges_[].step follows the direction
  // events), so an angle step inside a stage counts as it would at a stage's base.
  const double pa = inputs_[edges_[A].src]->steps[edges_[A].step].priority;
  const double pb = inputs_[edges_[B].src]->steps[edges_[B].step].priority;
  const bool keepA = pa >= pb;
  c.alive = false;
  SWEEP_TRACE("merge colinear corner %d (edges %d, %d) keeping %d", ci, A, B, keepA ? A : B);
  if (keepA) {
    const int b1 = edges_[B].end;
    const Vec2 pb = liveAt(b1, z);
    const int vb = addVertex(pb, z);
    killCorner(b1, vb);
    shareTop(A, B, vl, vb);  // B's face ends along its top; A's face goes on above it
    const int bNext = corners_[b1].next;
    edges_[B].alive = false;
    relink(A, bNext, vb, pb, z, depth);
  } else {
    const int a0 = edges_[A].start;
    const Vec2 pa = liveAt(a0, z);
    const int va = addVertex(pa, z);
    killCorner(a0, va);
    shareTop(A, B, vl, va);
    const int aPrev = corners_[a0].prev;
    edges_[A].alive = false;
    relink(aPrev, B, va, pa, z, depth);
  }
}

// ------------------------------------------------------------------ events

void Sweeper::checkClock() const {
  if (in_.timeLimitSeconds > 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > in_.timeLimitSeconds)
    throw Error("the extrusion took longer than its time limit of " + std::to_string(in_.timeLimitSeconds) + " s");
}

// Where the corner's path meets each other edge's direction plane above the sweep.
void Sweeper::predict(int ci) {
  const Corner& c = corners_[ci];
  if (!c.alive) return;
  // The corner's path: x(z) = q + v z.
  Vec2 v, q;
  if (c.parallel) {
    v = c.v;
    q = c.p0 - c.v * c.z0;
  } else {
    const Edge& a = edges_[c.prev];
    const Edge& b = edges_[c.next];
    const double det = cross2(a.n, b.n);
    v = Vec2((a.k * b.n[1] - b.k * a.n[1]) / det, (a.n[0] * b.k - b.n[0] * a.k) / det);
    q = Vec2((a.c * b.n[1] - b.c * a.n[1]) / det, (a.n[0] * b.c - b.n[0] * a.c) / det);
  }
  syncLive();
  const double after = c.z0 + settle(c), before = lastUseful(c);
  // All of them at once: the corner's heap is built in one go and only its head enters the
  // global queue (pushed one by one, every new minimum would).
  auto& h = pending_[ci];
  const std::size_t had = h.size();
  const bool wasEmpty = h.empty();
  const double oldHead = wasEmpty ? std::numeric_limits<double>::infinity() : h.front().z;
  h.reserve(had + liveEdges_.size());
  for (int ei : liveEdges_) {
    const Edge& e = edges_[ei];
    if (!e.alive || ei == c.prev || ei == c.next) continue;
    const double denom = OpenMesh::dot(e.n, v) - e.k;
    if (std::abs(denom) < 1e-14) continue;
    const double z = (e.c - OpenMesh::dot(e.n, q)) / denom;
    // A corner takes part in nothing more at the height it was made: everything at its
    // point and height was handled by the event that made it.
    if (!(z > after) || !std::isfinite(z) || z > before) continue;
    h.push_back({z, q + v * z, ci, ++nextId_});
  }
  if (h.size() == had) return;
  if (wasEmpty) std::make_heap(h.begin(), h.end(), std::greater<Candidate>());
  else
    for (std::size_t i = had; i < h.size(); ++i) std::push_heap(h.begin(), h.begin() + i + 1, std::greater<Candidate>());
  if (h.front().z < oldHead) queue_.push(h.front());
}

// Predictions this little above the height a corner was made at are what that event handled.
// δ1 for most corners; a racing corner covers metres in δ1 (an initial corner between a
// shallow roof and a wall 2.5e-7 rad off it races at 1e7 m per m of rise and may sweep its
// whole edge in that height), so for it, the height in which it moves kRaceSettle δ2.
constexpr double kRaceSettle = 2;

double Sweeper::settle(const Corner& c) const {
  return c.speed > 0 ? std::min(tol_.height, kRaceSettle * tol_.cluster / c.speed) : tol_.height;
}

// Predictions above this height can never be handled: at the next angle step of either of
// the corner's edges, the direction event replaces that edge and kills the corner (its
// candidates are then dropped unseen). The step's height comes from the input edge, which an
// edge keeps through splits. Four δ1 of margin cover the clustering of direction heights
// (each edge changes at the first kept height within δ1 below its step) and a sweep stopped
// near that height (it handles events up to δ1 past its stop). Most candidates of a corner
// between two steep mansard planes lie far above the shallow step that ends them: in the
// 50-corner re-extrusion benchmark this drops about half of them.
double Sweeper::lastUseful(const Corner& c) const {
  double h = std::numeric_limits<double>::infinity();
  for (int ei : {c.prev, c.next}) {
    const Edge& e = edges_[ei];
    const auto& steps = inputs_[e.src]->steps;
    if (e.step + 1 < static_cast<int>(steps.size())) h = std::min(h, steps[e.step + 1].z + 4 * tol_.height);
  }
  return h;
}

void Sweeper::syncLive() {
  auto compact = [](std::vector<int>& live, auto alive) {
    live.erase(std::remove_if(live.begin(), live.end(), [&](int i) { return !alive(i); }), live.end());
  };
  compact(liveCorners_, [&](int i) { return corners_[i].alive; });
  compact(liveEdges_, [&](int i) { return edges_[i].alive; });
  for (; syncedCorners_ < corners_.size(); ++syncedCorners_)
    if (corners_[syncedCorners_].alive) liveCorners_.push_back(static_cast<int>(syncedCorners_));
  for (; syncedEdges_ < edges_.size(); ++syncedEdges_)
    if (edges_[syncedEdges_].alive) liveEdges_.push_back(static_cast<int>(syncedEdges_));
}

void Sweeper::push(Candidate c) {
  c.id = ++nextId_;
  auto& h = pending_[c.corner];
  const bool head = h.empty() || c.z < h.front().z;
  h.push_back(c);
  std::push_heap(h.begin(), h.end(), std::greater<Candidate>());
  if (head) queue_.push(c);
}

// The earliest prediction of a live corner, if any (stale global entries are dropped).
bool Sweeper::nextCandidate(Candidate& out) {
  while (!queue_.empty()) {
    const Candidate& t = queue_.top();
    auto& h = pending_[t.corner];
    if (!corners_[t.corner].alive) {
      h.clear();
      h.shrink_to_fit();
      queue_.pop();
      continue;
    }
    if (!h.empty() && h.front().id == t.id) {
      out = t;
      return true;
    }
    queue_.pop();
  }
  return false;
}

void Sweeper::predictAgainst(const std::vector<int>& planes) {
  // Every live corner against each new plane, plane by plane; each corner's path and the
  // heights its predictions must lie between are worked out once for all the planes.
  syncLive();
  std::vector<CornerPath>& paths = paths_;
  paths.resize(liveCorners_.size());
  for (std::size_t k = 0; k < liveCorners_.size(); ++k) {
    const int ci = liveCorners_[k];
    const Corner& c = corners_[ci];
    if (!c.alive) continue;
    const Vec2 p0 = cornerAt(ci, z_), p1 = cornerAt(ci, z_ + 1.0);
    const Vec2 v = p1 - p0;
    paths[k] = {v, p0 - v * z_, std::max(c.z0 + settle(c), z_ + tol_.height), lastUseful(c)};
  }
  for (int ei : planes) {
    checkClock();
    const Edge& e = edges_[ei];
    for (std::size_t k = 0; k < liveCorners_.size(); ++k) {
      const int ci = liveCorners_[k];
      const Corner& c = corners_[ci];
      if (!c.alive || c.prev == ei || c.next == ei) continue;
      const CornerPath& path = paths[k];
      const double denom = OpenMesh::dot(e.n, path.v) - e.k;
      if (std::abs(denom) < 1e-14) continue;
      const double z = (e.c - OpenMesh::dot(e.n, path.q)) / denom;
      if (!(z > path.lo) || !std::isfinite(z) || z > path.hi) continue;
      push({z, path.q + path.v * z, ci});
    }
  }
}

// A generalized intersection event (Sec. 4.4): all edges whose planes meet at the point,
// grouped into chains of consecutive edges; interior edges of a chain vanish, chains of one
// edge are split at the point, and chains are relinked pairwise around the point.
bool Sweeper::handleIntersection(const Candidate& cand) {
  const double z = cand.z;
  if (!corners_[cand.corner].alive) return false;
  if ((nearestOnPath(cand.corner, cand.p, z) - cand.p).norm() > tol_.cluster) {
    SWEEP_TRACE("   its corner is no longer there");
    return false;
  }

  // Corners that arrive at the point.
  // (The lists are members, reused: most candidates are no event, and they cost more to
  // allocate than to fill.)
  std::vector<int>& K = arriving_;
  K.clear();
  Vec2 l(0.0, 0.0);
  syncLive();
  for (int ci : liveCorners_) {
    // Far corners are rejected from where their lines met at z0 and their speed alone; the
    // bound is loose by 2 δ2 plus a relative margin far above rounding, so no corner within δ2
    // of the point is ever skipped.
    const Corner& c = corners_[ci];
    const double travel = c.speed * (std::abs(z - c.z0) + tol_.height);
    const double reach = travel + 2 * tol_.cluster + 1e-12 * (c.baseNorm + travel);
    if ((c.base - cand.p).sqrnorm() > reach * reach) continue;
    const Vec2 p = nearestOnPath(ci, cand.p, z);
    if ((p - cand.p).norm() <= tol_.cluster) {
      K.push_back(ci);
      l += p;
    }
  }
  if (K.empty()) return false;
  l /= static_cast<double>(K.size());
  Marks& inK = inK_;
  inK.reset(corners_.size());
  for (int ci : K) inK.set(ci);

  // Edges through the point: those of arriving corners, and edges the point splits.
  std::vector<int>& involved = involvedList_;
  involved.clear();
  Marks& isInvolved = involved_;
  isInvolved.reset(edges_.size());
  auto involve = [&](int ei) {
    if (!isInvolved[ei]) {
      isInvolved.set(ei);
      involved.push_back(ei);
    }
  };
  for (int ci : K) {
    involve(corners_[ci].prev);
    involve(corners_[ci].next);
  }
  std::vector<int>& splits = splitList_;
  splits.clear();
  for (int ei : liveEdges_) {
    const Edge& e = edges_[ei];
    if (!e.alive || isInvolved[ei]) continue;
    if (std::abs(OpenMesh::dot(e.n, l) - (e.c + e.k * z)) > tol_.cluster) continue;
    const Vec2 s = liveAt(e.start, z), t = liveAt(e.end, z);
    const double along = OpenMesh::dot(e.d, l - s), length = OpenMesh::dot(e.d, t - s);
    if (along < -tol_.edgeMargin || along > length + tol_.edgeMargin) continue;
    involve(ei);
    splits.push_back(ei);
  }
  if (splits.empty()) {
    // Corners that an event made at this point a moment ago, meeting only one another again:
    // nothing has happened since; a prediction against a plane within rounding of one of
    // theirs (a wall 6e-9 rad off its colinear neighbour) brought the sweep back here, and
    // relinking them would undo what that event did. Two or more corners made at one vertex
    // qualify wherever the event point now lies: their paths are straight lines out of that
    // vertex, which meet again nowhere else, so a fast one that has moved more than δ2 off it
    // in the height by which the prediction is off has not met anything either (the sharp
    // corner a split made, at 3.4 m/m and 1.4e-7 m higher, relinked with its partner, undid
    // the split and left two corners on one path: random11959). A two-edge loop (fewer than
    // three planes) is left to the test below, which closes it.
    // (Corners an edge direction event has just made are exempt: it met nothing at their point.)
    bool madeHere = true, oneVertex = K.size() > 1 && involved.size() > 2;
    for (int ci : K) {
      if (corners_[ci].turned && z - points_[corners_[ci].vertex][2] <= tol_.height) madeHere = oneVertex = false;
      const Vec3& p = points_[corners_[ci].vertex];
      const bool recent = z - p[2] <= 1e3 * tol_.cluster;
      madeHere = madeHere && std::abs(p[0] - l[0]) <= tol_.cluster && std::abs(p[1] - l[1]) <= tol_.cluster && recent;
      oneVertex = oneVertex && corners_[ci].vertex == corners_[K[0]].vertex && recent;
    }
    if (madeHere || oneVertex) {
      SWEEP_TRACE("   only corners made here a moment ago meet there%s",
                  madeHere ? "" : " (at one vertex, moved off it)");
      return false;
    }
  }
  if (involved.size() < 3) {
    // Fewer than three planes meet only where a whole loop has shrunk to the point (a
    // two-edge sliver whose corners arrive together).
    bool closed = true;
    for (int ei : involved) closed = closed && inK[edges_[ei].start] && inK[edges_[ei].end];
    if (!closed) {
      SWEEP_TRACE("   only %zu planes meet there", involved.size());
      return false;
    }
  }

  // The event point: the least-squares meeting point of all involved lines at this height
  // (closer to every plane than the mean of the arriving corners), unless they are too close
  // to parallel to pin it down.
  {
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (int ei : involved) {
      const Edge& e = edges_[ei];
      const double r = e.c + e.k * z;
      a11 += e.n[0] * e.n[0], a12 += e.n[0] * e.n[1], a22 += e.n[1] * e.n[1];
      b1 += e.n[0] * r, b2 += e.n[1] * r;
    }
    const double det = a11 * a22 - a12 * a12;
    if (det > 1e-6 * (a11 + a22) * (a11 + a22)) {
      const Vec2 ls((a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det);
      if ((ls - l).norm() <= tol_.cluster) l = ls;
    }
  }
  // A cascade of events at one point within a sliver of height means the configuration
  // re-creates itself (coincident corner paths): stop with a reason instead of looping.
  if ((l - lastEventPoint_).norm() <= tol_.cluster && z - lastEventZ_ <= 1e3 * tol_.cluster) {
    if (++repeats_ > 32) {
      std::ostringstream m;
      m << "degenerate event cascade at (" << l[0] << ", " << l[1] << ", " << z
        << "): coincident corner paths the sweep cannot separate";
      throw Error(m.str());
    }
  } else {
    repeats_ = 0;
    lastEventPoint_ = l;
    lastEventZ_ = z;
  }
  {
    // However degenerate, a plan of n edges has no more than a few n events at one height
    // (each ends an edge or splits one, and splits are used up by the ends they cause). Far
    // more within a sliver of height means the events feed themselves: stop with a reason.
    if (z - burstZ_ > 1e3 * tol_.cluster) {
      burstZ_ = z;
      burst_ = 0;
    }
    if (++burst_ > 4 * inputs_.size() + 64) {
      std::ostringstream m;
      m << "degenerate event cascade at (" << l[0] << ", " << l[1] << ", " << z << "): " << burst_
        << " events without rising, from a plan of " << inputs_.size() << " edges (an earlier configuration was degenerate)";
      throw Error(m.str());
    }
  }
  {
    // Relinking the same edges again and again, each time a sliver higher, never ends the
    // sweep (it would crawl up at 1e-7 m per event): stop with a reason after 64 rounds.
    std::vector<int>& sig = signature_;
    sig.assign(involved.begin(), involved.end());
    std::sort(sig.begin(), sig.end());
    bool again = false;
    for (int k = 0; k < 2; ++k) again = again || (sig == lastInvolved_[k] && z - lastInvolvedZ_[k] <= 1e3 * tol_.cluster);
    swaps_ = again ? swaps_ + 1 : 0;
    if (swaps_ > 64) {
      std::ostringstream m;
      m << "degenerate event cycle at (" << l[0] << ", " << l[1] << ", " << z << "): the same " << sig.size()
        << " edges are relinked back and forth (the active plan overlaps itself along a line there)";
      throw Error(m.str());
    }
    // The three lists trade places, so none is allocated again.
    lastInvolved_[1].swap(lastInvolved_[0]);
    lastInvolvedZ_[1] = lastInvolvedZ_[0];
    lastInvolved_[0].swap(sig);
    lastInvolvedZ_[0] = z;
  }
  ++events_;
  const int vl = addVertex(l, z);
  SWEEP_TRACE("event %zu at (%g, %g, %g): %zu corners, %zu edges, %zu splits -> v%d", events_, l[0], l[1], z, K.size(),
              involved.size(), splits.size(), vl);
  for (int ci : K) killCorner(ci, vl);

  // Chains: follow arriving corners from each edge whose start did not arrive.
  std::vector<Chain>& chains = chains_;
  chains.clear();
  Marks& used = used_;
  used.reset(edges_.size());
  for (int ei : involved) {
    if (used[ei]) continue;
    const Edge& e = edges_[ei];
    if (inK[e.start]) continue;  // not the head of a chain
    if (!inK[e.end]) continue;   // an edge the point splits (below)
    used.set(ei);
    int last = ei;
    for (int cur = ei;;) {
      const int nxt = corners_[edges_[cur].end].next;
      used.set(nxt);
      if (nxt != ei && inK[edges_[nxt].end]) {
        edges_[nxt].alive = false;  // interior edge: shrank to nothing at l
        cur = nxt;
        continue;
      }
      last = nxt;
      break;
    }
    chains.push_back({ei, last});
  }
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
  if (chains.empty()) return true;

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
  const std::size_t firstMade = corners_.size() - newCorners.size();
  for (int ci : newCorners) resolveCorner(ci, z);
  for (int ci : newCorners)
    if (corners_[ci].alive) predict(ci);
  // Post inter-chain validation (Sec. 4.4): the corners made at l must keep the plan simple
  // just above it, below the next event. Where they do not, an earlier configuration was
  // already degenerate; the sweep says so.
  std::vector<int>& made = made_;
  made.clear();
  for (std::size_t ci = firstMade; ci < corners_.size(); ++ci)
    if (corners_[ci].alive && corners_[ci].vertex == vl) made.push_back(static_cast<int>(ci));
  if (traceOn()) {
    for (int ci : liveCorners_) {
      if (!corners_[ci].alive) continue;
      const Vec2 p = cornerAt(ci, z);
      SWEEP_TRACE("    live corner %d: edges %d -> %d at (%.9g, %.9g) v=(%g, %g)", ci, corners_[ci].prev, corners_[ci].next, p[0], p[1],
                  corners_[ci].v[0], corners_[ci].v[1]);
    }
  }
  const double next = queue_.empty() ? std::numeric_limits<double>::infinity() : queue_.top().z;
  if (next - z > 1e3 * tol_.height && !locallySimple(made, l, z, 0.25 * (next - z))) {
    SWEEP_TRACE("  post inter-chain check: the plan overlaps itself above (%g, %g, %g)", l[0], l[1], z);
    if (in_.stopAtOverlap && !stoppedAtOverlap_) {
      // Stop halfway to whatever comes next (an event, an edge direction event, the stop
      // height), where the overlap has grown but nothing else has happened yet: the stager
      // rebuilds the plan there by the winding rule and sweeps on from it.
      double upto = std::min(next, stopZ_);
      for (double d : directionHeights_)
        if (d > z + tol_.height) upto = std::min(upto, d);
      if (!std::isfinite(upto)) upto = z + 1e-3 * (tol_.cluster / 1e-8);
      stopZ_ = z + 0.5 * (upto - z);
      stoppedAtOverlap_ = true;
      SWEEP_TRACE("  stopping at %.12g for the winding rule", stopZ_);
    } else if (overlaps_++ == 0) {
      firstOverlap_ = Vec3(l[0], l[1], z);
    }
  }
  return true;
}

bool Sweeper::locallySimple(const std::vector<int>& made, const Vec2& l, double z, double maxRise) const {
  if (made.size() < 2) return true;
  // Within R (half the shortest edge of the made corners) only their edges matter, and each
  // corner's neighbourhood is a wedge: its apex moves from l with the corner, its sides are
  // its two edges.
  double R = std::numeric_limits<double>::infinity(), speed = 0;
  for (int ci : made) {
    const Corner& c = corners_[ci];
    R = std::min(R, (cornerAt(edges_[c.prev].start, z) - l).norm());
    R = std::min(R, (cornerAt(edges_[c.next].end, z) - l).norm());
    speed = std::max(speed, c.speed);
  }
  R *= 0.5;
  if (!(R > 10 * tol_.cluster) || !(speed > 0)) return true;
  struct Wedge {
    Vec2 p, a, b, v;  // apex, arriving and leaving directions, apex velocity
    bool convex;
  };
  std::vector<Wedge> w;
  std::vector<double> angles;  // every side's direction from l
  for (int ci : made) {
    const Corner& c = corners_[ci];
    const Vec2 a = edges_[c.prev].d, b = edges_[c.next].d;
    // A spike sharper than about 0.1° races along its ridge: its wedge says nothing reliable.
    if (std::abs(cross2(a, b)) <= 2e-3 && OpenMesh::dot(a, b) < 0) return true;
    w.push_back({Vec2(0.0, 0.0), a, b, c.v, cross2(a, b) >= 0});
    angles.push_back(std::atan2(-a[1], -a[0]));
    angles.push_back(std::atan2(b[1], b[0]));
  }
  std::sort(angles.begin(), angles.end());
  // The apexes may spread only a small part of the narrowest sector at the sampling radius, so
  // the samples see the wedges' order around l, not the noise of where their apexes are.
  const double rho = 0.1 * R;
  double narrowest = 2 * std::numbers::pi;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double gap = (i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * std::numbers::pi) - angles[i];
    if (gap > 1e-9) narrowest = std::min(narrowest, gap);
  }
  const double h = std::min(maxRise, 1e-3 * rho * narrowest / speed);
  for (Wedge& k : w) k.p = k.v * h;  // relative to l, so tiny offsets keep their digits
  auto inside = [](const Wedge& k, const Vec2& q) {
    const double s1 = cross2(k.a, q - k.p), s2 = cross2(k.b, q - k.p);
    return k.convex ? (s1 > 0 && s2 > 0) : (s1 > 0 || s2 > 0);
  };
  auto covered = [&](const Vec2& q) {
    int n = 0;
    for (const Wedge& k : w) n += inside(k, q);
    return n;
  };
  // Far samples: between every two sides, on a circle of radius rho around l (the origin).
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double a0 = angles[i], a1 = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * std::numbers::pi;
    if (a1 - a0 <= 1e-9) continue;
    const double m = 0.5 * (a0 + a1);
    if (covered(Vec2(std::cos(m), std::sin(m)) * rho) > 1) return false;
  }
  // Near samples: just inside each apex, on its bisector (colinear sides that overlap).
  double spread = 0;
  for (const Wedge& k : w) spread = std::max(spread, k.p.norm());
  if (spread > 0)
    for (const Wedge& k : w) {
      Vec2 bis = leftOf(k.a) + leftOf(k.b);
      if (bis.norm() < 1e-9) bis = leftOf(k.a);
      bis.normalize();
      if (covered(k.p + bis * (1e-2 * spread)) > 1) return false;
    }
  return true;
}

void Sweeper::meetAtTurn(const std::vector<int>& made, double h) {
  syncLive();
  for (int ci : made) {
    checkClock();
    const Corner& c = corners_[ci];
    if (!c.alive) continue;
    const Vec2 p = cornerAt(ci, h);
    for (int ei : liveEdges_) {
      const Edge& e = edges_[ei];
      if (!e.alive || ei == c.prev || ei == c.next) continue;
      if (std::abs(OpenMesh::dot(e.n, p) - (e.c + e.k * h)) > tol_.cluster) continue;
      const Vec2 s = liveAt(e.start, h), t = liveAt(e.end, h);
      const double along = OpenMesh::dot(e.d, p - s), length = OpenMesh::dot(e.d, t - s);
      if (along < -tol_.edgeMargin || along > length + tol_.edgeMargin) continue;
      SWEEP_TRACE("  turned corner %d lies on edge %d at (%g, %g, %g)", ci, ei, p[0], p[1], h);
      push({h, p, ci});
      break;
    }
  }
}

// Edge direction events (Sec. 4.5.1): every edge whose profile turns at height h continues
// on a new direction plane and starts a new face.
void Sweeper::handleDirectionChanges(double h) {
  std::vector<int> changing;
  for (int ei = 0; ei < static_cast<int>(edges_.size()); ++ei) {
    const Edge& e = edges_[ei];
    if (!e.alive) continue;
    const auto& steps = inputs_[e.src]->steps;
    if (e.step + 1 < static_cast<int>(steps.size()) && std::abs(steps[e.step + 1].z - h) <= tol_.height)
      changing.push_back(ei);
  }
  if (changing.empty()) return;
  std::map<int, int> replaced;  // old edge → new edge
  std::map<int, int> cornerVertex;
  std::map<int, Vec2> cornerPos;
  for (int ei : changing) {
    for (int ci : {edges_[ei].start, edges_[ei].end}) {
      if (cornerVertex.count(ci)) continue;
      const Vec2 p = cornerAt(ci, h);
      cornerPos[ci] = p;
      cornerVertex[ci] = addVertex(p, h);
    }
  }
  for (int ei : changing) {
    Edge next = edges_[ei];
    const auto& st = inputs_[next.src]->steps[next.step + 1];
    // The new plane holds the old one's line at h exactly (n·x = c + k h), rather than passing
    // through a corner computed on it: between almost colinear neighbours that corner is a
    // badly conditioned intersection whose residual off the line, ~1e-8 m, would move the
    // new corner metres along it (the lines' offsets divided by their sine).
    const Vec2 on = cornerPos[edges_[ei].start];
    setEdgePlane(next, edges_[ei].d, on, h, st.angle);
    next.c = edges_[ei].c + edges_[ei].k * h - next.k * h;
    next.step = edges_[ei].step + 1;
    next.face = addFace(next.src, st.segment, st.angle, next);
    edges_.push_back(next);
    const int nj = static_cast<int>(edges_.size()) - 1;
    replaced[ei] = nj;
  }
  // Old faces end along their top, new faces start along their bottom.
  for (int ei : changing) {
    const int vs = cornerVertex[edges_[ei].start], vt = cornerVertex[edges_[ei].end];
    faces_[edges_[ei].face].segments.emplace_back(vt, vs);
    faces_[edges_[replaced[ei]].face].segments.emplace_back(vs, vt);
  }
  // Corners of changing edges move along new paths from here.
  std::vector<int> fresh;
  turning_ = true;
  for (const auto& [ci, v] : cornerVertex) {
    const Corner old = corners_[ci];
    killCorner(ci, v);
    const int prev = replaced.count(old.prev) ? replaced[old.prev] : old.prev;
    const int next = replaced.count(old.next) ? replaced[old.next] : old.next;
    fresh.push_back(newCorner(prev, next, v, cornerPos[ci], h));
  }
  for (int ei : changing) edges_[ei].alive = false;
  const std::size_t firstMade = corners_.size() - fresh.size();
  for (int ci : fresh) resolveCorner(ci, h);
  turning_ = false;
  for (int ci : fresh) {
    checkClock();
    if (corners_[ci].alive) predict(ci);
  }
  // What the old corners would have met at h (an edge that shrinks to nothing just as it
  // turns, loops that touch as their flare ends) is the new corners' to meet, at h itself:
  // their predictions start above it, and corners on vertical walls predict nothing at all.
  std::vector<int> made;
  for (std::size_t ci = firstMade; ci < corners_.size(); ++ci)
    if (corners_[ci].alive) made.push_back(static_cast<int>(ci));
  meetAtTurn(made, h);
  std::vector<int> planes;
  for (const auto& [old, nj] : replaced)
    if (edges_[nj].alive) planes.push_back(nj);
  predictAgainst(planes);
}

// A loop left at the base when no event is left, every edge of which is vertical for good: it
// never rises, and capping it would make a shell of no volume. That is the spec's doing, not
// rounding's: each straight run of the plan mixes sloped edges with gables (vertical last
// segments), and the priority (Sec. 4.8) gives the run to a gable at the base, as volume
// maximising does (random33502, random35776). Said as bad input, naming the edges.
void Sweeper::refuseStandingLoop(const std::vector<int>& loop) const {
  std::vector<int> sources;
  const SweepEdge* first = nullptr;
  for (int ci : loop) {
    const Edge& e = edges_[corners_[ci].next];
    const SweepEdge& in = *inputs_[e.src];
    if (e.k != 0 || e.step + 1 < static_cast<int>(in.steps.size())) return;  // it rises, or will
    if (!first) first = &in;
    else if (in.step != first->step || in.sourceLoop != first->sourceLoop) return;  // not one loop of the spec's
    sources.push_back(in.sourceEdge);
  }
  if (!first) return;
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  std::ostringstream where, why;
  if (first->step >= 0) where << "steps[" << first->step << "]";
  else where << "loops[" << first->sourceLoop << "]";
  why << "the roof cannot close: every edge left of this loop at its base is vertical for good (edge";
  if (sources.size() > 1) why << "s";
  for (std::size_t i = 0; i < sources.size() && i < 12; ++i) why << (i ? ", " : " ") << sources[i];
  if (sources.size() > 12) why << ", ...";
  why << "), the sloped edges in line with them having given way by priority (Sec. 4.8), so nothing "
         "rises; give each straight run a sloped last segment, or let the sloped edges win "
         "(priority minimise_volume, or manual with their segments tagged high)";
  throw InputError(where.str(), why.str());
}

// Loops still open when no event is left (a missed event in a degenerate configuration):
// close each with a flat cap so the shell stays closed, and say so.
void Sweeper::capRemaining(double z, std::vector<std::vector<PlanCorner>>* plan) {
  std::vector<char> seen(corners_.size(), 0);
  int capped = 0;
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    if (!corners_[ci].alive || seen[ci]) continue;
    std::vector<int> loop;
    int cur = ci;
    while (!seen[cur]) {
      seen[cur] = 1;
      loop.push_back(cur);
      cur = edges_[corners_[cur].next].end;
      if (cur < 0) break;
    }
    if (!plan && in_.emitBase && z <= in_.baseZ + tol_.height) refuseStandingLoop(loop);
    FaceBuild cap;
    cap.normal = Vec3(0, 0, 1);
    cap.segment = -2;
    std::vector<int> verts;
    std::vector<PlanCorner> out;
    for (int c : loop) {
      const Vec2 p = cornerAt(c, z);
      verts.push_back(addVertex(p, z));
      out.push_back({p, verts.back(), edges_[corners_[c].next].src});
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int c = loop[i];
      killCorner(c, verts[i]);
      const int e = corners_[c].next;
      const int vs = verts[i], vt = verts[(i + 1) % loop.size()];
      faces_[edges_[e].face].segments.emplace_back(vt, vs);
      cap.segments.emplace_back(vs, vt);
      edges_[e].alive = false;
    }
    if (plan) {
      plan->push_back(std::move(out));
      continue;
    }
    faces_.push_back(std::move(cap));
    ++capped;
  }
  if (capped) {
    std::ostringstream s;
    s << "the roof did not close: " << capped << " loop(s) were capped flat at height " << z
      << " (a degenerate configuration, Sec. 4.4 Fig. 15)";
    warnings_.push_back(s.str());
  }
}

SweepOutput Sweeper::run() {
  started_ = std::chrono::steady_clock::now();
  z_ = in_.baseZ;
  // Room for what a plan of n edges usually makes (an event ends or splits an edge and makes
  // a corner or two; a face has a few pieces), so a small shell grows no list piece by piece.
  std::size_t n = 0, faces = 1;
  for (const auto& loop : in_.loops) {
    n += loop.size();
    for (const SweepEdge& e : loop) faces += e.steps.size();
  }
  const std::size_t room = 2 * n + 8;
  inputs_.reserve(n);
  edges_.reserve(room);
  corners_.reserve(room);
  pending_.reserve(room);
  points_.reserve(room);
  faces_.reserve(faces);
  liveCorners_.reserve(room);
  liveEdges_.reserve(room);
  recent_.reserve(n);
  for (Marks* m : {&inK_, &involved_, &used_}) m->reserve(room);
  {
    std::vector<Candidate> heads;
    heads.reserve(room);
    queue_ = decltype(queue_)(std::greater<Candidate>(), std::move(heads));
  }
  // Input edges, their first faces, and the base.
  FaceBuild base;
  base.base = true;
  base.normal = Vec3(0, 0, -1);
  base.segments.reserve(n);
  std::vector<int> verts;
  for (const auto& loop : in_.loops) {
    const int first = static_cast<int>(edges_.size());
    const int n = static_cast<int>(loop.size());
    verts.clear();
    verts.reserve(n);
    // (The clock is read every 1,024 corners here too: a plan of 100,000 takes a while to set up.)
    for (int i = 0; i < n; ++i) {
      if ((i & 1023) == 1023) checkClock();
      verts.push_back(addVertex(loop[i].start, z_));
    }
    for (int i = 0; i < n; ++i) {
      if ((i & 1023) == 1023) checkClock();
      inputs_.push_back(&loop[i]);
      Edge e;
      e.src = static_cast<int>(inputs_.size()) - 1;
      Vec2 d = loop[(i + 1) % n].start - loop[i].start;
      d.normalize();
      setEdgePlane(e, d, loop[i].start, z_, loop[i].steps[0].angle);
      e.face = addFace(e.src, loop[i].steps[0].segment, loop[i].steps[0].angle, e);
      edges_.push_back(e);
      faces_[e.face].segments.emplace_back(verts[i], verts[(i + 1) % n]);
      base.segments.emplace_back(verts[(i + 1) % n], verts[i]);
      for (std::size_t s = 1; s < loop[i].steps.size(); ++s) directionHeights_.push_back(loop[i].steps[s].z);
    }
    for (int i = 0; i < n; ++i) {
      const int prev = first + (i + n - 1) % n, next = first + i;
      newCorner(prev, next, verts[i], loop[i].start, z_);
    }
  }
  if (in_.emitBase) faces_.push_back(base);
  std::sort(directionHeights_.begin(), directionHeights_.end());
  directionHeights_.erase(std::unique(directionHeights_.begin(), directionHeights_.end(),
                                      [&](double a, double b) { return std::abs(a - b) <= tol_.height; }),
                          directionHeights_.end());
  const int initialCorners = static_cast<int>(corners_.size());
  for (int ci = 0; ci < initialCorners; ++ci) {
    if ((ci & 1023) == 1023) checkClock();
    resolveCorner(ci, z_);
  }
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    checkClock();
    if (corners_[ci].alive) predict(ci);
  }

  // No real event lies far above the plan: the roof over a plan of size s whose edges climb
  // at most k per metre inward tops out within s·k of the last profile change. Events far
  // beyond that mean the sweep has diverged in a degenerate configuration: fail at once
  // instead of chasing them up to the event limit, and cap what is left.
  double maxK = 1.0, lastChange = in_.baseZ;
  for (const SweepEdge* e : inputs_)
    for (const auto& st : e->steps) {
      maxK = std::max(maxK, std::abs(std::tan(st.angle)));
      lastChange = std::max(lastChange, st.z);
    }
  const double scale = tol_.minEdge / 1e-7;
  const double divergedZ = lastChange + 1e3 * scale * maxK;
  std::size_t nextDirection = 0;
  const std::size_t cap = 200000 + 400 * edges_.size() * edges_.size();
  std::size_t popped = 0;
  Candidate cand{};
  std::vector<std::vector<std::vector<PlanCorner>>> probed;
  while (true) {
    const bool any = nextCandidate(cand);
    const double nextEventZ = any ? cand.z : std::numeric_limits<double>::infinity();
    {
      // Probes below everything still to come see the plan as it is between events.
      double upcoming = nextEventZ;
      if (nextDirection < directionHeights_.size()) upcoming = std::min(upcoming, directionHeights_[nextDirection]);
      while (probed.size() < in_.probes.size() && in_.probes[probed.size()] + tol_.height < upcoming &&
             in_.probes[probed.size()] < stopZ_)
        probed.push_back(snapshot(in_.probes[probed.size()]));
    }
    if (nextDirection < directionHeights_.size() && directionHeights_[nextDirection] <= nextEventZ + tol_.height &&
        directionHeights_[nextDirection] < stopZ_ - tol_.height) {
      z_ = std::max(z_, directionHeights_[nextDirection]);
      handleDirectionChanges(directionHeights_[nextDirection++]);
      continue;
    }
    if (!any || nextEventZ > stopZ_ + tol_.height) break;
    if (++popped > cap) {
      warnings_.push_back("event limit reached; the result is incomplete");
      break;
    }
    if ((popped & 255) == 0) {
      if (progress_ && progress_->cancelled()) throw Cancelled();
      checkClock();
    }
    if (cand.z > divergedZ && std::isinf(stopZ_)) {
      // What is left is capped where the last real event was (capRemaining says so).
      std::ostringstream m;
      m << "the sweep diverged: the next event was at height " << cand.z << ", far above the plan";
      warnings_.push_back(m.str());
      diverged_ = true;
      break;
    }
    queue_.pop();
    auto& h = pending_[cand.corner];
    std::pop_heap(h.begin(), h.end(), std::greater<Candidate>());
    h.pop_back();
    if (!h.empty()) queue_.push(h.front());
    if (cand.z < z_ - tol_.height) continue;  // predicted before an earlier change
    SWEEP_TRACE(" candidate of corner %d at (%.12g, %.12g, %.12g)", cand.corner, cand.p[0], cand.p[1], cand.z);
    if (handleIntersection(cand)) {
      z_ = std::max(z_, cand.z);
      // An event can cost far more than a pop (hundreds of edges through one point in a
      // degenerate plan), so the time limit is also checked after every one.
      checkClock();
    }
  }
  if (overlaps_) {
    std::ostringstream m;
    m << "the active plan overlapped itself after " << overlaps_ << " event(s), first at (" << firstOverlap_[0] << ", "
      << firstOverlap_[1] << ", " << firstOverlap_[2] << "): a degenerate configuration (Sec. 4.4); the output may be undesirable";
    warnings_.push_back(m.str());
  }
  SweepOutput out;
  // Probes above the last event: the plan is empty if the roof closed, else as it stands.
  // (A sweep stopped for the winding rule leaves the probes above its stop to the next one.)
  while (probed.size() < in_.probes.size() && !(stoppedAtOverlap_ && in_.probes[probed.size()] >= stopZ_))
    probed.push_back(snapshot(in_.probes[probed.size()]));
  out.probed = std::move(probed);
  if (stoppedAtOverlap_) out.stoppedAt = stopZ_;
  if (std::isfinite(stopZ_)) capRemaining(stopZ_, &out.plan);
  else capRemaining(z_);
  buildFaces(out);
  out.warnings = std::move(warnings_);
  out.events = events_;
  out.diverged = diverged_;
  return out;
}

std::vector<std::vector<PlanCorner>> Sweeper::snapshot(double z) const {
  std::vector<std::vector<PlanCorner>> plan;
  std::vector<char> seen(corners_.size(), 0);
  for (int ci = 0; ci < static_cast<int>(corners_.size()); ++ci) {
    if (!corners_[ci].alive || seen[ci]) continue;
    std::vector<PlanCorner> loop;
    for (int cur = ci; cur >= 0 && !seen[cur]; cur = edges_[corners_[cur].next].end) {
      seen[cur] = 1;
      loop.push_back({cornerAt(cur, z), -1, edges_[corners_[cur].next].src});
    }
    if (loop.size() >= 3) plan.push_back(std::move(loop));
  }
  return plan;
}

// ------------------------------------------------------------------ faces

void Sweeper::buildFaces(SweepOutput& out) {
  out.points = std::move(points_);
  for (const Vec3& p : out.points) out.maxHeight = std::max(out.maxHeight, p[2]);
  std::vector<RawFace> raw;
  raw.reserve(faces_.size());
  for (FaceBuild& f : faces_) {
    RawFace r;
    r.segments = std::move(f.segments);
    r.info.normal = f.normal;
    r.info.base = f.base;
    r.info.segment = f.segment;
    r.info.angle = f.angle;
    if (f.src >= 0) {
      r.info.sourceLoop = inputs_[f.src]->sourceLoop;
      r.info.sourceEdge = inputs_[f.src]->sourceEdge;
      r.info.profile = inputs_[f.src]->profile;
      r.info.step = inputs_[f.src]->step;
    }
    raw.push_back(std::move(r));
  }
  if (in_.keepRaw) out.raw = std::move(raw);
  else traceFaces(out.points, raw, tol_, out.faces, warnings_);
}

}  // namespace

void traceFaces(const std::vector<Vec3>& points_, const std::vector<RawFace>& raw, const Tolerances& tol_,
                std::vector<ShellFace>& faces, std::vector<std::string>& warnings) {
  // Working lists shared by the faces (cleared for each): a shell has a few dozen faces of a
  // few pieces each, and allocating them anew for every face cost more than the tracing.
  std::vector<std::pair<int, int>> all, segs;
  std::vector<char> usedSeg;
  std::vector<int> outers, holes, loop, verts;
  std::vector<std::size_t> starts;
  std::vector<Vec2> flat2D;
  faces.reserve(faces.size() + raw.size());
  for (const RawFace& rf : raw) {
    const ShellFace& f = rf.info;
    // Drop zero-length pieces and pieces cancelled by their reverse (a face folded onto itself):
    // each piece keeps its count less its reverse's. Sorted vectors, not maps: faces are small
    // and this runs for every face of every shell.
    all.clear();
    all.reserve(rf.segments.size());
    for (auto [u, v] : rf.segments)
      if (u != v && (points_[u] - points_[v]).norm() > tol_.cluster * 1e-3) all.emplace_back(u, v);
    std::sort(all.begin(), all.end());
    segs.clear();
    for (std::size_t i = 0; i < all.size();) {
      std::size_t j = i;
      while (j < all.size() && all[j] == all[i]) ++j;
      const auto rev = std::equal_range(all.begin(), all.end(), std::make_pair(all[i].second, all[i].first));
      const long net = static_cast<long>(j - i) - static_cast<long>(rev.second - rev.first);
      for (long k = 0; k < net; ++k) segs.push_back(all[i]);
      i = j;
    }
    if (segs.size() < 3) continue;
    auto leaving = [&](int at) {
      return std::equal_range(segs.begin(), segs.end(), at, [](const auto& a, const auto& b) {
        if constexpr (std::is_same_v<std::decay_t<decltype(a)>, int>) return a < b.first;
        else return a.first < b;
      });
    };

    // 2D frame of the face plane, counter-clockwise seen from outside.
    Vec3 u = std::abs(f.normal[2]) < 0.9 ? OpenMesh::cross(Vec3(0, 0, 1), f.normal) : Vec3(1, 0, 0);
    u.normalize();
    const Vec3 w = OpenMesh::cross(f.normal, u);
    auto flat = [&](int v) { return Vec2(OpenMesh::dot(points_[v], u), OpenMesh::dot(points_[v], w)); };

    usedSeg.assign(segs.size(), 0);
    // The face's loops, end to end in `verts` (loop k is [starts[k], starts[k + 1])).
    verts.clear();
    starts.assign(1, 0);
    auto keep = [&](auto first, auto last) {
      if (last - first < 3) return;
      verts.insert(verts.end(), first, last);
      starts.push_back(verts.size());
    };
    for (int s0 = 0; s0 < static_cast<int>(segs.size()); ++s0) {
      if (usedSeg[s0]) continue;
      loop.clear();
      int s = s0;
      while (s >= 0 && !usedSeg[s]) {
        usedSeg[s] = 1;
        loop.push_back(segs[s].first);
        const int at = segs[s].second;
        // Among the pieces leaving `at`, the first one clockwise from the way back.
        int best = -1, candidates = 0;
        const auto range = leaving(at);
        for (auto it = range.first; it != range.second; ++it)
          if (!usedSeg[it - segs.begin()]) {
            ++candidates;
            best = static_cast<int>(it - segs.begin());
          }
        if (candidates > 1) {
          const Vec2 back = flat(segs[s].first) - flat(at);
          double bestTurn = 1e9;
          for (auto it = range.first; it != range.second; ++it) {
            const int k = static_cast<int>(it - segs.begin());
            if (usedSeg[k]) continue;
            const Vec2 out = flat(segs[k].second) - flat(at);
            double turn = std::atan2(cross2(out, back), OpenMesh::dot(out, back));  // clockwise angle back → out
            if (turn <= 0) turn += 2 * std::numbers::pi;
            if (turn < bestTurn) {
              bestTurn = turn;
              best = k;
            }
          }
        }
        s = best;
      }
      // A loop that passes one vertex twice (a dormer's ridge reaching the top of the wall it
      // stands on) is two loops touching there: a polygon mesh takes each as its own face.
      // Split at the first repeat, the part after it first, until none is left (rare: the
      // common loop goes straight to `verts`).
      auto repeatIn = [](const std::vector<int>& l) {
        for (std::size_t i = 0; i < l.size(); ++i)
          for (std::size_t j = i + 1; j < l.size(); ++j)
            if (l[i] == l[j]) return std::make_pair(i, j);
        return std::make_pair(l.size(), l.size());
      };
      if (repeatIn(loop).first == loop.size()) {
        keep(loop.begin(), loop.end());
        continue;
      }
      std::vector<std::vector<int>> pending{loop};
      while (!pending.empty()) {
        std::vector<int> l = std::move(pending.back());
        pending.pop_back();
        const auto [i, j] = repeatIn(l);
        if (i == l.size()) {
          keep(l.begin(), l.end());
          continue;
        }
        pending.emplace_back(l.begin() + i, l.begin() + j);
        std::vector<int> rest(l.begin(), l.begin() + i);
        rest.insert(rest.end(), l.begin() + j, l.end());
        pending.push_back(std::move(rest));
      }
    }
    const int loopCount = static_cast<int>(starts.size()) - 1;
    auto begin = [&](int k) { return verts.begin() + static_cast<std::ptrdiff_t>(starts[k]); };
    auto end = [&](int k) { return verts.begin() + static_cast<std::ptrdiff_t>(starts[k + 1]); };
    // Outer loops are counter-clockwise in the face frame; holes go to the outer loop that
    // contains them. Each vertex of a loop in the face's frame is worked out once (flat2D[i]
    // for verts[i]).
    flat2D.resize(verts.size());
    for (std::size_t i = 0; i < verts.size(); ++i) flat2D[i] = flat(verts[i]);
    auto signedArea = [&](int k) {
      const std::size_t first = starts[k], last = starts[k + 1];
      double a = 0;
      for (std::size_t i = first; i < last; ++i) a += cross2(flat2D[i], flat2D[i + 1 == last ? first : i + 1]);
      return 0.5 * a;
    };
    outers.clear();
    holes.clear();
    for (int i = 0; i < loopCount; ++i) {
      const double a = signedArea(i);
      if (std::abs(a) <= tol_.cluster * tol_.cluster) continue;
      (a > 0 ? outers : holes).push_back(i);
    }
    // The faces made here go straight to the output, from `made` on.
    const std::size_t made = faces.size();
    for (int o : outers) {
      faces.push_back(f);
      faces.back().loops.emplace_back(begin(o), end(o));
    }
    auto inside = [&](const Vec2& p, const std::vector<int>& loop) {
      bool in = false;
      for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec2 a = flat(loop[i]), b = flat(loop[j]);
        if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
      }
      return in;
    };
    for (int h : holes) {
      // A hole's test point: the midpoint of its first edge nudged to its inside is robust
      // against holes touching their outer loop at a vertex.
      const auto hl = begin(h);
      Vec2 probe = (flat(hl[0]) + flat(hl[1])) * 0.5;
      int owner = -1;
      double ownerArea = 1e300;
      for (std::size_t k = made; k < faces.size(); ++k) {
        const std::vector<int>& outer = faces[k].loops[0];
        if (!inside(probe, outer)) continue;
        const double a = signedArea(outers[k - made]);
        if (a < ownerArea) {
          ownerArea = a;
          owner = static_cast<int>(k);
        }
      }
      if (owner >= 0) faces[owner].loops.emplace_back(begin(h), end(h));
      else if (faces.size() > made) {
        warnings.push_back("a face boundary piece could not be placed (hole outside its face)");
      }
    }
  }
}

SweepOutput sweep(const SweepInput& input, const Tolerances& tol, Progress* progress) {
  Sweeper s(input, tol, progress);
  return s.run();
}

}  // namespace corbel::extrude
