// editor/growth_edits.h: Step and Run take one step more until the growth says every unit
// stopped, and never step a growth that already runs to the end.
#include "editor/growth_edits.h"

#include "core/document.h"
#include "core/history.h"
#include "core/project_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace corbel::editor {
namespace {

TEST(NextStep, AddsOneStepUntilEveryUnitStopped) {
  GrowthSpec s;
  s.steps = 4;
  s.seed = 9;
  const auto next = nextStep(s, -1);
  ASSERT_TRUE(next);
  EXPECT_EQ(next->steps, 5);
  EXPECT_EQ(next->seed, 9u);
  EXPECT_EQ(next->site, s.site);
  EXPECT_TRUE(nextStep(s, 7));   // stopped later than it has grown: a stale note, keep going
  EXPECT_FALSE(nextStep(s, 4));  // every unit stopped after the 4 steps it grows
  EXPECT_FALSE(nextStep(s, 2));
}

TEST(NextStep, AGrowthToTheEndHasNoNextStep) {
  GrowthSpec s;
  s.steps = -1;
  EXPECT_FALSE(nextStep(s, -1));
  s.steps = static_cast<int>(limits::kMaxGrowthSteps);
  EXPECT_FALSE(nextStep(s, -1));
}

}  // namespace
}  // namespace corbel::editor

// The site editor (editor/growth_edits.h) on a 20 × 10 m site of 2 storeys of 3 m with one
// 2 × 2 m core at (10, 4), one landing and one seed. Expected values are the coordinates typed in.
namespace corbel::editor {
namespace {

GrowthSpec smallSite() {
  GrowthSpec s;
  s.site = R"({"envelope": {"origin": [0, 0], "size": [20, 10]}, "storeys": 2, "storey_height": 3,)"
           R"( "cores": [{"name": "lift", "at": [10, 4], "size": [2, 2]}],)"
           R"( "circulation": [{"at": [13, 4, 0], "size": [2, 2, 3]}],)"
           R"( "seeds": [{"at": [1, 1], "target_area": 40}]})";
  return s;
}

Document withSite(const GrowthSpec& s) {
  Document d;
  d.add("Site", s);
  return d;
}

TEST(SiteEdits, AnAddedCoreIsSavedWithItsCoordinatesAndReloaded) {
  const GrowthSpec spec = smallSite();
  const SiteEditResult r = setCore(spec, 1, {2, 6, 5, 9});
  ASSERT_TRUE(r.spec) << r.error;
  const HandPlaced h = handPlaced(r.spec->site);
  ASSERT_EQ(h.cores.size(), 2u);
  EXPECT_EQ(h.cores[0], (growth::Rect{10, 4, 12, 6}));  // the old core untouched
  EXPECT_EQ(h.cores[1], (growth::Rect{2, 6, 5, 9}));
  // In the saved project: at [2, 6], size [3, 3]; and read back, the same spec.
  History history(withSite(spec));
  Document d = history.current();
  std::get<GrowthSpec>(d.objects[0].spec) = *r.spec;
  history.commit(d, "Add a core");
  const std::string text = serializeProject(history.current());
  const auto saved = nlohmann::json::parse(text)["objects"][0]["growth"]["site"]["cores"];
  ASSERT_EQ(saved.size(), 2u) << text;
  EXPECT_EQ(saved[1]["at"], nlohmann::json::parse("[2.0, 6.0]"));
  EXPECT_EQ(saved[1]["size"], nlohmann::json::parse("[3.0, 3.0]"));
  const Document back = parseProject(text).document;
  EXPECT_EQ(std::get<GrowthSpec>(back.objects[0].spec), *r.spec);
  // The kept name, and one for the new core.
  const auto j = nlohmann::json::parse(r.spec->site);
  EXPECT_EQ(j["cores"][0]["name"], "lift");
  EXPECT_EQ(j["cores"][1]["name"], "core 2");
}

TEST(SiteEdits, AnOverlappingCoreIsRefusedWithTheValidatorsMessageAndNothingChanges) {
  const GrowthSpec spec = smallSite();
  History history(withSite(spec));
  const Document before = history.current();
  // [11, 13] × [5, 7] overlaps the lift [10, 12] × [4, 6] by 1 × 1.
  const SiteEditResult r = setCore(spec, 1, {11, 5, 13, 7});
  EXPECT_FALSE(r.spec);
  EXPECT_EQ(r.error, "growth.site.cores[1]: overlaps cores[0]");
  if (r.spec) {
    Document d = before;
    std::get<GrowthSpec>(d.objects[0].spec) = *r.spec;
    history.commit(d, "bad");
  }
  EXPECT_EQ(history.current(), before);
  EXPECT_FALSE(history.canUndo());
  // Touching along an edge is not overlapping.
  EXPECT_TRUE(setCore(spec, 1, {12, 6, 13, 8}).spec);
  // Outside the envelope, a negative size, a NaN, no such entry.
  EXPECT_EQ(setCore(spec, 0, {18, 8, 21, 9}).error, "growth.site.cores[0]: lies outside the site envelope");
  EXPECT_EQ(setCore(spec, 0, {5, 5, 4, 6}).error, "growth.site.cores[0].size: must be positive");
  EXPECT_EQ(setCore(spec, 0, {std::nan(""), 5, 4, 6}).error, "growth.site.cores[0]: is not a finite number");
  EXPECT_EQ(setCore(spec, 3, {1, 1, 2, 2}).error, "growth.site.cores[3]: no such entry");
}

TEST(SiteEdits, MovingAndDeletingUndoRestoreTheSiteExactly) {
  const GrowthSpec spec = smallSite();
  History history(withSite(spec));
  const Document original = history.current();
  const SiteEditResult moved = setCore(spec, 0, {16, 1, 18, 3});
  ASSERT_TRUE(moved.spec) << moved.error;
  Document d = original;
  std::get<GrowthSpec>(d.objects[0].spec) = *moved.spec;
  history.commit(d, "Move core");
  const SiteEditResult gone = removeItem(*moved.spec, SiteItem::Circulation, 0);
  ASSERT_TRUE(gone.spec) << gone.error;
  EXPECT_TRUE(handPlaced(gone.spec->site).circulation.empty());
  EXPECT_EQ(nlohmann::json::parse(gone.spec->site).count("circulation"), 0u);  // no empty list left
  d = history.current();
  std::get<GrowthSpec>(d.objects[0].spec) = *gone.spec;
  history.commit(d, "Delete circulation");
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(std::get<GrowthSpec>(history.current().objects[0].spec), *moved.spec);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), original);
  EXPECT_EQ(removeItem(spec, SiteItem::Seed, 1).error, "growth.site.seeds[1]: no such entry");
}

TEST(SiteEdits, SeedsKeepTheirTargetBehaviourAndLockedFaces) {
  const GrowthSpec spec = smallSite();
  growth::Seed s;
  s.at = Vec2(4, 5);
  s.size = Vec2(3, 4);
  s.storey = 0;
  s.targetVolume = 150;
  s.locked[int(growth::Side::PosX)] = true;
  s.locked[int(growth::Side::Top)] = true;
  const SiteEditResult r = setSeed(spec, 0, s);
  ASSERT_TRUE(r.spec) << r.error;
  const auto j = nlohmann::json::parse(r.spec->site)["seeds"][0];
  EXPECT_EQ(j["at"], nlohmann::json::parse("[4.0, 5.0]"));
  EXPECT_EQ(j["size"], nlohmann::json::parse("[3.0, 4.0]"));
  EXPECT_EQ(j["target_volume"], 150.0);
  EXPECT_FALSE(j.contains("target_area"));  // the old target gone: exactly one
  EXPECT_EQ(j["locked"], nlohmann::json::parse(R"(["+x", "top"])"));
  EXPECT_EQ(j["behaviour"], "view");
  const growth::Seed back = handPlaced(r.spec->site).seeds.at(0);
  EXPECT_EQ(back.locked, s.locked);
  EXPECT_EQ(back.targetVolume, 150.0);
  EXPECT_EQ(back.targetArea, 0.0);
  // Unlocking every face drops the list.
  s.locked = {};
  EXPECT_FALSE(nlohmann::json::parse(setSeed(spec, 0, s).spec->site)["seeds"][0].contains("locked"));

  // Refusals name the field: the validator's, and the engine's.
  growth::Seed bad = s;
  bad.size = Vec2(2.5, 3);
  EXPECT_EQ(setSeed(spec, 0, bad).error, "growth.site.seeds[0].size: a seed is at least 3 m x 3 m (Sec. 5.3)");
  bad = s;
  bad.at = Vec2(9, 4);  // [9, 12] × [4, 8] meets the lift's 1 m clearance
  EXPECT_EQ(setSeed(spec, 0, bad).error, "growth.site.seeds[0]: lies within the clearance of cores[0]");
  bad = s;
  bad.behaviour = "wander";
  EXPECT_EQ(setSeed(spec, 0, bad).error, "growth.site.seeds[0].behaviour: no behaviour named \"wander\"");
  bad = s;
  bad.targetArea = 30;  // and the volume: two targets
  EXPECT_EQ(setSeed(spec, 0, bad).error, "growth.site.seeds[0]: needs exactly one of target_area and target_volume");
  bad = s;
  bad.storey = 1;  // on the upper storey, nothing under it and no core within reach
  bad.at = Vec2(1, 1);
  const std::string unsupported = setSeed(spec, 0, bad).error;
  EXPECT_EQ(unsupported.rfind("growth.site.seeds[0]: is not supported", 0), 0u) << unsupported;
  bad.storey = 2;
  EXPECT_EQ(setSeed(spec, 0, bad).error, "growth.site.seeds[0].storey: must lie in 0..1");
}

TEST(SiteEdits, AddFindsTheFirstFreePlaceOnTheGrid) {
  const growth::Site site = growth::parseSite(smallSite().site);
  // Row y = 0: x = 0 would overlap the seed's clearance? Cores keep no clearance from seeds in
  // the validator, but the seed's clearance from the new core is checked: the seed [1, 4] × [1, 4]
  // must be 1 m from the core, so the first core of 2 × 2 on row 0 is at x = 5 ([4, 5] is the gap).
  const auto core = freeCoreSpot(site, Vec2(2, 2));
  ASSERT_TRUE(core);
  EXPECT_EQ(*core, (growth::Rect{5, 0, 7, 2}));
  growth::Seed like;
  like.targetArea = 30;
  // Row 0: [0, 3] and up to x = 3 overlap the seed [1, 4] × [1, 4]; x = 4 touches it: free.
  const auto seed = freeSeedSpot(site, like);
  ASSERT_TRUE(seed);
  EXPECT_EQ(seed->at, Vec2(4, 0));
}

TEST(SiteEdits, DraggingInThePlanMovesInHalfMetreStepsAndIsRefusedLikeTyping) {
  const GrowthSpec spec = smallSite();
  const HandPlaced start = handPlaced(spec.site);
  // The seed [1, 4] × [1, 4] dragged by (2.3, -0.2): 2.5 m in x, nothing in y.
  const auto r = dragItem(spec, start, start, SiteItem::Seed, 0, 2.3, -0.2);
  ASSERT_TRUE(r && r->spec) << (r ? r->error : "no edit");
  EXPECT_EQ(handPlaced(r->spec->site).seeds[0].at, Vec2(3.5, 1));
  EXPECT_EQ(handPlaced(r->spec->site).seeds[0].storey, 0);
  // Further along the same drag, from the same start: (4.1, 1.8) rounds to (4, 2).
  const HandPlaced now = handPlaced(r->spec->site);
  const auto r2 = dragItem(*r->spec, start, now, SiteItem::Seed, 0, 4.1, 1.8);
  ASSERT_TRUE(r2 && r2->spec);
  EXPECT_EQ(handPlaced(r2->spec->site).seeds[0].at, Vec2(5, 3));
  // A move that rounds to where the entry already is: nothing to commit.
  EXPECT_FALSE(dragItem(spec, start, start, SiteItem::Seed, 0, 0.2, -0.24));
  EXPECT_FALSE(dragItem(*r->spec, start, now, SiteItem::Seed, 0, 2.6, 0.1));
  // The landing [13, 15] × [4, 6] keeps its height; the lift dragged onto the seed's clearance is
  // refused with the validator's message.
  const auto landing = dragItem(spec, start, start, SiteItem::Circulation, 0, 2, 2);
  ASSERT_TRUE(landing && landing->spec);
  EXPECT_EQ(handPlaced(landing->spec->site).circulation[0], (growth::Box{{15, 6, 0}, {17, 8, 3}}));
  const auto core = dragItem(spec, start, start, SiteItem::Core, 0, -5.5, -2);  // to [4.5, 6.5] × [2, 4]
  ASSERT_TRUE(core);
  EXPECT_FALSE(core->spec);
  EXPECT_EQ(core->error, "growth.site.seeds[0]: lies within the clearance of cores[0]");
  EXPECT_FALSE(dragItem(spec, start, start, SiteItem::Core, 3, 1, 1));  // no such entry
}

TEST(SiteEdits, AClickPicksTheSeedThenTheCirculationThenTheCoreUnderIt) {
  const GrowthSpec spec = smallSite();
  const growth::Site site = growth::parseSite(spec.site);
  const HandPlaced h = handPlaced(spec.site);
  using Pick = std::optional<std::pair<SiteItem, int>>;
  EXPECT_EQ(pickItem(h, site, 0, 2, 2), (Pick{{SiteItem::Seed, 0}}));
  EXPECT_EQ(pickItem(h, site, 1, 2, 2), Pick{});  // the seed is on storey 0
  EXPECT_EQ(pickItem(h, site, 0, 14, 5), (Pick{{SiteItem::Circulation, 0}}));
  EXPECT_EQ(pickItem(h, site, 1, 14, 5), Pick{});                       // the landing is 3 m high: storey 0 only
  EXPECT_EQ(pickItem(h, site, 1, 12, 6), (Pick{{SiteItem::Core, 0}}));  // cores run the full height; a corner
  EXPECT_EQ(pickItem(h, site, 0, 8, 8), Pick{});
}

// Commits `next` as the object's spec (as the panel does) and returns the history's document.
void commitSpec(History& history, const GrowthSpec& next, const std::string& label) {
  Document d = history.current();
  std::get<GrowthSpec>(d.objects[0].spec) = next;
  history.commit(d, label);
}

// The spec saved in a project and read back.
GrowthSpec savedAndReloaded(const History& history) {
  return std::get<GrowthSpec>(parseProject(serializeProject(history.current())).document.objects[0].spec);
}

TEST(SiteEdits, TypedCirculationOnACoreGetsTheValidatorsMessage) {
  const GrowthSpec spec = smallSite();
  // The landing moved to [11, 13] × [4, 6] shares [11, 12] × [4, 6] with the lift [10, 12] × [4, 6].
  EXPECT_EQ(setCirculation(spec, 0, {{11, 4, 0}, {13, 6, 3}}).error, "growth.site.circulation[0]: overlaps cores[0]");
  // The lift typed onto the landing [13, 15] × [4, 6]: the same pair, named the same way.
  EXPECT_EQ(setCore(spec, 0, {12.5, 4, 14.5, 6}).error, "growth.site.circulation[0]: overlaps cores[0]");
  // On the upper storey only ([3, 6] in z): the lift runs the full height, still an overlap.
  EXPECT_EQ(setCirculation(spec, 0, {{10, 4, 3}, {12, 6, 6}}).error, "growth.site.circulation[0]: overlaps cores[0]");
  // A landing against the lift's side ([12, 14] × [4, 6]) is where its door opens: accepted.
  EXPECT_TRUE(setCirculation(spec, 0, {{12, 4, 0}, {14, 6, 3}}).spec);
}

TEST(SiteEdits, TheEnvelopeBoxIsEditedSavedReloadedAndUndone) {
  const GrowthSpec spec = smallSite();
  History history(withSite(spec));
  const Document original = history.current();
  const SiteEditResult r = setEnvelopeBox(spec, Vec2(0, 0), Vec2(30, 12));
  ASSERT_TRUE(r.spec) << r.error;
  const SiteFrame f = siteFrame(r.spec->site);
  ASSERT_TRUE(f.valid);
  EXPECT_TRUE(f.box);
  EXPECT_EQ(f.plan, growth::rectanglePlan(0, 0, 30, 12));
  EXPECT_DOUBLE_EQ(growth::parseSite(r.spec->site).area(), 360.0);  // 30 × 12
  EXPECT_EQ(nlohmann::json::parse(r.spec->site)["envelope"],
            nlohmann::json::parse(R"({"origin": [0.0, 0.0], "size": [30.0, 12.0]})"));
  commitSpec(history, *r.spec, "Edit the envelope");
  EXPECT_EQ(savedAndReloaded(history), *r.spec);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), original);

  // Refusals: the lift [10, 12] no longer inside [0, 11]; the seed [1, 4] left of x = 2; a nil size.
  History untouched(withSite(spec));
  const Document before = untouched.current();
  EXPECT_EQ(setEnvelopeBox(spec, Vec2(0, 0), Vec2(11, 10)).error,
            "growth.site.cores[0]: lies outside the site envelope");
  EXPECT_EQ(setEnvelopeBox(spec, Vec2(2, 0), Vec2(20, 10)).error,
            "growth.site.seeds[0].at: the seed lies outside the site envelope");
  EXPECT_EQ(setEnvelopeBox(spec, Vec2(0, 0), Vec2(0, 10)).error, "growth.site.envelope.size: sizes must be positive");
  EXPECT_EQ(setEnvelopeBox(spec, Vec2(std::nan(""), 0), Vec2(20, 10)).error,
            "growth.site.envelope.origin: is not a finite number");
  EXPECT_EQ(untouched.current(), before);
  EXPECT_FALSE(untouched.canUndo());
}

TEST(SiteEdits, AnExtrudedPolygonEnvelopeReplacesTheBoxAndBack) {
  const GrowthSpec spec = smallSite();
  // An L: the 20 × 10 box and a 8 × 4 wing above its left end: 200 + 32 = 232 m².
  const std::vector<Vec2> l{Vec2(0, 0), Vec2(20, 0), Vec2(20, 10), Vec2(8, 10), Vec2(8, 14), Vec2(0, 14)};
  const SiteEditResult r = setEnvelopePolygon(spec, l);
  ASSERT_TRUE(r.spec) << r.error;
  const SiteFrame f = siteFrame(r.spec->site);
  EXPECT_FALSE(f.box);
  EXPECT_EQ(f.plan, l);
  EXPECT_DOUBLE_EQ(growth::parseSite(r.spec->site).area(), 232.0);
  const auto env = nlohmann::json::parse(r.spec->site)["envelope"];
  EXPECT_FALSE(env.contains("origin") || env.contains("size"));
  History history(withSite(spec));
  commitSpec(history, *r.spec, "Edit the envelope");
  EXPECT_EQ(savedAndReloaded(history), *r.spec);
  // Back to a box: the polygon goes.
  const SiteEditResult box = setEnvelopeBox(*r.spec, Vec2(0, 0), Vec2(20, 10));
  ASSERT_TRUE(box.spec);
  EXPECT_FALSE(nlohmann::json::parse(box.spec->site)["envelope"].contains("polygon"));
  // The lower half [0, 20] × [0, 5] cuts the lift [10, 12] × [4, 6]; two corners are no plan.
  EXPECT_EQ(setEnvelopePolygon(spec, {Vec2(0, 0), Vec2(20, 0), Vec2(20, 5), Vec2(0, 5)}).error,
            "growth.site.cores[0]: lies outside the site envelope");
  EXPECT_EQ(setEnvelopePolygon(spec, {Vec2(0, 0), Vec2(20, 0)}).error,
            "growth.site.envelope.polygon: needs at least 3 corners");
  EXPECT_EQ(setEnvelopePolygon(spec, {Vec2(0, 0), Vec2(20, 0), Vec2(20, INFINITY)}).error,
            "growth.site.envelope.polygon[2]: is not a finite number");
}

// The Site tab's corner buttons and the plan view's corner drag on the 20 × 10 box: a corner
// added halfway along an edge changes no area; moved 4 m inward it cuts a triangle of
// 20 × 4 / 2 = 40 m² off; removing it gives the box back; a corner dragged across the plan, one
// that no longer holds the lift, and indices out of range are refused by name.
TEST(SiteEdits, EnvelopeCornersAreAddedMovedAndRemovedOneAtATime) {
  const GrowthSpec spec = smallSite();
  const SiteEditResult added = insertEnvelopeCorner(spec, 2);  // edge (20, 10) → (0, 10)
  ASSERT_TRUE(added.spec) << added.error;
  const SiteFrame f = siteFrame(added.spec->site);
  EXPECT_FALSE(f.box);
  ASSERT_EQ(f.plan.size(), 5u);
  EXPECT_EQ(f.plan[3], Vec2(10, 10));
  EXPECT_DOUBLE_EQ(growth::parseSite(added.spec->site).area(), 200.0);

  // (10, 10) → (10, 6) stays clear of the lift [10, 12] × [4, 6] only at its corner: refused
  // by the lift; to (6, 7) the notch misses it.
  EXPECT_EQ(moveEnvelopeCorner(*added.spec, 3, Vec2(11, 5)).error,
            "growth.site.cores[0]: lies outside the site envelope");
  const SiteEditResult moved = moveEnvelopeCorner(*added.spec, 3, Vec2(4, 6));
  ASSERT_TRUE(moved.spec) << moved.error;
  // The notch (20, 10)–(4, 6)–(0, 10): the box less the triangle of base 20 and height 4.
  EXPECT_DOUBLE_EQ(growth::parseSite(moved.spec->site).area(), 200.0 - 40.0);

  // The plan view's drag: 0.5 m steps from where the drag started; nil moves commit nothing.
  const std::vector<Vec2> start = f.plan;
  EXPECT_FALSE(dragEnvelopeCorner(*added.spec, start, start, 3, 0.2, -0.2));
  const auto dragged = dragEnvelopeCorner(*added.spec, start, start, 3, -6.1, -3.9);
  ASSERT_TRUE(dragged && dragged->spec) << (dragged ? dragged->error : "");
  EXPECT_EQ(siteFrame(dragged->spec->site).plan[3], Vec2(4, 6));
  EXPECT_EQ(pickEnvelopeCorner(start, 10.3, 9.8, 0.5), std::optional<int>(3));
  EXPECT_EQ(pickEnvelopeCorner(start, 10.3, 9.0, 0.5), std::nullopt);

  // A corner pulled through the opposite edge makes the plan cross itself.
  EXPECT_EQ(moveEnvelopeCorner(*added.spec, 3, Vec2(10, -5)).error,
            "growth.site.envelope.polygon: is not a simple polygon (two edges cross or touch, or a corner repeats)");
  const SiteEditResult removed = removeEnvelopeCorner(*moved.spec, 3);
  ASSERT_TRUE(removed.spec) << removed.error;
  EXPECT_EQ(siteFrame(removed.spec->site).plan, growth::rectanglePlan(0, 0, 20, 10));
  EXPECT_EQ(insertEnvelopeCorner(spec, 4).error, "growth.site.envelope.polygon[4]: no such corner");
  EXPECT_EQ(removeEnvelopeCorner(spec, -1).error, "growth.site.envelope.polygon[-1]: no such corner");
  const SiteEditResult triangle =
      setEnvelopePolygon(spec, {Vec2(0, 0), Vec2(40, 0), Vec2(0, 40)});  // holds the lift and the seed
  ASSERT_TRUE(triangle.spec) << triangle.error;
  EXPECT_EQ(removeEnvelopeCorner(*triangle.spec, 0).error, "growth.site.envelope.polygon: needs at least 3 corners");
}

// The 3D view's grab on the small site (2 storeys of 3 m; lift [10, 12] × [4, 6] full height,
// landing [13, 15] × [4, 6] × [0, 3], seed [1, 4] × [1, 4] on the ground storey): rays from
// above and from the side, their entry points by hand, and the drag plane through them.
TEST(SiteEdits, ThreeDViewGrabsWhatTheRayEntersFirstAndDragsOnItsPlane) {
  const GrowthSpec spec = smallSite();
  const growth::Site site = growth::parseSite(spec.site);
  const HandPlaced h = handPlaced(spec.site);
  const Vec3 down(0, 0, -1);
  // Straight down onto the lift's roof at (11, 5): entered at the top, z = 6.
  auto g = grabInView(h, site, Vec3(11, 5, 20), down);
  ASSERT_TRUE(g && g->item);
  EXPECT_EQ(*g->item, SiteItem::Core);
  EXPECT_EQ(g->index, 0);
  EXPECT_DOUBLE_EQ(g->z, 6.0);
  EXPECT_EQ(g->at, Vec2(11, 5));
  // Down onto the landing's roof (z = 3) and onto the seed's (z = 3, one storey high).
  g = grabInView(h, site, Vec3(14, 5, 20), down);
  ASSERT_TRUE(g && g->item);
  EXPECT_EQ(*g->item, SiteItem::Circulation);
  EXPECT_DOUBLE_EQ(g->z, 3.0);
  g = grabInView(h, site, Vec3(2, 2, 20), down);
  ASSERT_TRUE(g && g->item);
  EXPECT_EQ(*g->item, SiteItem::Seed);
  // From the +x side at z = 1 along y = 5: the landing (x = 15) comes before the lift (x = 12).
  g = grabInView(h, site, Vec3(40, 5, 1), Vec3(-1, 0, 0));
  ASSERT_TRUE(g && g->item);
  EXPECT_EQ(*g->item, SiteItem::Circulation);
  EXPECT_EQ(g->at, Vec2(15, 5));
  // At z = 4.5 the landing is below the ray: the lift is entered at x = 12.
  g = grabInView(h, site, Vec3(40, 5, 4.5), Vec3(-1, 0, 0));
  ASSERT_TRUE(g && g->item);
  EXPECT_EQ(*g->item, SiteItem::Core);
  EXPECT_EQ(g->at, Vec2(12, 5));
  // A ray along y = 10.2 at z = 2 from x = 40 passes 0.2 m beside the envelope's corner
  // (20, 10) (corner 2) 20 m away, and beside (0, 10) only after it: it grabs corner 2.
  g = grabInView(h, site, Vec3(40, 10.2, 2), Vec3(-1, 0, 0));
  ASSERT_TRUE(g);
  EXPECT_FALSE(g->item);
  EXPECT_EQ(g->index, 2);
  EXPECT_DOUBLE_EQ(g->z, 2.0);
  // 1 m beside it, 40 m away: nothing (the reach there is max(0.3, 0.6) m).
  EXPECT_FALSE(grabInView(h, site, Vec3(21, -30, 2), Vec3(0, 1, 0)));
  // A ray along x = 20.2 from y = -30 passes (20, 0) (corner 1) before (20, 10).
  g = grabInView(h, site, Vec3(20.2, -30, 2), Vec3(0, 1, 0));
  ASSERT_TRUE(g);
  EXPECT_FALSE(g->item);
  EXPECT_EQ(g->index, 1);
  EXPECT_FALSE(grabInView(h, site, Vec3(30, 30, 20), down));  // outside the site

  // The drag plane: a ray from (11, 5, 20) towards (17, 8, 6) meets z = 6 at (17, 8).
  Vec3 d(6, 3, -14);
  d.normalize();
  const auto p = rayOnPlane(Vec3(11, 5, 20), d, 6.0);
  ASSERT_TRUE(p);
  EXPECT_NEAR((*p)[0], 17, 1e-12);
  EXPECT_NEAR((*p)[1], 8, 1e-12);
  EXPECT_FALSE(rayOnPlane(Vec3(0, 0, 1), Vec3(1, 0, 0), 6.0));  // parallel
  EXPECT_FALSE(rayOnPlane(Vec3(0, 0, 1), down, 6.0));           // behind the eye
  // Grabbed at (11, 5) and dragged to (17, 8): the lift moves by (6, 3) to [16, 18] × [7, 9];
  // by (10, 0) it would leave the envelope, refused with the validator's message.
  auto r = dragItem(spec, h, h, SiteItem::Core, 0, (*p)[0] - 11, (*p)[1] - 5);
  ASSERT_TRUE(r && r->spec) << (r ? r->error : "");
  EXPECT_EQ(handPlaced(r->spec->site).cores[0], (growth::Rect{16, 7, 18, 9}));
  r = dragItem(spec, h, h, SiteItem::Core, 0, 10, 0);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->error, "growth.site.cores[0]: lies outside the site envelope");
}

TEST(SiteEdits, StoreysAndTheirHeightAreCheckedAgainstTheCirculation) {
  const GrowthSpec spec = smallSite();
  History history(withSite(spec));
  const Document original = history.current();
  const SiteEditResult r = setStoreys(spec, 4, 2.8);
  ASSERT_TRUE(r.spec) << r.error;
  const growth::Site site = growth::parseSite(r.spec->site);
  EXPECT_EQ(site.storeys, 4);
  EXPECT_DOUBLE_EQ(site.top(), 11.2);  // 4 × 2.8
  commitSpec(history, *r.spec, "Edit the storeys");
  EXPECT_EQ(savedAndReloaded(history), *r.spec);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), original);
  // One storey of 2.5 m: the 3 m landing sticks out of the top.
  EXPECT_EQ(setStoreys(spec, 1, 2.5).error, "growth.site.circulation[0]: lies outside the site envelope");
  EXPECT_EQ(setStoreys(spec, 0, 3).error, "growth.site.storeys: must lie in 1..1000");
  EXPECT_EQ(setStoreys(spec, 2, -1).error, "growth.site.storey_height: must be positive");
  EXPECT_EQ(setStoreys(spec, 2, std::nan("")).error, "growth.site.storey_height: must be positive");
}

// The Growth behaviour fields: what is set reads back through the site reader as the same
// settings, a default is not written, every key back at its default removes "growth", and a
// value the reader refuses is refused with its message, changing nothing.
TEST(SiteEdits, GrowthBehaviourSettingsAreWrittenReadBackAndChecked) {
  const GrowthSpec spec = smallSite();
  History history(withSite(spec));
  const Document original = history.current();
  growth::GrowthSettings g;
  g.tau = 0.45;
  g.doubleVolumeChance = 0;
  g.minSubUnits = g.maxSubUnits = 1;
  const SiteEditResult r = setGrowthSettings(spec, g);
  ASSERT_TRUE(r.spec) << r.error;
  EXPECT_EQ(growth::parseSite(r.spec->site).growth, g);
  const nlohmann::json written = nlohmann::json::parse(r.spec->site)["growth"];
  EXPECT_EQ(written, nlohmann::json::parse(R"({"tau": 0.45, "double_volume_chance": 0.0, "sub_units": [1, 1]})"));
  EXPECT_EQ(siteFrame(r.spec->site).growth, g);
  commitSpec(history, *r.spec, "Edit the growth behaviour");
  EXPECT_EQ(savedAndReloaded(history), *r.spec);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), original);

  const SiteEditResult back = setGrowthSettings(*r.spec, growth::GrowthSettings{});
  ASSERT_TRUE(back.spec) << back.error;
  EXPECT_FALSE(nlohmann::json::parse(back.spec->site).contains("growth"));
  growth::GrowthSettings bad;
  bad.tau = 1.5;
  EXPECT_NE(setGrowthSettings(spec, bad).error.find("growth.site.growth.tau"), std::string::npos)
      << setGrowthSettings(spec, bad).error;
  bad = {};
  bad.aspectChance = std::nan("");
  EXPECT_FALSE(setGrowthSettings(spec, bad).spec);
}

TEST(SiteEdits, SeedGenerationControlsAreWrittenAndGiveTheExitsCountedByHand) {
  // A 6 m landing [13, 19] × [4, 6] on storey 0. 3 m seeds step 3 m along its ∓y sides:
  // x = 13 and 16, at y = 4 - 3 = 1 and y = 6: four exits, all clear of the lift's 1 m
  // clearance [9, 13] × [3, 7] (touching it at x = 13) and of the seed [1, 4]²; its ∓x sides
  // are 2 m long, too short for a 3 m seed.
  const SiteEditResult wide = setCirculation(smallSite(), 0, {{13, 4, 0}, {19, 6, 3}});
  ASSERT_TRUE(wide.spec) << wide.error;
  const GrowthSpec spec = *wide.spec;
  History history(withSite(spec));
  const Document original = history.current();
  growth::SeedControls c;
  c.count = 10;
  c.areaLo = c.areaHi = 50;
  c.storeys = {0};
  c.seed = 7;
  const SiteEditResult r = setSeedControls(spec, c);
  ASSERT_TRUE(r.spec) << r.error;
  const growth::Site site = growth::parseSite(r.spec->site);
  ASSERT_EQ(site.seeds.size(), 5u);  // the hand-placed one and the four exits
  std::vector<std::pair<double, double>> at;
  for (std::size_t i = 1; i < site.seeds.size(); ++i) {
    at.push_back({site.seeds[i].at[0], site.seeds[i].at[1]});
    EXPECT_EQ(site.seeds[i].targetArea, 50.0);
    EXPECT_EQ(site.seeds[i].storey, 0);
  }
  std::sort(at.begin(), at.end());
  EXPECT_EQ(at, (std::vector<std::pair<double, double>>{{13, 1}, {13, 6}, {16, 1}, {16, 6}}));
  EXPECT_EQ(handPlaced(r.spec->site).seeds.size(), 1u);  // generated seeds are not hand-placed
  const auto saved = nlohmann::json::parse(r.spec->site)["generate_seeds"];
  EXPECT_EQ(saved, nlohmann::json::parse(R"({"count": 10, "size": [3.0, 3.0], "spacing": 0.0,
      "target_area": [50.0, 50.0], "storeys": [0], "seed": 7, "behaviour": "view"})"));
  const auto back = siteFrame(r.spec->site).controls;
  ASSERT_TRUE(back);
  EXPECT_EQ(back->count, 10);
  EXPECT_EQ(back->storeys, std::vector<int>{0});
  EXPECT_EQ(back->seed, 7u);
  commitSpec(history, *r.spec, "Generate seeds");
  EXPECT_EQ(savedAndReloaded(history), *r.spec);
  ASSERT_TRUE(history.undo());
  EXPECT_EQ(history.current(), original);

  // Two of the four; none again when the controls go.
  c.count = 2;
  EXPECT_EQ(growth::parseSite(setSeedControls(spec, c).spec->site).seeds.size(), 3u);
  const SiteEditResult none = setSeedControls(*r.spec, std::nullopt);
  ASSERT_TRUE(none.spec);
  EXPECT_FALSE(nlohmann::json::parse(none.spec->site).contains("generate_seeds"));
  EXPECT_EQ(growth::parseSite(none.spec->site).seeds.size(), 1u);
  // Refusals name the control.
  c.areaLo = 60, c.areaHi = 40;
  EXPECT_EQ(setSeedControls(spec, c).error,
            "growth.site.generate_seeds.target_area: expected [lo, hi] with 0 < lo <= hi");
  c.areaLo = c.areaHi = 50;
  c.storeys = {2};
  EXPECT_EQ(setSeedControls(spec, c).error, "growth.site.generate_seeds.storeys: storey 2 is not in 0..1");
  c.storeys = {};
  c.size = Vec2(2, 3);
  EXPECT_EQ(setSeedControls(spec, c).error, "growth.site.generate_seeds.size: a seed is at least 3 m x 3 m (Sec. 5.3)");
}

}  // namespace
}  // namespace corbel::editor
