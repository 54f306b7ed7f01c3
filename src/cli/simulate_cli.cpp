// corbel-cli simulate: build the masonry model, run the collapse simulation with the requested
// perturbations, render frames, print the summary.
#include "cli/guarded.h"
#include "cli/run.h"
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "render/headless_context.h"
#include "sim/posed_mesh.h"
#include "sim/session.h"
#include "statics/examples.h"
#include "statics/kernel.h"
#include "compose/stone_extrusion.h"
#include "statics/thresholds.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace corbel::cli {

namespace {

double numberOf(const std::string& option, const std::string& text, double lo, double hi, const char* expected) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
    throw UsageError(option + ": expected " + expected + ", got '" + text + "'");
  return v;
}

struct Model {
  statics::Assembly assembly;
  std::string label;  // "example NAME" or the object's name
  double friction = 0.7;
  double kern = 0.0;  // the kern shrink the design is analysed with (the object's; 0 for an example)
};

void applySets(const SimulateRequest& r, statics::ParameterSet& values) {
  for (const std::string& s : r.sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw UsageError("--set: expected NAME=VALUE, got '" + s + "'");
    values.set(s.substr(0, eq), numberOf("--set " + s.substr(0, eq), s.substr(eq + 1), -1e300, 1e300, "a number"));
  }
}

Model modelFrom(const SimulateRequest& r) {
  Model m;
  if (!r.example.empty()) {
    const statics::ParametricModel model = statics::exampleByName(r.example);
    statics::ParameterSet values = model.parameters;
    applySets(r, values);
    m.assembly = model.build(values);
    m.label = "example " + model.name;
    return m;
  }
  if (r.project.empty()) throw UsageError("simulate: expected one PROJECT or --example NAME");
  const std::string& path = r.project;
  const LoadedProject p = loadProject(path);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << path << ": " << w << "\n";
  const std::string& only = r.object;
  std::vector<const DocObject*> masonry;
  for (const DocObject& o : p.document.objects) {
    const auto* e = std::get_if<ExtrusionSpec>(&o.spec);
    if ((std::holds_alternative<MasonrySpec>(o.spec) || (e && e->masonry)) && (only.empty() || o.name == only))
      masonry.push_back(&o);
  }
  if (masonry.empty())
    throw Error(path + (only.empty() ? ": not a masonry project (it has no masonry object to simulate)"
                                     : ": no masonry object named \"" + only + "\""));
  if (masonry.size() > 1) {
    std::string names;
    for (const DocObject* o : masonry) names += (names.empty() ? "\"" : ", \"") + o->name + "\"";
    throw Error(path + ": several masonry objects (" + names + "); choose one with --object NAME");
  }
  // A masonry object, or an extrusion built in stone (its walls coursed, loaded by its roof).
  const DocObject& o = *masonry[0];
  const auto* stone = std::get_if<ExtrusionSpec>(&o.spec);
  statics::ParametricModel model;
  try {
    model = stone ? statics::stoneModel(*stone) : statics::modelOf(std::get<MasonrySpec>(o.spec));
  } catch (const InputError& err) {
    throw InputError(o.name + ": " + (stone ? "extrusion." : "") + err.where, err.reason);
  }
  statics::ParameterSet values = model.parameters;
  applySets(r, values);
  m.assembly = model.build(values);
  m.label = o.name;
  if (const auto* spec = std::get_if<MasonrySpec>(&o.spec)) {
    m.friction = spec->friction;
    m.kern = spec->kern;
  }
  return m;
}

// Renders the session's current state into DIR/frame-NNNN.png.
class FrameWriter {
 public:
  FrameWriter(std::filesystem::path dir, int width, int height, const BBox& view)
      : dir_(std::move(dir)), width_(width), height_(height) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw Error("--frames: cannot create " + dir_.string() + ": " + ec.message());
    camera_.frame(view, double(width) / height);
    camera_.azimuth_deg = -60;
    camera_.elevation_deg = 20;
  }
  void write(const sim::Session& s) {
    scene_.replaceObject(1, Kind::Block, "simulation", sim::posedMesh(s));
    render::RenderSettings settings;
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", count_++);
    render::writePng(render::renderImage(renderer_, scene_, camera_, width_, height_, settings),
                     (dir_ / name).string());
  }
  int count() const { return count_; }

 private:
  std::filesystem::path dir_;
  int width_, height_, count_ = 0;
  render::HeadlessContext context_;
  render::Renderer renderer_;
  render::OrbitCamera camera_;
  Scene scene_;
};

// The resolution of the kern margin simulate reports (an LP bisection over [0, 0.95]).
constexpr double kKernMarginStep = 0.01;

}  // namespace

int run(const SimulateRequest& r) {
  const double seconds = r.seconds, at = r.at, fps = r.fps;
  if (at > seconds) throw UsageError("--at: the perturbation time is after the end (--seconds)");
  const int width = r.size.width, height = r.size.height;

  const Model model = modelFrom(r);
  sim::SimSettings settings;
  settings.friction = r.friction.value_or(model.friction);
  settings.solver = r.solver == "qp" ? sim::Solver::ContactQp : sim::Solver::SequentialImpulse;
  sim::Session session(model.assembly, settings);
  const BBox moving = sim::movingBounds(model.assembly);

  // Check every block name before any work, so a typo fails at once.
  std::vector<int> removes;
  std::vector<int> breaks;
  for (const auto& [option, names] : {std::pair{"--remove", &r.removes}, {"--break", &r.breaks}})
    for (const std::string& name : *names) {
      (names == &r.removes ? removes : breaks).push_back(session.blockIndex(name));
      if (model.assembly.blocks[session.blockIndex(name)].fixed)
        throw Error(std::string(option) + ": block \"" + name + "\" is fixed (the ground) and stays");
    }
  const int dropOn = r.drop.empty() ? -1 : session.blockIndex(r.drop);
  const double dropMass = r.dropMass, dropHeight = r.dropHeight;
  double shakeVelocity = 0, shakeDuration = sim::kPaperShakeDuration;
  if (!r.shake.empty()) {
    if (r.shake == "paper") {
      const sim::ShakeSpec paper = sim::paperShake(model.assembly);
      shakeVelocity = paper.velocity;
      shakeDuration = paper.duration;
    } else {
      shakeVelocity = numberOf("--shake", r.shake, -1e3, 1e3, "a velocity in m/s or 'paper'");
    }
  }

  std::unique_ptr<FrameWriter> frames;
  if (!r.frames.empty()) {
    BBox view = moving;
    view.add(Vec3(moving.lo[0], moving.lo[1], 0.0));
    frames = std::make_unique<FrameWriter>(r.frames, width, height, view);
  }
  const auto start = std::chrono::steady_clock::now();
  double simulatedWall = 0;  // wall time spent stepping, without rendering
  auto runTo = [&](double t) {
    const auto t0 = std::chrono::steady_clock::now();
    session.runUntil(t);
    simulatedWall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  bool perturbed = false;
  auto perturb = [&] {
    if (shakeVelocity != 0) session.shake(Vec3(shakeVelocity, 0, 0), shakeDuration);
    for (int b : removes) session.removeBlock(b);
    for (int b : breaks) session.breakBlock(b);
    if (dropOn >= 0) session.dropLoad(dropOn, dropMass, dropHeight);
    perturbed = true;
  };
  if (frames) {
    for (int k = 0;; ++k) {
      const double t = std::min(k / fps, seconds);
      if (!perturbed && at <= t) {
        runTo(at);
        perturb();
      }
      runTo(t);
      frames->write(session);
      if (t >= seconds) break;
    }
  } else {
    runTo(at);
    perturb();
    runTo(seconds);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto& blocks = model.assembly.blocks;
  nlohmann::ordered_json out;
  out["model"] = model.label;
  out["blocks"] = blocks.size();
  out["seconds"] = session.time();
  out["step"] = settings.timeStep;
  out["steps"] = session.steps();
  out["solver"] = r.solver;
  if (settings.solver == sim::Solver::ContactQp)
    out["qp"] = {{"iterations", session.qpIterations()}, {"fallback_steps", session.qpFailures()}};
  out["perturbed_at"] = at;
  out["shake"] = {{"velocity", shakeVelocity}, {"duration", shakeVelocity != 0 ? shakeDuration : 0.0}};
  nlohmann::ordered_json removed = nlohmann::json::array(), fallen = nlohmann::json::array();
  for (int b : removes) removed.push_back(blocks[b].name);
  out["removed"] = removed;
  nlohmann::ordered_json broken = nlohmann::json::array();
  for (int b : breaks) broken.push_back(blocks[b].name);
  out["broken"] = broken;
  if (dropOn >= 0) out["drop"] = {{"block", blocks[dropOn].name}, {"mass", dropMass}, {"height", dropHeight}};
  for (int b : session.fallenBlocks()) fallen.push_back(blocks[b].name);
  out["fallen_count"] = fallen.size();
  out["fallen"] = fallen;
  double largest = 0;
  nlohmann::ordered_json perBlock;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (blocks[i].fixed) continue;
    perBlock[blocks[i].name] = session.maxDisplacement()[i];
    if (!session.removed(int(i))) largest = std::max(largest, session.maxDisplacement()[i]);
  }
  out["largest_displacement"] = largest;
  out["max_displacement"] = perBlock;
  // What the statics analysis says of the design with the simulation's friction: whether it
  // stands at its kern (strict LP) and its kern margin, the largest kern shrink at which it
  // still stands (to 0.01). A design that stands only with the thrust on its joints' edges has
  // no margin, and the simulation may settle or hinge where the analysis calls it standing.
  statics::AnalysisOptions staticsOptions;
  staticsOptions.friction = settings.friction;
  staticsOptions.kernShrink = model.kern;
  const bool standsAtKern = statics::checkFeasibility(model.assembly, staticsOptions).feasible;
  const double margin = statics::largestKernMargin(model.assembly, staticsOptions, kKernMarginStep);
  nlohmann::ordered_json st;
  st["kern"] = model.kern;
  st["stands"] = standsAtKern;
  st["kern_margin"] = margin < 0 ? nlohmann::json(nullptr) : nlohmann::json(margin);
  std::string note;
  if (margin < 0)
    note = "the statics analysis says it does not stand, even with no kern margin";
  else if (margin < kKernMarginStep)
    note = "no kern margin: it stands only with the thrust on its joints' edges (kern 0)";
  if (!note.empty()) {
    st["note"] = note;
    std::cerr << "corbel-cli: simulate: " << model.label << ": " << note << "\n";
  }
  out["statics"] = st;
  out["frames"] = frames ? frames->count() : 0;
  out["wall_seconds"] = wall;
  out["simulated_seconds_per_wall_second"] = simulatedWall > 0 ? session.time() / simulatedWall : 0.0;
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace corbel::cli
