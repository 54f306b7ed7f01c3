#include "editor/app.h"

#include "editor/camera_views.h"
#include "editor/widget_marks.h"

#include "compose/export_scene.h"
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
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace corbel::editor {

namespace {

ScriptOptions scriptOptionsOf(const EditorOptions& o) {
  return {o.actions, o.script, o.scriptShots, o.screenshot, o.quitAfterFrames};
}

std::string stateDirOr(const std::string& dir) { return dir.empty() ? defaultStateDir() : dir; }

}  // namespace

App::App(GLFWwindow* window, EditorOptions options)
    : window_(window),
      options_(std::move(options)),
      script_(scriptOptionsOf(options_)),
      recovery_(stateDirOr(options_.stateDir)),
      recent_(stateDirOr(options_.stateDir) + "/recent.json") {
  input_ = std::make_unique<GlfwInput>(window_);
  if (!options_.testLog.empty()) testLog_ = std::make_unique<TestLog>(options_.testLog);
  marks::enable(testLog_ != nullptr);
  if (!options_.latencyLog.empty()) {
    latencyLog_ = std::make_unique<std::ofstream>(options_.latencyLog, std::ios::trunc);
    if (!*latencyLog_) throw Error("--latency-log: cannot write " + options_.latencyLog);
  }
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
  settings_.visible = [this](ObjectId id) {
    const DocObject* o = history_.current().find(id);
    return o && o->visible;
  };
  log("OpenGL " + render::glDescription());
  loadSettings();
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
  if (!script_.problem().empty()) log(script_.problem(), true);
  if (!options_.select.empty()) {
    if (const DocObject* o = history_.current().findByName(options_.select))
      selection_.select(o->id);
    else
      log("--select: the project has no object named \"" + options_.select + "\"", true);
  }
  claimRecovery();
  syncScene(true);
  frameAll();
  checkRecovery();
}

App::~App() = default;

void App::log(const std::string& line, bool error) {
  log_.push_back({line, error});
  // A scripted run (tests, CI) has no one to read the panel: its log goes to stderr too.
  if (scripted()) std::fprintf(stderr, "corbel: %s%s\n", error ? "error: " : "", line.c_str());
  while (log_.size() > 200) log_.pop_front();
}

// ---------------------------------------------------------------- document and files

void App::commit(Document doc, const std::string& label, const std::string& mergeKey) {
  const std::uint64_t before = history_.stateId();
  history_.commit(std::move(doc), label, mergeKey);
  if (latencyLog_ && !batch_.events.empty() && history_.stateId() != before)
    latency_.caused(history_.stateId(), batch_.events.front().time);
}

bool App::scripted() const { return script_.scripted(); }

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
  selection_.prune(history_.current());
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
  view_.frame(box);
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
    selection_.clear();
    recovery_.discard();
    claimRecovery();
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
          selection_.clear();
          recent_.add(path);
          recovery_.discard();
          claimRecovery();
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
    const bool moved = path != path_;
    path_ = path;
    history_.markSaved();
    recent_.add(path);
    recovery_.discard();
    if (moved) claimRecovery();  // the autosaves of this document now go to its new file's slot
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
                     // What the view shows, all of it (compose/export_scene.h): ray-marched KIFS
                     // buildings are meshed and towns split into buildings, in the background.
                     auto snapshot = std::make_shared<Scene>(scene_);
                     auto doc = std::make_shared<Document>(history_.current());
                     auto notes = std::make_shared<std::vector<std::string>>();
                     startJob(
                         "Exporting " + std::filesystem::path(p).filename().string(),
                         [snapshot, doc, notes, towns = townCache_, p](Progress& progress) {
                           progress.report(0.1, "preparing");
                           const compose::ExportableScene e =
                               compose::exportableScene(*doc, *snapshot, towns.get(), nullptr);
                           *notes = e.notes;
                           progress.report(0.6, "writing");
                           ExportOptions opt;
                           opt.textured = e.textured;
                           opt.tagTextures = e.tagTextures;
                           opt.placements = e.placements;
                           corbel::exportScene(e.scene, p, opt);
                           progress.report(1.0, "done");
                         },
                         [this, p, notes] {
                           for (const std::string& n : *notes) log("Export: " + n);
                           log("Exported " + p);
                         });
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

// This document's recovery slot: one per open document, so two editors never autosave over
// each other; a second editor on the same file is told.
void App::claimRecovery() {
  try {
    if (const auto other = recovery_.claim(path_)) {
      const std::string name = std::filesystem::path(path_).filename().string();
      errorMessage_ = name + " is open in another corbel (process " + std::to_string(*other) +
                      "). This window autosaves apart from it, but saving here and there overwrites one with the other.";
      showError_ = true;
      log("warning: " + errorMessage_, true);
      std::fprintf(stderr, "corbel: warning: %s\n", errorMessage_.c_str());
    }
  } catch (const std::exception& e) {
    log(std::string("Autosave is off: ") + e.what(), true);
  }
}

// Brings a recovered document into this window; the editor autosaves it in its slot from now on.
void App::recover(const RecoveredWork& work) {
  try {
    recovery_.adopt(work);
  } catch (const std::exception& e) {
    log(e.what(), true);
    return;
  }
  history_.reset(history_.current());
  commit(work.document, "Recover unsaved work");
  path_ = work.originalPath;
  selection_.clear();
  syncScene(true);
  frameAll();
  log("Recovered unsaved work" + (work.originalPath.empty() ? std::string() : " of " + work.originalPath) +
      (work.savedAt.empty() ? std::string() : " from " + work.savedAt));
}

void App::checkRecovery() {
  std::vector<std::string> problems;
  std::vector<RecoveredWork> found = recovery_.orphans(&problems);
  for (const std::string& p : problems) log("A recovery file exists but cannot be read: " + p, true);
  if (found.empty()) return;
  switch (options_.recover) {
    case EditorOptions::Recover::No:
      for (const RecoveredWork& w : found) recovery_.discardOrphan(w);
      break;
    case EditorOptions::Recover::Yes:  // the newest; the others wait for the next start
      recover(found.front());
      break;
    case EditorOptions::Recover::Ask:
      recoveryOffers_ = std::move(found);
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

const DocObject* App::selectedMasonry() const {
  const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr;
  return o && std::holds_alternative<MasonrySpec>(o->spec) ? o : nullptr;
}

StaticsHost App::staticsHost() {
  StaticsHost host;
  host.doc = &history_.current();
  host.scene = &scene_;
  host.object = selected().value_or(0);
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
  host.object = selected().value_or(0);
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
  host.busy = job_ != nullptr;
  host.startJob = [this](std::string title, BackgroundJob::Work work, std::function<void()> done) {
    startJob(std::move(title), std::move(work), std::move(done));
  };
  return host;
}

const DocObject* App::selectedGrowth() const {
  const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr;
  return o && std::holds_alternative<GrowthSpec>(o->spec) ? o : nullptr;
}

const DocObject* App::selectedTown() const {
  const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr;
  return o && std::holds_alternative<TownSpec>(o->spec) ? o : nullptr;
}

TownHost App::townHost() {
  TownHost host;
  host.doc = &history_.current();
  host.object = selected().value_or(0);
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
  host.object = selected().value_or(0);
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

// ---------------------------------------------------------------- the frame

bool App::settled() const {
  return !job_ && !live_.building() && live_.current() && !growthPanel_.running() && !statics_.simulationPlaying() &&
         input_->queue().empty() && script_.idle() && !kifsRefining_ && !growthPanel_.viewDragging() && !tool_.busy() &&
         !transform_.active() && !pushPull_.active();
}

void App::writeTestLog() {
  if (!testLog_ || !settled()) return;
  SettledFrame s;
  s.frame = frame_;
  const Document& doc = history_.current();
  for (ObjectId id : selection_.ids())
    if (const DocObject* o = doc.find(id)) s.selection.push_back(o->name);
  if (const DocObject* o = selected() ? doc.find(*selected()) : nullptr) s.active = o->name;
  if (const DocObject* o = selection_.hover ? doc.find(*selection_.hover) : nullptr) s.hover = o->name;
  s.camera = view_.camera;
  s.lastAction = actions_.lastRun();
  s.actionsRun = actions_.runCount();
  s.objects = doc.objects.size();
  s.dirty = history_.dirty();
  s.undo = history_.canUndo() ? history_.undoLabel() : "";
  if (panesFor_) s.planCorners = panes_.cornersOnScreen();
  if (panesFor_) {
    s.profilePoints = panes_.profilePointsOnScreen();
    for (const auto& [loop, edge] : panes_.selectedEdges()) s.planEdges.push_back({loop, edge});
    const DocObject* o = doc.find(*panesFor_);
    const auto* e = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
    if (e && panes_.shownProfile() >= 0 && panes_.shownProfile() < static_cast<int>(e->profiles.size()))
      s.profile = e->profiles[panes_.shownProfile()].name;
  }
  s.view = {float(view_.x()), float(view_.y()), float(view_.width()), float(view_.height())};
  for (const auto& [id, st] : sync_.status())
    if (const DocObject* o = doc.find(id); o && !st.error.empty()) s.failed.push_back(o->name);
  if (selected()) {
    const BBox box = objectBounds(*selected());
    if (!box.empty()) s.activeInView = boxInView(view_.camera, view_.aspect(), box);
  }
  if (searchShown_) s.search = searchText_;
  s.widgets = marks::all();
  if (tape_.done()) {
    const TapePoint &a = *tape_.start(), &b = *tape_.end();
    s.tape = SettledFrame::Tape{{a.at[0], a.at[1], a.at[2]}, {b.at[0], b.at[1], b.at[2]}, snapName(a.snap), snapName(b.snap),
                                (b.at - a.at).norm()};
  }
  testLog_->write(s);
}

int App::run() {
  std::string lastTitle;
  ScriptHost scriptHost;
  scriptHost.trigger = [this](const std::string& id) {
    const Action* a = actions_.find(id);
    if (!a || !actions_.isEnabled(*a) || !a->run) return false;
    runAction(*a);
    return true;
  };
  // One line of the edit script, committed like a user's edit, its object selected so the
  // panes show it.
  scriptHost.edit = [this](const nlohmann::json& op) {
    Document d = history_.current();
    std::vector<std::string> removed;
    const std::string label = extrude::edit::applyEdit(d, op, &removed);
    commit(std::move(d), label);
    for (const std::string& n : removed) log("script: " + n + " (Undo restores it)");
    history_.closeMerge();
    const std::string object = op.contains("object") ? op["object"].get<std::string>() : op.value("name", "");
    if (const DocObject* o = history_.current().findByName(object)) selection_.select(o->id);
    log("script: " + label);
  };
  scriptHost.log = [this](const std::string& line, bool error) { log(line, error); };
  scriptHost.reframe = [this] { firstFrame_ = true; };
  while (true) {
    if (glfwWindowShouldClose(window_)) {
      glfwSetWindowShouldClose(window_, GLFW_FALSE);
      guardUnsaved([this] { quitRequested_ = true; });
    }
    if (quitRequested_) break;
    // Sleep until input arrives unless something is moving, scripted or still queued.
    if (job_ || live_.building() || growthPanel_.running() || statics_.simulationPlaying() ||
        options_.quitAfterFrames > 0 || frame_ < 3 || !input_->queue().empty() || kifsRefining_)
      glfwPollEvents();
    else
      glfwWaitEventsTimeout(0.1);
    if (options_.frameDelayMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(options_.frameDelayMs));
    const auto now = std::chrono::steady_clock::now();
    frameSeconds_ = frame_ == 0 ? 0.0 : std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;

    batch_ = input_->queue().takeFrame();
    applyUiScale();
    ImGui_ImplOpenGL3_NewFrame();
    input_->newFrame(batch_);
    ImGui::NewFrame();
    marks::beginFrame();

    script_.startFrame(frame_, scriptHost);
    pollJob();
    syncScene();

    // "Build in stone" of a selected extrusion: its work collected before the left panel draws it.
    if (const DocObject* o = selected() ? history_.current().find(*selected()) : nullptr;
        o && std::holds_alternative<ExtrusionSpec>(o->spec)) {
      if (stoneFor_ != o->id) stone_.reset();
      stoneFor_ = o->id;
      stone_.update(staticsHost());
    } else if (stoneFor_) {
      stone_.reset();
      stoneFor_.reset();
    }
    drawMenuBar();
    drawLeftPanel();
    drawStatusBar();
    // A kernel's panel right of the 3D view for the selected object, when the window has room.
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const Layout layout = layoutWindow(vp->Size.x, vp->Size.y, ImGui::GetFrameHeight(), true, panelSizes());
    const Rect& pane = layout.rightPane;
    const DocObject* sel = selected() ? history_.current().find(*selected()) : nullptr;  // looked up again below
    // The plan and profile panes of a selected extrusion.
    const bool panes = sel && std::holds_alternative<ExtrusionSpec>(sel->spec) && layout.rightPaneShown;
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
      panes_.draw(host, pane.x, pane.y, pane.w, pane.h);
    } else {
      panesFor_.reset();
    }
    // The KIFS panel of a selected KIFS building. (The extrusion panes may have committed:
    // look the selection up again.)
    sel = selected() ? history_.current().find(*selected()) : nullptr;
    const bool kifsPane = sel && std::holds_alternative<KifsSpec>(sel->spec) && layout.rightPaneShown;
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
      host.townBuildings = [this](ObjectId town) {
        std::vector<std::string> ids;
        for (const city::BuiltBuilding& b : townCache_->buildings(town))
          if (b.error.empty()) ids.push_back(b.id);
        return ids;
      };
      kifsPanel_.draw(host, pane.x, pane.y, pane.w, pane.h);
    }
    // The growth panel of a selected growth site, the form completion panel under it.
    const bool growthPane = sel && std::holds_alternative<GrowthSpec>(sel->spec) && layout.rightPaneShown;
    if (growthPane) {
      if (growthFor_ != sel->id) growthPanel_.reset(), completion_.reset();
      growthFor_ = sel->id;
      const GrowthHost host = growthHost();
      growthPanel_.update(host);
      const float growthH = std::min(kGrowthPanelHeight * uiScale(), 0.6f * pane.h);
      growthPanel_.draw(host, pane.x, pane.y, pane.w, growthH);
      growthPanel_.drawViewMaps(host, layout.view.x + 10, layout.view.y + 10, layout.view.w - 20);
      completion_.draw(completionHost(), pane.x, pane.y + growthH, pane.w, pane.h - growthH);
    } else {
      if (growthFor_) completion_.reset();
      growthFor_.reset();
      growthPanel_.reset();
    }
    // The Town panel of a selected town.
    if (const DocObject* town = selectedTown(); town && layout.rightPaneShown) {
      if (townFor_ != town->id) townPanel_.reset();
      townFor_ = town->id;
      townPanel_.draw(townHost(), pane.x, pane.y, pane.w, pane.h);
    } else {
      townFor_.reset();
    }
    // The statics panel of a selected masonry object.
    const DocObject* masonry = selectedMasonry();
    const bool staticsPane = masonry && layout.rightPaneShown;
    if (staticsPane) {
      if (staticsFor_ != masonry->id) statics_.reset();
      staticsFor_ = masonry->id;
      statics_.update(staticsHost());
      statics_.draw(staticsHost(), pane.x, pane.y, pane.w, pane.h);
    } else {
      staticsFor_.reset();
      if (statics_.searching()) statics_.update(staticsHost());  // a search started before the selection changed
    }
    for (auto& change : deferred_) change();
    deferred_.clear();
    // Shortcuts after the panels: a key the pane under the pointer or with focus takes (Delete
    // on a selected corner) is not also a command.
    // (Only while a kernel's panel is drawn there: the view's own windows, the axis widget's,
    // may lie right of where the pane would be.)
    paneHasKeys_ = (panes || kifsPane || growthPane || staticsPane || townFor_.has_value()) && rightPaneHasKeys(pane);
    handleShortcuts();
    drawHelp();
    drawCommandSearch();
    drawModals();
    syncScene();  // edits made by the panels this frame

    // The view is what the panels leave; a selected kind with a panel keeps the right splitter
    // even while that panel is hidden.
    const bool townPane = selectedTown() && layout.rightPaneShown;
    const DocObject* selNow = selected() ? history_.current().find(*selected()) : nullptr;  // after this frame's commits
    const bool hasPanel = selNow && !std::holds_alternative<BoxSpec>(selNow->spec) && !std::holds_alternative<UnitSpec>(selNow->spec);
    const bool rightPane = panes || staticsPane || kifsPane || growthPane || townPane || (hasPanel && !panelSizes().rightShown);
    const Layout shown = layoutWindow(vp->Size.x, vp->Size.y, ImGui::GetFrameHeight(), rightPane, panelSizes());
    view_.setRect(vp->Pos.x + shown.view.x, vp->Pos.y + shown.view.y, shown.view.w, shown.view.h);
    if (firstFrame_) {
      frameAll();
      firstFrame_ = false;
    }
    revealAdded();
    drawToolbar(shown);
    drawSplitters(shown);
    drawAxisWidget();
    handleViewInput();
    syncScene();  // edits made in the 3D view this frame (Push/Pull, the gizmo), shown in this frame
    ImGui::Render();
    drawView();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (const auto shot = script_.dueShot(frame_)) {
      bool ok = true;
      try {
        takeScreenshot(*shot);
        log("script: screenshot " + *shot);
      } catch (const std::exception& e) {
        log(e.what(), true);
        ok = false;
      }
      script_.shotDone(ok);
    }
    if (screenshotDue_) {
      screenshotDue_ = false;
      saveScreenshot();
    }
    ++frame_;
    if (script_.quitAfter(frame_)) {
      if (!script_.finalScreenshot().empty()) {
        try {
          takeScreenshot(script_.finalScreenshot());
        } catch (const std::exception& e) {
          std::fprintf(stderr, "corbel: %s\n", e.what());
          return 1;
        }
      }
      autosaveIfDue();
      writeTestLog();
      break;
    }
    glfwSwapBuffers(window_);
    if (latencyLog_) {
      glFinish();  // the frame is on screen, not only queued
      if (const auto s = latency_.presented(live_.shownState(), glfwGetTime()))
        *latencyLog_ << "{\"frame\":" << frame_ << ",\"state\":" << *live_.shownState() << ",\"ms\":" << *s * 1000 << "}\n"
                     << std::flush;
    }
    autosaveIfDue();
    writeTestLog();
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
  if (const std::string why = script_.incomplete(); !why.empty()) {
    std::fprintf(stderr, "corbel: %s\n", why.c_str());
    return 1;
  }
  return 0;
}

}  // namespace corbel::editor
