#pragma once
// The growth panel of a selected growth site (Ng, Ch. 4), right of the 3D view, in three tabs:
//  - Grow: the site's summary, the run's seed, Step, Run, Pause, Grow to the end and Reset, the
//    view maps the runs grow on (exact CPU or GL, an editor setting), and
//    the slice (Fig. 8.3): everything at or above a height is hidden in the 3D view, a view
//    setting that never changes the Document; and the 3D view's shadows with the sun's azimuth
//    and elevation (Fig. 8.5), view settings too;
//  - Site: the hand-placed cores, circulation and seeds, listed, typed or dragged in a plan view,
//    added and deleted; a seed's target, behaviour and locked faces (editor/growth_edits.h);
//  - Statistics: Table 8.1 for the model as grown (editor/growth_inspect.h), and the view-map
//    inspector, a window with the four view maps (those the model grew on) in false colour by
//    unit id and in grey by depth.
// The Document holds the site and how many steps it grows (core/growth_spec.h); every change is
// one commit and the object's Scene build grows it off the UI thread (core/live_sync.h), so the
// window never waits and a whole Run is one undo step. A refused change names the field and
// leaves the Document as it was.
#include "core/document.h"
#include "core/progress.h"
#include "editor/growth_edits.h"
#include "editor/growth_inspect.h"
#include "render/overlay.h"

#include <array>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace corbel::editor {

struct GrowthHost {
  const Document* doc = nullptr;
  ObjectId object = 0;
  bool current = true;                // the Scene shows the current document
  bool wait = false;                  // scripted runs: measure the model at once, not in the background
  std::string error;                  // the kernel's message for the object
  std::vector<std::string> warnings;  // of its last build (growth/kernel.h: when every unit stopped)
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void()> endDrag;
  std::function<void(const std::string&, bool)> log;
  // The editor's background job (progress bar and Cancel in the status bar), for Freeze.
  std::function<void(std::string title, BackgroundJob::Work work, std::function<void()> onDone)> startJob;
  bool busy = false;  // that job is taken
  // The 3D view's shadows and sun (Fig. 8.5), view settings the Grow tab changes; may be null.
  bool* shadows = nullptr;
  double* sunAzimuth = nullptr;
  double* sunElevation = nullptr;
  // The view maps the object's build grows on and the inspector measures with (null: the exact
  // CPU mapper), and their name ("exact", or the GL mapper's: editor/view_map_context.h).
  std::shared_ptr<growth::ViewMapper> mapper;
  std::string maps = "exact";
  // The Grow tab's choice of GL view maps, an editor setting; null when there is no GL mapper.
  bool* glViewMaps = nullptr;
  double* glPixel = nullptr;  // and the GL maps' pixel size (m), with it
};

class GrowthPanel {
 public:
  // Freeze: grows the model as the build does (a background job; at once when the host waits),
  // then turns its units into unit objects (freezeGrowth), if the site has not changed meanwhile.
  void freeze(const GrowthHost& host);
  // Advances a running growth by one step once the Scene has caught up with the last one.
  void update(const GrowthHost& host);
  void draw(const GrowthHost& host, float x, float y, float w, float h);
  // The view-map inspector, a window of its own over the 3D view at (x, y), w wide, when first shown.
  void drawViewMaps(const GrowthHost& host, float x, float y, float w);
  void reset();
  // The buttons, also the actions growth.step and growth.run.
  void step(const GrowthHost& host);
  void toggleRun(const GrowthHost& host);
  bool running() const { return running_; }
  // Site editing, also the actions growth.add_core, growth.add_circulation, growth.add_seed and
  // growth.delete (of the entry selected in the Site tab).
  void add(const GrowthHost& host, SiteItem item);
  void removeSelected(const GrowthHost& host);
  bool hasSelection() const { return selected_ >= 0; }
  // The Site tab's frame edits as actions: growth.add_storey (one storey more, of the same
  // height) and growth.widen_site (a box envelope dx metres longer in x); each one undo step,
  // refused (logged) as the tab's fields are.
  void addStorey(const GrowthHost& host);
  void widenSite(const GrowthHost& host, double dx);
  // The slice height, when slicing (growth.slice_down lowers it a storey, growth.slice_up raises
  // it, past the top it is off).
  std::optional<double> sliceHeight() const { return slicing_ ? std::optional<double>(slice_) : std::nullopt; }
  void sliceStorey(const GrowthHost& host, int by);
  // Shows a tab (0 Grow, 1 Site, 2 Statistics), also the actions growth.site and growth.statistics.
  void showTab(int tab) { wantTab_ = tab; }
  void toggleViewMaps() { showViewMaps_ = !showViewMaps_; }
  // Dragging in the 3D view while the Site tab is shown: a press on a hand-placed core,
  // circulation box or seed, or next to an envelope corner's vertical edge, grabs it (true: the
  // view does not orbit); each move drags it in plan on the horizontal plane through the grabbed
  // point, in 0.5 m steps, refused as the plan view's drag is; the release closes the one undo
  // step. The grabbed entry is drawn in the view (drawViewOverlay).
  bool siteShown() const { return siteShown_; }
  bool beginViewDrag(const GrowthHost& host, const Vec3& origin, const Vec3& dir);
  void viewDrag(const GrowthHost& host, const Vec3& origin, const Vec3& dir);
  void endViewDrag(const GrowthHost& host);
  bool viewDragging() const { return viewGrab_.has_value(); }
  // While the Site tab is shown: the envelope's outline at the base and the top with its corner
  // edges, and the chosen entry's box in yellow.
  void drawViewOverlay(render::Overlay& overlay) const;
  bool viewMapsShown() const { return showViewMaps_; }

 private:
  void commitSteps(const GrowthHost& host, int steps, const std::string& label, const std::string& merge = {});
  // Commits an edit's spec, or shows (and with `report`, logs) its refusal.
  bool commitSite(const GrowthHost& host, const SiteEditResult& r, const std::string& label, const std::string& merge,
                  bool report);
  void parseSite(const GrowthSpec& spec);
  void drawGrow(const GrowthHost& host, const GrowthSpec& spec);
  void drawSite(const GrowthHost& host, const GrowthSpec& spec);
  void drawFrame(const GrowthHost& host, const GrowthSpec& spec);
  void drawPlan(const GrowthHost& host, const GrowthSpec& spec, float w, float h);
  void drawStatistics(const GrowthHost& host);
  void applyFreeze(const GrowthHost& host);
  // Starts (or, waiting, does) measuring the model when the shown one is not of `spec`.
  void requestInspection(const GrowthHost& host, const growth::GrowthInput& input);
  void pollInspection();
  void uploadViewMaps();

  bool running_ = false;
  std::string summaryOf_, summary_;   // the site text summarised, and the summary
  std::optional<growth::Site> site_;  // of summaryOf_, when it parses
  HandPlaced hand_;                   // the site file's own entries (of summaryOf_)
  SiteFrame frame_;                   // its envelope, storeys and seed controls (of summaryOf_)

  int wantTab_ = -1;
  SiteItem kind_ = SiteItem::Core;
  int selected_ = -1;
  std::string siteError_;
  int planStorey_ = 0;
  bool dragging_ = false;
  bool siteEditOpen_ = false;         // a site edit's merge is open (a field or the plan is held)
  double dragX_ = 0, dragY_ = 0;      // where the drag started, meters
  HandPlaced dragFrom_;               // the entries when the drag started
  int dragCorner_ = -1;               // the envelope corner being dragged in the plan view, or -1
  std::vector<Vec2> dragPlan_;        // the envelope's plan when that drag started
  bool siteShown_ = false;            // the Site tab was drawn last frame
  std::optional<SiteGrab> viewGrab_;  // what a drag in the 3D view holds

  bool slicing_ = false;
  double slice_ = 0;

  struct Freezing {
    growth::GrowthInput of;
    growth::GrownModel grown;
    bool done = false;
  };
  std::shared_ptr<Freezing> freezing_;  // a Freeze on its way

  bool statsShown_ = false;
  bool showViewMaps_ = false;
  std::shared_ptr<const GrowthInspection> inspection_;
  std::future<std::shared_ptr<const GrowthInspection>> pending_;
  std::optional<growth::GrowthInput> pendingFor_, failedFor_;
  std::string pendingMaps_, failedMaps_;  // the view maps of pendingFor_ and failedFor_
  std::string inspectError_;
  std::array<unsigned, 8> textures_{};  // per direction its unit ids, then (4 + d) its depth
  std::array<ViewMapImage, 4> images_;
  const GrowthInspection* texturesOf_ = nullptr;
};

}  // namespace corbel::editor
