// Editing operations (the plan and profile panes' actions, and edit scripts): each keeps the
// spec valid or refuses with a reason, and the Fig. 4 (j–n) house built by its edit script has
// the faces and tags each stage should give.
#include "extrude/edit.h"
#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "core/scene.h"
#include "core/scene_sync.h"
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
  s = ed::addLoop(s, rectangle(4, 4, 8, 8), 0);  // drawn counter-clockwise
  EXPECT_LT(shoelace(s.loops[1].points), 0) << "a hole runs clockwise";
  s = ed::addLoop(s, reversed(rectangle(2, 2, 9, 9)), 0);  // an island in the hole, drawn clockwise
  EXPECT_GT(shoelace(s.loops[2].points), 0) << "an island runs counter-clockwise";
  s = ed::addLoop(s, reversed(rectangle(3, 3, 30, 0)), 0);  // a second building beside
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

// Sec. 3.3: the overhang's "starting height will remain synchronized": every profile that spans
// the height gets its horizontal segment at that absolute height. A step's profiles start at
// the step's anchor, so they get it that much lower; profiles that start above it get none;
// a profile that a main edge and a step share is copied for the step.
TEST(Edit, AddOverhangIsAtOneAbsoluteHeightOnEveryProfile) {
  auto horizontals = [](const Profile& p) {
    std::vector<double> zs;
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i)
      if (p.points[i][1] == p.points[i + 1][1]) zs.push_back(p.points[i][1]);
    return zs;
  };
  // The Fig. 1 house: eaves and gables from the base, a bay at the base, dormers at 5.5 m, a
  // chimney at 8.4 m.
  const Document house = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/house.corbel").document;
  const ExtrusionSpec s = std::get<ExtrusionSpec>(house.objects[0].spec);
  const ExtrusionSpec o = ed::addOverhang(s, 3.0, 0.3);
  ASSERT_EQ(o.profiles.size(), s.profiles.size()) << "no profile is shared between heights";
  for (std::size_t k = 0; k < o.profiles.size(); ++k) {
    SCOPED_TRACE(o.profiles[k].name);
    std::vector<double> before = horizontals(s.profiles[k]), after = horizontals(o.profiles[k]);
    const std::string& n = o.profiles[k].name;
    if (n == "eaves" || n == "gable" || n == "bay") before.push_back(3.0);  // from the base
    std::sort(before.begin(), before.end());
    EXPECT_EQ(after, before);
  }
  // Built: every face looking straight down is at 3 m (the new overhang), 5.5 m (the eaves'
  // own overhang and the dormers' undersides) or 8.4 m (the chimney's underside on the roof).
  const ExtrusionResult r = extrude(o);
  EXPECT_TRUE(r.shell.warnings.empty());
  std::set<double> soffits;
  for (const ShellFace& f : r.shell.faces)
    if (!f.base && f.normal[2] < -1 + 1e-12)
      for (const auto& l : f.loops)
        for (int v : l) soffits.insert(std::round(r.shell.points[v][2] * 1e6) / 1e6);
  EXPECT_EQ(soffits, (std::set<double>{3.0, 5.5, 8.4}));

  // A profile shared by the main edges (from the base) and a step anchored at 1 m, and another
  // shared with a step anchored at 4 m: the steps get copies, at 3 − 1 = 2 m and none.
  ExtrusionSpec t;
  t.profiles = {ed::profileLibrary()[1], ed::profileLibrary()[2]};  // hip (walls 3 m), gable
  t.profiles[1].points = {{0, 0}, {0, 5}, {0, 6}};
  t.loops.push_back({rectangle(10, 6), {0, 1, 0, 1}});
  PlanStep oriel;
  oriel.name = "oriel";
  oriel.anchor = {0, 0, false, 0.5, 1.0};
  oriel.width = 2;
  oriel.depth = 0.5;
  oriel.frontProfile = oriel.sideProfile = 0;
  PlanStep dormer = oriel;
  dormer.name = "dormer";
  dormer.anchor = {0, 2, false, 0.5, 4.0};
  dormer.frontProfile = dormer.sideProfile = 1;
  t.steps = {oriel, dormer};
  const ExtrusionSpec u = ed::addOverhang(t, 3.0, 0.3);
  ASSERT_EQ(u.profiles.size(), 4u);
  EXPECT_EQ(u.loops[0].profile, (std::vector<int>{0, 1, 0, 1})) << "the main edges keep theirs";
  EXPECT_EQ(horizontals(u.profiles[0]), (std::vector<double>{3.0}));
  EXPECT_EQ(horizontals(u.profiles[1]), (std::vector<double>{3.0}));
  const Profile& orielP = u.profiles.at(u.steps[0].frontProfile);
  const Profile& dormerP = u.profiles.at(u.steps[1].frontProfile);
  EXPECT_EQ(u.steps[0].sideProfile, u.steps[0].frontProfile);
  EXPECT_EQ(u.steps[1].sideProfile, u.steps[1].frontProfile);
  EXPECT_EQ(horizontals(orielP), (std::vector<double>{2.0}));
  EXPECT_EQ(dormerP.points, t.profiles[1].points) << "the dormer starts above the overhang";
  EXPECT_NE(orielP.name, u.profiles[0].name);
  EXPECT_NE(dormerP.name, u.profiles[1].name);
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
  EXPECT_EQ(reason(R"({"op": "new_extrusion", "name": "A", "profile": "hip", "points": [[0, 0], [4, 0], [4, 4]]})"),
            "<accepted>");
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
  EXPECT_EQ(std::get<ExtrusionSpec>(history.current().find(id)->spec).anchors[0].anchor,
            (Anchor{0, 1, false, 0.25, 0.5}));
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
  EXPECT_EQ(reason([&] {
              return ed::setFeatureSize(one, 0, {1, 0, 1});
            }),
            "size[1]: must be greater than 0 and at most 1000 m");
  EXPECT_EQ(reason([&] { return ed::setFeatureSize(one, 3, {1, 1, 1}); }), "index: no mesh anchor 3");
  EXPECT_EQ(reason([&] {
              return ed::setFeatureRepeat(one, 0, {RepeatKind::Row, 0.9, 0, 0, 1});
            }),
            "repeat.spacing: must be greater than 0 m");
  EXPECT_NE(reason([&] {
              return ed::setFeatureRepeat(one, 0, {RepeatKind::Grid, 1.0, 1e4, 1e-3, 1e-3});
            }).find("limit of 10000"),
            std::string::npos);
  EXPECT_EQ(reason([&] {
              return ed::moveMeshAnchor(one, 0, {0, 0, false, 1.5, 1});
            }),
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
  EXPECT_EQ(
      script(
          R"({"op": "add_feature", "object": "H", "feature": "door", "size": [1, 2], "anchor": {"loop": 0, "edge": 0}})"),
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
// One face of a shell as the Scene holds it: its tag, outward unit normal and area.
struct TaggedFace {
  std::string tag;
  Vec3 normal;
  double area;
};

// Fig. 4 (j–n) as the user guide builds it, checked face by face against areas by hand. The
// plan is 12 × 8; every profile has walls to 3 m. s = 1/√2 (a 45° slope).
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
  const double s = 1 / std::sqrt(2.0), r2 = std::sqrt(2.0);
  const Vec3 down(0, 0, -1), front(0, -1, 0), back(0, 1, 0), right(1, 0, 0), left(-1, 0, 0);
  const Vec3 frontRoof(0, -s, s), backRoof(0, s, s), rightRoof(s, 0, s), leftRoof(-s, 0, s);
  const std::vector<TaggedFace> walls = {
      {"base", down, 96}, {"wall", front, 36}, {"wall", right, 24}, {"wall", back, 36}, {"wall", left, 24}};
  auto with = [&](std::vector<TaggedFace> more) {
    std::vector<TaggedFace> all = walls;
    all.insert(all.end(), more.begin(), more.end());
    return all;
  };
  // With the 0.4 m overhang at 3 m the roof starts on a 12.8 × 8.8 ring whose soffit is four
  // mitred trapezoids; the ridge is at 3 + 4.4 m, the gables 8.8 m wide and 4.4 m high.
  const std::vector<TaggedFace> overhang = {
      {"soffit", down, (12 + 12.8) / 2 * 0.4}, {"soffit", down, (12 + 12.8) / 2 * 0.4},
      {"soffit", down, (8 + 8.8) / 2 * 0.4},   {"soffit", down, (8 + 8.8) / 2 * 0.4},
      {"gable", right, 8.8 * 4.4 / 2},         {"gable", left, 8.8 * 4.4 / 2},
      {"roof", backRoof, 12.8 * 4.4 * r2}};
  std::map<std::string, std::vector<TaggedFace>> expect = {
      // Hip at 45° from 3 m: the ridge 4 m long at 7 m; trapezoids on the long sides, triangles
      // on the short ones, their slant height 4√2.
      {"plan", with({{"roof", frontRoof, (12 + 4) / 2.0 * 4 * r2},
                     {"roof", backRoof, (12 + 4) / 2.0 * 4 * r2},
                     {"roof", rightRoof, 8 * 4 / 2.0 * r2},
                     {"roof", leftRoof, 8 * 4 / 2.0 * r2}})},
      // Gables on the short sides: triangles 8 m wide and 4 m high over their walls.
      {"profiles", with({{"gable", right, 16},
                         {"gable", left, 16},
                         {"roof", frontRoof, 12 * 4 * r2},
                         {"roof", backRoof, 12 * 4 * r2}})},
      {"overhang", with({{"roof", frontRoof, 12.8 * 4.4 * r2}})},
      // The roof window: at 4.2 m the front roof line is at y = 0.8 and the active edge runs
      // from x = −0.4 to 12.4, so the step is x 5.2 to 6.8, y 0.5 to 0.8. Its front stands at
      // y = 0.5 (1.2 m of wall, then a gable to the ridge at 6.2 m); its sides rise 1.2 m, from
      // 0.3 to 1.5 m long as the main roof (z = 3.4 + y) recedes, then lean in at 45°, each
      // dormer roof reaching back to y = 2 + u at u metres in from its side (1.52 m² in plan).
      // It hides 2.56 m² of the front roof in plan; it stands on a 1.6 × 0.3 m floor at 4.2 m,
      // untagged (no profile segment made it).
      {"roof window", with({{"roof", frontRoof, (12.8 * 4.4 - 2.56) * r2},
                            {"dormer", front, 1.6 * 1.2 + 1.6 * 0.8 / 2},
                            {"dormer", right, (0.3 + 1.5) / 2 * 1.2},
                            {"dormer", left, (0.3 + 1.5) / 2 * 1.2},
                            {"dormer roof", rightRoof, 1.52 * r2},
                            {"dormer roof", leftRoof, 1.52 * r2},
                            {"", down, 1.6 * 0.3}})},
  };
  for (const char* st : {"overhang", "roof window"})
    for (const TaggedFace& f : overhang) expect[st].push_back(f);
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
    // Every face of the kernel's shell (the Scene cuts faces with holes into pieces) matched
    // to one expected face of its tag, normal and area.
    const ExtrusionSpec& spec = std::get<ExtrusionSpec>(doc.findByName("House")->spec);
    const ExtrusionResult r = extrude(spec);
    std::vector<TaggedFace> want = expect.at(stage);
    for (const ShellFace& f : r.shell.faces) {
      std::string tag = f.base ? "base" : "";
      if (!f.base && f.profile >= 0 && f.segment >= 0 &&
          static_cast<std::size_t>(f.segment) < spec.profiles[f.profile].tags.size())
        tag = spec.profiles[f.profile].tags[f.segment];
      const double area = faceArea(r.shell, f);
      auto it = std::find_if(want.begin(), want.end(), [&](const TaggedFace& w) {
        return w.tag == tag && (w.normal - f.normal).norm() < 1e-9 && std::abs(w.area - area) < 1e-9;
      });
      if (it == want.end()) {
        ADD_FAILURE() << "unexpected face: " << tag << " (profile " << f.profile << ", segment " << f.segment
                      << ", step " << f.step << "), normal (" << f.normal[0] << ", " << f.normal[1] << ", "
                      << f.normal[2] << "), area " << area;
        continue;
      }
      want.erase(it);
    }
    for (const TaggedFace& w : want)
      ADD_FAILURE() << "missing face: " << w.tag << ", normal (" << w.normal[0] << ", " << w.normal[1] << ", "
                    << w.normal[2] << "), area " << w.area;
    if (stage == "profiles") {
      EXPECT_NEAR(v.volume, 12 * 8 * 3 + 12 * (8 * 4 / 2.0), 1e-9);  // walls + gabled prism
    }
  }
}

// Forced steps drawn on the plan (the plan pane's Draw forced step, Sec. 3.5).
namespace forced {

// A 10 × 6 box turned 30° about the origin: edge 0 runs along d = (cos 30°, sin 30°), the
// outward side of it is out = (sin 30°, −cos 30°).
const double c30 = std::sqrt(3.0) / 2, s30 = 0.5;
Vec2 turned(double x, double y) { return Vec2(c30 * x - s30 * y, s30 * x + c30 * y); }

// Walls 3 m high closed flat: the inward ledge at 3 m is wider than the plan, so the top is one
// flat face over the whole active plan and the solid is the plan's prism.
Profile flatTopBox() {
  Profile p;
  p.name = "box";
  p.points = {Vec2(0, 0), Vec2(0, 3), Vec2(1000, 3), Vec2(1001, 4)};
  return p;
}

TEST(Edit, ForcedStepDrawnOnATurnedEdgeIsStoredInTheAnchorsFrame) {
  std::vector<Vec2> box;
  for (const Vec2& p : rectangle(10, 6)) box.push_back(turned(p[0], p[1]));
  const ExtrusionSpec s = uniformSpec({box}, flatTopBox());
  // A 2 × 2 square drawn across edge 0, from 3 to 5 m along it, 1 m in and 1 m out; in world
  // coordinates (x, y) = u d + v out, e.g. (u, v) = (3, 1): (3 c30 + s30, 3 s30 − c30).
  const std::vector<Vec2> world = {Vec2(3 * c30 + s30, 3 * s30 - c30), Vec2(5 * c30 + s30, 5 * s30 - c30),
                                   Vec2(5 * c30 - s30, 5 * s30 + c30), Vec2(3 * c30 - s30, 3 * s30 + c30)};
  const ExtrusionSpec e = ed::addForcedStep(s, 0, 0, world, 0.0, 0, "wing");
  ASSERT_EQ(e.steps.size(), 1u);
  const PlanStep& st = e.steps[0];
  EXPECT_EQ(st.shape, StepShape::Forced);
  EXPECT_EQ(st.name, "wing");
  EXPECT_FALSE(st.anchor.absolute);
  EXPECT_NEAR(st.anchor.along, 0.4, 1e-12) << "the middle of the 3 .. 5 m it covers, of 10 m";
  EXPECT_EQ(st.anchor.height, 0.0);
  // Anchor at 4 m: (u, v) relative to it.
  const std::vector<Vec2> uv = {Vec2(-1, 1), Vec2(1, 1), Vec2(1, -1), Vec2(-1, -1)};
  ASSERT_EQ(st.points.size(), uv.size());
  for (std::size_t i = 0; i < uv.size(); ++i) EXPECT_NEAR((st.points[i] - uv[i]).norm(), 0, 1e-12) << i;

  // The shell: closed, and its volume the union's area × 3 m. The union's outline, walked
  // counter-clockwise in the box's own frame, by the shoelace formula: 60 + 2 × 1.
  const ExtrusionResult r = extrude(e);
  for (const auto& w : r.shell.warnings) ADD_FAILURE() << w;
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, e, "plaster"));
  const ValidityReport v = scene.validate(1);
  EXPECT_TRUE(v.closedManifold());
  for (const auto& p : v.problems()) ADD_FAILURE() << p;
  const std::vector<Vec2> outline = {Vec2(0, 0), Vec2(3, 0),  Vec2(3, -1), Vec2(5, -1),
                                     Vec2(5, 0), Vec2(10, 0), Vec2(10, 6), Vec2(0, 6)};
  const double area = shoelace(outline);
  EXPECT_NEAR(area, 62, 1e-12);
  EXPECT_NEAR(v.volume, area * 3, 1e-9 * area * 3);
  EXPECT_NEAR(measure(r.shell).baseArea, area, 1e-9);
}

TEST(Edit, ForcedStepApartFromItsEdgeAnchorsAtTheNearestPoint) {
  const ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, flatTopBox());
  // A triangle below edge 0 (which runs along +x, outward is −y), its tip 1 m from the edge at
  // x = 3: the anchor is at 3 m; out is −y, so (2, −3) is u = −1, v = 3.
  const ExtrusionSpec e = ed::addForcedStep(s, 0, 0, {Vec2(2, -3), Vec2(4, -3), Vec2(3, -1)}, 2.5, 0);
  const PlanStep& st = e.steps.at(0);
  EXPECT_NEAR(st.anchor.along, 0.3, 1e-12);
  EXPECT_EQ(st.anchor.height, 2.5);
  const std::vector<Vec2> uv = {Vec2(-1, 3), Vec2(1, 3), Vec2(0, 1)};
  for (std::size_t i = 0; i < uv.size(); ++i) EXPECT_NEAR((st.points.at(i) - uv[i]).norm(), 0, 1e-12) << i;
  // On edge 1 (x = 10, running +y, outward +x) a square beyond its end at y = 6 anchors at the end.
  const ExtrusionSpec f = ed::addForcedStep(s, 0, 1, rectangle(1, 1, 11, 7), 0, 0);
  EXPECT_NEAR(f.steps.at(0).anchor.along, 1.0, 1e-12);
  EXPECT_NEAR((f.steps[0].points[0] - Vec2(1, 1)).norm(), 0, 1e-12) << "(11, 7) is 1 m on and 1 m out from (10, 6)";
}

TEST(Edit, ForcedStepRefusesBadPolygonsWithAReason) {
  const ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, flatTopBox());
  auto reason = [&](const std::vector<Vec2>& pts, int loop = 0, int edge = 0, double h = 0) -> std::string {
    try {
      ed::addForcedStep(s, loop, edge, pts, h, 0);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(reason({Vec2(0, 0), Vec2(1, -1)}).find("at least three"), std::string::npos);
  EXPECT_NE(reason({Vec2(0, -1), Vec2(2, -1), Vec2(4, -1)}).find("no area"), std::string::npos);
  EXPECT_NE(reason({Vec2(0, -1), Vec2(2, -1), Vec2(2, -1), Vec2(2, -3)}).find("zero-length"), std::string::npos);
  EXPECT_NE(reason({Vec2(0, -1), Vec2(3, -3), Vec2(3, -1), Vec2(0, -2)}).find("not simple"), std::string::npos)
      << "a bow tie";
  EXPECT_NE(reason({Vec2(0, -1), Vec2(std::nan(""), -1), Vec2(0, -3)}).find("finite"), std::string::npos);
  EXPECT_NE(reason(rectangle(1, 1, 2, -2), 0, 7).find("no edge"), std::string::npos);
  EXPECT_NE(reason(rectangle(1, 1, 2, -2), 3).find("no loop"), std::string::npos);
  EXPECT_NE(reason(rectangle(1, 1, 2, -2), 0, 0, -1).find("height"), std::string::npos);
  EXPECT_THROW(ed::addForcedStep(s, 0, 0, rectangle(1, 1, 2, -2), 0, 5), InputError) << "no profile 5";
  EXPECT_EQ(reason(rectangle(1, 1, 2, -2)), "");
}

TEST(Edit, ForcedStepScriptCommand) {
  Document doc;
  ed::applyEdit(
      doc,
      nlohmann::json::parse(
          R"({"op": "new_extrusion", "name": "H", "profile": "hip", "points": [[0, 0], [10, 0], [10, 6], [0, 6]]})"));
  const std::string label = ed::applyEdit(
      doc,
      nlohmann::json::parse(
          R"({"op": "add_forced_step", "object": "H", "loop": 0, "edge": 0, "points": [[4, 1], [6, 1], [6, -2], [4, -2]], "height": 0, "profile": "hip", "name": "porch"})"));
  EXPECT_EQ(label, "Add forced step (H)");
  const auto& spec = std::get<ExtrusionSpec>(doc.findByName("H")->spec);
  ASSERT_EQ(spec.steps.size(), 1u);
  EXPECT_EQ(spec.steps[0].name, "porch");
  EXPECT_NEAR(spec.steps[0].anchor.along, 0.5, 1e-12);
  EXPECT_NEAR((spec.steps[0].points[2] - Vec2(1, 2)).norm(), 0, 1e-12);
  EXPECT_THROW(
      ed::applyEdit(
          doc,
          nlohmann::json::parse(
              R"({"op": "add_forced_step", "object": "H", "loop": 0, "edge": 0, "points": [[4, 1], [6, 1]], "profile": "hip"})")),
      InputError);
  const ExtrusionResult r = extrude(spec);
  EXPECT_TRUE(r.shell.warnings.empty());
}

TEST(Edit, BackgroundScriptCommandsChangeTheObjectNotItsSpec) {
  Document doc;
  ed::applyEdit(
      doc,
      nlohmann::json::parse(
          R"({"op": "new_extrusion", "name": "H", "profile": "hip", "points": [[0, 0], [10, 0], [10, 6], [0, 6]]})"));
  const ExtrusionSpec before = std::get<ExtrusionSpec>(doc.findByName("H")->spec);
  EXPECT_EQ(
      ed::applyEdit(
          doc,
          nlohmann::json::parse(
              R"({"op": "set_background", "object": "H", "image": "/scans/h.png", "scale": 0.02, "origin": [-1, 2]})")),
      "Set background (H)");
  const DocObject* o = doc.findByName("H");
  ASSERT_TRUE(o->background);
  EXPECT_EQ(*o->background, (PlanBackground{"/scans/h.png", 0.02, Vec2(-1, 2), 0.5}));
  EXPECT_EQ(std::get<ExtrusionSpec>(o->spec), before);
  // Fields left out keep their value.
  ed::applyEdit(doc, nlohmann::json::parse(
                         R"({"op": "set_background", "object": "H", "image": "/scans/h2.png", "opacity": 0.8})"));
  EXPECT_EQ(*doc.findByName("H")->background, (PlanBackground{"/scans/h2.png", 0.02, Vec2(-1, 2), 0.8}));
  try {
    ed::applyEdit(doc,
                  nlohmann::json::parse(R"({"op": "set_background", "object": "H", "image": "a.png", "opacity": 2})"));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where, "opacity");
  }
  EXPECT_THROW(ed::applyEdit(doc, nlohmann::json::parse(
                                      R"({"op": "set_background", "object": "H", "image": "a.png", "scale": 0})")),
               InputError);
  EXPECT_THROW(ed::applyEdit(doc, nlohmann::json::parse(R"({"op": "set_background", "object": "H", "image": ""})")),
               InputError);
  EXPECT_EQ(doc.findByName("H")->background->image, "/scans/h2.png") << "a refused edit changes nothing";
  ed::applyEdit(doc, nlohmann::json::parse(R"({"op": "clear_background", "object": "H"})"));
  EXPECT_FALSE(doc.findByName("H")->background);
}

}  // namespace forced

}  // namespace
}  // namespace corbel::extrude::test
