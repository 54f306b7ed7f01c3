#pragma once
// The sweep's state (Kelly & Wonka, Sec. 4.2–4.5 and 4.8), shared by the files that implement
// it; private to src/extrude. docs/extrude.md maps the paper's steps to the files.
//
// Active plan: loops of corners and edges. Edge e lies at height z on the line
// n_e·x = c_e + k_e·z (n_e its inward normal, k_e = tan θ_e), i.e. on its direction plane.
// A corner is where its two edges' lines meet, so its position is always recomputed from the
// lines (no drift). Every face of the output is traced by one edge between two events.
#include "extrude/sweep.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

namespace corbel::extrude::sweeping {

// CORBEL_SWEEP_TRACE=1 prints every event to stderr (for debugging kernels, never in tests).
inline bool traceOn() {
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

inline double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
inline Vec2 leftOf(const Vec2& d) { return Vec2(-d[1], d[0]); }

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
  bool merged = false;  // has taken over a colinear neighbour's extent (mergeColinear)
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

  // Topology (active_plan.cpp); resolving a new corner (ambiguities.cpp).
  int newCorner(int prev, int next, int vertex, const Vec2& at, double z);
  void arc(int corner, int topVertex);
  void stepToWhereItStarts(int corner, const Vec2& at, double z);
  void killCorner(int c, int topVertex);
  void resolveCorner(int c, double z, int depth = 0);
  void zipSpike(int c, double z, int depth);
  // Edges A (arriving) and B (leaving) of a closed corner meet along vl–v: their faces' tops.
  void shareTop(int A, int B, int vl, int v);
  // A corner that replaces closed ones: made, resolved and, if it lives, predicted.
  void relink(int prev, int next, int vertex, const Vec2& at, double z, int depth);
  void mergeColinear(int c, double z, int depth);
  bool samePiece(int A, int B) const;

  // The event queue (event_queue.cpp).
  void predict(int corner);
  void predictAgainst(const std::vector<int>& planes);

  // A generalized intersection event (Sec. 4.4), step by step: intersection_event.cpp finds
  // and places it, chains.cpp changes the plan, post_inter_chain.cpp checks the result.
  bool handleIntersection(const Candidate& cand);
  // Event clustering: the live corners whose paths pass within δ2 of the candidate's point
  // within δ1 of its height (arriving_, inK_), and l, their mean. False: no event there.
  bool clusterEvent(const Candidate& cand, Vec2& l);
  // Filtering invalid events: the edges through l (involvedList_, involved_), among them the
  // edges l splits (splitList_). False where what remains is no event.
  bool filterEvent(const Vec2& l, double z);
  // Moves l to the least-squares meeting point of the involved lines, where that is better.
  void placeEvent(Vec2& l, double z) const;
  // Throws Error where events at one point or height feed themselves (the pathological
  // inputs of Sec. 4.4's clustering).
  void refuseCascades(const Vec2& l, double z);
  // Chain construction: the open chains (chains_) and the interior edges of each (interior_).
  void buildChains();
  // The intra-chain stage: interior edges and closed chains leave the plan.
  void intraChain();
  // The inter-chain stage: chains of one edge are split at l, then adjacent chains are linked
  // by new corners at vertex vl (newCorners_). False where no chain is left.
  bool interChain(int vl, const Vec2& l, double z);
  // Post inter-chain check: the corners made at l from corners_[firstMade] on.
  void postInterChain(std::size_t firstMade, int vl, const Vec2& l, double z);
  // Do the corners an event made at l keep the active plan simple up to maxRise above it?
  // False where their wedges overlap or their edges cross.
  bool locallySimple(const std::vector<int>& made, const Vec2& l, double z, double maxRise) const;

  // Edge direction events (direction_events.cpp).
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
  std::vector<int> signature_, newCorners_, made_, interior_;
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

inline Vec2 Sweeper::cornerAt(int ci, double z) const {
  const Corner& c = corners_[ci];
  if (c.parallel) return c.p0 + c.v * (z - c.z0);
  const Edge& a = edges_[c.prev];
  const Edge& b = edges_[c.next];
  const double det = cross2(a.n, b.n);
  const double ra = a.c + a.k * z, rb = b.c + b.k * z;
  return Vec2((ra * b.n[1] - rb * a.n[1]) / det, (a.n[0] * rb - b.n[0] * ra) / det);
}

inline Vec2 Sweeper::liveAt(int ci, double z) const { return cornerAt(ci, std::max(z, corners_[ci].z0)); }

}  // namespace corbel::extrude::sweeping
