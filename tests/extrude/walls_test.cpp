// Anchors belong to walls (core/extrusion_spec.h, extrude/walls.h, issue 27): splitting an
// edge where the shape does not change leaves the shell as it was, insert-then-delete of a
// corner is the identity, and deleting a corner between two walls keeps what still lies on
// the joined wall where it was and names what went with the other.
#include "core/error.h"
#include "core/history.h"
#include "core/project_io.h"
#include "extrude/edit.h"
#include "support.h"

#include <gtest/gtest.h>

#include <random>

namespace corbel::extrude::test {
namespace {

namespace ed = corbel::extrude::edit;

std::vector<ExtrusionSpec> exampleExtrusions() {
  std::vector<ExtrusionSpec> out;
  for (const char* name : {"house", "temple", "terrace", "extrusions", "courtyard"}) {
    const Document d = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/" + name + ".corbel").document;
    for (const DocObject& o : d.objects)
      if (const auto* e = std::get_if<ExtrusionSpec>(&o.spec)) out.push_back(*e);
  }
  return out;
}

double diagonal(const ExtrusionSpec& s) {
  BBox box;
  for (const PlanLoop& l : s.loops)
    for (const Vec2& p : l.points) box.add(Vec3(p[0], p[1], 0));
  return box.diagonal();
}

// Two results are the same building: volume, faces, and every mesh anchor where it was.
void expectSameBuilding(const ExtrusionResult& a, const ExtrusionResult& b, double scale) {
  const ShellMeasures ma = measure(a.shell), mb = measure(b.shell);
  EXPECT_EQ(ma.faces, mb.faces);
  EXPECT_NEAR(ma.volume, mb.volume, 1e-9 * ma.volume);
  EXPECT_EQ(unpairedEdges(b.shell), 0u);
  ASSERT_EQ(a.anchors.size(), b.anchors.size());
  for (std::size_t k = 0; k < a.anchors.size(); ++k) {
    EXPECT_EQ(a.anchors[k].instanced, b.anchors[k].instanced) << a.anchors[k].name;
    if (a.anchors[k].instanced && b.anchors[k].instanced) {
      EXPECT_NEAR((a.anchors[k].position - b.anchors[k].position).norm(), 0.0, 1e-9 * scale) << a.anchors[k].name;
    }
  }
}

std::size_t instanced(const ExtrusionResult& r) {
  std::size_t n = 0;
  for (const AnchorFrame& f : r.anchors) n += f.instanced;
  return n;
}

TEST(Walls, SplittingTheFigureOneHousesFrontAtSixLeavesItAsItWas) {
  const ExtrusionSpec house = exampleExtrusions().front();
  const ExtrusionResult before = extrude(house);
  const ExtrusionSpec split = ed::insertCorner(house, 0, 0, Vec2(6, 0));
  ASSERT_EQ(split.loops[0].points.size(), 5u);
  const ExtrusionResult after = extrude(split);
  expectSameBuilding(before, after, diagonal(house));
  EXPECT_EQ(instanced(after), instanced(before));
  // The chimney and the door stay on their walls: their edges are renumbered, not repointed.
  EXPECT_EQ(split.steps[2].anchor.edge, 3);  // the chimney, on the back (edge 2 before)
  EXPECT_EQ(split.anchors[0].anchor.edge, 2);  // the front door, on the right (edge 1 before)
  // Faces of the front's halves name the edge the wall starts with (0), none the second half.
  for (const ShellFace& f : after.shell.faces) EXPECT_FALSE(f.step < 0 && f.sourceLoop == 0 && f.sourceEdge == 1);
}

// (a) Any edge split anywhere on it: the shell and every feature instance are unchanged.
TEST(Walls, SplittingAnyEdgeWhereTheShapeStaysChangesNothing) {
  std::mt19937 rng(27);
  std::size_t splits = 0;
  for (const ExtrusionSpec& s : exampleExtrusions()) {
    const ExtrusionResult before = extrude(s);
    for (int li = 0; li < static_cast<int>(s.loops.size()); ++li)
      for (int e = 0; e < static_cast<int>(s.loops[li].points.size()); ++e) {
        const Vec2 a = s.loops[li].points[e], b = s.loops[li].points[(e + 1) % s.loops[li].points.size()];
        const double t = std::uniform_real_distribution<double>(0.05, 0.95)(rng);
        SCOPED_TRACE("loop " + std::to_string(li) + " edge " + std::to_string(e) + " at " + std::to_string(t));
        ExtrusionSpec split = ed::insertCorner(s, li, e, a + (b - a) * t);
        // And once more in the second half, so a wall of three edges is tried too.
        split = ed::insertCorner(split, li, e + 1, a + (b - a) * (t + (1 - t) / 2));
        expectSameBuilding(before, extrude(split), diagonal(s));
        ++splits;
      }
  }
  EXPECT_GT(splits, 40u);
}

// (c) Inserting a corner anywhere (on the edge or off it) and deleting it again gives back the
// spec itself.
TEST(Walls, InsertThenDeleteOfACornerIsTheIdentity) {
  std::mt19937 rng(4);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  for (const ExtrusionSpec& s0 : exampleExtrusions()) {
    const ExtrusionSpec& s = s0;
    for (int li = 0; li < static_cast<int>(s.loops.size()); ++li)
      for (int e = 0; e < static_cast<int>(s.loops[li].points.size()); ++e) {
        const Vec2 a = s.loops[li].points[e], b = s.loops[li].points[(e + 1) % s.loops[li].points.size()];
        for (const Vec2& p : {a + (b - a) * u(0.1, 0.9), a + (b - a) * u(0.1, 0.9) + Vec2(u(-2, 2), u(-2, 2))}) {
          std::vector<std::string> notes;
          const ExtrusionSpec back = ed::deleteCorner(ed::insertCorner(s, li, e, p), li, e + 1, &notes);
          EXPECT_EQ(back, s) << "loop " << li << " edge " << e;
          EXPECT_TRUE(notes.empty());
        }
      }
  }
}

ExtrusionSpec twoWallsInALine() {
  // Edge 0 (0,0)-(6,0) and edge 1 (6,0)-(12,0) are two walls in one line.
  ExtrusionSpec s = uniformSpec({{Vec2(0, 0), Vec2(6, 0), Vec2(12, 0), Vec2(12, 8), Vec2(0, 8)}},
                                wallAndRoofProfile(3.0, 45 * kDeg));
  assignWalls(s);
  s.anchors.push_back(MeshAnchor("door", Anchor{0, 0, false, 0.5, 0.0}, FeatureKind::Door));
  s.anchors.push_back(MeshAnchor("window", Anchor{0, 1, false, 0.5, 1.0}, FeatureKind::Window));
  s.anchors.push_back(MeshAnchor("side window", Anchor{0, 2, true, 2.0, 1.0}, FeatureKind::Window));
  return s;
}

TEST(Walls, DeletingACornerBetweenTwoWallsInALineKeepsEveryPoint) {
  const ExtrusionSpec s = twoWallsInALine();
  std::vector<std::string> notes;
  const ExtrusionSpec d = ed::deleteCorner(s, 0, 1, &notes);
  EXPECT_TRUE(notes.empty());
  ASSERT_EQ(d.anchors.size(), 3u);
  EXPECT_NEAR((*anchorPoint(d, d.anchors[0].anchor) - Vec2(3, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((*anchorPoint(d, d.anchors[1].anchor) - Vec2(9, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(d.anchors[0].anchor.along, 0.25, 1e-12);
  EXPECT_NEAR(d.anchors[1].anchor.along, 0.75, 1e-12);
  // The right side is edge 1 now, 2 m up it as before.
  EXPECT_EQ(d.anchors[2].anchor.edge, 1);
  EXPECT_NEAR((*anchorPoint(d, d.anchors[2].anchor) - Vec2(12, 2)).norm(), 0.0, 1e-12);
  // One wall now: the two walls' ids became one.
  EXPECT_EQ(d.loops[0].walls[0], s.loops[0].walls[0]);
  const ExtrusionResult r = extrude(d);
  EXPECT_EQ(instanced(r), 3u);
}

TEST(Walls, DeletingACornerNamesWhatWentWithTheOtherWallAndUndoBringsItBack) {
  // A 12 x 8 rectangle: door on the right wall (edge 1), window on the front (edge 0).
  ExtrusionSpec s = uniformSpec({rectangle(12, 8)}, wallAndRoofProfile(3.0, 45 * kDeg));
  assignWalls(s);
  s.anchors.push_back(MeshAnchor("side door", Anchor{0, 1, false, 0.5, 0.0}, FeatureKind::Door));
  s.anchors.push_back(MeshAnchor("front window", Anchor{0, 0, false, 0.5, 1.0}, FeatureKind::Window));
  s.anchors.push_back(MeshAnchor("back window", Anchor{0, 2, false, 0.25, 1.0}, FeatureKind::Window));
  const Vec2 back = *anchorPoint(s, s.anchors[2].anchor);
  std::vector<std::string> notes;
  // Corner 1 (12, 0): the front now runs to (12, 8); the right wall is gone.
  const ExtrusionSpec d = ed::deleteCorner(s, 0, 1, &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("removed feature \"side door\""), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("corner 1"), std::string::npos) << notes[0];
  ASSERT_EQ(d.anchors.size(), 2u);
  EXPECT_EQ(d.anchors[0].name, "front window");
  // The front window keeps its place along the edge that turned: half way to (12, 8).
  EXPECT_NEAR((*anchorPoint(d, d.anchors[0].anchor) - Vec2(6, 4)).norm(), 0.0, 1e-12);
  // The back window did not move.
  EXPECT_NEAR((*anchorPoint(d, d.anchors[1].anchor) - back).norm(), 0.0, 1e-12);
  // As the editor does it: one undo step, and undo restores the door.
  Document doc;
  const ObjectId id = doc.add("house", s);
  History h(doc);
  Document edited = doc;
  std::get<ExtrusionSpec>(edited.find(id)->spec) = d;
  h.commit(edited, "Delete corner");
  ASSERT_TRUE(h.undo());
  EXPECT_EQ(std::get<ExtrusionSpec>(h.current().find(id)->spec), s);
}

TEST(Walls, DeletingALoopNamesWhatWasOnItAndRenumbersTheRest) {
  ExtrusionSpec s = uniformSpec({rectangle(20, 20), reversed(rectangle(4, 4, 8, 8)), reversed(rectangle(2, 2, 2, 2))},
                                wallAndRoofProfile(3.0, 45 * kDeg));
  s.anchors.push_back(MeshAnchor("court door", Anchor{1, 0, false, 0.5, 0.0}, FeatureKind::Door));
  s.anchors.push_back(MeshAnchor("well door", Anchor{2, 0, false, 0.5, 0.0}, FeatureKind::Door));
  std::vector<std::string> notes;
  const ExtrusionSpec d = ed::deleteLoop(s, 1, &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("\"court door\""), std::string::npos);
  ASSERT_EQ(d.anchors.size(), 1u);
  EXPECT_EQ(d.anchors[0].anchor.loop, 1);
  EXPECT_EQ(*anchorPoint(d, d.anchors[0].anchor), *anchorPoint(s, s.anchors[1].anchor));
}

// A wall split and then bent (the new corner moved): anchors keep their fraction of the whole
// wall, and a repeat counts its columns along the whole wall.
TEST(Walls, ARepeatSpansTheCornerOfASplitWall) {
  ExtrusionSpec s = uniformSpec({rectangle(12, 8)}, wallAndRoofProfile(4.0, 45 * kDeg));
  MeshAnchor row("windows", Anchor{0, 0, true, 1.0, 1.0}, FeatureKind::Window);
  row.repeat.kind = RepeatKind::Row;
  row.repeat.along = 11.0;
  row.repeat.spacing = 2.0;
  s.anchors.push_back(row);
  const ExtrusionSpec split = ed::insertCorner(s, 0, 0, Vec2(5, 0));
  EXPECT_EQ(repeatGrid(split, split.anchors[0].anchor, split.anchors[0].repeat).columns, 6u);  // 1, 3, ... 11
  const ExtrusionResult a = extrude(s), b = extrude(split);
  expectSameBuilding(a, b, diagonal(s));
  // Two profiles on the halves: the wall no longer joins, yet every window stays in place.
  ExtrusionSpec two = split;
  two.profiles.push_back(wallAndRoofProfile(4.0, 50 * kDeg));
  two.loops[0].profile[1] = 1;
  const ExtrusionResult c = extrude(two);
  ASSERT_EQ(c.anchors.size(), a.anchors.size());
  for (std::size_t k = 0; k < c.anchors.size(); ++k) {
    ASSERT_TRUE(c.anchors[k].instanced);
    EXPECT_NEAR((c.anchors[k].position - a.anchors[k].position).norm(), 0.0, 1e-9) << k;
  }
}

TEST(Walls, TheFileKeepsWallsOnlyOnceTheyDifferFromOnePerEdge) {
  const ExtrusionSpec house = exampleExtrusions().front();
  Document d;
  d.add("house", house);
  EXPECT_EQ(serializeProject(d).find("\"walls\""), std::string::npos);
  Document split = d;
  std::get<ExtrusionSpec>(split.objects[0].spec) = ed::insertCorner(house, 0, 0, Vec2(6, 0));
  const std::string text = serializeProject(split);
  EXPECT_NE(text.find("\"walls\": [[1, 1, 2, 3, 4]]"), std::string::npos) << text.substr(0, 600);
  EXPECT_EQ(parseProject(text).document, split);
  // A wall in two loops, or one wall in two places of a loop, is refused with its path.
  const auto fault = [](const std::string& walls) {
    try {
      parseProject(R"({"format": "corbel", "version": 1, "objects": [{"id": 1, "name": "A", "extrusion": {"plan":
        {"loops": [[[0, 0], [4, 0], [4, 3], [0, 3]], [[1, 1], [1, 2], [2, 2], [2, 1]]], "walls": )" + walls + R"(},
        "profiles": [{"name": "p", "points": [[0, 0], [0, 3], [1, 4]]}]}}]})");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(fault("[[1, 2, 3, 4], [4, 5, 6, 7]]").find("wall 4 is in loops 0 and 1"), std::string::npos);
  EXPECT_NE(fault("[[1, 2, 1, 3], [5, 6, 7, 8]]").find("each wall's edges must follow each other"), std::string::npos);
  EXPECT_NE(fault("[[1, 2, 3], [5, 6, 7, 8]]").find("expected one wall per edge"), std::string::npos);
}

}  // namespace
}  // namespace corbel::extrude::test
