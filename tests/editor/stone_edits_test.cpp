// editor/stone_edits.h: an extrusion built in stone from the editor. The oracles: the stone
// model analysed by the statics kernel directly (what corbel-cli statics --object does), the
// strict LP on the walls Make It Stand writes back, and the section's own fields.
#include "editor/stone_edits.h"

#include "compose/stone_extrusion.h"
#include "core/error.h"
#include "core/project_io.h"
#include "statics/analysis.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

Document stoneHouses() {
  return loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/stone-house.corbel").document;
}

const ExtrusionSpec& extrusion(const Document& d, ObjectId id) { return std::get<ExtrusionSpec>(d.find(id)->spec); }

TEST(StoneEdits, BuildInStoneSwitchesTheSectionOnAndOff) {
  const Document d = stoneHouses();
  const Document off = setStone(d, 1, false);
  EXPECT_FALSE(extrusion(off, 1).masonry);
  const Document on = setStone(off, 1, true);
  ASSERT_TRUE(extrusion(on, 1).masonry);
  EXPECT_EQ(*extrusion(on, 1).masonry, StoneWalls{});  // the defaults of core/stone_walls.h
  EXPECT_EQ(setStone(d, 1, true), d);                 // already on: kept as it is
  Document withBox = d;
  DocObject box;
  box.id = 9;
  box.name = "box";
  box.spec = BoxSpec{};
  withBox.objects.push_back(box);
  EXPECT_THROW(setStone(withBox, 9, true), InputError);
}

TEST(StoneEdits, ASettingIsCheckedAgainstTheStoneModelsRange) {
  const Document d = stoneHouses();
  const Document thicker = setStoneSetting(d, 1, "thickness", 0.6);
  EXPECT_DOUBLE_EQ(extrusion(thicker, 1).masonry->thickness, 0.6);
  EXPECT_EQ(extrusion(thicker, 1).masonry->openings, extrusion(d, 1).masonry->openings);  // heads kept
  EXPECT_TRUE(extrusion(setStoneSetting(d, 1, "ties", 1), 1).masonry->ties);
  EXPECT_DOUBLE_EQ(extrusion(setStoneSetting(d, 1, "windPressure", 800), 1).masonry->windPressure, 800);
  // A wall thicker than a third of the house's shortest wall is outside the model.
  try {
    setStoneSetting(d, 1, "thickness", 50);
    ADD_FAILURE() << "a 50 m wall was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("masonry.thickness"), std::string::npos) << e.what();
  }
  EXPECT_THROW(setStoneSetting(d, 1, "mortar", 1), InputError);
  EXPECT_THROW(setStoneSetting(d, 1, "thickness", std::nan("")), InputError);
  EXPECT_THROW(setStoneSetting(setStone(d, 1, false), 1, "thickness", 0.4), InputError);
}

// A head chosen per door or window: a lintel is the default and leaves the list; the list stays
// sorted by anchor, as the project file writes it; every choice builds in the stone model.
TEST(StoneEdits, EachDoorAndWindowGetsTheHeadChosenForIt) {
  const Document d = stoneHouses();
  auto heads = [](const Document& doc) {
    std::vector<std::pair<std::string, OpeningHead>> out;
    for (const StoneOpening& o : extrusion(doc, 1).masonry->openings) out.emplace_back(o.anchor, o.head);
    return out;
  };
  const Document lintel = setOpeningHead(d, 1, "door", OpeningHead::Lintel);
  for (const auto& [anchor, head] : heads(lintel)) EXPECT_NE(anchor, "door");
  EXPECT_EQ(heads(lintel).size(), heads(d).size() - 1);
  const Document flat = setOpeningHead(lintel, 1, "door", OpeningHead::FlatArch);
  EXPECT_EQ(heads(flat).size(), heads(d).size());
  for (std::size_t i = 1; i < heads(flat).size(); ++i) EXPECT_LT(heads(flat)[i - 1].first, heads(flat)[i].first);
  for (const auto& [anchor, head] : heads(flat)) {
    if (anchor == "door") {
      EXPECT_EQ(head, OpeningHead::FlatArch);
    }
  }
  for (const Document& doc : {lintel, flat}) EXPECT_NO_THROW(statics::stoneModel(extrusion(doc, 1)));
  try {
    setOpeningHead(d, 1, "chimney", OpeningHead::FlatArch);
    ADD_FAILURE() << "an unknown anchor was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("masonry.openings.chimney"), std::string::npos) << e.what();
  }
  EXPECT_THROW(setOpeningHead(setStone(d, 1, false), 1, "door", OpeningHead::FlatArch), InputError);
}

// The panel's analysis is the kernel's: the same y/W² and strict verdict as the stone model
// analysed directly; the house stands and the thin-walled one does not.
TEST(StoneEdits, TheAnalysisIsTheStoneModelsAsTheKernelAnalysesIt) {
  const Document d = stoneHouses();
  for (ObjectId id : {ObjectId(1), ObjectId(2)}) {
    const MasonryView v = analyseStone(extrusion(d, id));
    ASSERT_TRUE(v.error.empty()) << v.error;
    const statics::ParametricModel model = statics::stoneModel(extrusion(d, id));
    const statics::Assembly a = model.build(model.parameters);
    EXPECT_EQ(v.blockFaces.size(), a.blocks.size());
    EXPECT_DOUBLE_EQ(v.result.yNormalised, statics::analyse(a).yNormalised);
    EXPECT_EQ(v.strict.feasible, statics::checkFeasibility(a).feasible);
    EXPECT_EQ(v.strict.feasible, id == 1) << id;
  }
  ExtrusionSpec bad = extrusion(d, 1);
  bad.masonry->thickness = 99;  // outside the model
  EXPECT_FALSE(analyseStone(bad).error.empty());
}

// Make It Stand thickens the thin walls until the strict LP holds them, and only the thickness
// changes; the result is refused when the extrusion was edited while the search ran.
TEST(StoneEdits, MakeItStandWritesStandingWallsBack) {
  const Document d = stoneHouses();
  const ExtrusionSpec start = extrusion(d, 2);
  const statics::SearchResult r = searchStone(start);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  std::string why;
  const std::optional<Document> next = applyStoneSearch(d, 2, start, r, &why);
  ASSERT_TRUE(next) << why;
  const StoneWalls& after = *extrusion(*next, 2).masonry;
  EXPECT_GT(after.thickness, start.masonry->thickness);
  StoneWalls same = after;
  same.thickness = start.masonry->thickness;
  EXPECT_EQ(same, *start.masonry);
  const statics::ParametricModel model = statics::stoneModel(extrusion(*next, 2));
  EXPECT_TRUE(statics::checkFeasibility(model.build(model.parameters)).feasible);

  const Document edited = setStoneSetting(d, 2, "blockLength", 0.7);
  EXPECT_FALSE(applyStoneSearch(edited, 2, start, r, &why));
  EXPECT_NE(why.find("edited"), std::string::npos) << why;
}

// Make It Stand allowed only the buttresses' depth adds buttresses to the thin-walled house as
// steps of its extrusion, and the walls written back stand by the strict LP; the depth set as a
// setting adds them too, and a second setting resizes the same steps.
TEST(StoneEdits, MakeItStandMayAddButtressSteps) {
  const Document d = stoneHouses();
  const ExtrusionSpec start = extrusion(d, 2);
  // The panel's "add buttresses" frees the depth from 0.1 m to the wall height (5 m) beside
  // the thickness; without it only the thickness is free on a house without buttresses.
  EXPECT_EQ(stoneSearchFree(start, false).size(), 1u);
  const std::vector<statics::FreeParameter> both = stoneSearchFree(start, true);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[1].name, "buttressDepth");
  EXPECT_DOUBLE_EQ(both[1].lo, 0.1);
  EXPECT_DOUBLE_EQ(both[1].hi, 5.0);
  const std::vector<statics::FreeParameter> free = {{"buttressDepth", 0.1, 2.0}};
  const statics::SearchResult r = searchStone(start, nullptr, 200, &free);
  ASSERT_EQ(r.status, statics::SearchStatus::Feasible) << r.message;
  std::string why;
  const std::optional<Document> next = applyStoneSearch(d, 2, start, r, &why);
  ASSERT_TRUE(next) << why;
  const ExtrusionSpec& after = extrusion(*next, 2);
  EXPECT_EQ(*after.masonry, *start.masonry);  // the walls as they were
  ASSERT_FALSE(after.steps.empty());
  for (const PlanStep& st : after.steps) EXPECT_DOUBLE_EQ(st.depth, r.values["buttressDepth"]);
  const statics::ParametricModel model = statics::stoneModel(after);
  EXPECT_TRUE(statics::checkFeasibility(model.build(model.parameters)).feasible);

  const Document set = setStoneSetting(d, 2, "buttressDepth", 0.5);
  const std::size_t added = extrusion(set, 2).steps.size();
  EXPECT_EQ(added, after.steps.size());
  const Document resized = setStoneSetting(set, 2, "buttressDepth", 0.8);
  ASSERT_EQ(extrusion(resized, 2).steps.size(), added);
  for (const PlanStep& st : extrusion(resized, 2).steps) EXPECT_DOUBLE_EQ(st.depth, 0.8);
  EXPECT_DOUBLE_EQ(buttressDepthOf(extrusion(resized, 2)), 0.8);
  // With buttresses, Make It Stand's default frees their depth too.
  EXPECT_EQ(stoneSearchFree(extrusion(resized, 2), false).size(), 2u);
}

}  // namespace
}  // namespace corbel::editor
