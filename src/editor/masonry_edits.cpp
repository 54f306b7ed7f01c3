#include "editor/masonry_edits.h"

#include "core/error.h"
#include "statics/kernel.h"

#include <algorithm>
#include <cmath>

namespace corbel::editor {

MasonrySpec& masonryOf(Document& doc, ObjectId id) {
  DocObject* o = doc.find(id);
  if (!o) throw Error("there is no object with id " + std::to_string(id));
  auto* spec = std::get_if<MasonrySpec>(&o->spec);
  if (!spec) throw Error(o->name + " is not a masonry object");
  return *spec;
}

namespace {

// Throws with the model's reason when the spec does not make a model with valid free bounds.
void check(const MasonrySpec& spec) {
  statics::ParametricModel model;
  try {
    model = statics::modelOf(spec);
  } catch (const InputError& e) {
    throw Error(e.reason);
  }
  std::vector<statics::FreeParameter> free;
  for (const MasonryFree& f : spec.free) free.push_back({f.name, f.lo, f.hi});
  statics::validateFreeParameters(model.parameters, free);
}

}  // namespace

void setMasonryParameter(Document& doc, ObjectId id, const std::string& name, double value) {
  MasonrySpec spec = masonryOf(doc, id);
  auto it = std::lower_bound(spec.parameters.begin(), spec.parameters.end(), name,
                             [](const MasonryParameter& p, const std::string& n) { return p.name < n; });
  if (it != spec.parameters.end() && it->name == name)
    it->value = value;
  else
    spec.parameters.insert(it, MasonryParameter{name, value});
  check(spec);
  masonryOf(doc, id) = std::move(spec);
}

void setMasonryFree(Document& doc, ObjectId id, const std::string& name,
                    std::optional<std::pair<double, double>> bounds) {
  MasonrySpec spec = masonryOf(doc, id);
  auto it = std::find_if(spec.free.begin(), spec.free.end(), [&](const MasonryFree& f) { return f.name == name; });
  if (!bounds) {
    if (it != spec.free.end()) spec.free.erase(it);
  } else if (it != spec.free.end()) {
    it->lo = bounds->first;
    it->hi = bounds->second;
  } else {
    spec.free.push_back({name, bounds->first, bounds->second});
  }
  check(spec);
  masonryOf(doc, id) = std::move(spec);
}

std::pair<double, double> defaultBounds(const statics::Parameter& p,
                                        const std::vector<statics::FreeParameter>& suggested) {
  for (const statics::FreeParameter& f : suggested)
    if (f.name == p.name) return {f.lo, f.hi};
  const double half = p.value == 0 ? 1.0 : 0.5 * std::abs(p.value);
  double lo = std::max(p.lo, p.value - half), hi = std::min(p.hi, p.value + half);
  if (lo > hi) lo = hi = p.value;
  return {lo, hi};
}

std::vector<statics::FreeParameter> searchFreeOf(const MasonrySpec& spec) {
  std::vector<statics::FreeParameter> free;
  for (const MasonryFree& f : spec.free) free.push_back({f.name, f.lo, f.hi});
  if (free.empty()) free = statics::modelOf(spec).suggestedFree;
  return free;
}

namespace {

// The search settings of a spec, reporting evaluations to `progress` and stopping when it is
// cancelled.
statics::SearchOptions searchOptionsOf(const MasonrySpec& spec, Progress* progress, int maxEvaluations,
                                       SearchTrace* trace = nullptr) {
  statics::SearchOptions options;
  options.analysis.friction = spec.friction;
  options.analysis.kernShrink = spec.kern;
  options.maxEvaluations = maxEvaluations;
  options.progress = [progress, maxEvaluations, trace](const statics::SearchProgress& p) {
    if (trace) trace->add(p.measure, p.values);
    if (!progress) return true;
    progress->report(std::min(1.0, double(p.evaluation) / maxEvaluations), "searching");
    return !progress->cancelled();
  };
  return options;
}

statics::SearchResult cancelledSearch() {
  statics::SearchResult r;
  r.status = statics::SearchStatus::Cancelled;
  r.message = "cancelled";
  return r;
}

}  // namespace

statics::SearchResult searchMasonry(const MasonrySpec& spec, Progress* progress, int maxEvaluations,
                                    SearchTrace* trace) {
  const statics::ParametricModel model = statics::modelOf(spec);
  if (progress && progress->cancelled()) return cancelledSearch();
  return statics::searchParameters(model, searchFreeOf(spec), searchOptionsOf(spec, progress, maxEvaluations, trace),
                                   &model.parameters);
}

statics::SearchResult resolveAfterEdit(const MasonrySpec& spec, const std::string& name, Progress* progress) {
  const statics::ParametricModel model = statics::modelOf(spec);
  if (progress && progress->cancelled()) return cancelledSearch();
  statics::SearchOptions options = searchOptionsOf(spec, progress, 200);
  options.strictCheck = false;
  return statics::updateAfterEdit(model, searchFreeOf(spec), model.parameters, name, model.parameters[name], options);
}

std::optional<Document> applySearch(const Document& doc, ObjectId id, const MasonrySpec& started,
                                    const statics::SearchResult& result, std::string* why) {
  auto refuse = [why](std::string reason) -> std::optional<Document> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (result.status == statics::SearchStatus::Cancelled) return refuse("the search was cancelled");
  if (result.status == statics::SearchStatus::Failed) return refuse("the search failed: " + result.message);
  const DocObject* o = doc.find(id);
  const auto* spec = o ? std::get_if<MasonrySpec>(&o->spec) : nullptr;
  if (!spec) return refuse("the object is gone");
  if (!(*spec == started)) return refuse("the object was edited while the search ran");
  Document next = doc;
  for (const statics::FreeParameter& f : result.free) setMasonryParameter(next, id, f.name, result.values[f.name]);
  return next;
}

}  // namespace corbel::editor
