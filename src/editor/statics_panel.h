#pragma once
// The statics panel of a selected masonry object (Whiting et al. 2009), right of the 3D view:
// the model's parameters, which are free for the search and within what bounds, the analysis
// (y, y/W², status, iterations, tension sites), "Make it stand" (Sec. 4) with progress and
// Cancel, keeping it standing while a fixed parameter is dragged (Fig. 13), and the energy
// landscape over one parameter (Fig. 8), and the collapse simulation (Sec. 5, Fig. 14: Play,
// Step, Reset, a shake, removing a block; editor/simulation.h), drawn in place of the design
// while it is shown and never written to the Document. With a second parameter chosen, the
// landscape is a grid over both, drawn as coloured cells (the standing ones red, as Fig. 8).
// The analysis, the landscape and the search run on worker threads (core/progress.h); the
// panel only reads their results and commits Document changes (editor/masonry_edits.h), so
// every edit is undoable. The viewport shows blocks coloured by their share of tension, the
// interface forces and the ground reactions.
#include "core/document.h"
#include "core/progress.h"
#include "editor/masonry_edits.h"
#include "editor/masonry_loads.h"
#include "editor/masonry_view.h"
#include "editor/simulation.h"
#include "render/overlay.h"
#include "statics/search.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace corbel::editor {

struct StaticsHost {
  const Document* doc = nullptr;
  const Scene* scene = nullptr;  // the built Scene (for "Every block in the Scene")
  ObjectId object = 0;
  bool wait = false;        // scripted runs: wait for the workers so every frame shows the current state
  double frameSeconds = 0;  // wall time since the last frame (the simulation plays by it)
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void()> endDrag;
  std::function<void(const std::string&, bool)> log;
};

class StaticsPanel {
 public:
  StaticsPanel() = default;
  ~StaticsPanel();  // cancels and joins the workers
  StaticsPanel(const StaticsPanel&) = delete;
  StaticsPanel& operator=(const StaticsPanel&) = delete;

  // Once per frame while a masonry object is selected: collects finished work (a finished
  // search is applied as one undoable change) and starts the analysis of a changed spec.
  void update(const StaticsHost& host);
  void draw(const StaticsHost& host, float x, float y, float w, float h);
  // Block colours (into `overlay`, depth-tested) and force arrows (into `onTop`, seen through
  // the blocks: they act inside them, on the interfaces) of the analysis, when it is of `spec`.
  // `placement` is the object's: the Scene's and the together analyses are in the world's frame
  // and are taken back into the object's, as the caller places everything drawn here.
  void drawOverlay(render::Overlay& overlay, render::Overlay& onTop, const MasonrySpec& spec,
                   const Placement& placement = {}) const;
  // "Make it stand" for the host's object; ignored while a search runs.
  void makeItStand(const StaticsHost& host);
  void cancelSearch();
  // The landscape over two parameters: the spec's first two free ones (the model's suggested
  // ones when fewer are free), or back to one parameter when two are chosen.
  void toggleLandscapeGrid(const StaticsHost& host);
  bool landscapeGridChosen() const { return !landscapeChoice2_.empty(); }
  bool searching() const { return search_ != nullptr; }
  void reset();  // another object was selected

  // The Simulate section. Each makes the simulation of the host's object first if there is
  // none (an error goes to the log). update() plays it within kSimFrameBudget per frame and
  // closes it when the object's spec changes.
  void simulatePlay(const StaticsHost& host);  // Play / Pause
  void simulateStep(const StaticsHost& host, int steps = 1);
  void simulateReset(const StaticsHost& host);
  void simulateShake(const StaticsHost& host);
  void simulateRemove(const StaticsHost& host);  // the block chosen in the list (the top one at first)
  void closeSimulation() { sim_.reset(); }
  // "Every block in the Scene" (statics/scene_blocks.h): every object of kind Block analysed
  // together, with the objects chosen in the list carried as loads, the selected object's
  // friction and kern; on a worker. While its result is shown, the view draws it in place of
  // the selected model's analysis.
  void analyseScene(const StaticsHost& host);
  bool sceneShown() const { return sceneView_.has_value() && showScene_; }
  // "All masonry objects together" (statics/composite.h): the object analysed with every other
  // masonry object of the Document, faces of different objects within the contact tolerance
  // touching; on a worker. makeThemStand searches the free parameters of all of them and
  // applies every object's values as one undo step.
  void analyseTogether(const StaticsHost& host);
  void makeThemStand(const StaticsHost& host);
  bool togetherShown() const { return togetherView_.has_value() && showTogether_; }
  bool simulating() const { return sim_ != nullptr; }
  bool simulationPlaying() const { return sim_ && sim_->playing(); }
  // The simulation to draw in place of the object's design, when there is one of `spec`.
  const Simulation* shownSimulation(const MasonrySpec& spec) const;
  // The load tool: while it is on, a click on a block of the selected masonry object places a
  // load there (editor/masonry_loads.h), one undo step; the tool stays on for more.
  bool placingLoad() const { return placingLoad_; }
  void setPlacingLoad(bool on) { placingLoad_ = on; }
  // A click in the 3D view at a ray (in the object's frame) while the load tool is on: places
  // the chosen kind of load on the block it hits. Returns whether a block was hit.
  bool placeLoad(const StaticsHost& host, const Vec3& origin, const Vec3& direction);
  // A click in the 3D view at a ray: chooses the simulated block it hits for removal, or
  // removes it at once with "remove on click". Returns whether a block was hit.
  bool pickBlock(const StaticsHost& host, const Vec3& origin, const Vec3& direction);

 private:
  void startAnalysis(const MasonrySpec& spec);
  void finishSearch(const StaticsHost& host);
  // Interactive editing (Fig. 13): re-solves the free parameters after a fixed one was dragged.
  void updateResolve(const StaticsHost& host);
  void drawParameters(const StaticsHost& host, const MasonrySpec& spec);
  void drawSettings(const StaticsHost& host, const MasonrySpec& spec);  // friction, α/√2, kern margin
  void drawLoads(const StaticsHost& host, const MasonrySpec& spec);
  void drawAnalysis(const MasonrySpec& spec);
  void drawSearch(const StaticsHost& host);
  void drawLandscape(const MasonrySpec& spec);
  void drawSimulation(const StaticsHost& host);
  void drawScene(const StaticsHost& host);
  void drawTogether(const StaticsHost& host);
  void collectTogether(const StaticsHost& host);  // a finished together analysis or search
  void collectScene(const StaticsHost& host);                       // a finished "Analyse the Scene" into sceneView_
  Simulation* simulationFor(const StaticsHost& host);               // made on first use; null when it cannot be
  using Range = std::pair<std::string, std::pair<double, double>>;  // a parameter and its bounds
  // The landscape's parameter and range for a spec: the chosen one, else the first free one.
  std::optional<Range> landscapeFor(const MasonrySpec& spec) const;
  // The second parameter of a two-parameter landscape: the one chosen, when it is continuous
  // and not the first.
  std::optional<Range> landscape2For(const MasonrySpec& spec) const;
  std::optional<Range> rangeOf(const MasonrySpec& spec, const std::string& name) const;
  bool gridMatches(const std::optional<Range>& x, const std::optional<Range>& y) const;
  void drawGrid(const LandscapeGrid& grid, const std::vector<std::pair<double, double>>& path);

  struct AnalysisWork {
    MasonrySpec spec;
    std::optional<Range> range, range2;  // of the landscape
    MasonryView view;
    std::atomic<bool> viewDone{false};  // the view is computed (the landscape may be cancelled after it)
    std::optional<Landscape> landscape;
    std::optional<LandscapeGrid> grid;
  };
  std::unique_ptr<BackgroundJob> analysis_;
  std::shared_ptr<AnalysisWork> analysing_;
  std::optional<MasonryView> view_;
  std::optional<Landscape> landscape_;
  std::optional<LandscapeGrid> grid_;
  std::string landscapeChoice_;   // "" = the first free parameter
  std::string landscapeChoice2_;  // "" = none: the landscape is over one parameter

  std::unique_ptr<BackgroundJob> search_;
  ObjectId searchObject_ = 0;
  MasonrySpec searchStart_;
  std::shared_ptr<statics::SearchResult> searchResult_;
  std::shared_ptr<SearchTrace> searchTrace_;        // the last search's evaluations, drawn live
  std::vector<statics::FreeParameter> searchFree_;  // what it moves (for its path on the grid)
  std::optional<statics::SearchResult> lastSearch_;
  std::vector<ParameterChange> lastChanges_;  // what the last applied search changed (before → after)

  bool placingLoad_ = false;
  int loadKind_ = 0;  // 0: a weight (kg) at the clicked point, 1: a pressure (Pa) on the clicked face
  float loadMass_ = float(kDefaultLoadMass), windPressure_ = float(kDefaultWindPressure);

  bool interactive_ = false;
  std::optional<std::string> pendingResolve_;  // a fixed parameter dragged since the last re-solve
  std::unique_ptr<BackgroundJob> resolve_;
  ObjectId resolveObject_ = 0;
  MasonrySpec resolveStart_;
  std::string resolveParameter_;
  std::shared_ptr<statics::SearchResult> resolveResult_;

  std::unique_ptr<Simulation> sim_;
  std::string removeChoice_;  // the block the remove tool takes ("" = the top one)
  bool removeOnClick_ = false;

  std::unique_ptr<BackgroundJob> sceneJob_;
  std::shared_ptr<MasonryView> sceneResult_;
  std::uint64_t sceneJobRevision_ = 0;
  std::optional<MasonryView> sceneView_;
  std::uint64_t sceneRevision_ = 0;  // the Scene's revision when sceneView_ was analysed
  std::set<ObjectId> sceneLoads_;    // objects carried as loads
  bool showScene_ = true;

  struct TogetherWork {
    MasonryTogether together;
    Document started;  // the Document it was made from
    bool search = false;
    MasonryView view;
    statics::SearchResult result;
  };
  std::unique_ptr<BackgroundJob> togetherJob_;
  std::shared_ptr<TogetherWork> togetherWork_;
  std::optional<MasonryView> togetherView_;
  Document togetherOf_;  // the Document togetherView_ was analysed on
  std::vector<ParameterChange> togetherChanges_;  // what the last "Make them stand" changed, "object/parameter"
  float togetherToleranceMm_ = 1.0f;
  bool showTogether_ = true;

  bool colours_ = true, arrows_ = true;
};

}  // namespace corbel::editor
