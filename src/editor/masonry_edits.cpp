#include "editor/masonry_edits.h"

#include "core/error.h"
#include "editor/masonry_view.h"
#include "statics/composite.h"
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
  // A spec that frees nothing is valid (the search then takes the model's suggestion).
  if (spec.free.empty()) return;
  std::vector<statics::FreeParameter> free;
  for (const MasonryFree& f : spec.free) free.push_back({f.name, f.lo, f.hi});
  statics::validateFreeParameters(model.parameters, free);
}

// Throws with the kernel's reason when a load names a block or face the model does not have.
void checkLoads(const MasonrySpec& spec) {
  check(spec);
  try {
    const statics::ParametricModel model = statics::modelOf(spec);
    model.build(model.parameters);  // applies the loads, which throws for one that does not fit
  } catch (const InputError& e) {
    throw Error(e.reason);
  }
}

}  // namespace

void setMasonryAnalysis(Document& doc, ObjectId id, double friction, bool conservative, double kern) {
  if (!std::isfinite(friction) || friction < 0 || friction > 100)
    throw Error("the friction coefficient must be a number in [0, 100]");
  if (!std::isfinite(kern) || kern < 0 || kern >= 1)
    throw Error("the kern margin must be in [0, 1): 1 would shrink every contact to a point");
  MasonrySpec& spec = masonryOf(doc, id);
  spec.friction = friction;
  spec.conservativeFriction = conservative;
  spec.kern = kern;
}

std::size_t addMasonryLoad(Document& doc, ObjectId id, MasonryLoad load) {
  MasonrySpec spec = masonryOf(doc, id);
  if (spec.loads.size() >= limits::kMaxMasonryLoads)
    throw Error("an object carries at most " + std::to_string(limits::kMaxMasonryLoads) + " loads");
  if (load.name.empty()) {
    // "load 3": the first number no load of the object is called by.
    for (std::size_t k = 1;; ++k) {
      const std::string n = (load.face >= 0 ? "wind " : "load ") + std::to_string(k);
      if (std::none_of(spec.loads.begin(), spec.loads.end(), [&](const MasonryLoad& l) { return l.name == n; })) {
        load.name = n;
        break;
      }
    }
  }
  spec.loads.push_back(std::move(load));
  checkLoads(spec);
  masonryOf(doc, id) = std::move(spec);
  return masonryOf(doc, id).loads.size() - 1;
}

void setMasonryLoad(Document& doc, ObjectId id, std::size_t index, MasonryLoad load) {
  MasonrySpec spec = masonryOf(doc, id);
  if (index >= spec.loads.size()) throw Error("there is no load " + std::to_string(index));
  spec.loads[index] = std::move(load);
  checkLoads(spec);
  masonryOf(doc, id) = std::move(spec);
}

void removeMasonryLoad(Document& doc, ObjectId id, std::size_t index) {
  MasonrySpec& spec = masonryOf(doc, id);
  if (index >= spec.loads.size()) throw Error("there is no load " + std::to_string(index));
  spec.loads.erase(spec.loads.begin() + std::ptrdiff_t(index));
}

std::vector<ParameterChange> parameterChanges(const MasonrySpec& before, const MasonrySpec& after) {
  std::vector<ParameterChange> out;
  if (before.model != after.model) return out;
  const statics::ParametricModel a = statics::modelOf(before), b = statics::modelOf(after);
  for (const statics::Parameter& p : a.parameters.all()) {
    const double now = b.parameters[p.name];
    if (now != p.value) out.push_back({p.name, p.value, now});
  }
  return out;
}

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

statics::SearchOptions reportingSearchOptions(const statics::AnalysisOptions& analysis, Progress* progress,
                                              int maxEvaluations, SearchTrace* trace) {
  statics::SearchOptions options;
  options.analysis = analysis;
  options.maxEvaluations = maxEvaluations;
  options.progress = [progress, maxEvaluations, trace](const statics::SearchProgress& p) {
    if (trace) trace->add(p.measure, p.values);
    if (!progress) return true;
    progress->report(std::min(1.0, double(p.evaluation) / maxEvaluations), "searching");
    return !progress->cancelled();
  };
  return options;
}

namespace {

// The search settings of a spec, reporting evaluations to `progress` and stopping when it is
// cancelled.
statics::SearchOptions searchOptionsOf(const MasonrySpec& spec, Progress* progress, int maxEvaluations,
                                       SearchTrace* trace = nullptr) {
  return reportingSearchOptions(analysisOptionsOf(spec), progress, maxEvaluations, trace);
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

MasonryTogether masonryTogether(const Document& doc, ObjectId lead, double contactTolerance) {
  MasonryTogether t;
  std::vector<statics::CompositePart> parts;
  for (const DocObject& o : doc.objects) {
    const auto* spec = std::get_if<MasonrySpec>(&o.spec);
    if (!spec) continue;
    try {
      parts.push_back({o.name, statics::modelOf(*spec), o.placement});
    } catch (const InputError& e) {
      throw Error(o.name + ": " + e.reason);
    }
    for (const MasonryFree& f : spec->free) t.free.push_back({o.name + "/" + f.name, f.lo, f.hi});
    t.objects.push_back(o.id);
    if (o.id == lead) t.options = analysisOptionsOf(*spec);
  }
  if (parts.size() < 2) throw Error("there is no other masonry object to analyse this one with");
  t.model = statics::compositeModel(std::move(parts));
  if (t.free.empty()) t.free = t.model.suggestedFree;
  t.options.contactTolerance = contactTolerance;
  return t;
}

statics::SearchResult searchTogether(const MasonryTogether& together, Progress* progress, int maxEvaluations) {
  return statics::searchParameters(together.model, together.free,
                                   reportingSearchOptions(together.options, progress, maxEvaluations),
                                   &together.model.parameters);
}

std::optional<Document> applyTogether(const Document& doc, const Document& started, const MasonryTogether& together,
                                      const statics::SearchResult& result, std::string* why) {
  auto refuse = [why](std::string reason) -> std::optional<Document> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (result.status == statics::SearchStatus::Cancelled) return refuse("the search was cancelled");
  if (result.status != statics::SearchStatus::Feasible) return refuse("they do not stand together: " + result.message);
  Document next = doc;
  for (ObjectId id : together.objects) {
    const DocObject* now = doc.find(id);
    const DocObject* then = started.find(id);
    if (!now || !then || !(now->spec == then->spec) || !(now->placement == then->placement) || now->name != then->name)
      return refuse("an object was edited while the search ran");
  }
  for (const statics::FreeParameter& f : result.free) {
    const auto [object, parameter] = statics::splitCompositeName(f.name);
    for (ObjectId id : together.objects)
      if (next.find(id)->name == object) setMasonryParameter(next, id, parameter, result.values[f.name]);
  }
  return next;
}

}  // namespace corbel::editor
