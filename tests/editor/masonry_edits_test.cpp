// editor/masonry_edits.h: the statics panel's Document changes are checked against the model,
// undoable through the History, and "Make it stand" applies a structure that stands by the
// strict LP test (an algorithm independent of the penalty QP the search minimises).
#include "editor/masonry_edits.h"

#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "editor/masonry_view.h"
#include "statics/analysis.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace corbel::editor {
namespace {

struct Example {
  Document doc;
  ObjectId id = 0;
  Example() {
    doc = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-arch.corbel").document;
    id = doc.objects.at(0).id;
  }
  const MasonrySpec& spec() const { return std::get<MasonrySpec>(doc.find(id)->spec); }
};

const MasonryFree* freeOf(const MasonrySpec& s, const std::string& name) {
  for (const MasonryFree& f : s.free)
    if (f.name == name) return &f;
  return nullptr;
}

TEST(SetMasonryFree, FreeingAndFixingAreUndoableSteps) {
  Example e;
  History history(e.doc);
  Document d = history.current();
  setMasonryFree(d, e.id, "columnHeight", std::make_pair(0.5, 1.5));
  history.commit(d, "Free columnHeight");
  const MasonryFree* f = freeOf(std::get<MasonrySpec>(history.current().find(e.id)->spec), "columnHeight");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->lo, 0.5);
  EXPECT_EQ(f->hi, 1.5);

  d = history.current();
  setMasonryFree(d, e.id, "thickness", std::nullopt);
  history.commit(d, "Fix thickness");
  EXPECT_EQ(freeOf(std::get<MasonrySpec>(history.current().find(e.id)->spec), "thickness"), nullptr);

  ASSERT_TRUE(history.undo());
  EXPECT_NE(freeOf(std::get<MasonrySpec>(history.current().find(e.id)->spec), "thickness"), nullptr);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), e.doc);
  ASSERT_TRUE(history.redo());
  EXPECT_NE(freeOf(std::get<MasonrySpec>(history.current().find(e.id)->spec), "columnHeight"), nullptr);
}

TEST(SetMasonryFree, ChangingBoundsKeepsOneEntry) {
  Example e;
  setMasonryFree(e.doc, e.id, "thickness", std::make_pair(0.1, 0.3));
  EXPECT_EQ(std::count_if(e.spec().free.begin(), e.spec().free.end(),
                          [](const MasonryFree& f) { return f.name == "thickness"; }),
            1);
  EXPECT_EQ(freeOf(e.spec(), "thickness")->hi, 0.3);
}

TEST(SetMasonryFree, BadBoundsAndNamesAreRefusedAndChangeNothing) {
  Example e;
  const Document before = e.doc;
  auto refused = [&](const std::string& name, double lo, double hi, const std::string& mention) {
    try {
      setMasonryFree(e.doc, e.id, name, std::make_pair(lo, hi));
      ADD_FAILURE() << name << " [" << lo << ", " << hi << "] was accepted";
    } catch (const Error& err) {
      EXPECT_NE(std::string(err.what()).find(mention), std::string::npos) << err.what();
    }
    EXPECT_EQ(e.doc, before);
  };
  refused("thickness", 0.3, 0.1, "thickness");   // lo > hi
  refused("thickness", -1.0, 0.3, "thickness");  // outside where the template makes geometry
  refused("nonsense", 0.1, 0.2, "nonsense");     // no such parameter
  refused("voussoirs", 5, 20, "voussoirs");      // a count cannot be freed
}

TEST(SetMasonryParameter, SetsInNameOrderAndRefusesValuesTheModelRejects) {
  Example e;
  setMasonryParameter(e.doc, e.id, "columnHeight", 1.2);
  setMasonryParameter(e.doc, e.id, "thickness", 0.15);
  const auto& ps = e.spec().parameters;
  for (std::size_t i = 1; i < ps.size(); ++i) EXPECT_LT(ps[i - 1].name, ps[i].name);
  EXPECT_EQ(statics::modelOf(e.spec()).parameters["columnHeight"], 1.2);
  EXPECT_EQ(statics::modelOf(e.spec()).parameters["thickness"], 0.15);
  const Document before = e.doc;
  EXPECT_THROW(setMasonryParameter(e.doc, e.id, "thickness", -0.5), Error);
  EXPECT_THROW(setMasonryParameter(e.doc, e.id, "voussoirs", 6.5), Error);
  EXPECT_EQ(e.doc, before);
  Document boxes;
  const ObjectId box = boxes.add("Box", BoxSpec{});
  EXPECT_THROW(setMasonryParameter(boxes, box, "thickness", 0.2), Error);
}

TEST(DefaultBounds, TheModelsSuggestionElseHalfTheValueEachWayInsideTheValidRange) {
  statics::Parameter p{"h", 2.0, 1.5, 10.0, true, ""};
  EXPECT_EQ(defaultBounds(p, {{"h", 1.8, 3.0}}), std::make_pair(1.8, 3.0));
  EXPECT_EQ(defaultBounds(p, {}), std::make_pair(1.5, 3.0));  // 1.0 is below the valid 1.5
  statics::Parameter zero{"x", 0.0, -5.0, 5.0, true, ""};
  EXPECT_EQ(defaultBounds(zero, {}), std::make_pair(-1.0, 1.0));
}

TEST(MakeItStand, TheExampleArchIsAppliedAsOneChangeAndThenStandsStrictly) {
  Example e;
  ASSERT_FALSE(
      statics::checkFeasibility(statics::modelOf(e.spec()).build(statics::modelOf(e.spec()).parameters)).feasible);
  const MasonrySpec start = e.spec();
  const statics::SearchResult r = searchMasonry(start);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  std::string why;
  const auto next = applySearch(e.doc, e.id, start, r, &why);
  ASSERT_TRUE(next) << why;
  const MasonrySpec& after = std::get<MasonrySpec>(next->find(e.id)->spec);
  // Only the free parameters' values changed; bounds, friction, kern and model stay.
  EXPECT_EQ(after.free, start.free);
  EXPECT_EQ(after.model, start.model);
  EXPECT_EQ(after.friction, start.friction);
  const statics::ParametricModel m = statics::modelOf(after);
  for (const MasonryFree& f : after.free) {
    EXPECT_GE(m.parameters[f.name], f.lo);
    EXPECT_LE(m.parameters[f.name], f.hi);
  }
  statics::AnalysisOptions options;
  options.friction = after.friction;
  EXPECT_TRUE(statics::checkFeasibility(m.build(m.parameters), options).feasible);

  History history(e.doc);
  history.commit(*next, "Make it stand");
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), e.doc);
}

// The panel draws the history from the trace while the search runs: it must be the search's
// own record, evaluation by evaluation, with the free values each was made at.
TEST(MakeItStand, TheLiveTraceIsTheSearchsHistoryAsItCame) {
  Example e;
  SearchTrace trace;
  const statics::SearchResult r = searchMasonry(e.spec(), nullptr, 200, &trace);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  EXPECT_EQ(trace.measures(), r.history);
  ASSERT_EQ(trace.values().size(), r.history.size());
  for (const auto& v : trace.values()) EXPECT_EQ(v.size(), r.free.size());
  // Already standing: one evaluation, reported too.
  MasonrySpec standing = e.spec();
  for (const statics::FreeParameter& f : r.free)
    for (MasonryParameter& p : standing.parameters)
      if (p.name == f.name) p.value = r.values[f.name];
  SearchTrace again;
  const statics::SearchResult s = searchMasonry(standing, nullptr, 200, &again);
  EXPECT_EQ(s.evaluations, 1);
  EXPECT_EQ(again.measures(), s.history);
}

TEST(MakeItStand, ACancelledSearchChangesNothing) {
  Example e;
  Progress progress;
  progress.cancel();
  const statics::SearchResult r = searchMasonry(e.spec(), &progress);
  EXPECT_EQ(r.status, statics::SearchStatus::Cancelled);
  std::string why;
  EXPECT_FALSE(applySearch(e.doc, e.id, e.spec(), r, &why));
  EXPECT_NE(why.find("cancelled"), std::string::npos);
}

TEST(MakeItStand, AResultForAStructureEditedMeanwhileIsNotApplied) {
  Example e;
  const MasonrySpec start = e.spec();
  const statics::SearchResult r = searchMasonry(start);
  setMasonryParameter(e.doc, e.id, "columnHeight", 1.1);  // the user edited during the search
  std::string why;
  EXPECT_FALSE(applySearch(e.doc, e.id, start, r, &why));
  EXPECT_NE(why.find("edited"), std::string::npos) << why;
  Document gone = e.doc;
  gone.remove(e.id);
  EXPECT_FALSE(applySearch(gone, e.id, start, r, &why));
}

// Fig. 13: narrowing the columns (a fixed parameter) makes the arch fall; the free thickness,
// searched again from where it was, makes it stand on the narrower columns, by the strict LP
// test (thicker, the arch's thrust line stays inside the columns).
TEST(ResolveAfterEdit, TheFreeParametersFollowADraggedFixedOne) {
  Example e;
  setMasonryFree(e.doc, e.id, "columnWidth", std::nullopt);  // only the thickness is free, in [0.05, 0.5]
  setMasonryParameter(e.doc, e.id, "columnWidth", 0.5);
  setMasonryParameter(e.doc, e.id, "thickness", 0.2);
  statics::AnalysisOptions options;
  options.friction = e.spec().friction;
  auto stands = [&](const MasonrySpec& s) {
    const statics::ParametricModel m = statics::modelOf(s);
    return statics::checkFeasibility(m.build(m.parameters), options).feasible;
  };
  ASSERT_TRUE(stands(e.spec()));
  setMasonryParameter(e.doc, e.id, "columnWidth", 0.3);  // the drag
  ASSERT_FALSE(stands(e.spec()));
  const MasonrySpec started = e.spec();
  const statics::SearchResult r = resolveAfterEdit(started, "columnWidth");
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  const auto next = applySearch(e.doc, e.id, started, r);
  ASSERT_TRUE(next);
  const MasonrySpec& after = std::get<MasonrySpec>(next->find(e.id)->spec);
  const statics::ParametricModel m = statics::modelOf(after);
  EXPECT_EQ(m.parameters["columnWidth"], 0.3);
  EXPECT_GT(m.parameters["thickness"], 0.2);
  EXPECT_LE(m.parameters["thickness"], 0.5);
  EXPECT_TRUE(stands(after));
  EXPECT_THROW(resolveAfterEdit(started, "thickness"), Error);  // a free parameter: the search sets it
}

TEST(MakeItStand, WithNoFreeParameterTheModelsSuggestionIsSearched) {
  Example e;
  MasonrySpec s = e.spec();
  s.free.clear();
  const auto free = searchFreeOf(s);
  const auto suggested = statics::modelOf(s).suggestedFree;
  ASSERT_EQ(free.size(), suggested.size());
  for (std::size_t i = 0; i < free.size(); ++i) EXPECT_EQ(free[i].name, suggested[i].name);
}

}  // namespace
}  // namespace corbel::editor

namespace corbel::editor {
namespace {

// The panel's before → after list: exactly the parameters the search moved, with the values the
// spec had (the model's defaults where it set none) and has.
TEST(MakeItStand, TheChangesListIsEveryMovedParameterBeforeAndAfter) {
  Example e;
  const MasonrySpec start = e.spec();
  const statics::SearchResult r = searchMasonry(start);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  const auto next = applySearch(e.doc, e.id, start, r);
  ASSERT_TRUE(next);
  const MasonrySpec& after = std::get<MasonrySpec>(next->find(e.id)->spec);
  const std::vector<ParameterChange> changes = parameterChanges(start, after);
  const statics::ParametricModel before = statics::modelOf(start), now = statics::modelOf(after);
  std::size_t moved = 0;
  for (const statics::Parameter& p : before.parameters.all()) moved += now.parameters[p.name] != p.value;
  ASSERT_EQ(changes.size(), moved);
  ASSERT_GT(moved, 0u);
  for (const ParameterChange& c : changes) {
    EXPECT_EQ(c.before, before.parameters[c.name]) << c.name;
    EXPECT_EQ(c.after, now.parameters[c.name]) << c.name;
    EXPECT_TRUE(std::any_of(r.free.begin(), r.free.end(), [&](const auto& f) { return f.name == c.name; }))
        << c.name << " was not free";
  }
  EXPECT_TRUE(parameterChanges(start, start).empty());
}

// An object that frees no parameter (as Object > Add makes one) takes edits to its values, and
// fixing its last free parameter is allowed: the search then falls back on the model's suggestion.
TEST(SetMasonryParameter, AnObjectWithNothingFreeCanBeEdited) {
  Document d;
  MasonrySpec column;
  column.model = "column";
  const ObjectId id = d.add("Column", column);
  EXPECT_NO_THROW(setMasonryParameter(d, id, "height", 4.0));
  EXPECT_EQ(statics::modelOf(masonryOf(d, id)).parameters["height"], 4.0);
  setMasonryFree(d, id, "radius", std::make_pair(0.1, 0.5));
  EXPECT_NO_THROW(setMasonryFree(d, id, "radius", std::nullopt));
  EXPECT_TRUE(masonryOf(d, id).free.empty());
}

// Friction, α/√2 and the kern margin are one undoable change each, checked, and reach the analysis:
// α/√2 at α analyses as α/√2 does without it (the identity the option is defined by).
TEST(SetMasonryAnalysis, SettingsAreCheckedUndoableAndReachTheAnalysis) {
  Example e;
  History history(e.doc);
  Document d = history.current();
  setMasonryAnalysis(d, e.id, 0.9, true, 0.1);
  history.commit(d, "Edit friction");
  const MasonrySpec& s = std::get<MasonrySpec>(history.current().find(e.id)->spec);
  EXPECT_EQ(s.friction, 0.9);
  EXPECT_TRUE(s.conservativeFriction);
  EXPECT_EQ(s.kern, 0.1);
  MasonrySpec plain = s;
  plain.conservativeFriction = false;
  plain.friction = 0.9 / std::sqrt(2.0);
  const statics::ParametricModel m = statics::modelOf(s);
  const statics::Assembly a = m.build(m.parameters);
  EXPECT_NEAR(statics::analyse(a, analysisOptionsOf(s)).yNormalised,
              statics::analyse(a, analysisOptionsOf(plain)).yNormalised, 1e-12);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), e.doc);

  Document bad = e.doc;
  EXPECT_THROW(setMasonryAnalysis(bad, e.id, -0.1, false, 0), Error);
  EXPECT_THROW(setMasonryAnalysis(bad, e.id, 0.7, false, 1.0), Error);
  EXPECT_THROW(setMasonryAnalysis(bad, e.id, std::nan(""), false, 0), Error);
  EXPECT_EQ(bad, e.doc);
}

// Loads: named by what they are, checked against the model, removed again; a load on a block the
// model lacks is refused and changes nothing.
TEST(MasonryLoadEdits, AddNamesChecksAndRemoves) {
  Example e;
  Document d = e.doc;
  MasonryLoad bell;
  bell.block = "arch/voussoir 4";
  bell.force = Vec3(0, 0, -9810);
  EXPECT_EQ(addMasonryLoad(d, e.id, bell), 0u);
  EXPECT_EQ(addMasonryLoad(d, e.id, bell), 1u);
  MasonryLoad wind;
  wind.block = "left column/drum 0";
  wind.face = 0;
  wind.pressure = 600;
  EXPECT_EQ(addMasonryLoad(d, e.id, wind), 2u);
  const auto names = [&] {
    std::vector<std::string> n;
    for (const MasonryLoad& l : masonryOf(d, e.id).loads) n.push_back(l.name);
    return n;
  };
  EXPECT_EQ(names(), (std::vector<std::string>{"load 1", "load 2", "wind 1"}));
  removeMasonryLoad(d, e.id, 0);
  EXPECT_EQ(names(), (std::vector<std::string>{"load 2", "wind 1"}));
  EXPECT_EQ(addMasonryLoad(d, e.id, bell), 2u);
  EXPECT_EQ(names().back(), "load 1") << "the first free number";

  const Document before = d;
  MasonryLoad lost = bell;
  lost.block = "arch/voussoir 400";
  EXPECT_THROW(addMasonryLoad(d, e.id, lost), Error);
  EXPECT_THROW(setMasonryLoad(d, e.id, 0, lost), Error);
  EXPECT_THROW(removeMasonryLoad(d, e.id, 9), Error);
  EXPECT_EQ(d, before);
}

}  // namespace
}  // namespace corbel::editor

namespace corbel::editor {
namespace {

// The arch on columns as three objects (0.3 m columns at x = ±1, a 0.12 m arch on them), each
// freeing its own size: as the composed example at those values, it does not stand.
Document arcade() {
  Document d;
  MasonrySpec column;
  column.model = "column";
  column.parameters = {{"drums", 1}, {"height", 1.5}, {"radius", 0.3 / std::sqrt(2.0)}, {"sides", 4}};
  column.free = {{"radius", 0.1, 1.0}};
  MasonrySpec arch;
  arch.model = "semicircular-arch";
  arch.parameters = {{"radius", 1.0}, {"thickness", 0.12}, {"voussoirs", 8}};
  arch.free = {{"thickness", 0.05, 0.5}};
  d.find(d.add("Left", column))->placement.translation = Vec3(-1, 0, 0);
  d.find(d.add("Right", column))->placement.translation = Vec3(1, 0, 0);
  d.find(d.add("Arch", arch))->placement.translation = Vec3(0, 0, 1.5);
  return d;
}

// Together, the objects' free parameters are searched at once and applied as one undoable change
// to each object's own spec; the result stands together by the strict LP.
TEST(MasonryTogether, MakeThemStandChangesEachObjectInOneUndoStep) {
  const Document d = arcade();
  const ObjectId arch = d.objects[2].id;
  const MasonryTogether t = masonryTogether(d, arch, 0.001);
  EXPECT_EQ(t.objects.size(), 3u);
  ASSERT_EQ(t.free.size(), 3u);
  EXPECT_EQ(t.free[0].name, "Left/radius");
  EXPECT_EQ(t.options.contactTolerance, 0.001);
  EXPECT_FALSE(statics::checkFeasibility(t.model.build(t.model.parameters), t.options).feasible);
  const statics::SearchResult r = searchTogether(t);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  std::string why;
  const auto next = applyTogether(d, d, t, r, &why);
  ASSERT_TRUE(next) << why;
  const MasonryTogether after = masonryTogether(*next, arch, 0.001);
  EXPECT_TRUE(statics::checkFeasibility(after.model.build(after.model.parameters), after.options).feasible);
  for (const statics::FreeParameter& f : r.free) {
    const auto slash = f.name.find('/');
    const DocObject* o = nullptr;
    for (const DocObject& x : next->objects)
      if (x.name == f.name.substr(0, slash)) o = &x;
    ASSERT_NE(o, nullptr);
    EXPECT_EQ(statics::modelOf(std::get<MasonrySpec>(o->spec)).parameters[f.name.substr(slash + 1)], r.values[f.name]);
  }
  History history(d);
  history.commit(*next, "Make the masonry objects stand together");
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), d);

  Document moved = d;
  moved.objects[0].placement.translation = Vec3(-1.1, 0, 0);
  EXPECT_FALSE(applyTogether(moved, d, t, r, &why));
  EXPECT_EQ(why, "an object was edited while the search ran");
  Document alone;
  const ObjectId only = alone.add("Arch", std::get<MasonrySpec>(d.objects[2].spec));
  EXPECT_THROW(masonryTogether(alone, only, 0.001), Error);
}

}  // namespace
}  // namespace corbel::editor
