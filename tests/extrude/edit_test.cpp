// Editing operations (the plan and profile panes' actions, and edit scripts): each keeps the
// spec valid or refuses with a reason, and the Fig. 4 (j–n) house built by its edit script has
// the faces and tags each stage should give.
#include "core/error.h"
#include "core/history.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "extrude/edit.h"
#include "extrude/kernel.h"
#include "support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <set>

namespace corbel::extrude::test {
namespace {

namespace ed = corbel::extrude::edit;

TEST(Edit, LoopsDrawnInsideAnotherBecomeHolesWhicheverWayTheyWereDrawn) {
  ExtrusionSpec s = uniformSpec({rectangle(20, 20)}, hipProfile(45 * kDeg));
  s = ed::addLoop(s, rectangle(4, 4, 8, 8), 0);               // drawn counter-clockwise
  EXPECT_LT(shoelace(s.loops[1].points), 0) << "a hole runs clockwise";
  s = ed::addLoop(s, reversed(rectangle(2, 2, 9, 9)), 0);     // an island in the hole, drawn clockwise
  EXPECT_GT(shoelace(s.loops[2].points), 0) << "an island runs counter-clockwise";
  s = ed::addLoop(s, reversed(rectangle(3, 3, 30, 0)), 0);    // a second building beside
  EXPECT_GT(shoelace(s.loops[3].points), 0);
  const ExtrusionResult r = extrude(s);
  EXPECT_TRUE(r.shell.warnings.empty());
  const double area = 400 - 16 + 4 + 9;
  EXPECT_NEAR(measure(r.shell).baseArea, area, 1e-9);
}

TEST(Edit, CornersSplitDeleteAndMoveWithTheirProfiles) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, hipProfile(45 * kDeg));
  s.profiles.push_back(ed::profileLibrary()[0]);  // vertical wall
  s.loops[0].profile[1] = 1;
  s = ed::insertCorner(s, 0, 1, Vec2(10, 3));
  ASSERT_EQ(s.loops[0].points.size(), 5u);
  EXPECT_EQ(s.loops[0].profile, (std::vector<int>{0, 1, 1, 0, 0})) << "both halves keep the split edge's profile";
  s = ed::moveCorner(s, 0, 2, Vec2(12, 3));
  EXPECT_EQ(s.loops[0].points[2], Vec2(12, 3));
  s = ed::deleteCorner(s, 0, 2);
  EXPECT_EQ(s.loops[0].points, rectangle(10, 6));
  EXPECT_THROW(ed::deleteCorner(uniformSpec({{Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}}, hipProfile(1)), 0, 0), InputError);
  EXPECT_THROW(ed::moveCorner(s, 0, 9, Vec2(0, 0)), InputError);
  EXPECT_THROW(ed::moveCorner(s, 0, 0, Vec2(std::nan(""), 0)), InputError);
}

TEST(Edit, DraggedProfilePointsStayVerticallyMonotone) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, ed::profileLibrary()[3]);  // mansard: z 0, 3, 5.5, 6.8
  s = ed::moveProfilePoint(s, 0, 2, Vec2(1.0, 9.0));
  EXPECT_EQ(s.profiles[0].points[2], Vec2(1.0, 6.8)) << "clamped to the next point's height";
  s = ed::moveProfilePoint(s, 0, 2, Vec2(1.0, -2.0));
  EXPECT_EQ(s.profiles[0].points[2], Vec2(1.0, 3.0)) << "clamped to the previous point's height";
  s = ed::moveProfilePoint(s, 0, 0, Vec2(5, 5));
  EXPECT_EQ(s.profiles[0].points[0], Vec2(0, 0)) << "the first point stays at the plan";
  EXPECT_FALSE(checkSpec(s).has_value());
  s = ed::insertProfilePoint(s, 0, 0, Vec2(0, 1.5));
  EXPECT_EQ(s.profiles[0].points.size(), 5u);
  s = ed::deleteProfilePoint(s, 0, 1);
  EXPECT_EQ(s.profiles[0].points.size(), 4u);
  EXPECT_THROW(ed::deleteProfilePoint(s, 0, 0), InputError);
}

TEST(Edit, AddOverhangIsOneChangeToEveryProfile) {
  // Sec. 3.3: every profile gets the horizontal pair at one height; the roof above keeps its
  // slope, moved out by the depth.
  ExtrusionSpec s;
  s.profiles = {ed::profileLibrary()[1], ed::profileLibrary()[2]};  // hip, gable
  s.loops.push_back({rectangle(10, 6), {0, 1, 0, 1}});
  const ExtrusionSpec o = ed::addOverhang(s, 3.0, 0.5);
  for (const Profile& p : o.profiles) {
    SCOPED_TRACE(p.name);
    int horizontal = 0;
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i)
      if (p.points[i][1] == 3.0 && p.points[i + 1][1] == 3.0) {
        ++horizontal;
        EXPECT_EQ(p.points[i + 1][0] - p.points[i][0], -0.5);
      }
    EXPECT_EQ(horizontal, 1);
  }
  EXPECT_EQ(o.profiles[0].points.back(), Vec2(2.5, 6)) << "the hip's top moved out by 0.5";
  const ShellMeasures m = measure(extrude(o).shell);
  EXPECT_NEAR(m.soffitArea, 11 * 7 - 60, 1e-9);  // every edge overhangs: the ring around the plan
  EXPECT_THROW(ed::addOverhang(s, 0.0, 0.5), InputError);
  EXPECT_THROW(ed::addOverhang(s, 3.0, 0.0), InputError);
}

TEST(Edit, ScriptsRefuseBadOperationsWithAReason) {
  Document d;
  auto reason = [&](const std::string& json) {
    try {
      ed::applyEdit(d, nlohmann::json::parse(json));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("<accepted>");
  };
  EXPECT_EQ(reason(R"({"op": "new_extrusion", "name": "A", "profile": "hip", "points": [[0, 0], [4, 0], [4, 4]]})"), "<accepted>");
  EXPECT_EQ(reason(R"({"op": "new_extrusion", "name": "A", "profile": "hip", "points": [[0, 0], [4, 0], [4, 4]]})"),
            R"(name: an object called "A" exists already)");
  EXPECT_EQ(reason(R"({"op": "fly", "object": "A"})"), R"(op: unknown edit "fly")");
  EXPECT_EQ(reason(R"({"op": "move_corner", "object": "B", "loop": 0, "corner": 0, "to": [1, 1]})"),
            R"(object: no object called "B")");
  EXPECT_EQ(reason(R"({"op": "move_corner", "object": "A", "loop": 0, "corner": "x", "to": [1, 1]})"),
            "corner: expected an integer");
  EXPECT_EQ(reason(R"({"op": "set_edge_profile", "object": "A", "edges": [[0, 1]], "profile": "nope"})"),
            R"(profile: no profile named "nope")");
  EXPECT_EQ(reason("[1]"), "op: an edit is a JSON object");
}

// Sum of the signed volumes of the object's faces with a tag (divergence theorem on fans).
double taggedVolume(const Scene& scene, ObjectId id, const std::string& tag) {
  double v = 0;
  for (auto f : scene.faces(id)) {
    if (scene.faceTag(f) != tag) continue;
    std::vector<Vec3> p;
    for (auto vh : scene.mesh().fv_range(f)) p.push_back(scene.mesh().point(vh));
    for (std::size_t i = 1; i + 1 < p.size(); ++i) v += OpenMesh::dot(p[0], OpenMesh::cross(p[i], p[i + 1])) / 6.0;
  }
  return v;
}

// A window added, resized and repeated by an edit script, each step one undoable commit: the
// window's volume follows its control points (frame 0.06 m, pane half the depth, sill), and
// undo brings the earlier size back.
TEST(Edit, FeatureScriptAddsResizesRepeatsAndUndoes) {
  auto windowVolume = [](double W, double H, double D) {
    const double f = 0.06;
    return (W * H - (W - 2 * f) * (H - 2 * f)) * D + (W - 2 * f) * (H - 2 * f) * D / 2 + (W + 0.1) * 0.06 * (D + 0.05);
  };
  History history;
  SceneSync sync;
  registerKernel(sync);
  Scene scene;
  auto run = [&](const std::string& json) {
    Document d = history.current();
    const std::string label = ed::applyEdit(d, nlohmann::json::parse(json));
    history.commit(std::move(d), label);
    sync.update(history.current(), scene);
  };
  run(R"({"op": "new_extrusion", "name": "H", "profile": "hip", "points": [[0, 0], [10, 0], [10, 6], [0, 6]]})");
  const ObjectId id = history.current().findByName("H")->id;
  run(R"({"op": "add_feature", "object": "H", "feature": "window", "anchor": {"loop": 0, "edge": 0, "fraction": 0.5, "height": 1}})");
  EXPECT_EQ(history.undoLabel(), "Add window (H)");
  EXPECT_NEAR(taggedVolume(scene, id, "window"), windowVolume(1.2, 1.4, 0.12), 1e-12) << "the kind's default size";
  run(R"({"op": "set_feature_size", "object": "H", "index": 0, "size": [2, 1, 0.2]})");
  EXPECT_NEAR(taggedVolume(scene, id, "window"), windowVolume(2, 1, 0.2), 1e-12);
  run(R"({"op": "set_feature_repeat", "object": "H", "index": 0, "repeat": {"kind": "row", "along": 0.9, "spacing": 2}})");
  EXPECT_NEAR(taggedVolume(scene, id, "window"), 3 * windowVolume(2, 1, 0.2), 1e-12) << "0.5 .. 0.9 of 10 m at 2 m: 3";
  EXPECT_TRUE(scene.validate(id).closedManifold());
  ASSERT_TRUE(history.undo());
  ASSERT_TRUE(history.undo());
  sync.update(history.current(), scene);
  EXPECT_NEAR(taggedVolume(scene, id, "window"), windowVolume(1.2, 1.4, 0.12), 1e-12);
  const auto& spec = std::get<ExtrusionSpec>(history.current().find(id)->spec);
  EXPECT_EQ(spec.anchors.at(0).size, (FeatureSize{1.2, 1.4, 0.12}));
  run(R"({"op": "move_feature", "object": "H", "index": 0, "anchor": {"loop": 0, "edge": 1, "fraction": 0.25, "height": 0.5}})");
  EXPECT_EQ(std::get<ExtrusionSpec>(history.current().find(id)->spec).anchors[0].anchor, (Anchor{0, 1, false, 0.25, 0.5}));
  run(R"({"op": "delete_feature", "object": "H", "index": 0})");
  EXPECT_EQ(taggedVolume(scene, id, "window"), 0.0);
}

TEST(Edit, FeatureEditsRefuseBadInputNamingTheField) {
  const ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, hipProfile(45 * kDeg));
  auto reason = [](const std::function<ExtrusionSpec()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("<accepted>");
  };
  MeshAnchor w{"w", {0, 0, false, 0.5, 1}, FeatureKind::Window, {1, 1, 0.1}};
  EXPECT_EQ(reason([&] { return ed::addMeshAnchor(s, w); }), "<accepted>");
  w.anchor.edge = 4;
  EXPECT_EQ(reason([&] { return ed::addMeshAnchor(s, w); }), "anchor.edge: loop 0 has no edge 4");
  w.anchor.edge = 0;
  w.size.width = -1;
  EXPECT_EQ(reason([&] { return ed::addMeshAnchor(s, w); }), "size[0]: must be greater than 0 and at most 1000 m");
  w.size.width = 1;
  const ExtrusionSpec one = ed::addMeshAnchor(s, w);
  EXPECT_EQ(reason([&] { return ed::setFeatureSize(one, 0, {1, 0, 1}); }), "size[1]: must be greater than 0 and at most 1000 m");
  EXPECT_EQ(reason([&] { return ed::setFeatureSize(one, 3, {1, 1, 1}); }), "index: no mesh anchor 3");
  EXPECT_EQ(reason([&] { return ed::setFeatureRepeat(one, 0, {RepeatKind::Row, 0.9, 0, 0, 1}); }),
            "repeat.spacing: must be greater than 0 m");
  EXPECT_NE(reason([&] { return ed::setFeatureRepeat(one, 0, {RepeatKind::Grid, 1.0, 1e4, 1e-3, 1e-3}); }).find("limit of 10000"),
            std::string::npos);
  EXPECT_EQ(reason([&] { return ed::moveMeshAnchor(one, 0, {0, 0, false, 1.5, 1}); }),
            "anchor.along: a relative anchor needs a fraction within [0, 1]");
  EXPECT_EQ(reason([&] { return ed::deleteMeshAnchor(one, -1); }), "index: no mesh anchor -1");
  Document d;
  d.add("H", s);
  auto script = [&](const std::string& json) {
    try {
      ed::applyEdit(d, nlohmann::json::parse(json));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("<accepted>");
  };
  EXPECT_EQ(script(R"({"op": "add_feature", "object": "H", "feature": "gargoyle", "anchor": {"loop": 0, "edge": 0}})"),
            R"(feature: expected "none", "door", "window", "roof_window" or "chimney_pot")");
  EXPECT_EQ(script(R"({"op": "add_feature", "object": "H", "feature": "door", "size": [1, 2], "anchor": {"loop": 0, "edge": 0}})"),
            "size: expected [width, height, depth] numbers");
  EXPECT_EQ(script(R"({"op": "add_feature", "object": "H", "feature": "door"})"), "anchor: expected an object");
  EXPECT_EQ(script(R"({"op": "move_anchor", "object": "H", "step": 0})"), "anchor: expected an object");
  EXPECT_EQ(script(R"({"op": "set_feature_repeat", "object": "H", "index": 0, "repeat": {"kind": "spiral"}})"),
            R"(repeat.kind: expected "row", "grid" or "none")");
  EXPECT_EQ(script(R"({"op": "delete_feature", "object": "H", "index": 0})"), "index: no mesh anchor 0");
}

// The acceptance session of issue 4 as a script: the house of Fig. 4 (j–n) — a plan, two
// profiles, an overhang, a roof window through an anchored natural step — checked after each
// stage through the same SceneSync the editor uses.
TEST(Edit, Figure4HouseScriptBuildsStageByStage) {
  std::ifstream in(std::string(CORBEL_SOURCE_DIR) + "/assets/scripts/fig4-house.jsonl");
  ASSERT_TRUE(in.good());
  std::vector<nlohmann::json> ops;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) ops.push_back(nlohmann::json::parse(line));
  Document doc;
  SceneSync sync;
  registerKernel(sync);
  Scene scene;
  std::map<std::string, std::set<std::string>> expectTags = {
      {"plan", {"base", "wall", "roof"}},
      {"profiles", {"base", "wall", "roof", "gable"}},
      {"overhang", {"base", "wall", "roof", "gable", "soffit"}},
      {"roof window", {"base", "wall", "roof", "gable", "soffit", "dormer", "dormer roof"}},
  };
  for (std::size_t i = 0; i < ops.size(); ++i) {
    ed::applyEdit(doc, ops[i]);
    const std::string stage = ops[i]["stage"];
    if (i + 1 < ops.size() && ops[i + 1]["stage"] == stage) continue;  // check once a stage is complete
    SCOPED_TRACE(stage);
    sync.update(doc, scene);
    const ObjectId id = doc.findByName("House")->id;
    const auto& st = sync.status().at(id);
    EXPECT_EQ(st.error, "");
    EXPECT_TRUE(st.warnings.empty());
    const ValidityReport v = scene.validate(id);
    EXPECT_TRUE(v.problems().empty()) << (v.problems().empty() ? "" : v.problems()[0]);
    EXPECT_EQ(v.euler, 2);
    std::set<std::string> tags;
    for (auto f : scene.faces(id)) tags.insert(scene.faceTag(f));
    EXPECT_EQ(tags, expectTags.at(stage));
    if (stage == "profiles") {
      EXPECT_NEAR(v.volume, 12 * 8 * 3 + 12 * (8 * 4 / 2.0), 1e-9);  // walls + gabled prism
    }
  }
}

}  // namespace
}  // namespace corbel::extrude::test
