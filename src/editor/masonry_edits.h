#pragma once
// The statics panel's changes to a masonry object (core/masonry_spec.h), as pure functions
// on a Document: the panel commits what they return, so every change is one undo step and
// the tests replay exactly what a click does. Each checks the result against the model
// (statics::modelOf, statics::validateFreeParameters) and throws corbel::Error with the
// model's reason, leaving the Document as it was.
#include "core/document.h"
#include "core/progress.h"
#include "statics/search.h"

#include <mutex>
#include <optional>
#include <string>

namespace corbel::editor {

// The masonry spec of object `id`; throws corbel::Error when there is none.
MasonrySpec& masonryOf(Document& doc, ObjectId id);

// Sets parameter `name` of the object's model to `value` (kept in name order).
void setMasonryParameter(Document& doc, ObjectId id, const std::string& name, double value);

// Frees parameter `name` for the search within [lo, hi], or, with nullopt, fixes it again.
void setMasonryFree(Document& doc, ObjectId id, const std::string& name,
                    std::optional<std::pair<double, double>> bounds);

// The analysis settings: friction α (Sec. 3.1), whether to use α/√2 (the pyramid inside the
// cone), and the kern margin (Sec. 3.4). Throws for α outside [0, 100] or a margin outside [0, 1).
void setMasonryAnalysis(Document& doc, ObjectId id, double friction, bool conservative, double kern);

// Loads on the object's blocks (core/masonry_spec.h). Each checks the load against the model
// (a block and face it has, finite numbers) and throws with the kernel's reason, changing
// nothing. An unnamed load is called "load N" (a point load) or "wind N" (a pressure), N the
// first number free. addMasonryLoad returns the new load's index.
std::size_t addMasonryLoad(Document& doc, ObjectId id, MasonryLoad load);
void setMasonryLoad(Document& doc, ObjectId id, std::size_t index, MasonryLoad load);
void removeMasonryLoad(Document& doc, ObjectId id, std::size_t index);

// What a change did to the model's parameters (after "Make it stand": the before → after list),
// every parameter whose value differs, in the model's order; the model's defaults stand for
// parameters a spec does not set.
struct ParameterChange {
  std::string name;
  double before = 0, after = 0;
};
std::vector<ParameterChange> parameterChanges(const MasonrySpec& before, const MasonrySpec& after);

// Bounds offered when the user frees `p`: the model's suggestion for it when there is one,
// else its value ± 50 % (± 1 at zero), clipped into its valid range.
std::pair<double, double> defaultBounds(const statics::Parameter& p,
                                        const std::vector<statics::FreeParameter>& suggested);

// The free parameters a search moves: the spec's, or the model's suggestion when it frees none.
std::vector<statics::FreeParameter> searchFreeOf(const MasonrySpec& spec);

// The evaluations of a running search as they come (y/W² and the free values of each), written
// by the search's thread and read by the panel's while it runs, for the infeasibility history.
class SearchTrace {
 public:
  void add(double measure, std::vector<double> values) {
    std::lock_guard<std::mutex> lock(mutex_);
    measures_.push_back(measure);
    values_.push_back(std::move(values));
  }
  std::vector<double> measures() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return measures_;
  }
  std::vector<std::vector<double>> values() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return values_;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<double> measures_;
  std::vector<std::vector<double>> values_;
};

// "Make it stand" (Sec. 4): the search from the spec's values over searchFreeOf(spec), with
// the spec's friction and kern. Progress gets the evaluation count as a fraction of the cap
// and the search stops (status Cancelled) when the progress is cancelled; `trace`, when given,
// gets every evaluation as it is made (the same ones, in order, as the result's history).
statics::SearchResult searchMasonry(const MasonrySpec& spec, Progress* progress = nullptr, int maxEvaluations = 200,
                                    SearchTrace* trace = nullptr);

// Interactive editing (Sec. 5, Fig. 13): the user has just set the fixed parameter `name` (the
// spec holds its new value); the free parameters are searched again from the spec's values,
// which are usually close (statics::updateAfterEdit, without the strict LP check, for speed).
// Throws corbel::Error when `name` is free or unknown. Apply the result with applySearch.
statics::SearchResult resolveAfterEdit(const MasonrySpec& spec, const std::string& name, Progress* progress = nullptr);

// Applies a search result to object `id` as one change: the free parameters take the
// result's values. Nothing is applied (nullopt, with the reason in `why`) when the search was
// cancelled or failed, or when the object's spec is no longer `started` (it was edited or
// removed while the search ran: the result belongs to a structure that is gone).
std::optional<Document> applySearch(const Document& doc, ObjectId id, const MasonrySpec& started,
                                    const statics::SearchResult& result, std::string* why = nullptr);

// Every masonry object of the document as one structure (statics/composite.h): the parts in the
// document's order, the objects' free parameters under "object/parameter" (their models'
// suggested ones when no object frees any), and the analysis settings of `lead` (the selected
// object: its friction, α/√2 and kern) with faces of different objects within
// `contactTolerance` m touching. Throws corbel::Error with the kernel's reason.
struct MasonryTogether {
  statics::ParametricModel model;
  std::vector<statics::FreeParameter> free;
  statics::AnalysisOptions options;
  std::vector<ObjectId> objects;
};
MasonryTogether masonryTogether(const Document& doc, ObjectId lead, double contactTolerance);

// Search settings with `analysis` that report each evaluation to `progress` (may be null) as a
// fraction of `maxEvaluations`, record it in `trace` (may be null) and stop once the progress is
// cancelled: what every search the editor runs in the background uses.
statics::SearchOptions reportingSearchOptions(const statics::AnalysisOptions& analysis, Progress* progress,
                                              int maxEvaluations, SearchTrace* trace = nullptr);

// Make them stand together: the search over `together.free`, then (applyTogether) every object's
// own values written into the Document as one change. Nothing is applied (nullopt, the reason in
// `why`) when the search did not stand or any of the objects changed while it ran.
statics::SearchResult searchTogether(const MasonryTogether& together, Progress* progress = nullptr,
                                     int maxEvaluations = 200);
std::optional<Document> applyTogether(const Document& doc, const Document& started, const MasonryTogether& together,
                                      const statics::SearchResult& result, std::string* why = nullptr);

}  // namespace corbel::editor
