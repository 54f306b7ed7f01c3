// editor/masonry_edits.h: the statics panel's Document changes are checked against the model,
// undoable through the History, and "Make it stand" applies a structure that stands by the
// strict LP test (an algorithm independent of the penalty QP the search minimises).
#include "editor/masonry_edits.h"

#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "statics/analysis.h"
#include "statics/kernel.h"

#include <gtest/gtest.h>

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
