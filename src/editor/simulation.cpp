#include "editor/simulation.h"

#include "core/error.h"
#include "sim/posed_mesh.h"
#include "statics/kernel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace corbel::editor {

namespace {

statics::Assembly designOf(const MasonrySpec& spec) {
  const statics::ParametricModel model = statics::modelOf(spec);
  return model.build(model.parameters);
}

sim::SimSettings settingsOf(const MasonrySpec& spec) {
  sim::SimSettings s;
  s.friction = spec.friction;
  return s;
}

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Simulation::Simulation(const MasonrySpec& spec, Clock clock)
    : spec_(spec), session_(designOf(spec), settingsOf(spec)), clock_(clock ? std::move(clock) : Clock(steadySeconds)) {
  show(capture());
}

Simulation::~Simulation() {
  if (batch_.valid()) batch_.wait();
}

Simulation::State Simulation::capture() const {
  State st;
  st.time = session_.time();
  st.steps = session_.steps();
  st.poses = session_.poses();
  st.removed.resize(session_.design().blocks.size());
  for (std::size_t b = 0; b < st.removed.size(); ++b) st.removed[b] = session_.removed(int(b));
  const auto& d = session_.maxDisplacement();
  st.largest = d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
  st.fallen = int(session_.fallenBlocks().size());
  st.mesh = sim::posedMesh(session_, spec_.material);
  return st;
}

void Simulation::show(State state) {
  shown_ = std::move(state);
  ++revision_;
}

void Simulation::finish() {
  if (batch_.valid()) show(batch_.get());
}

void Simulation::play() {
  finish();
  playing_ = true;
}

void Simulation::pause() {
  finish();
  playing_ = false;
}

void Simulation::step(int steps) {
  finish();
  session_.step(steps);
  show(capture());
}

int Simulation::advance(double wallSeconds, double budget) {
  if (batch_.valid()) {
    if (batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return 0;
    const long before = shown_.steps;
    finish();
    return int(shown_.steps - before);
  }
  if (!playing_ || !(wallSeconds > 0)) return 0;
  const double dt = session_.settings().timeStep;
  // Steps due: the frame's wall time plus what earlier frames left over (under one step).
  pending_ += wallSeconds;
  const long due = long(std::floor(pending_ / dt));
  pending_ -= double(due) * dt;
  if (due == 0) return 0;
  if (stepCost_ > budget) {
    // One step would overrun the frame: the worker takes as many as one step costs frames of
    // this length, at least one, and the window goes on drawing the last state meanwhile.
    const long n = std::max(1L, std::min(due, long(wallSeconds / stepCost_)));
    pending_ = 0;
    batch_ = std::async(std::launch::async, [this, n] {
      const double t0 = clock_();
      session_.step(int(n));
      stepCost_ = (clock_() - t0) / double(n);
      return capture();
    });
    return 0;
  }
  const double start = clock_();
  double last = start;
  long taken = 0;
  while (taken < due) {
    session_.step(1);
    ++taken;
    const double now = clock_();
    stepCost_ = now - last;
    last = now;
    if (now - start >= budget) break;
  }
  if (taken < due) pending_ = 0;  // out of budget: drop the backlog
  show(capture());
  return int(taken);
}

void Simulation::reset() {
  finish();
  session_.reset();
  playing_ = false;
  pending_ = 0;
  show(capture());
}

void Simulation::shake() {
  finish();
  const sim::ShakeSpec s = sim::paperShake(session_.design());
  session_.shake(Vec3(s.velocity, 0, 0), s.duration);
}

void Simulation::removeBlock(const std::string& name) {
  finish();
  const int b = session_.blockIndex(name);
  if (session_.design().blocks[b].fixed) throw Error("block \"" + name + "\" is fixed (the ground) and stays");
  if (session_.removed(b)) throw Error("block \"" + name + "\" was already removed");
  session_.removeBlock(b);
  show(capture());
}

std::vector<std::string> Simulation::removableBlocks() const {
  std::vector<std::string> names;
  const auto& blocks = session_.design().blocks;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!blocks[i].fixed && !shown_.removed[i]) names.push_back(blocks[i].name);
  return names;
}

std::string Simulation::topBlock() const {
  std::string best;
  double top = -std::numeric_limits<double>::infinity();
  const auto& blocks = session_.design().blocks;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (blocks[i].fixed || shown_.removed[i]) continue;
    for (const Vec3& v : blocks[i].vertices)
      if (v[2] > top) {
        top = v[2];
        best = blocks[i].name;
      }
  }
  return best;
}

int Simulation::blockAt(const Vec3& origin, const Vec3& direction) const {
  int best = -1;
  double nearest = std::numeric_limits<double>::infinity();
  const auto& blocks = session_.design().blocks;
  std::vector<Vec3> posed, face;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (shown_.removed[i]) continue;
    posed.clear();
    for (const Vec3& v : blocks[i].vertices) posed.push_back(shown_.poses[i].apply(v));
    // A convex block is where the ray is behind every face's plane: clip [0, ∞) by each.
    double enter = 0, leave = std::numeric_limits<double>::infinity();
    for (const auto& f : blocks[i].faces) {
      face.clear();
      for (int v : f) face.push_back(posed[v]);
      const Vec3 n = newellNormal(face);  // outward: the loops are counter-clockwise from outside
      const double along = n.dot(direction), offset = n.dot(posed[f[0]] - origin);
      if (along == 0) {
        if (offset < 0) enter = leave;  // parallel and outside
      } else if (along < 0) {
        enter = std::max(enter, offset / along);
      } else {
        leave = std::min(leave, offset / along);
      }
      if (enter >= leave) break;
    }
    if (enter < leave && enter < nearest) {
      nearest = enter;
      best = int(i);
    }
  }
  return best;
}

void showSimulation(Scene& scene, ObjectId id, const Simulation& simulation, const Placement& placement) {
  const auto it = scene.objects().find(id);
  const Kind kind = it == scene.objects().end() ? Kind::Block : it->second.kind;
  const std::string name = it == scene.objects().end() ? std::string() : it->second.name;
  MeshData mesh = simulation.mesh();
  applyPlacement(mesh, placement);  // the object's placement, as its design is shown
  scene.replaceObject(id, kind, name, mesh);
}

}  // namespace corbel::editor
