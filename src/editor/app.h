#pragma once
// The editor application: one Document with undo history, the Scene derived from it, the
// renderer, and the ImGui shell (menu bar, left panel, status/log bar, 3D viewport).
#include "city/kernel.h"
#include "core/app_state.h"
#include "core/history.h"
#include "core/kifs_spec.h"
#include "core/live_sync.h"
#include "core/progress.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "editor/actions.h"
#include "editor/completion_panel.h"
#include "editor/extrusion_panes.h"
#include "editor/file_dialog.h"
#include "editor/growth_panel.h"
#include "editor/kifs_panel.h"
#include "editor/options.h"
#include "editor/statics_panel.h"
#include "editor/town_panel.h"
#include "editor/view_map_context.h"
#include "render/camera.h"
#include "render/kifs_layer.h"
#include "render/kifs_pass.h"
#include "render/renderer.h"

#include <array>
#include <atomic>
#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace corbel::editor {

class App {
 public:
  App(GLFWwindow* window, EditorOptions options);
  ~App();
  int run();

 private:
  // Document and files.
  void commit(Document doc, const std::string& label, const std::string& mergeKey = {});
  void newDocument();
  void openFile(const std::string& path);
  bool saveTo(const std::string& path);
  void save();
  void saveAs();
  void exportScene();
  void guardUnsaved(std::function<void()> then);  // asks before discarding changes
  void autosaveIfDue();
  void checkRecovery();

  // Frame.
  void registerActions();
  void handleShortcuts();
  void handleViewportInput();
  // The ray under window point (x, y) of the 3D view, as an origin and a unit direction.
  std::pair<Vec3, Vec3> viewRay(float x, float y) const;
  void drawMenuBar();
  void drawLeftPanel();
  void drawObjectProperties(const DocObject& object);
  void drawStatusBar();
  void drawModals();
  void drawHelp();
  void pollJob();
  void startJob(std::string title, BackgroundJob::Work work, std::function<void()> onDone);
  void log(const std::string& line, bool error = false);
  // Brings the Scene to the current document: off the UI thread (a build longer than a few
  // milliseconds keeps the last result on screen, marked as updating), or, with wait, at once.
  void syncScene(bool wait = false);
  bool scripted() const;  // a scripted or screenshot run: every frame shows the current state
  void frameAll();
  void takeScreenshot(const std::string& path);
  void runScriptLine();
  // The selected object when it is masonry, for the statics panel.
  const DocObject* selectedMasonry() const;
  StaticsHost staticsHost();
  GrowthHost growthHost();
  CompletionHost completionHost();
  TownHost townHost();
  const DocObject* selectedTown() const;
  const DocObject* selectedGrowth() const;
  std::function<void(Document, const std::string&, const std::string&)> deferredCommit();
  std::function<void()> deferredEndDrag();
  std::string windowTitle() const;

  GLFWwindow* window_;
  EditorOptions options_;
  History history_;
  Scene scene_;
  // The GL view maps (editor/view_map_context.h; null without a context), before sync_ and the
  // panels: their builds and measurements use it, so it goes after them. growOnGl_ is what the
  // growth builds read (off the UI thread); glViewMaps_ the Grow tab's setting, which becomes
  // growOnGl_ (and regrows the growth objects) when no build runs, as glPixel_ becomes the
  // mapper's pixel size.
  std::shared_ptr<render::ContextViewMapper> glMaps_;
  bool glViewMaps_ = true;
  double glPixel_ = kEditorViewMapPixel;  // the Grow tab's; glMaps_ has it once applied
  std::atomic<bool> growOnGl_{false};
  void applyViewMapSetting();
  std::shared_ptr<growth::ViewMapper> growthMapper() const;
  std::string growthMapsName() const;
  SceneSync sync_;
  LiveSync live_{sync_};  // after sync_: its builds use it
  std::unique_ptr<render::Renderer> renderer_;
  render::OrbitCamera camera_;
  render::RenderSettings settings_;
  // The sun of the shadows (degrees; azimuth from +X towards +Y): the studio sun's direction.
  double sunAzimuth_ = -37.9, sunElevation_ = 55.2;
  ActionRegistry actions_;
  FileDialog fileDialog_;
  Recovery recovery_;
  RecentFiles recent_;

  std::string path_;  // current file ("" = never saved)
  std::optional<ObjectId> selected_;
  std::uint64_t autosavedState_ = 0;
  std::chrono::steady_clock::time_point lastAutosave_;

  struct LogLine {
    std::string text;
    bool error;
  };
  std::deque<LogLine> log_;
  std::map<ObjectId, std::string> reported_;  // last kernel message logged per object

  std::unique_ptr<BackgroundJob> job_;
  std::function<void()> jobDone_;

  // Modals.
  std::function<void()> afterUnsavedPrompt_;
  bool showUnsavedPrompt_ = false;
  std::string errorMessage_;
  bool showError_ = false;
  std::optional<RecoveredWork> recoveryOffer_;
  bool showHelp_ = false;
  bool quitRequested_ = false;

  // Viewport rectangle in window pixels (top-left origin).
  float vpX_ = 0, vpY_ = 0, vpW_ = 1, vpH_ = 1;
  int frame_ = 0;
  std::size_t scriptedIndex_ = 0;
  ExtrusionPanes panes_;
  std::optional<ObjectId> panesFor_;
  std::vector<std::function<void()>> deferred_;  // the panels' commits of this frame (deferredCommit)
  StaticsPanel statics_;
  std::optional<ObjectId> staticsFor_;
  double frameSeconds_ = 0;  // wall time since the last frame began
  std::chrono::steady_clock::time_point lastFrame_;
  // What the viewport draws while a simulation is shown: the Scene with the simulated object's
  // blocks where the simulation has them, remade when either changes.
  Scene simScene_;
  std::uint64_t simSceneOf_ = 0, simRevisionOf_ = 0;
  ObjectId simObjectOf_ = 0;
  // The shown scene with the selected growth site sliced (Fig. 8.3), cached by what it shows.
  Scene sliceScene_;
  std::uint64_t sliceSceneOf_ = 0;
  double sliceHeightOf_ = 0;
  ObjectId sliceObjectOf_ = 0;
  const Scene& shownScene();
  KifsPanel kifsPanel_;
  GrowthPanel growthPanel_;
  CompletionPanel completion_;  // under the growth panel
  std::optional<ObjectId> growthFor_;
  std::shared_ptr<city::TownCache> townCache_;  // the town kernel's per-building results
  TownPanel townPanel_;
  std::optional<ObjectId> townFor_;
  std::unique_ptr<render::KifsPass> kifsPass_;    // made when a KIFS building is first shown
  std::unique_ptr<render::KifsLayer> kifsLayer_;  // the cached march (progressive refinement)
  std::vector<KifsSpec> kifsSpecs_;               // what the layer shows, to see it change
  std::array<double, 9> kifsView_{};
  std::chrono::steady_clock::time_point kifsChanged_{};
  unsigned long kifsGeneration_ = 0;
  bool kifsFailed_ = false;  // its shader did not build (logged once)
  std::vector<std::string> scriptLines_;
  std::size_t scriptLine_ = 0;
  int shotAtFrame_ = -1;
  std::string shotPath_;
  int shotCount_ = 0;
  bool scriptFailed_ = false;
  bool firstFrame_ = true;
};

}  // namespace corbel::editor
