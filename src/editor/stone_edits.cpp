#include "editor/stone_edits.h"

#include "compose/stone_extrusion.h"
#include "editor/masonry_edits.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace corbel::editor {

namespace {

ExtrusionSpec& extrusionIn(Document& doc, ObjectId id) {
  DocObject* o = doc.find(id);
  auto* e = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
  if (!e) throw InputError("object " + std::to_string(id), "not a procedural extrusion");
  return *e;
}

}  // namespace

Document setStone(const Document& doc, ObjectId id, bool on) {
  Document next = doc;
  ExtrusionSpec& e = extrusionIn(next, id);
  if (on && !e.masonry) e.masonry = StoneWalls{};
  if (!on) e.masonry.reset();
  return next;
}

Document setStoneSetting(const Document& doc, ObjectId id, const std::string& name, double value) {
  Document next = doc;
  ExtrusionSpec& e = extrusionIn(next, id);
  if (!e.masonry) throw InputError("masonry", "the extrusion is not built in stone: switch Build in stone on first");
  const statics::ParametricModel model = statics::stoneModel(e);  // throws naming what cannot be stone
  if (!model.parameters.has(name)) throw InputError("masonry." + name, "no such stone setting");
  const statics::Parameter& p = model.parameters.find(name);
  if (!std::isfinite(value) || value < p.lo || value > p.hi)
    throw InputError("masonry." + name, std::to_string(value) + " is outside [" + std::to_string(p.lo) + ", " +
                                            std::to_string(p.hi) + "] (" + p.description + ")");
  statics::ParameterSet values = model.parameters;
  values.set(name, p.continuous ? value : std::round(value));
  e = statics::stoneSpecAt(e, values);
  return next;
}

Document setOpeningHead(const Document& doc, ObjectId id, const std::string& anchor, OpeningHead head) {
  Document next = doc;
  ExtrusionSpec& e = extrusionIn(next, id);
  if (!e.masonry) throw InputError("masonry", "the extrusion is not built in stone: switch Build in stone on first");
  bool found = false;
  for (const MeshAnchor& a : e.anchors)
    found = found || (a.name == anchor && (a.feature == FeatureKind::Door || a.feature == FeatureKind::Window));
  if (!found) throw InputError("masonry.openings." + anchor, "no door or window anchor named \"" + anchor + "\"");
  std::vector<StoneOpening>& list = e.masonry->openings;
  std::erase_if(list, [&](const StoneOpening& o) { return o.anchor == anchor; });
  if (head != OpeningHead::Lintel) list.push_back({anchor, head});
  std::sort(list.begin(), list.end(), [](const StoneOpening& a, const StoneOpening& b) { return a.anchor < b.anchor; });
  return next;
}

MasonryView analyseStone(const ExtrusionSpec& spec, Progress* progress) {
  try {
    const statics::ParametricModel model = statics::stoneModel(spec);
    return analyseModel(model, model.parameters, statics::AnalysisOptions{}, progress);
  } catch (const Cancelled&) {
    throw;
  } catch (const std::exception& ex) {
    MasonryView v;
    v.fromModel = true;
    v.error = ex.what();
    return v;
  }
}

statics::SearchResult searchStone(const ExtrusionSpec& spec, Progress* progress, int maxEvaluations,
                                  const std::vector<statics::FreeParameter>* free) {
  const statics::ParametricModel model = statics::stoneModel(spec);
  return statics::searchParameters(model, free ? *free : model.suggestedFree,
                                   reportingSearchOptions(statics::AnalysisOptions{}, progress, maxEvaluations),
                                   &model.parameters);
}

std::vector<statics::FreeParameter> stoneSearchFree(const ExtrusionSpec& spec, bool addButtresses) {
  const statics::ParametricModel model = statics::stoneModel(spec);
  std::vector<statics::FreeParameter> free = model.suggestedFree;
  const bool has = std::any_of(free.begin(), free.end(), [](const statics::FreeParameter& f) { return f.name == "buttressDepth"; });
  if (addButtresses && !has) {
    const statics::Parameter& p = model.parameters.find("buttressDepth");
    free.push_back({"buttressDepth", std::min(0.1, p.hi), p.hi});
  }
  return free;
}

double buttressDepthOf(const ExtrusionSpec& spec) {
  double deepest = 0;
  for (const PlanStep& st : spec.steps) deepest = std::max(deepest, st.depth);
  return deepest;
}

std::optional<Document> applyStoneSearch(const Document& doc, ObjectId id, const ExtrusionSpec& started,
                                         const statics::SearchResult& result, std::string* why) {
  auto refuse = [why](std::string reason) -> std::optional<Document> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (result.status == statics::SearchStatus::Cancelled) return refuse("the search was cancelled");
  if (result.status != statics::SearchStatus::Feasible) return refuse("no standing walls found: " + result.message);
  const DocObject* o = doc.find(id);
  const auto* e = o ? std::get_if<ExtrusionSpec>(&o->spec) : nullptr;
  if (!e || !(*e == started) || !e->masonry) return refuse("the extrusion was edited while the search ran");
  Document next = doc;
  ExtrusionSpec& target = extrusionIn(next, id);
  target = statics::stoneSpecAt(target, result.values);
  return next;
}

}  // namespace corbel::editor
