#pragma once
// The editor application: one Document with undo history, the Scene derived from it, the
// renderer, and the ImGui shell (menu bar, left panel, status/log bar, 3D viewport). App wires
// the editor's rooms together each frame: the input queue (glfw_input.h), the view and its
// tool (viewport.h, navigate_tool.h), the selection (selection.h), the layout (layout.h) and
// scripted runs (script_runner.h, test_log.h). Its members are spread over app.cpp (life,
// files, jobs, the frame), app_actions.cpp (commands, menus, shortcuts), app_panels.cpp (the
// left panel, status bar and dialogs) and app_view.cpp (the 3D view).
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
#include "editor/glfw_input.h"
#include "editor/growth_panel.h"
#include "editor/kifs_panel.h"
#include "editor/latency.h"
#include "editor/layout.h"
#include "editor/navigate_tool.h"
#include "editor/script_runner.h"
#include "editor/selection.h"
#include "editor/options.h"
#include "editor/push_pull.h"
#include "editor/statics_panel.h"
#include "editor/stone_panel.h"
#include "editor/kifs_followers.h"
#include "editor/tape_measure.h"
#include "editor/test_log.h"
#include "editor/transform.h"
#include "editor/town_panel.h"
#include "editor/user_settings.h"
#include "editor/view_map_context.h"
#include "editor/viewport.h"
#include "render/kifs_layer.h"
#include "render/kifs_pass.h"
#include "render/renderer.h"

#include <imgui.h>
#include <array>
#include <atomic>
#include <chrono>
#include <deque>
#include <fstream>
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
  void claimRecovery();
  void checkRecovery();
  void recover(const RecoveredWork& work);

  // Frame.
  void registerActions();
  void runAction(const Action& a);  // every way an action runs (menu, shortcut, script)
  void handleShortcuts();
  bool rightPaneHasKeys(const Rect& pane) const;
  // This frame's input events to the 3D view's tool (what a click or a drag there means).
  void handleViewInput();
  // A click in the 3D view: selects what the ray meets first (Shift adds, Ctrl toggles, empty
  // space clears); on the active object itself, that kind's own pick (a face, a building, a block).
  void clickInView(const Ray& r);
  std::optional<ObjectId> objectUnder(const Ray& r);
  void drawView();
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
  bool settled() const;   // nothing builds, runs, moves or waits in the input queue
  void writeTestLog();
  void frameAll();
  // Navigation aids (app_navigation.cpp): the axis widget in the view's corner, and new objects
  // brought into view once built.
  void drawAxisWidget();
  BBox objectBounds(ObjectId id);
  void reveal(ObjectId id);
  void revealAdded();
  void drawErrorMarks(render::Overlay& onTop);  // crossing plan edges of extrusions that failed
  std::vector<ObjectId> reveal_;
  int revealFrom_ = 0;  // the frame from which reveal_ is looked at
  // The layout as the user shapes it (app_layout.cpp): panel sizes, splitters, toolbar, UI
  // scale, kept in settings.json beside the recent files.
  void loadSettings();
  void saveSettings();
  float uiScale() const;  // the user's choice, else the monitor's content scale
  void setUiScale(std::optional<float> scale);
  void applyUiScale();
  PanelSizes panelSizes() const;
  void togglePanel(bool left);
  void drawSplitters(const Layout& layout);
  void drawToolbar(const Layout& layout);
  void drawMenuItems(const std::string& menu);  // the actions of a menu path, submenus nested
  UserSettings userSettings_;
  std::string settingsPath_;
  float monitorScale_ = 1.0f, appliedScale_ = 0.0f;
  bool splitterMoved_ = false;
  float splitterFrom_ = 0.0f;  // the panel's width when the splitter was pressed
  // The command search (app_search.cpp).
  void openCommandSearch();
  void drawCommandSearch();
  bool searchOpen_ = false, searchShown_ = false;
  char searchText_[160] = {};
  int searchPick_ = 0;
  void takeScreenshot(const std::string& path);
  // "Save Screenshot": the window as NAME-shot-N.png beside the project (the first N free), logged.
  void saveScreenshot();
  std::optional<ObjectId> selected() const { return selection_.active(); }
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

  // The studio's selection and placement (app_studio.cpp).
  void registerStudioActions();
  bool pickable(ObjectId id) const;  // shown and not locked
  BBox objectBounds(ObjectId id) const;  // placed; a ray-marched KIFS building's too
  std::vector<ObjectId> movableSelection() const;  // the selected objects that are not locked
  Vec3 selectionPivot() const;  // the centre of their base
  float gizmoLength() const;
  void beginTransform(Transform::Mode mode, bool dragged);
  void previewTransform();
  void endTransform(bool confirm);
  void transformInput();
  bool grabGizmo(float px, float py);
  void updateHover(bool overUi);
  void boxSelect(float x0, float y0, float x1, float y1);
  void drawStudioOverlay();
  void drawBoxBand();
  void frameSelected();
  void duplicateSelected();
  void drawPlacementFields(const DocObject& object);  // the left panel's Placement section
  void drawUnitEdits(const DocObject& object);        // a unit's Split and Merge
  struct {
    ObjectId object = 0;
    int axis = 0;
    double at = 0;
  } unitSplit_;  // the split plane the unit panel offers
  // The Push/Pull tool (app_push_pull.cpp).
  struct PushPullPick {
    ObjectId object = 0;
    Ray ray;  // in the object's frame
    extrude::pushpull::Target target;
    std::optional<UnitFace> unit;  // a unit object's side (target.outline and hit are its)
  };
  void registerPushPullActions();
  void togglePushPullTool();
  std::optional<PushPullPick> pushPullPick(const Ray& world);
  bool beginPushPull(const Ray& world);
  void previewPushPull();
  void endPushPull(bool confirm);
  void pushPullInput();
  void updatePushPullHover();
  void drawPushPullOverlay();
  // The tape measure (app_tape.cpp).
  void registerTapeActions();
  void toggleTapeTool();
  void tapeClick(const Ray& world);  // a click in the view while the tool is on
  void tapeInput();                  // Esc while the tool is on
  void updateTapeHover();
  void drawTapeOverlay();  // with the scene
  void drawTapeLabels();   // within the UI's frame
  double worldPerPixel(const Vec3& p) const;  // metres a window pixel spans at p

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
  std::unique_ptr<GlfwInput> input_;
  InputBatch batch_;  // this frame's events
  Viewport view_;
  NavigateTool tool_;
  Selection selection_;
  ScriptRunner script_;
  std::unique_ptr<TestLog> testLog_;
  render::RenderSettings settings_;
  // The sun of the shadows (degrees; azimuth from +X towards +Y): the studio sun's direction.
  double sunAzimuth_ = -37.9, sunElevation_ = 55.2;
  ActionRegistry actions_;
  FileDialog fileDialog_;
  Recovery recovery_;
  RecentFiles recent_;

  std::string path_;  // current file ("" = never saved)
  bool screenshotDue_ = false;  // "Save Screenshot" was asked for: taken once this frame is drawn
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
  std::vector<RecoveredWork> recoveryOffers_;  // work of editors that are gone, newest first
  bool showHelp_ = false;
  ImGuiTextFilter helpFilter_;  // the F1 window's filter
  bool quitRequested_ = false;

  int frame_ = 0;
  bool paneHasKeys_ = false;  // a kernel's pane is under the pointer or has focus (this frame)
  ExtrusionPanes panes_;
  std::optional<ObjectId> panesFor_;
  std::vector<std::function<void()>> deferred_;  // the panels' commits of this frame (deferredCommit)
  StaticsPanel statics_;
  std::optional<ObjectId> staticsFor_;
  StonePanel stone_;  // "Build in stone" of a selected extrusion, in the left panel
  std::optional<ObjectId> stoneFor_;
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
  std::vector<std::pair<KifsSpec, Placement>> kifsSpecs_;  // what the layer shows, to see it change
  std::array<double, 10> kifsView_{};
  std::chrono::steady_clock::time_point kifsChanged_{};
  unsigned long kifsGeneration_ = 0;
  KifsFollowers followers_;  // the masses of KIFS buildings that follow another object, baked in the background
  bool kifsFailed_ = false;  // its shader did not build (logged once)
  bool kifsRefining_ = false;  // the march is coarse and will sharpen once the view is still
  bool firstFrame_ = true;
  Transform transform_;             // G, R or a gizmo drag in progress
  bool transformDragged_ = false;   // begun by a press on the gizmo: ends at the release
  bool transformCommitted_ = false; // its preview is in the History (one merged step)
  std::array<double, 8> hoverKey_{};  // what the hover was picked for
  FrameLatency latency_;                 // --latency-log: input stamps waiting for their frame
  std::unique_ptr<std::ofstream> latencyLog_;
  bool tapeTool_ = false;           // M: clicks measure instead of selecting
  TapeMeasure tape_;
  bool pushPullTool_ = false;       // P: a press on a face pushes or pulls it
  PushPull pushPull_;               // the drag in progress
  bool pushPullDragged_ = false;    // the button is held (else the face follows until a click)
  bool pushPullCommitted_ = false;  // its preview is in the History (one merged step)
  ObjectId pushPullObject_ = 0;
  Placement pushPullPlacement_;
  std::string pushPullError_;       // why the typed value is refused
  struct {
    ObjectId object = 0;
    std::uint64_t state = 0;
    extrude::ExtrusionResult result;
  } pushPullBuilt_;  // the shell picks are made on, built once per object and state
  struct {
    ObjectId object = 0;
    std::vector<Vec3> outline;
  } pushPullHover_;  // the face under the pointer while the tool is on
  std::optional<ObjectId> listFollows_;  // the active object the object list last scrolled to
};

}  // namespace corbel::editor
