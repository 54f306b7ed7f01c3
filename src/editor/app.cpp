#include "editor/app.h"

#include "core/error.h"
#include "core/export.h"
#include "core/materials.h"
#include "core/project_io.h"
#include "extrude/edit.h"
#include "extrude/kernel.h"
#include "growth/kernel.h"
#include "kifs/kernel.h"
#include "render/gl.h"
#include "render/image.h"
#include "render/kifs_layer.h"
#include "statics/kernel.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace corbel::editor {

namespace {

constexpr float kLeftPanelWidth = 320.0f;
constexpr float kStatusBarHeight = 118.0f;
constexpr float kPaneWidth = 460.0f;          // the plan and profile panes, right of the 3D view
constexpr float kGrowthPanelHeight = 470.0f;  // over the form completion panel

std::string stateDirOr(const std::string& dir) { return dir.empty() ? defaultStateDir() : dir; }

}  // namespace

App::App(GLFWwindow* window, EditorOptions options)
    : window_(window),
      options_(std::move(options)),
      recovery_(stateDirOr(options_.stateDir)),
      recent_(stateDirOr(options_.stateDir) + "/recent.json") {
  extrude::registerKernel(sync_);
  statics::registerKernel(sync_);
  kifs::registerKernel(sync_);
  {
    std::string why;
    glMaps_ = makeEditorGlViewMapper(kEditorViewMapPixel, &why);
    if (!glMaps_) log("GL view maps unavailable (" + why + "): growth grows on the exact CPU maps", true);
    growOnGl_ = glMaps_ && glViewMaps_;
  }
  growth::registerKernelWith(sync_, [this] { return growthMapper(); });
  townCache_ = city::registerKernel(sync_);
  renderer_ = std::make_unique<render::Renderer>();
  log("OpenGL " + render::glDescription());
  registerActions();
  lastAutosave_ = std::chrono::steady_clock::now();
  Document doc;
  history_.reset(doc);
  if (!options_.project.empty()) {
    try {
      LoadedProject p = loadProject(options_.project);
      for (const auto& w : p.warnings) log("warning: " + w);
      history_.reset(std::move(p.document));
      path_ = options_.project;
      recent_.add(path_);
      log("Opened " + path_);
    } catch (const std::exception& e) {
      errorMessage_ = e.what();
      showError_ = true;
      log(e.what(), true);
    }
  }
  if (!options_.script.empty()) {
    std::ifstream in(options_.script);
    if (!in) log("cannot read the edit script " + options_.script, true), scriptFailed_ = true;
    for (std::string line; std::getline(in, line);) scriptLines_.push_back(line);
    if (!options_.scriptShots.empty()) std::filesystem::create_directories(options_.scriptShots);
  }
  if (!options_.select.empty()) {
    if (const DocObject* o = history_.current().findByName(options_.select))
      selected_ = o->id;
    else
      log("--select: the project has no object named \"" + options_.select + "\"", true);
  }
  syncScene(true);
  frameAll();
  checkRecovery();
}

App::~App() = default;

void App::log(const std::string& line, bool error) {
  log_.push_back({line, error});
  while (log_.size() > 200) log_.pop_front();
}

// ---------------------------------------------------------------- document and files

void App::commit(Document doc, const std::string& label, const std::string& mergeKey) {
  history_.commit(std::move(doc), label, mergeKey);
}

bool App::scripted() const {
  return !scriptLines_.empty() || !options_.actions.empty() || options_.quitAfterFrames > 0 ||
         !options_.screenshot.empty();
}

std::shared_ptr<growth::ViewMapper> App::growthMapper() const {
  return growOnGl_ ? std::shared_ptr<growth::ViewMapper>(glMaps_) : nullptr;
}

std::string App::growthMapsName() const { return growOnGl_ ? glMapsName(glMaps_->pixelSize()) : "exact"; }

void App::applyViewMapSetting() {
  const bool want = glMaps_ && glViewMaps_;
  const bool newPixel = want && glMaps_->pixelSize() != glPixel_;
  if ((want == growOnGl_ && !newPixel) || live_.building()) return;
  // The growth objects' builds read growOnGl_ and the mapper's pixel; none runs now, so each is
  // rebuilt on the new maps by the next update (the Document does not change: not an undo step).
  if (newPixel) glMaps_->setPixelSize(glPixel_);
  growOnGl_ = want;
  for (const DocObject& o : history_.current().objects)
    if (std::holds_alternative<GrowthSpec>(o.spec)) sync_.invalidate(o.id);
  live_.refresh();
  log(std::string("Growth: view maps ") + (want ? glMapsName(glPixel_) : "exact (CPU)"), false);
}

void App::syncScene(bool wait) {
  if (selected_ && !history_.current().find(*selected_)) selected_.reset();
  applyViewMapSetting();
  if (wait || scripted())
    live_.settle(history_.current(), history_.stateId(), scene_);
  else if (!live_.update(history_.current(), history_.stateId(), scene_))
    return;
  // Kernel messages go to the log once per change; a failed object keeps its last good shell.
  for (const auto& [id, st] : sync_.status()) {
    const DocObject* o = history_.current().find(id);
    const std::string name = o ? o->name : std::to_string(id);
    std::string text = st.error.empty() ? std::string() : name + ": " + st.error;
    for (const auto& w : st.warnings) text += (text.empty() ? name + ": " : "; ") + w;
    auto& last = reported_[id];
    if (text != last) {
      if (!text.empty()) log(text, !st.error.empty());
      last = text;
    }
  }
}

void App::frameAll() {
  BBox box;
  for (const DocObject& o : history_.current().objects)
    if (o.visible) box.add(scene_.bounds(o.id));
  box.add(render::raymarchedKifs(history_.current(), settings_.visible).bounds);
  camera_.frame(box, vpW_ / std::max(vpH_, 1.0f));
}

void App::guardUnsaved(std::function<void()> then) {
  if (!history_.dirty()) {
    then();
    return;
  }
  afterUnsavedPrompt_ = std::move(then);
  showUnsavedPrompt_ = true;
}

void App::newDocument() {
  guardUnsaved([this] {
    history_.reset(Document{});
    path_.clear();
    selected_.reset();
    recovery_.discard();
    syncScene(true);
    frameAll();
    log("New document");
  });
}

void App::openFile(const std::string& path) {
  guardUnsaved([this, path] {
    auto result = std::make_shared<LoadedProject>();
    startJob(
        "Opening " + std::filesystem::path(path).filename().string(),
        [result, path](Progress& progress) {
          progress.report(0.1, "reading");
          *result = loadProject(path);
          progress.report(1.0, "done");
        },
        [this, result, path] {
          for (const auto& w : result->warnings) log("warning: " + w);
          history_.reset(std::move(result->document));
          path_ = path;
          selected_.reset();
          recent_.add(path);
          recovery_.discard();
          syncScene(true);
          frameAll();
          log("Opened " + path);
        });
  });
}

bool App::saveTo(const std::string& path) {
  try {
    Document doc = history_.current();
    if (doc.name == "untitled" || doc.name.empty()) doc.name = std::filesystem::path(path).stem().string();
    saveProject(doc, path);
    path_ = path;
    history_.markSaved();
    recent_.add(path);
    recovery_.discard();
    log("Saved " + path);
    return true;
  } catch (const std::exception& e) {
    errorMessage_ = std::string("Could not save: ") + e.what();
    showError_ = true;
    log(errorMessage_, true);
    return false;
  }
}

void App::save() {
  if (path_.empty())
    saveAs();
  else
    saveTo(path_);
}

void App::saveAs() {
  fileDialog_.open(FileDialog::Mode::Save, "Save project as", {".corbel"}, path_,
                   [this](const std::string& p) { saveTo(p); });
}

void App::exportScene() {
  std::string start =
      path_.empty() ? std::string("scene.glb") : std::filesystem::path(path_).replace_extension(".glb").string();
  fileDialog_.open(FileDialog::Mode::Save, "Export scene", {".glb", ".obj", ".ply", ".off"}, start,
                   [this](const std::string& p) {
                     auto snapshot = std::make_shared<Scene>(scene_);
                     std::vector<ObjectId> visible;
                     for (const DocObject& o : history_.current().objects)
                       if (o.visible) visible.push_back(o.id);
                     startJob(
                         "Exporting " + std::filesystem::path(p).filename().string(),
                         [snapshot, visible, p](Progress& progress) {
                           progress.report(0.2, "writing");
                           ExportOptions opt;
                           opt.include = [visible](ObjectId id) {
                             return std::find(visible.begin(), visible.end(), id) != visible.end();
                           };
                           corbel::exportScene(*snapshot, p, opt);
                           progress.report(1.0, "done");
                         },
                         [this, p] { log("Exported " + p); });
                   });
}

void App::autosaveIfDue() {
  if (!history_.dirty() || history_.stateId() == autosavedState_) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - lastAutosave_).count() < options_.autosaveSeconds) return;
  lastAutosave_ = now;
  try {
    recovery_.write(history_.current(), path_);
    autosavedState_ = history_.stateId();
    log("Autosaved to " + recovery_.documentPath());
  } catch (const std::exception& e) {
    log(std::string("Autosave failed: ") + e.what(), true);
  }
}

void App::checkRecovery() {
  std::string problem;
  auto found = recovery_.find(&problem);
  if (!problem.empty()) log("A recovery file exists but cannot be read: " + problem, true);
  if (!found) return;
  switch (options_.recover) {
    case EditorOptions::Recover::No:
      recovery_.discard();
      break;
    case EditorOptions::Recover::Yes:
      history_.reset(Document{});
      commit(found->document, "Recover unsaved work");
      path_ = found->originalPath;
      syncScene(true);
      frameAll();
      log("Recovered unsaved work from " + found->savedAt);
      break;
    case EditorOptions::Recover::Ask:
      recoveryOffer_ = std::move(found);
      break;
  }
}

// ---------------------------------------------------------------- jobs

void App::startJob(std::string title, BackgroundJob::Work work, std::function<void()> onDone) {
  if (job_) {
    log("Busy with " + job_->title() + "; try again when it finishes.", true);
    return;
  }
  log(title + "…");
  job_ = std::make_unique<BackgroundJob>(std::move(title), std::move(work));
  jobDone_ = std::move(onDone);
}

void App::pollJob() {
  if (!job_ || !job_->finished()) return;
  job_->wait();
  std::unique_ptr<BackgroundJob> job = std::move(job_);
  auto done = std::move(jobDone_);
  try {
    job->rethrow();
    if (job->progress().cancelled())
      log(job->title() + ": cancelled");
    else if (done)
      done();
  } catch (const Cancelled&) {
    log(job->title() + ": cancelled");
  } catch (const std::exception& e) {
    errorMessage_ = job->title() + " failed:\n" + e.what();
    showError_ = true;
    log(errorMessage_, true);
  }
}

// ---------------------------------------------------------------- actions

void App::registerActions() {
  auto doc = [this] { return history_.current(); };
  auto add = [this](Action a) { actions_.add(std::move(a)); };
  add({"file.new", "File", "New", "Start an empty project.", {GLFW_KEY_N, true}, false, [this] { newDocument(); }});
  add({"file.open", "File", "Open…", "Open a project file (.corbel).", {GLFW_KEY_O, true}, false, [this] {
         guardUnsaved([this] {
           fileDialog_.open(FileDialog::Mode::Open, "Open project", {".corbel"}, path_, [this](const std::string& p) {
             // The unsaved-changes question was already answered.
             history_.markSaved();
             openFile(p);
           });
         });
       }});
  add({"file.save",
       "File",
       "Save",
       "Save the project (atomic: the old file stays intact until the new one is complete).",
       {GLFW_KEY_S, true},
       false,
       [this] { save(); }});
  add({"file.save_as",
       "File",
       "Save As…",
       "Save the project under a new name.",
       {GLFW_KEY_S, true, true},
       false,
       [this] { saveAs(); }});
  add({"file.export",
       "File",
       "Export…",
       "Export the visible objects to glTF (.glb), OBJ, PLY or OFF.",
       {GLFW_KEY_E, true},
       false,
       [this] { exportScene(); },
       {},
       {},
       true});
  add({"file.quit",
       "File",
       "Quit",
       "Close corbel (asks before discarding changes).",
       {GLFW_KEY_Q, true},
       false,
       [this] { guardUnsaved([this] { quitRequested_ = true; }); },
       {},
       {},
       true});

  add({"edit.undo",
       "Edit",
       "Undo",
       "Undo the last change to the document.",
       {GLFW_KEY_Z, true},
       false,
       [this] {
         if (history_.undo()) log("Undo");
       },
       [this] { return history_.canUndo(); }});
  add({"edit.redo",
       "Edit",
       "Redo",
       "Redo the change undone last.",
       {GLFW_KEY_Z, true, true},
       false,
       [this] {
         if (history_.redo()) log("Redo");
       },
       [this] { return history_.canRedo(); }});
  add({"edit.redo_y",
       "",
       "Redo",
       "Redo the change undone last (Ctrl+Y, as on Windows).",
       {GLFW_KEY_Y, true},
       false,
       [this] {
         if (history_.redo()) log("Redo");
       },
       [this] { return history_.canRedo(); }});

  add({"object.add_box",
       "Object",
       "Add Box",
       "Add a mass-model box next to the existing objects.",
       {GLFW_KEY_B, true},
       true,
       [this, doc] {
         Document d = doc();
         BoxSpec b;
         BBox box = scene_.bounds();
         if (!box.empty()) b.origin = Vec3(box.hi[0] + 4.0 + b.size[0] / 2, box.center()[1], 0.0);
         const ObjectId id = d.add("Box", b);
         commit(std::move(d), "Add box");
         selected_ = id;
       }});
  add({"object.add_extrusion",
       "Object",
       "Add Extrusion",
       "Add a procedural extrusion (a 12 × 8 m plan on the hip profile) next to the existing objects; edit it in the "
       "plan and profile panes.",
       {GLFW_KEY_X, true, true},
       false,
       [this, doc] {
         Document d = doc();
         ExtrusionSpec e;
         e.profiles.push_back(extrude::edit::profileLibrary()[1]);
         e.roofMaterial = "roof_tile";
         const BBox box = scene_.bounds();
         const double x0 = box.empty() ? 0.0 : box.hi[0] + 4.0, y0 = box.empty() ? 0.0 : box.center()[1] - 4.0;
         e.loops.push_back({{Vec2(x0, y0), Vec2(x0 + 12, y0), Vec2(x0 + 12, y0 + 8), Vec2(x0, y0 + 8)}, {0, 0, 0, 0}});
         const ObjectId id = d.add("Extrusion", e);
         commit(std::move(d), "Add extrusion");
         selected_ = id;
         if (box.empty()) firstFrame_ = true;  // frame the first object of a new scene
       }});
  add({"object.add_kifs",
       "Object",
       "Add KIFS Building",
       "Add a KIFS fractal building (McGraw; the box preset) at the origin; edit it in the KIFS panel.",
       {},
       true,
       [this, doc] {
         Document d = doc();
         const ObjectId id = d.add("KIFS building", kifs::specOf(kifs::preset("box"), "box"));
         commit(std::move(d), "Add KIFS building");
         selected_ = id;
         firstFrame_ = true;
       }});
  add({"object.add_town",
       "Object",
       "Add Town...",
       "Add a town (Kelly & Wonka Sec. 3.7): choose a GeoJSON footprint file; it is styled with "
       "assets/styles/mixed.json until another style is picked in the Town panel.",
       {},
       false,
       [this, doc] {
         fileDialog_.open(FileDialog::Mode::Open, "Open footprints", {".geojson", ".json"}, path_,
                          [this, doc](const std::string& path) {
                            Document d = doc();
                            TownSpec t;
                            t.footprints = path;
                            t.style = std::string(CORBEL_ASSETS_DIR) + "/styles/mixed.json";
                            const ObjectId id = d.add("Town", t);
                            commit(std::move(d), "Add town");
                            selected_ = id;
                            firstFrame_ = true;
                          });
       }});
  add({"object.duplicate",
       "Object",
       "Duplicate",
       "Copy the selected object beside itself.",
       {GLFW_KEY_D, true},
       true,
       [this, doc] {
         Document d = doc();
         const DocObject* o = d.find(*selected_);
         DocObject copy = *o;
         const BBox box = scene_.bounds(copy.id);
         const double shift = box.empty() ? 10.0 : box.size()[0] + 2.0;
         if (auto* b = std::get_if<BoxSpec>(&copy.spec)) b->origin[0] += shift;
         if (auto* e = std::get_if<ExtrusionSpec>(&copy.spec))
           for (auto& loop : e->loops)
             for (auto& p : loop.points) p[0] += shift;
         const ObjectId id = d.add(o->name, copy.spec);
         commit(std::move(d), "Duplicate " + copy.name);
         selected_ = id;
       },
       [this] { return selected_.has_value(); }});
  add({"object.delete",
       "Object",
       "Delete",
       "Delete the selected object.",
       {GLFW_KEY_DELETE},
       true,
       [this, doc] {
         Document d = doc();
         const std::string name = d.find(*selected_)->name;
         d.remove(*selected_);
         selected_.reset();
         commit(std::move(d), "Delete " + name);
       },
       [this] { return selected_.has_value(); }});

  auto preset = [this](render::CameraPreset p) {
    return [this, p] {
      render::applyPreset(camera_, p);
      frameAll();
    };
  };
  add({"view.frame", "View", "Frame All", "Fit the visible objects in the view.", {GLFW_KEY_HOME}, false, [this] {
         frameAll();
       }});
  add({"view.perspective",
       "View",
       "Perspective",
       "Look from above at an angle.",
       {GLFW_KEY_KP_5},
       false,
       preset(render::CameraPreset::Perspective),
       {},
       {},
       true});
  add({"view.front", "View", "Front", "Look along +Y.", {GLFW_KEY_KP_1}, false, preset(render::CameraPreset::Front)});
  add({"view.right", "View", "Right", "Look along −X.", {GLFW_KEY_KP_3}, false, preset(render::CameraPreset::Right)});
  add({"view.top", "View", "Top", "Look straight down.", {GLFW_KEY_KP_7}, false, preset(render::CameraPreset::Top)});
  add({"view.wireframe",
       "View",
       "Wireframe",
       "Draw edges only.",
       {GLFW_KEY_W, false, false, true},
       false,
       [this] { settings_.wireframe = !settings_.wireframe; },
       {},
       [this] { return settings_.wireframe; },
       true});
  add({"view.edges",
       "View",
       "Edges",
       "Outline every face.",
       {},
       false,
       [this] { settings_.edges = !settings_.edges; },
       {},
       [this] { return settings_.edges; }});
  add({"view.grid",
       "View",
       "Ground Grid",
       "Show the ground grid at z = 0.",
       {},
       false,
       [this] { settings_.grid = !settings_.grid; },
       {},
       [this] { return settings_.grid; }});
  // Shadows from a movable sun (Ng, Fig. 8.5); the growth panel's Grow tab has the sun's sliders.
  add({"view.shadows",
       "View",
       "Shadows",
       "Cast shadows from the sun onto the model and the ground.",
       {},
       false,
       [this] { settings_.shadows = !settings_.shadows; },
       {},
       [this] { return settings_.shadows; },
       true});
  add({"view.sun_later", "View", "Sun Later", "Move the sun 15° on (its azimuth, towards +Y).", {}, false, [this] {
         sunAzimuth_ = std::remainder(sunAzimuth_ + 15.0, 360.0);
       }});
  add({"view.sun_earlier", "View", "Sun Earlier", "Move the sun 15° back.", {}, false, [this] {
         sunAzimuth_ = std::remainder(sunAzimuth_ - 15.0, 360.0);
       }});
  add({"view.sun_lower",
       "View",
       "Sun Lower",
       "Lower the sun by 10° (at least 5° above the ground).",
       {},
       false,
       [this] { sunElevation_ = std::max(5.0, sunElevation_ - 10.0); }});

  add({"tools.validate",
       "Tools",
       "Validate All Objects",
       "Check every object's shell (closed, 2-manifold, Euler characteristic), in the background.",
       {},
       false,
       [this] {
         auto snapshot = std::make_shared<Scene>(scene_);
         auto lines = std::make_shared<std::vector<std::string>>();
         startJob(
             "Validating objects",
             [snapshot, lines](Progress& progress) {
               std::size_t i = 0;
               const std::size_t n = snapshot->objects().size();
               for (const auto& [id, info] : snapshot->objects()) {
                 if (progress.cancelled()) throw Cancelled();
                 const ValidityReport r = snapshot->validate(id);
                 std::string line = info.name + ": " + (r.closedManifold() ? "closed 2-manifold" : "PROBLEMS") + ", " +
                                    std::to_string(r.faces) + " faces, Euler " + std::to_string(r.euler);
                 for (const auto& p : r.problems()) line += "; " + p;
                 lines->push_back(line);
                 progress.report(double(++i) / n, info.name);
               }
             },
             [this, lines] {
               for (const auto& l : *lines) log(l, l.find("PROBLEMS") != std::string::npos);
             });
       }});
  add({"statics.make_stand",
       "Statics",
       "Make It Stand",
       "Search the selected masonry object's free parameters, within their bounds, for a structure that stands "
       "(in the background; one undo step).",
       {GLFW_KEY_M, true, true},
       true,
       [this] { statics_.makeItStand(staticsHost()); },
       [this] { return selectedMasonry() && !statics_.searching(); }});
  add({"statics.cancel",
       "Statics",
       "Cancel Search",
       "Stop the running search; nothing changes.",
       {},
       false,
       [this] { statics_.cancelSearch(); },
       [this] { return statics_.searching(); }});
  // The collapse simulation (Sec. 5): never a Document change, so none is undoable.
  auto masonrySelected = [this] { return selectedMasonry() != nullptr; };
  add({"statics.sim_play",
       "Statics",
       "Simulate: Play / Pause",
       "Play the selected masonry object's collapse simulation in real time (as fast as the frame budget "
       "allows); again to pause.",
       {},
       false,
       [this] { statics_.simulatePlay(staticsHost()); },
       masonrySelected,
       [this] { return statics_.simulationPlaying(); },
       true});
  add({"statics.sim_step",
       "Statics",
       "Simulate: Step",
       "Advance the simulation by one fixed step (1/240 s).",
       {},
       false,
       [this] { statics_.simulateStep(staticsHost()); },
       masonrySelected});
  add({"statics.simulate",
       "Statics",
       "Simulate: Run 1 s",
       "Advance the simulation by one simulated second at once (240 steps; the window waits for it).",
       {},
       false,
       [this] { statics_.simulateStep(staticsHost(), 240); },
       masonrySelected});
  add({"statics.sim_reset",
       "Statics",
       "Simulate: Reset",
       "Return the simulation to the design state, paused.",
       {},
       false,
       [this] { statics_.simulateReset(staticsHost()); },
       masonrySelected});
  add({"statics.sim_shake",
       "Statics",
       "Simulate: Shake",
       "Shake the ground as in the paper (4 m/s within 1/60 s on a 10 m model, scaled to this one).",
       {},
       false,
       [this] { statics_.simulateShake(staticsHost()); },
       masonrySelected});
  add({"statics.sim_remove",
       "Statics",
       "Simulate: Remove Block",
       "Take the block chosen in the Simulate section (at first the top one) out of the simulation.",
       {},
       false,
       [this] { statics_.simulateRemove(staticsHost()); },
       masonrySelected});
  add({"statics.landscape_grid",
       "Statics",
       "Energy Landscape over Two Parameters",
       "Sample y/W² over a grid of the selected masonry object's first two free parameters (Fig. 8) in the "
       "statics panel; again for the landscape over one parameter.",
       {},
       false,
       [this] { statics_.toggleLandscapeGrid(staticsHost()); },
       masonrySelected,
       [this] { return statics_.landscapeGridChosen(); }});
  add({"statics.analyse_scene",
       "Statics",
       "Analyse Every Block in the Scene",
       "Analyse every object of kind Block in the Scene together (each connected piece one block, density by "
       "material, the objects ticked in the statics panel carried as loads), and show it in the view.",
       {},
       false,
       [this] { statics_.analyseScene(staticsHost()); },
       masonrySelected});
  add({"statics.sim_close",
       "Statics",
       "Simulate: Close",
       "Stop simulating and show the design again.",
       {},
       false,
       [this] { statics_.closeSimulation(); },
       [this] { return statics_.simulating(); }});
  auto growthSelected = [this] { return selectedGrowth() != nullptr; };
  add({"growth.step",
       "Growth",
       "Step",
       "Grow the selected site one step more (one undo step).",
       {},
       true,
       [this] { growthPanel_.step(growthHost()); },
       growthSelected});
  add({"growth.run",
       "Growth",
       "Run / Pause",
       "Grow the selected site step by step as the view catches up, until every unit stops; again to pause.",
       {},
       true,
       [this] { growthPanel_.toggleRun(growthHost()); },
       growthSelected,
       [this] { return growthPanel_.running(); }});
  // The site editor, the slice, the statistics and the view maps of the selected growth site.
  add({"growth.add_core",
       "Growth",
       "Add Core",
       "Add a 3 x 3 m core at the first free place of the selected site (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Core); },
       growthSelected,
       {},
       true});
  add({"growth.add_circulation",
       "Growth",
       "Add Circulation",
       "Add a 3 x 3 m landing, one storey high, on the Site tab's plan storey (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Circulation); },
       growthSelected});
  add({"growth.add_seed",
       "Growth",
       "Add Seed",
       "Add a 3 x 3 m seed of 60 m² at the first free, supported place on the plan storey (one undo step).",
       {},
       true,
       [this] { growthPanel_.add(growthHost(), SiteItem::Seed); },
       growthSelected});
  add({"growth.delete",
       "Growth",
       "Delete Site Entry",
       "Delete the core, circulation or seed picked in the Site tab.",
       {},
       true,
       [this] { growthPanel_.removeSelected(growthHost()); },
       [this, growthSelected] { return growthSelected() && growthPanel_.hasSelection(); }});
  add({"growth.add_storey",
       "Growth",
       "Add a Storey",
       "Give the selected site one storey more, of the same height (one undo step).",
       {},
       true,
       [this] { growthPanel_.addStorey(growthHost()); },
       growthSelected});
  add({"growth.widen_site",
       "Growth",
       "Widen the Site by 5 m",
       "Make the selected site's box envelope 5 m longer in x (one undo step).",
       {},
       true,
       [this] { growthPanel_.widenSite(growthHost(), 5.0); },
       growthSelected});
  add({"growth.site",
       "Growth",
       "Show the Site",
       "Show the Site tab: cores, circulation and seeds.",
       {},
       false,
       [this] { growthPanel_.showTab(1); },
       growthSelected});
  add({"growth.slice_down",
       "Growth",
       "Slice a Storey Lower",
       "Hide one storey more of the selected site in the 3D view (Fig. 8.3; a view setting).",
       {},
       false,
       [this] { growthPanel_.sliceStorey(growthHost(), -1); },
       growthSelected,
       {},
       true});
  add({"growth.slice_up",
       "Growth",
       "Slice a Storey Higher",
       "Show one storey more; past the top, no slice.",
       {},
       false,
       [this] { growthPanel_.sliceStorey(growthHost(), 1); },
       growthSelected});
  add({"growth.statistics",
       "Growth",
       "Statistics",
       "Show Table 8.1 for the model as grown.",
       {},
       false,
       [this] { growthPanel_.showTab(2); },
       growthSelected});
  add({"growth.gl_view_maps",
       "Growth",
       "GL View Maps",
       "Grow and measure growth sites on view maps rendered with OpenGL (unchecked: the exact CPU maps).",
       {},
       false,
       [this] { glViewMaps_ = !glViewMaps_; },
       [this] { return glMaps_ != nullptr; },
       [this] { return glMaps_ && glViewMaps_; }});
  add({"growth.gl_pixel_next",
       "Growth",
       "GL View Map Pixels: Next Size",
       "The next pixel size of the GL view maps (0.1, 0.25, 0.5 m, then 0.1 again); the sites regrow on it.",
       {},
       false,
       [this] {
         const auto& sizes = kEditorViewMapPixels;
         const auto at = std::find(std::begin(sizes), std::end(sizes), glPixel_);
         glPixel_ = at == std::end(sizes) || at + 1 == std::end(sizes) ? sizes[0] : *(at + 1);
       },
       [this] { return glMaps_ && glViewMaps_; }});
  add({"growth.view_maps",
       "Growth",
       "View Maps",
       "Show the four view maps (Sec. 5.2) of the model as grown, unit ids in false colour.",
       {},
       false,
       [this] { growthPanel_.toggleViewMaps(); },
       growthSelected,
       [this] { return growthPanel_.viewMapsShown(); }});
  // Form completion (Ch. 7, Fig. 8.6) in a region of the selected growth site.
  add({"completion.seeds",
       "Growth",
       "Completion: Seeds From the Model",
       "Grow the selected site's model (in the background) and take the entrances its units open onto the "
       "completion region as the seeds.",
       {},
       false,
       [this] { completion_.takeSeeds(completionHost()); },
       growthSelected});
  add({"completion.generate",
       "Growth",
       "Completion: Generate Forms",
       "Generate forms of the chosen complexity range from the seeds (in the background, with Cancel).",
       {},
       false,
       [this] { completion_.generate(completionHost()); },
       [this, growthSelected] { return growthSelected() && !job_; }});
  add({"completion.fit",
       "Growth",
       "Completion: Fit to Region",
       "Fit the picked form into the completion region and size it (Fig. 8.6).",
       {},
       false,
       [this] { completion_.fit(completionHost()); },
       [this, growthSelected] { return growthSelected() && completion_.canFit(); }});
  add({"completion.extrude",
       "Growth",
       "Completion: Extrude to Units",
       "Add the fitted form's units to the model as unit objects (one undo step).",
       {},
       true,
       [this] { completion_.extrude(completionHost()); },
       [this, growthSelected] { return growthSelected() && completion_.canExtrude(); }});
  // The Town panel (Kelly & Wonka Sec. 3.7): its building list and override, for scripts.
  const auto townSelected = [this] { return selectedTown() != nullptr; };
  add({"town.next",
       "Town",
       "Select Next Building",
       "Select the next building of the selected town.",
       {},
       false,
       [this] { townPanel_.selectNext(townHost()); },
       townSelected});
  add({"town.next_type",
       "Town",
       "Override: Next Type",
       "Give the selected building the style's next building type (an undoable override).",
       {},
       false,
       [this] { townPanel_.overrideNextType(townHost()); },
       townSelected});
  add({"town.next_edge",
       "Town",
       "Pick Next Edge",
       "Pick the selected building's next edge in the Town panel's plan view.",
       {},
       false,
       [this] { townPanel_.selectNextEdge(townHost()); },
       townSelected});
  add({"town.next_edge_profile",
       "Town",
       "Override: Next Edge Profile",
       "Give the picked edge of the selected building the style's next profile (an undoable override of that edge).",
       {},
       false,
       [this] { townPanel_.overrideNextEdgeProfile(townHost()); },
       townSelected});
  add({"town.add_street",
       "Town",
       "Add Street",
       "Add a street along the selected town's south side (Fig. 26).",
       {},
       false,
       [this] { townPanel_.addStreet(townHost()); },
       townSelected});
  add({"town.bend_street",
       "Town",
       "Bend Street",
       "Move the chosen street's middle point 10 m south.",
       {},
       false,
       [this] { townPanel_.bendStreet(townHost()); },
       townSelected});
  add({"help.shortcuts",
       "Help",
       "Keyboard Shortcuts",
       "List every command and its shortcut.",
       {GLFW_KEY_F1},
       false,
       [this] { showHelp_ = true; }});
}

void App::handleShortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || fileDialog_.isOpen()) return;
  for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
    if (!ImGui::IsKeyPressed(key, false)) continue;
    const Action* a = actions_.match(key, io.KeyCtrl, io.KeyShift, io.KeyAlt);
    if (a && actions_.isEnabled(*a) && a->run) {
      a->run();
      break;
    }
  }
}

// ---------------------------------------------------------------- frame

void App::drawMenuBar() {
  if (!ImGui::BeginMainMenuBar()) return;
  std::vector<std::string> menus;
  for (const Action& a : actions_.all())
    if (!a.menu.empty() && std::find(menus.begin(), menus.end(), a.menu) == menus.end()) menus.push_back(a.menu);
  for (const std::string& menu : menus) {
    if (!ImGui::BeginMenu(menu.c_str())) continue;
    for (const Action& a : actions_.all()) {
      if (a.menu != menu) continue;
      if (a.separatorBefore) ImGui::Separator();
      std::string label = a.label;
      if (a.id == "edit.undo" && history_.canUndo()) label += " " + history_.undoLabel();
      if (a.id == "edit.redo" && history_.canRedo()) label += " " + history_.redoLabel();
      const std::string shortcut = a.shortcut.text();
      if (ImGui::MenuItem(label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), a.checked && a.checked(),
                          actions_.isEnabled(a)) &&
          a.run)
        a.run();
      if (ImGui::IsItemHovered() && !a.help.empty()) ImGui::SetTooltip("%s", a.help.c_str());
      if (a.id == "file.open") {
        if (ImGui::BeginMenu("Open Recent", !recent_.paths().empty())) {
          for (const std::string& p : recent_.paths())
            if (ImGui::MenuItem(p.c_str())) {
              const std::string chosen = p;
              openFile(chosen);
              break;
            }
          ImGui::EndMenu();
        }
      }
    }
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void App::drawObjectProperties(const DocObject& object) {
  Document d = history_.current();
  DocObject* o = d.find(object.id);
  const std::string key = "obj" + std::to_string(object.id) + ".";
  bool changed = false;
  std::string label, field;
  auto edited = [&](const char* what, const char* fieldName) {
    changed = true;
    label = std::string("Edit ") + what + " of " + object.name;
    field = fieldName;
  };

  char name[limits::kMaxNameLength + 1];
  std::snprintf(name, sizeof name, "%s", o->name.c_str());
  if (ImGui::InputText("Name", name, sizeof name, ImGuiInputTextFlags_EnterReturnsTrue)) {
    std::string n = name;
    if (n.empty())
      log("An object needs a name.", true);
    else if (n != o->name && d.findByName(n))
      log("Another object is already called \"" + n + "\".", true);
    else if (n != o->name) {
      o->name = n;
      edited("name", "name");
    }
  }
  if (auto* bp = std::get_if<BoxSpec>(&o->spec)) {
    BoxSpec& b = *bp;
    ImGui::Separator();
    ImGui::TextDisabled("Box");
    float origin[3] = {float(b.origin[0]), float(b.origin[1]), float(b.origin[2])};
    if (ImGui::DragFloat3("Origin (m)", origin, 0.1f, -1e5f, 1e5f, "%.2f")) {
      b.origin = Vec3(origin[0], origin[1], origin[2]);
      edited("origin", "origin");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float size[3] = {float(b.size[0]), float(b.size[1]), float(b.size[2])};
    if (ImGui::DragFloat3("Size (m)", size, 0.05f, 0.1f, 1e4f, "%.2f", ImGuiSliderFlags_AlwaysClamp)) {
      b.size = Vec3(size[0], size[1], size[2]);
      edited("size", "size");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float rot = float(b.rotation_deg);
    if (ImGui::DragFloat("Rotation (°)", &rot, 0.5f, -360.f, 360.f, "%.1f")) {
      b.rotation_deg = rot;
      edited("rotation", "rotation");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    if (ImGui::BeginCombo("Material", b.material.c_str())) {
      for (const auto& m : builtinMaterials()) {
        const Rgb c = m.color;
        ImGui::ColorButton(("##c" + std::string(m.name)).c_str(), ImVec4(c[0], c[1], c[2], 1),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
        ImGui::SameLine();
        if (ImGui::Selectable(std::string(m.name).c_str(), b.material == m.name)) {
          b.material = m.name;
          edited("material", "material");
        }
      }
      ImGui::EndCombo();
    }
    int rep[2] = {b.repeat_x, b.repeat_y};
    if (ImGui::DragInt2("Repeat", rep, 0.1f, 1, 100, "%d", ImGuiSliderFlags_AlwaysClamp)) {
      b.repeat_x = std::max(1, rep[0]);
      b.repeat_y = std::max(1, rep[1]);
      edited("repeat", "repeat");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    float spacing[2] = {float(b.spacing_x), float(b.spacing_y)};
    if (ImGui::DragFloat2("Spacing (m)", spacing, 0.1f, -1e3f, 1e3f, "%.2f")) {
      b.spacing_x = spacing[0];
      b.spacing_y = spacing[1];
      edited("spacing", "spacing");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    if (changed) {
      if (auto problem = checkBoxSpec(b)) {
        log(object.name + ": " + *problem, true);
        changed = false;
      }
    }
  } else if (auto* e = std::get_if<ExtrusionSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Procedural extrusion");
    std::size_t corners = 0;
    for (const auto& l : e->loops) corners += l.points.size();
    ImGui::Text("%zu loop%s, %zu corners, %zu profile%s", e->loops.size(), e->loops.size() == 1 ? "" : "s", corners,
                e->profiles.size(), e->profiles.size() == 1 ? "" : "s");
    if (ImGui::BeginCombo("Material", e->material.c_str())) {
      for (const auto& m : builtinMaterials())
        if (ImGui::Selectable(std::string(m.name).c_str(), e->material == m.name)) {
          e->material = m.name;
          edited("material", "material");
        }
      ImGui::EndCombo();
    }
    float base = float(e->baseZ);
    if (ImGui::DragFloat("Base height (m)", &base, 0.05f, -1e4f, 1e4f, "%.2f")) {
      e->baseZ = base;
      edited("base height", "base");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.closeMerge();
    int priority = e->priority == Priority::MaximiseVolume ? 0 : 1;
    if (ImGui::Combo("Ambiguity", &priority, "maximise volume\0minimise volume\0")) {
      e->priority = priority == 0 ? Priority::MaximiseVolume : Priority::MinimiseVolume;
      edited("ambiguity priority", "priority");
    }
    for (const Profile& p : e->profiles)
      ImGui::BulletText("%s: %zu segment%s", p.name.c_str(), p.points.size() - 1, p.points.size() == 2 ? "" : "s");
  } else if (auto* t = std::get_if<TownSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Town from footprints (Kelly & Wonka Sec. 3.7); edit it in the Town panel");
    ImGui::Text("seed %llu, %s detail, %zu override%s", static_cast<unsigned long long>(t->seed), t->detail.c_str(),
                t->overrides.size(), t->overrides.size() == 1 ? "" : "s");
  } else if (auto* u = std::get_if<UnitSpec>(&o->spec)) {
    ImGui::Separator();
    ImGui::TextDisabled("Housing unit (a completed form's, Ng Ch. 7)");
    double floor = 0;
    for (const UnitPart& p : u->parts) floor += (p.hi[0] - p.lo[0]) * (p.hi[1] - p.lo[1]);
    ImGui::Text("%zu part%s, floor area %.1f m²", u->parts.size(), u->parts.size() == 1 ? "" : "s", floor);
    if (ImGui::BeginCombo("Material", u->material.c_str())) {
      for (const auto& m : builtinMaterials())
        if (ImGui::Selectable(std::string(m.name).c_str(), u->material == m.name)) {
          u->material = m.name;
          edited("material", "material");
        }
      ImGui::EndCombo();
    }
  }
  if (changed) commit(std::move(d), label, key + field);

  ImGui::Separator();
  ImGui::TextDisabled("Shell");
  if (const auto* k = std::get_if<KifsSpec>(&object.spec); k && k->meshResolution == 0) {
    ImGui::TextWrapped("Ray-marched: no shell in the Scene (KIFS panel > Mesh to Scene makes one).");
    return;
  }
  const ValidityReport r = scene_.validate(object.id);
  ImGui::Text("%zu faces, %zu vertices, %zu edges", r.faces, r.vertices, r.edges);
  ImGui::Text("Euler characteristic %ld, %zu component%s", r.euler, r.components, r.components == 1 ? "" : "s");
  ImGui::Text("Area %.2f m², volume %.2f m³", r.area, r.volume);
  if (r.closedManifold()) ImGui::TextColored(ImVec4(0.4f, 0.85f, 0.4f, 1), "closed, 2-manifold, consistent");
  for (const auto& p : r.problems()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", p.c_str());
}

void App::drawLeftPanel() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + top));
  ImGui::SetNextWindowSize(ImVec2(kLeftPanelWidth, vp->Size.y - top - kStatusBarHeight));
  ImGui::Begin("Panel", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushItemWidth(-110.0f);  // leave room for the labels
  const Document& current = history_.current();
  ImGui::Separator();
  ImGui::TextDisabled("Objects");
  if (current.objects.empty()) ImGui::TextDisabled("No objects. Object > Add Box (Ctrl+B).");
  for (const DocObject& o : current.objects) {
    ImGui::PushID(static_cast<int>(o.id));
    bool visible = o.visible;
    if (ImGui::Checkbox("##visible", &visible)) {
      Document d = current;
      d.find(o.id)->visible = visible;
      commit(std::move(d), std::string(visible ? "Show " : "Hide ") + o.name);
      ImGui::PopID();
      break;  // `current` changed
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Visible");
    ImGui::SameLine();
    if (ImGui::Selectable(o.name.c_str(), selected_ && *selected_ == o.id)) selected_ = o.id;
    ImGui::PopID();
  }
  if (selected_) {
    if (const DocObject* o = history_.current().find(*selected_)) drawObjectProperties(*o);
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void App::drawStatusBar() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - kStatusBarHeight));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, kStatusBarHeight));
  ImGui::Begin("Status", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
  if (job_) {
    ImGui::ProgressBar(static_cast<float>(job_->progress().fraction()), ImVec2(260, 0),
                       (job_->title() + " " + job_->progress().stage()).c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) job_->progress().cancel();
    ImGui::SameLine();
  }
  if (live_.cancelled()) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Build cancelled (the view shows the previous result)");
    ImGui::SameLine();
  } else if (!live_.current()) {
    // A build longer than a frame runs off the UI thread; the 3D view keeps the last result.
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Updating geometry... (the view shows the previous result)");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "An edit takes longer than a frame to build: it runs in the background and the newest edit wins");
    ImGui::SameLine();
  }
  ImGui::Text("%s%s  |  %zu objects, %zu triangles  |  %.0f fps", path_.empty() ? "(unsaved project)" : path_.c_str(),
              history_.dirty() ? " *" : "", history_.current().objects.size(), renderer_->triangleCount(),
              ImGui::GetIO().Framerate);
  ImGui::Separator();
  ImGui::BeginChild("log");
  for (const LogLine& l : log_) {
    if (l.error)
      ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", l.text.c_str());
    else
      ImGui::TextUnformatted(l.text.c_str());
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 4) ImGui::SetScrollHereY(1.0f);
  ImGui::EndChild();
  ImGui::End();
}

void App::drawHelp() {
  if (!showHelp_) return;
  ImGui::SetNextWindowSize(ImVec2(560, 440), ImGuiCond_Appearing);
  if (ImGui::Begin("Keyboard shortcuts", &showHelp_)) {
    if (ImGui::BeginTable("actions", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders)) {
      ImGui::TableSetupColumn("Command");
      ImGui::TableSetupColumn("Shortcut");
      ImGui::TableSetupColumn("What it does");
      ImGui::TableHeadersRow();
      for (const Action& a : actions_.all()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%s > %s", a.menu.c_str(), a.label.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.shortcut.text().c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", a.help.c_str());
      }
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted("Viewport");
      ImGui::TableNextColumn();
      ImGui::TextUnformatted("mouse");
      ImGui::TableNextColumn();
      ImGui::TextWrapped("Left drag: orbit. Right or middle drag (or Shift+left): pan. Wheel: zoom.");
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

void App::drawModals() {
  if (showUnsavedPrompt_) {
    ImGui::OpenPopup("Unsaved changes");
    showUnsavedPrompt_ = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The project has unsaved changes. Save them first?");
    if (ImGui::Button("Save")) {
      ImGui::CloseCurrentPopup();
      if (!path_.empty() && saveTo(path_)) {
        if (afterUnsavedPrompt_) afterUnsavedPrompt_();
      } else if (path_.empty()) {
        auto then = afterUnsavedPrompt_;
        fileDialog_.open(FileDialog::Mode::Save, "Save project as", {".corbel"}, "",
                         [this, then](const std::string& p) {
                           if (saveTo(p) && then) then();
                         });
      }
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      ImGui::CloseCurrentPopup();
      history_.markSaved();  // the user chose to drop them
      recovery_.discard();
      if (afterUnsavedPrompt_) afterUnsavedPrompt_();
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      ImGui::CloseCurrentPopup();
      afterUnsavedPrompt_ = nullptr;
    }
    ImGui::EndPopup();
  }

  if (recoveryOffer_) {
    ImGui::OpenPopup("Recover unsaved work?");
  }
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("corbel found work that was not saved (autosaved %s%s%s).", recoveryOffer_->savedAt.c_str(),
                recoveryOffer_->originalPath.empty() ? "" : ", from ", recoveryOffer_->originalPath.c_str());
    ImGui::Text("%zu objects. Recover it? (Your current document is kept until you choose.)",
                recoveryOffer_->document.objects.size());
    if (ImGui::Button("Recover")) {
      history_.reset(history_.current());
      commit(recoveryOffer_->document, "Recover unsaved work");
      path_ = recoveryOffer_->originalPath;
      syncScene(true);
      frameAll();
      log("Recovered unsaved work");
      recoveryOffer_.reset();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      recovery_.discard();
      recoveryOffer_.reset();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  if (showError_) {
    ImGui::OpenPopup("Error");
    showError_ = false;
  }
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(560);
    ImGui::TextUnformatted(errorMessage_.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("OK")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  fileDialog_.draw();
}

void App::handleViewportInput() {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 m = io.MousePos;
  const bool inside = m.x >= vpX_ && m.x < vpX_ + vpW_ && m.y >= vpY_ && m.y < vpY_ + vpH_;
  // A drag of a growth site's entry or envelope corner (the Site tab shown) holds the mouse
  // until the button is let go, wherever it is then.
  const bool growthSite = selectedGrowth() != nullptr;
  if (growthPanel_.viewDragging()) {
    if (!growthSite || !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      growthPanel_.endViewDrag(growthHost());
    } else if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0) {
      const auto [origin, dir] = viewRay(m.x, m.y);
      growthPanel_.viewDrag(growthHost(), origin, dir);
    }
    return;
  }
  if (io.WantCaptureMouse || !inside) return;
  if (growthSite && growthPanel_.siteShown() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyShift) {
    const auto [origin, dir] = viewRay(m.x, m.y);
    if (growthPanel_.beginViewDrag(growthHost(), origin, dir)) return;
  }
  const ImVec2 d = io.MouseDelta;
  const bool panning = ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                       (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
  if (panning)
    camera_.pan(d.x, d.y, static_cast<int>(vpH_));
  else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
    camera_.orbit(d.x, d.y);
  if (io.MouseWheel != 0) camera_.zoom(io.MouseWheel);
  // A click (no drag) on the selected extrusion picks a face: its provenance is shown and its
  // plan edge and profile segment are highlighted in the panes.
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !io.KeyShift) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    const DocObject* o = selected_ ? history_.current().find(*selected_) : nullptr;
    const auto* spec = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
    const bool click = std::hypot(drag.x, drag.y) < 3.0f;
    if (spec && click) {
      const auto [origin, dir] = viewRay(m.x, m.y);
      const std::string what = panes_.pick(*spec, origin, dir);
      if (!what.empty()) log(o->name + ": picked " + what);
    }
    // A click on a town picks one of its buildings for the Town panel.
    if (selectedTown() && click) {
      const auto [origin, dir] = viewRay(m.x, m.y);
      townPanel_.pick(townHost(), origin, dir);
    }
    // A click on a simulated block chooses it for the remove-block tool.
    if (const DocObject* masonry = selectedMasonry(); masonry && click && statics_.simulating()) {
      const auto [origin, dir] = viewRay(m.x, m.y);
      statics_.pickBlock(staticsHost(), origin, dir);
    }
  }
}

std::pair<Vec3, Vec3> App::viewRay(float px, float py) const {
  const double x = 2.0 * (px - vpX_) / vpW_ - 1.0, y = 1.0 - 2.0 * (py - vpY_) / vpH_;
  const glm::dmat4 inv = glm::inverse(camera_.projection(vpW_ / std::max(vpH_, 1.0f)) * camera_.view());
  glm::dvec4 a = inv * glm::dvec4(x, y, -1.0, 1.0), b = inv * glm::dvec4(x, y, 1.0, 1.0);
  a /= a.w;
  b /= b.w;
  Vec3 dir(b.x - a.x, b.y - a.y, b.z - a.z);
  dir.normalize();
  return {Vec3(a.x, a.y, a.z), dir};
}

const Scene& App::shownScene() {
  // The selected growth site sliced at a height (Fig. 8.3): its faces below the cut only.
  if (const auto h = growthFor_ && selected_ == growthFor_ ? growthPanel_.sliceHeight() : std::nullopt;
      h && scene_.hasObject(*growthFor_)) {
    if (sliceSceneOf_ != scene_.revision() || sliceHeightOf_ != *h || sliceObjectOf_ != *growthFor_) {
      sliceScene_ = scene_;
      const Scene::ObjectInfo& info = scene_.objects().at(*growthFor_);
      sliceScene_.replaceObject(*growthFor_, info.kind, info.name, sliceBelow(objectMesh(scene_, *growthFor_), *h));
      sliceSceneOf_ = scene_.revision();
      sliceHeightOf_ = *h;
      sliceObjectOf_ = *growthFor_;
    }
    return sliceScene_;
  }
  const DocObject* m = selectedMasonry();
  const Simulation* sim = m && m->visible ? statics_.shownSimulation(std::get<MasonrySpec>(m->spec)) : nullptr;
  if (!sim) return scene_;
  if (simSceneOf_ != scene_.revision() || simRevisionOf_ != sim->revision() || simObjectOf_ != m->id) {
    simScene_ = scene_;
    showSimulation(simScene_, m->id, *sim);
    simSceneOf_ = scene_.revision();
    simRevisionOf_ = sim->revision();
    simObjectOf_ = m->id;
  }
  return simScene_;
}

// One line of the edit script: an edit (extrude/edit.h) committed like a user's, its object
// selected so the panes show it; at the end of each stage, a screenshot once the preview has
// caught up.
void App::runScriptLine() {
  if (scriptLine_ >= scriptLines_.size() || shotAtFrame_ >= 0) return;
  const std::string& line = scriptLines_[scriptLine_++];
  if (line.find_first_not_of(" \t\r") == std::string::npos) return;
  try {
    const nlohmann::json op = nlohmann::json::parse(line);
    Document d = history_.current();
    const std::string label = extrude::edit::applyEdit(d, op);
    commit(std::move(d), label);
    history_.closeMerge();
    const std::string object = op.contains("object") ? op["object"].get<std::string>() : op.value("name", "");
    if (const DocObject* o = history_.current().findByName(object)) selected_ = o->id;
    log("script: " + label);
    const std::string stage = op.value("stage", "");
    std::string nextStage;
    for (std::size_t k = scriptLine_; k < scriptLines_.size(); ++k)
      if (scriptLines_[k].find_first_not_of(" \t\r") != std::string::npos) {
        nextStage = nlohmann::json::parse(scriptLines_[k]).value("stage", "");
        break;
      }
    if (!options_.scriptShots.empty() && !stage.empty() && stage != nextStage) {
      std::string file = stage;
      std::replace(file.begin(), file.end(), ' ', '-');
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%02d-", ++shotCount_);
      shotPath_ = (std::filesystem::path(options_.scriptShots) / (prefix + file + ".png")).string();
      shotAtFrame_ = frame_ + 3;
      firstFrame_ = true;  // frame the new state
    }
  } catch (const std::exception& e) {
    log("script line " + std::to_string(scriptLine_) + ": " + e.what(), true);
    scriptFailed_ = true;
  }
}

void App::takeScreenshot(const std::string& path) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  render::Image img(w, h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  img.flipVertically();
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  render::writePng(img, path);
}

const DocObject* App::selectedMasonry() const {
  const DocObject* o = selected_ ? history_.current().find(*selected_) : nullptr;
  return o && std::holds_alternative<MasonrySpec>(o->spec) ? o : nullptr;
}

StaticsHost App::staticsHost() {
  StaticsHost host;
  host.doc = &history_.current();
  host.scene = &scene_;
  host.object = selected_.value_or(0);
  host.wait = scripted();
  host.frameSeconds = frameSeconds_;
  host.commit = deferredCommit();
  host.endDrag = deferredEndDrag();
  host.log = [this](const std::string& line, bool error) { log(line, error); };
  return host;
}

GrowthHost App::growthHost() {
  GrowthHost host;
  host.doc = &history_.current();
  host.object = selected_.value_or(0);
  host.current = live_.current();
  host.wait = scripted();
  host.shadows = &settings_.shadows;
  host.sunAzimuth = &sunAzimuth_;
  host.sunElevation = &sunElevation_;
  host.mapper = growthMapper();
  host.maps = growthMapsName();
  host.glViewMaps = glMaps_ ? &glViewMaps_ : nullptr;
  host.glPixel = glMaps_ ? &glPixel_ : nullptr;
  if (auto it = sync_.status().find(host.object); it != sync_.status().end()) {
    host.error = it->second.error;
    host.warnings = it->second.warnings;
  }
  host.commit = deferredCommit();
  host.endDrag = deferredEndDrag();
  host.log = [this](const std::string& line, bool error) { log(line, error); };
  return host;
}

const DocObject* App::selectedGrowth() const {
  const DocObject* o = selected_ ? history_.current().find(*selected_) : nullptr;
  return o && std::holds_alternative<GrowthSpec>(o->spec) ? o : nullptr;
}

const DocObject* App::selectedTown() const {
  const DocObject* o = selected_ ? history_.current().find(*selected_) : nullptr;
  return o && std::holds_alternative<TownSpec>(o->spec) ? o : nullptr;
}

TownHost App::townHost() {
  TownHost host;
  host.doc = &history_.current();
  host.object = selected_.value_or(0);
  host.cache = townCache_.get();
  host.building = live_.building();
  host.current = live_.current();
  host.cancelled = live_.cancelled();
  host.fraction = live_.fraction();
  if (auto it = sync_.status().find(host.object); it != sync_.status().end()) host.error = it->second.error;
  host.stylesFolder = std::string(CORBEL_ASSETS_DIR) + "/styles";
  host.cancel = [this] {
    live_.cancel();
    log("town build cancelled: the buildings extruded so far are kept for the next build");
  };
  host.retry = [this] { live_.retry(); };
  host.openFile = [this](const std::string& title, std::vector<std::string> extensions, const std::string& start,
                         std::function<void(const std::string&)> then) {
    fileDialog_.open(FileDialog::Mode::Open, title, std::move(extensions), start, std::move(then));
  };
  host.commit = deferredCommit();
  host.log = [this](const std::string& line, bool error) { log(line, error); };
  return host;
}

CompletionHost App::completionHost() {
  CompletionHost host;
  host.doc = &history_.current();
  host.object = selected_.value_or(0);
  host.wait = scripted();
  host.busy = job_ != nullptr;
  host.settled = live_.current() && !growthPanel_.running();
  host.mapper = growthMapper();
  host.maps = growthMapsName();
  host.startJob = [this](std::string title, BackgroundJob::Work work, std::function<void()> done) {
    startJob(std::move(title), std::move(work), std::move(done));
  };
  host.commit = deferredCommit();
  host.log = [this](const std::string& line, bool error) { log(line, error); };
  return host;
}

// The panels right of the 3D view commit through these: the change is applied after they are
// drawn, so nothing they still read of the current document moves under them (a commit may
// reallocate the history), and in the order they made it.
std::function<void(Document, const std::string&, const std::string&)> App::deferredCommit() {
  return [this](Document d, const std::string& label, const std::string& key) {
    auto doc = std::make_shared<Document>(std::move(d));
    deferred_.push_back([this, doc, label, key] { commit(std::move(*doc), label, key); });
  };
}

std::function<void()> App::deferredEndDrag() {
  return [this] { deferred_.push_back([this] { history_.closeMerge(); }); };
}

std::string App::windowTitle() const {
  std::string name = path_.empty() ? "untitled" : std::filesystem::path(path_).filename().string();
  return (history_.dirty() ? "* " : "") + name + " — corbel";
}

int App::run() {
  std::string lastTitle;
  while (true) {
    if (glfwWindowShouldClose(window_)) {
      glfwSetWindowShouldClose(window_, GLFW_FALSE);
      guardUnsaved([this] { quitRequested_ = true; });
    }
    if (quitRequested_) break;
    // Sleep until input arrives unless something is moving or scripted.
    if (job_ || live_.building() || growthPanel_.running() || statics_.simulationPlaying() ||
        options_.quitAfterFrames > 0 || frame_ < 3)
      glfwPollEvents();
    else
      glfwWaitEventsTimeout(0.1);
    const auto now = std::chrono::steady_clock::now();
    frameSeconds_ = frame_ == 0 ? 0.0 : std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    if (scriptedIndex_ < options_.actions.size() && frame_ >= 2) {
      const std::string& id = options_.actions[scriptedIndex_++];
      if (!actions_.trigger(id)) log("script: action '" + id + "' is unknown or disabled", true);
    } else if (frame_ >= 2) {
      runScriptLine();
    }
    handleShortcuts();
    pollJob();
    syncScene();

    drawMenuBar();
    drawLeftPanel();
    drawStatusBar();
    // The plan and profile panes of a selected extrusion, right of the 3D view.
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const DocObject* sel = selected_ ? history_.current().find(*selected_) : nullptr;  // looked up again below
    const bool panes =
        sel && std::holds_alternative<ExtrusionSpec>(sel->spec) && vp->Size.x > kLeftPanelWidth + kPaneWidth + 200;
    if (panes) {
      if (panesFor_ != sel->id) panes_.reset();
      panesFor_ = sel->id;
      PaneHost host;
      host.doc = &history_.current();
      host.object = sel->id;
      if (auto it = sync_.status().find(sel->id); it != sync_.status().end()) host.error = it->second.error;
      host.commit = [this](Document d, const std::string& label, const std::string& key) {
        commit(std::move(d), label, key);
      };
      host.endDrag = [this] { history_.closeMerge(); };
      host.log = [this](const std::string& line, bool error) { log(line, error); };
      const float top = ImGui::GetFrameHeight();
      panes_.draw(host, vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top, kPaneWidth,
                  vp->Size.y - top - kStatusBarHeight);
    } else {
      panesFor_.reset();
    }
    // The KIFS panel of a selected KIFS building, in the same place. (The extrusion panes may
    // have committed: look the selection up again.)
    sel = selected_ ? history_.current().find(*selected_) : nullptr;
    const bool kifsPane =
        sel && std::holds_alternative<KifsSpec>(sel->spec) && vp->Size.x > kLeftPanelWidth + kPaneWidth + 200;
    if (kifsPane) {
      KifsHost host;
      host.doc = &history_.current();
      host.object = sel->id;
      host.building = live_.building();
      host.fraction = live_.fraction();
      if (auto it = sync_.status().find(sel->id); it != sync_.status().end()) host.error = it->second.error;
      host.commit = deferredCommit();
      host.endDrag = deferredEndDrag();
      host.log = [this](const std::string& line, bool error) { log(line, error); };
      const float top = ImGui::GetFrameHeight();
      kifsPanel_.draw(host, vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top, kPaneWidth,
                      vp->Size.y - top - kStatusBarHeight);
    }
    // The growth panel of a selected growth site, in the same place.
    const bool growthPane =
        sel && std::holds_alternative<GrowthSpec>(sel->spec) && vp->Size.x > kLeftPanelWidth + kPaneWidth + 200;
    if (growthPane) {
      if (growthFor_ != sel->id) growthPanel_.reset(), completion_.reset();
      growthFor_ = sel->id;
      const GrowthHost host = growthHost();
      growthPanel_.update(host);
      const float top = ImGui::GetFrameHeight();
      // The growth panel on top, the form completion panel under it.
      const float paneH = vp->Size.y - top - kStatusBarHeight, growthH = std::min(kGrowthPanelHeight, 0.6f * paneH);
      growthPanel_.draw(host, vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top, kPaneWidth, growthH);
      growthPanel_.drawViewMaps(host, vp->Pos.x + kLeftPanelWidth + 10, vp->Pos.y + top + 10,
                                vp->Size.x - kLeftPanelWidth - kPaneWidth - 20);
      completion_.draw(completionHost(), vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top + growthH, kPaneWidth,
                       paneH - growthH);
    } else {
      if (growthFor_) completion_.reset();
      growthFor_.reset();
      growthPanel_.reset();
    }
    // The Town panel of a selected town, in the same place.
    if (const DocObject* town = selectedTown(); town && vp->Size.x > kLeftPanelWidth + kPaneWidth + 200) {
      if (townFor_ != town->id) townPanel_.reset();
      townFor_ = town->id;
      const float top = ImGui::GetFrameHeight();
      townPanel_.draw(townHost(), vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top, kPaneWidth,
                      vp->Size.y - top - kStatusBarHeight);
    } else {
      townFor_.reset();
    }
    // The statics panel of a selected masonry object, in the same place.
    const DocObject* masonry = selectedMasonry();
    const bool staticsPane = masonry && vp->Size.x > kLeftPanelWidth + kPaneWidth + 200;
    if (staticsPane) {
      if (staticsFor_ != masonry->id) statics_.reset();
      staticsFor_ = masonry->id;
      statics_.update(staticsHost());
      const float top = ImGui::GetFrameHeight();
      statics_.draw(staticsHost(), vp->Pos.x + vp->Size.x - kPaneWidth, vp->Pos.y + top, kPaneWidth,
                    vp->Size.y - top - kStatusBarHeight);
    } else {
      staticsFor_.reset();
      if (statics_.searching()) statics_.update(staticsHost());  // a search started before the selection changed
    }
    for (auto& change : deferred_) change();
    deferred_.clear();
    drawHelp();
    drawModals();
    syncScene();  // edits made by the panels this frame

    vpX_ = vp->Pos.x + kLeftPanelWidth;
    vpY_ = vp->Pos.y + ImGui::GetFrameHeight();
    const bool rightPane = panes || staticsPane || kifsPane || growthPane;
    vpW_ = std::max(1.0f, vp->Size.x - kLeftPanelWidth - (rightPane ? kPaneWidth : 0.0f));
    vpH_ = std::max(1.0f, vp->Size.y - ImGui::GetFrameHeight() - kStatusBarHeight);
    if (firstFrame_) {
      frameAll();
      firstFrame_ = false;
    }
    handleViewportInput();
    ImGui::Render();

    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    const float sx = fbw / std::max(vp->Size.x, 1.0f), sy = fbh / std::max(vp->Size.y, 1.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbw, fbh);
    glClearColor(0.11f, 0.11f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const Document& doc = history_.current();
    settings_.visible = [&doc](ObjectId id) {
      const DocObject* o = doc.find(id);
      return o && o->visible;
    };
    // The sun of the shadows; without them the studio sun, so the model looks as it always did.
    settings_.sun =
        settings_.shadows ? std::optional<Vec3>(render::sunDirection(sunAzimuth_, sunElevation_)) : std::nullopt;
    // A selected town is not tinted as a whole: its picked building is outlined instead.
    settings_.highlight = selectedTown() ? std::nullopt : selected_;
    // Tension colours and force arrows of the selected masonry object, when it is shown.
    renderer_->overlay().clear();
    renderer_->overlayOnTop().clear();
    if (const DocObject* m = selectedMasonry(); m && m->visible)
      statics_.drawOverlay(renderer_->overlay(), renderer_->overlayOnTop(), std::get<MasonrySpec>(m->spec));
    if (growthFor_ && selected_ == growthFor_) completion_.drawOverlay(renderer_->overlayOnTop());
    if (selectedTown()) townPanel_.drawOverlay(townHost(), renderer_->overlayOnTop());
    if (selectedGrowth()) growthPanel_.drawViewOverlay(renderer_->overlayOnTop());
    renderer_->setScene(shownScene(), settings_);
    const int px = int(vpX_ * sx), py = int((vp->Size.y - vpY_ - vpH_) * sy), pw = int(vpW_ * sx), ph = int(vpH_ * sy);
    renderer_->draw(camera_, px, py, pw, ph, settings_);
    // KIFS buildings that are not meshed: ray-marched over the Scene, depth-tested against it.
    const render::RaymarchedKifs raymarched = render::raymarchedKifs(doc, settings_.visible);
    if (!raymarched.buildings.empty() && !kifsFailed_) {
      try {
        if (!kifsPass_) kifsPass_ = std::make_unique<render::KifsPass>();
        if (!kifsLayer_) kifsLayer_ = std::make_unique<render::KifsLayer>();
        // Progressive refinement: march again only when the buildings, the camera or the
        // viewport changed; coarse (1/4 of the pixels each way) while they keep changing, full
        // size once they have been still for a moment. Other frames reuse the cached layer.
        std::vector<KifsSpec> specs;
        for (const DocObject& o : doc.objects)
          if (const auto* k = std::get_if<KifsSpec>(&o.spec); k && k->meshResolution == 0 && settings_.visible(o.id))
            specs.push_back(*k);
        const std::array<double, 9> view{
            camera_.target[0], camera_.target[1], camera_.target[2], camera_.azimuth_deg, camera_.elevation_deg,
            camera_.distance,  camera_.fov_deg,   double(pw),        double(ph)};
        const auto now = std::chrono::steady_clock::now();
        if (specs != kifsSpecs_ || view != kifsView_) {
          kifsSpecs_ = std::move(specs);
          kifsView_ = view;
          kifsChanged_ = now;
          ++kifsGeneration_;
        }
        const bool still = now - kifsChanged_ > std::chrono::milliseconds(300);
        std::vector<kifs::KifsParams> buildings;
        for (const kifs::KifsParams& p : raymarched.buildings) buildings.push_back(render::kifsForView(p, camera_, ph));
        kifsLayer_->update(*kifsPass_, buildings, camera_, pw, ph, still ? 1 : 4, render::KifsMode::Shaded,
                           std::to_string(kifsGeneration_));
        kifsLayer_->composite(px, py, pw, ph);
      } catch (const std::exception& e) {
        log(std::string("KIFS buildings cannot be drawn: ") + e.what(), true);
        kifsFailed_ = true;
      }
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (shotAtFrame_ >= 0 && frame_ >= shotAtFrame_) {
      try {
        takeScreenshot(shotPath_);
        log("script: screenshot " + shotPath_);
      } catch (const std::exception& e) {
        log(e.what(), true);
        scriptFailed_ = true;
      }
      shotAtFrame_ = -1;
    }
    ++frame_;
    if (options_.quitAfterFrames > 0 && frame_ >= options_.quitAfterFrames) {
      if (!options_.screenshot.empty()) {
        try {
          takeScreenshot(options_.screenshot);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "corbel: %s\n", e.what());
          return 1;
        }
      }
      autosaveIfDue();
      break;
    }
    glfwSwapBuffers(window_);
    autosaveIfDue();
    const std::string title = windowTitle();
    if (title != lastTitle) {
      glfwSetWindowTitle(window_, title.c_str());
      lastTitle = title;
    }
  }
  if (job_) {
    job_->progress().cancel();
    job_->wait();
  }
  // A clean exit with nothing unsaved needs no recovery file.
  if (!history_.dirty()) recovery_.discard();
  if (!scriptLines_.empty() && (scriptFailed_ || scriptLine_ < scriptLines_.size())) {
    std::fprintf(stderr, "corbel: the edit script did not complete (%zu of %zu lines)%s\n", scriptLine_,
                 scriptLines_.size(), scriptFailed_ ? " and a line failed" : "");
    return 1;
  }
  return 0;
}

}  // namespace corbel::editor
