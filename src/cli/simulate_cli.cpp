// corbel-cli simulate: build the masonry model, run the collapse simulation with the requested
// perturbations, render frames, print the summary.
#include "cli/simulate_cli.h"

#include "cli/guarded.h"
#include "core/error.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "render/headless_context.h"
#include "sim/posed_mesh.h"
#include "sim/session.h"
#include "statics/examples.h"
#include "statics/kernel.h"

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

const char* const kSimulateUsage = R"(  corbel-cli simulate PROJECT [--object NAME] | --example NAME [--set NAME=V ...]
                    [--seconds S] [--shake V|paper] [--remove BLOCK ...] [--break BLOCK ...]
                    [--drop BLOCK [--drop-mass KG] [--drop-height M]] [--at T] [--friction A]
                    [--frames DIR [--fps N] [--size WxH]]
                    Rigid-body simulation of a masonry model (Bullet; docs/sim.md) for S
                    seconds (default 5). At time T (default 0): a ground shake of V m/s along
                    x within 1/60 s ("paper": the paper's 4 m/s on 10 m, scaled to the
                    model), blocks removed or broken along a 45° crack, a stone dropped on a
                    block. Prints a JSON summary (largest displacement per block, fallen
                    blocks); --frames writes PNGs.
)";

namespace {

struct UsageError : Error {
  using Error::Error;
};

struct Request {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;              // the last value of each option
  std::map<std::string, std::vector<std::string>> lists;  // every value of --set, --remove and --break
  const std::vector<std::string>& list(const std::string& name) const {
    static const std::vector<std::string> none;
    const auto it = lists.find(name);
    return it == lists.end() ? none : it->second;
  }
};

// Every option takes a value; --set, --remove and --break may repeat.
Request parse(int argc, char** argv) {
  static const std::set<std::string> kSingle = {"--object",   "--example",   "--seconds",     "--shake",
                                                "--drop",     "--drop-mass", "--drop-height", "--at",
                                                "--friction", "--frames",    "--fps",         "--size"};
  static const std::set<std::string> kRepeated = {"--set", "--remove", "--break"};
  Request r;
  int i = 2;
  while (i < argc) {
    const std::string word = argv[i++];
    if (word.rfind("--", 0) != 0) {
      r.positional.push_back(word);
    } else if (!kSingle.count(word) && !kRepeated.count(word)) {
      throw UsageError("simulate: unknown option " + word);
    } else if (i == argc) {
      throw UsageError("simulate: " + word + " needs a value");
    } else if (kRepeated.count(word)) {
      r.lists[word].push_back(argv[i++]);
    } else {
      r.values[word] = argv[i++];
    }
  }
  return r;
}

double numberOf(const std::string& option, const std::string& text, double lo, double hi, const char* expected) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
    throw UsageError(option + ": expected " + expected + ", got '" + text + "'");
  return v;
}

double option(const Request& r, const std::string& name, double def, double lo, double hi, const char* expected) {
  const auto it = r.values.find(name);
  return it == r.values.end() ? def : numberOf(name, it->second, lo, hi, expected);
}

struct Model {
  statics::Assembly assembly;
  std::string label;  // "example NAME" or the object's name
  double friction = 0.7;
};

void applySets(const Request& r, statics::ParameterSet& values) {
  for (const std::string& s : r.list("--set")) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw UsageError("--set: expected NAME=VALUE, got '" + s + "'");
    values.set(s.substr(0, eq), numberOf("--set " + s.substr(0, eq), s.substr(eq + 1), -1e300, 1e300, "a number"));
  }
}

Model modelFrom(const Request& r) {
  Model m;
  if (r.values.count("--example")) {
    if (!r.positional.empty()) throw UsageError("simulate: give a PROJECT or --example NAME, not both");
    if (r.values.count("--object"))
      throw UsageError("simulate: --object names an object of a PROJECT, not of an example");
    const statics::ParametricModel model = statics::exampleByName(r.values.at("--example"));
    statics::ParameterSet values = model.parameters;
    applySets(r, values);
    m.assembly = model.build(values);
    m.label = "example " + model.name;
    return m;
  }
  if (r.positional.size() != 1) throw UsageError("simulate: expected one PROJECT or --example NAME");
  const std::string& path = r.positional[0];
  const LoadedProject p = loadProject(path);
  for (const auto& w : p.warnings) std::cerr << "corbel-cli: warning: " << path << ": " << w << "\n";
  const std::string only = r.values.count("--object") ? r.values.at("--object") : "";
  std::vector<const DocObject*> masonry;
  for (const DocObject& o : p.document.objects)
    if (std::holds_alternative<MasonrySpec>(o.spec) && (only.empty() || o.name == only)) masonry.push_back(&o);
  if (masonry.empty())
    throw Error(path + (only.empty() ? ": not a masonry project (it has no masonry object to simulate)"
                                     : ": no masonry object named \"" + only + "\""));
  if (masonry.size() > 1) {
    std::string names;
    for (const DocObject* o : masonry) names += (names.empty() ? "\"" : ", \"") + o->name + "\"";
    throw Error(path + ": several masonry objects (" + names + "); choose one with --object NAME");
  }
  const auto& spec = std::get<MasonrySpec>(masonry[0]->spec);
  statics::ParametricModel model;
  try {
    model = statics::modelOf(spec);
  } catch (const InputError& e) {
    throw InputError(masonry[0]->name + ": " + e.where, e.reason);
  }
  statics::ParameterSet values = model.parameters;
  applySets(r, values);
  m.assembly = model.build(values);
  m.label = masonry[0]->name;
  m.friction = spec.friction;
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

int simulate(const Request& r) {
  const double seconds = option(r, "--seconds", 5.0, 0, 1e5, "a number of seconds ≥ 0");
  const double at = option(r, "--at", 0.0, 0, 1e5, "a time in seconds ≥ 0");
  if (at > seconds) throw UsageError("--at: the perturbation time is after the end (--seconds)");
  const double fps = option(r, "--fps", 30, 1, 240, "frames per second in 1..240");
  int width = 640, height = 480;
  if (r.values.count("--size")) {
    const std::string& s = r.values.at("--size");
    const auto x = s.find('x');
    if (x == std::string::npos) throw UsageError("--size: expected WxH, like 640x480");
    width = int(numberOf("--size", s.substr(0, x), 16, 4096, "WxH with sides in 16..4096"));
    height = int(numberOf("--size", s.substr(x + 1), 16, 4096, "WxH with sides in 16..4096"));
  }
  if (!r.values.count("--drop") && (r.values.count("--drop-mass") || r.values.count("--drop-height")))
    throw UsageError("simulate: --drop-mass and --drop-height need --drop BLOCK");

  const Model model = modelFrom(r);
  sim::SimSettings settings;
  settings.friction = option(r, "--friction", model.friction, 0, 100, "a friction coefficient in [0, 100]");
  sim::Session session(model.assembly, settings);
  const BBox moving = sim::movingBounds(model.assembly);

  // Check every block name before any work, so a typo fails at once.
  std::vector<int> removes;
  std::vector<int> breaks;
  for (const char* option : {"--remove", "--break"})
    for (const std::string& name : r.list(option)) {
      (std::string(option) == "--remove" ? removes : breaks).push_back(session.blockIndex(name));
      if (model.assembly.blocks[session.blockIndex(name)].fixed)
        throw Error(std::string(option) + ": block \"" + name + "\" is fixed (the ground) and stays");
    }
  const int dropOn = r.values.count("--drop") ? session.blockIndex(r.values.at("--drop")) : -1;
  const double dropMass = option(r, "--drop-mass", 100, 1e-6, 1e9, "a mass in kg > 0");
  const double dropHeight = option(r, "--drop-height", 0.5, 0, 1e4, "a height in m ≥ 0");
  double shakeVelocity = 0, shakeDuration = sim::kPaperShakeDuration;
  if (r.values.count("--shake")) {
    if (r.values.at("--shake") == "paper") {
      const sim::ShakeSpec paper = sim::paperShake(model.assembly);
      shakeVelocity = paper.velocity;
      shakeDuration = paper.duration;
    } else {
      shakeVelocity = numberOf("--shake", r.values.at("--shake"), -1e3, 1e3, "a velocity in m/s or 'paper'");
    }
  }

  std::unique_ptr<FrameWriter> frames;
  if (r.values.count("--frames")) {
    BBox view = moving;
    view.add(Vec3(moving.lo[0], moving.lo[1], 0.0));
    frames = std::make_unique<FrameWriter>(r.values.at("--frames"), width, height, view);
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
  out["frames"] = frames ? frames->count() : 0;
  out["wall_seconds"] = wall;
  out["simulated_seconds_per_wall_second"] = simulatedWall > 0 ? session.time() / simulatedWall : 0.0;
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace

int runSimulate(int argc, char** argv) {
  return guarded<UsageError>([&] { return simulate(parse(argc, argv)); });
}

}  // namespace corbel::cli
