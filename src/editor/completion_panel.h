#pragma once
// The form completion panel of a selected growth site (Ng, Ch. 7 and Fig. 8.6), under the growth
// panel: a region of the site (typed, or dragged by its corners in the plan view), the seeds the
// completion starts from (the entrances the grown units open onto the region, growth/entrances.h,
// or a count), a complexity range F_q ∈ [LO, HI] and how many forms; Generate runs the completion
// (growth/completion.h) as the editor's background job, with progress and Cancel; the forms come
// back as thumbnails with their F_q; a picked one is fitted into the region (growth/form_fit.h),
// shown in the plan view and the 3D view, and extruded into unit objects (editor/completion_edits.h)
// in one undoable commit.
#include "core/document.h"
#include "core/progress.h"
#include "growth/completion.h"
#include "growth/entrances.h"
#include "growth/form_fit.h"
#include "growth/kernel.h"
#include "render/overlay.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace corbel::editor {

struct CompletionHost {
  const Document* doc = nullptr;
  ObjectId object = 0;  // the selected growth site
  bool wait = false;    // scripted runs: the work runs at once, so every frame shows the current state
  bool busy = false;    // the editor's background job is taken
  bool settled = true;  // the site's build is current and no growth run is stepping it
  // The editor's background job (progress bar and Cancel in the status bar).
  std::function<void(std::string title, BackgroundJob::Work work, std::function<void()> onDone)> startJob;
  std::function<void(Document, const std::string& label, const std::string& mergeKey)> commit;
  std::function<void(const std::string&, bool)> log;
  // The view maps the site's build grows on (null: the exact CPU mapper) and their name, so the
  // model completed is the one the 3D view shows.
  std::shared_ptr<growth::ViewMapper> mapper;
  std::string maps = "exact";
};

class CompletionPanel {
 public:
  void draw(const CompletionHost& host, float x, float y, float w, float h);
  // The region and the fitted form in the 3D view.
  void drawOverlay(render::Overlay& overlay) const;
  void reset();  // another object was selected

  // The buttons, also the actions completion.seeds, .generate, .fit and .extrude.
  void takeSeeds(const CompletionHost& host);
  void generate(const CompletionHost& host);
  void fit(const CompletionHost& host);
  void extrude(const CompletionHost& host);
  bool canFit() const { return picked_ >= 0 && picked_ < int(forms_.forms.size()); }
  // A fitted form may become units when it obeys the growth rules among the grown model's.
  bool canExtrude() const { return fitted_.has_value() && fittedViolations_.empty(); }
  const std::vector<std::string>& fittedViolations() const { return fittedViolations_; }

 private:
  struct Model {
    growth::GrowthInput of;
    std::string maps;  // the view maps it grew on (CompletionHost::maps)
    growth::GrownModel grown;
  };
  const GrowthSpec* specOf(const CompletionHost& host) const;
  growth::GrowthInput inputOf(const CompletionHost& host) const;  // what the site's build grows from
  bool modelCurrent(const CompletionHost& host) const;
  void run(const CompletionHost& host, std::string title, BackgroundJob::Work work, std::function<void()> done);
  void defaultRegion(const growth::Site& site);
  void gapRegion();  // the region becomes the model's most enclosed gap on the storey (growth::findGap)
  void updateEntrances();
  // The storey's entrance options and what blocks an entrance (circulation and cores).
  std::pair<growth::EntranceOptions, std::vector<growth::Box>> entranceSetup() const;
  double storeyZ() const;
  void drawPlan(const CompletionHost& host, float w, float h);
  void drawThumbnails(float w);

  growth::PlanRect region_{};
  bool regionSet_ = false;
  bool regionChosen_ = false;
  bool zoom_ = true;              // the plan view shows the region and its surroundings, not the whole site
  bool dragging_ = false;         // a corner handle is held
  growth::PlanRect mapBounds_{};  // typed or dragged: the model's gap no longer replaces it
  int storey_ = 0;
  bool fromModel_ = true;
  int count_ = 5;
  float lo_ = 0.25f, hi_ = 0.30f;
  int forms_wanted_ = 8;
  int seed_ = 1;
  int storeys_ = 1;

  std::shared_ptr<const Model> model_;
  std::optional<growth::GrowthInput> attempted_;  // the spec last grown for (a failed one is not retried by itself)
  std::vector<growth::Entrance> entrances_;
  growth::PlanRect entrancesFor_{};
  int entrancesStorey_ = -1;
  const Model* entrancesModel_ = nullptr;

  growth::FormSet forms_;
  int formsSeeds_ = 0;
  int picked_ = -1;
  std::optional<growth::FittedForm> fitted_;
  std::vector<std::string> fittedViolations_;  // growth::formViolations of fitted_ in the model
  std::vector<bool> formFits_;  // per form, among a grown model: it obeys the growth rules in the region
  std::vector<Vec2> doors() const;               // the entrances a fit is to meet
  growth::FitOptions fitOptions() const;
  void judgeForms();
  int fittedForm_ = -1;
  double fittedZ_ = 0;
  growth::PlanRect fittedRegion_{};
  std::string status_;
};

}  // namespace corbel::editor
