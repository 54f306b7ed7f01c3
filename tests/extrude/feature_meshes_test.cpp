// Feature meshes at mesh anchors (Fig. 28) and repeats of anchored features (Sec. 3.6): every
// part a closed, outward 2-manifold whose volume is the hand-computed one for its control
// points; resizing stretches only the panes; instances sit where the anchor frame says; and a
// repeat gives the counts and places of hand arithmetic.
#include "core/error.h"
#include "core/scene.h"
#include "core/scene_sync.h"
#include "extrude/features.h"
#include "extrude/kernel.h"
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace corbel::extrude::test {
namespace {

// An oracle of its own: the divergence theorem over a fan of triangles per face.
double signedVolume(const FeaturePart& p) {
  double v = 0;
  for (const auto& f : p.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i)
      v += OpenMesh::dot(p.points[f[0]], OpenMesh::cross(p.points[f[i]], p.points[f[i + 1]])) / 6.0;
  return v;
}

// Directed edges without exactly one reverse partner (0: closed and consistently oriented).
std::size_t unpaired(const FeaturePart& p) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& f : p.faces)
    for (std::size_t i = 0; i < f.size(); ++i) ++count[{f[i], f[(i + 1) % f.size()]}];
  std::size_t bad = 0;
  for (const auto& [e, n] : count) {
    auto it = count.find({e.second, e.first});
    if (n != 1 || it == count.end() || it->second != 1) ++bad;
  }
  return bad;
}

ValidityReport validated(const FeaturePart& p) {
  MeshData m;
  m.points = p.points;
  for (const auto& f : p.faces) m.addFace(f);
  Scene scene;
  scene.replaceObject(1, Kind::Feature, "part", m);
  return scene.validate(1);
}

const FeaturePart& part(const std::vector<FeaturePart>& parts, const std::string& name) {
  for (const FeaturePart& p : parts)
    if (p.name == name) return p;
  ADD_FAILURE() << "no part " << name;
  return parts.front();
}

// A wall facing −y at the origin, and a 45° roof rising towards +y.
AnchorFrame wallFrame(Vec3 at = Vec3(0, 0, 0)) {
  AnchorFrame f;
  f.instanced = true;
  f.position = at;
  f.along = Vec3(1, 0, 0);
  f.normal = Vec3(0, -1, 0);
  f.up = OpenMesh::cross(f.normal, f.along);
  return f;
}
AnchorFrame roofFrame(Vec3 at = Vec3(0, 0, 3)) {
  AnchorFrame f = wallFrame(at);
  f.normal = Vec3(0, -1, 1) / std::sqrt(2.0);
  f.up = OpenMesh::cross(f.normal, f.along);
  return f;
}

// Coordinates of p in the anchor's frame: (along, up, out).
Vec3 local(const AnchorFrame& f, const Vec3& p) {
  const Vec3 d = p - f.position;
  return Vec3(OpenMesh::dot(d, f.along), OpenMesh::dot(d, f.up), OpenMesh::dot(d, f.normal));
}

const FeatureKind kAll[] = {FeatureKind::Door, FeatureKind::Window, FeatureKind::RoofWindow, FeatureKind::ChimneyPot};

TEST(FeatureMeshes, EveryPartIsAClosedOutwardTwoManifold) {
  for (FeatureKind k : kAll)
    for (const AnchorFrame& f : {wallFrame(Vec3(3, -2, 1)), roofFrame()})
      for (const FeatureSize& size : {defaultFeatureSize(k), FeatureSize{2.5, 0.4, 0.3}, FeatureSize{0.05, 0.05, 0.01}}) {
        const auto parts = featureParts(k, size, f);
        ASSERT_GE(parts.size(), 2u) << featureName(k);
        for (const FeaturePart& p : parts) {
          SCOPED_TRACE(std::string(featureName(k)) + " " + p.name + " " + std::to_string(size.width));
          EXPECT_EQ(unpaired(p), 0u);
          EXPECT_GT(signedVolume(p), 0) << "outward";
          const ValidityReport v = validated(p);
          for (const auto& problem : v.problems()) ADD_FAILURE() << problem;
          EXPECT_EQ(v.components, 1u);
          EXPECT_EQ(v.euler, p.name == "frame" || p.name == "rim" ? 0 : 2) << "a ring is a torus, a prism a sphere";
          EXPECT_NEAR(v.volume, signedVolume(p), 1e-12);
        }
      }
}

TEST(FeatureMeshes, VolumesAreTheHandComputedOnesForTheControlPoints) {
  // Door 1 × 2.2 × 0.15: a 0.15 m step 1.2 wide and 0.3 deep, a frame 0.08 thick above it
  // (outer 1 × 2.05, opening 0.84 × 1.89), the leaf in the opening 0.075 deep.
  const auto door = featureParts(FeatureKind::Door, {1.0, 2.2, 0.15}, wallFrame());
  EXPECT_NEAR(signedVolume(part(door, "step")), 1.2 * 0.15 * 0.3, 1e-12);
  EXPECT_NEAR(signedVolume(part(door, "frame")), (1.0 * 2.05 - 0.84 * 1.89) * 0.15, 1e-12);
  EXPECT_NEAR(signedVolume(part(door, "leaf")), 0.84 * 1.89 * 0.075, 1e-12);
  // Window 1.2 × 1.4 × 0.12: frame 0.06 (opening 1.08 × 1.28), pane 0.06 deep, sill 1.3 wide,
  // 0.06 high, 0.17 deep.
  const auto window = featureParts(FeatureKind::Window, {1.2, 1.4, 0.12}, roofFrame());
  EXPECT_NEAR(signedVolume(part(window, "frame")), (1.2 * 1.4 - 1.08 * 1.28) * 0.12, 1e-12);
  EXPECT_NEAR(signedVolume(part(window, "pane")), 1.08 * 1.28 * 0.06, 1e-12);
  EXPECT_NEAR(signedVolume(part(window, "sill")), 1.3 * 0.06 * 0.17, 1e-12);
  // Chimney pot 0.3 × 0.6 × 0.3 on a 45° roof: an octagon of circumradius 0.15 (area
  // 2√2 r²) reaching 0.19 m below the anchor (rim radius 0.19 × slope 1), and a rim ring
  // 0.08 high out to circumradius 0.19.
  const auto pot = featureParts(FeatureKind::ChimneyPot, {0.3, 0.6, 0.3}, roofFrame());
  const double octagon = 2 * std::sqrt(2.0) * 0.15 * 0.15, rimOctagon = 2 * std::sqrt(2.0) * 0.19 * 0.19;
  EXPECT_NEAR(signedVolume(part(pot, "pot")), octagon * (0.6 + 0.19), 1e-12);
  EXPECT_NEAR(signedVolume(part(pot, "rim")), (rimOctagon - octagon) * 0.08, 1e-12);
}

// The extent of a part's points in the anchor frame.
struct Extent {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};
Extent extent(const AnchorFrame& f, const FeaturePart& p) {
  Extent e;
  for (const Vec3& q : p.points) {
    const Vec3 l = local(f, q);
    e.lo.minimize(l);
    e.hi.maximize(l);
  }
  return e;
}

TEST(FeatureMeshes, ResizingStretchesThePanesAndKeepsTheFrameThickness) {
  for (FeatureKind k : {FeatureKind::Window, FeatureKind::RoofWindow, FeatureKind::Door}) {
    const double f = k == FeatureKind::Window ? 0.06 : k == FeatureKind::RoofWindow ? 0.07 : 0.08;
    const double step = k == FeatureKind::Door ? 0.15 : 0.0;
    const char* paneName = k == FeatureKind::Door ? "leaf" : "pane";
    for (const FeatureSize& s : {FeatureSize{1.2, 2.4, 0.12}, FeatureSize{3.0, 1.0, 0.2}, FeatureSize{0.7, 1.6, 0.1}}) {
      SCOPED_TRACE(std::string(featureName(k)) + " " + std::to_string(s.width) + " x " + std::to_string(s.height));
      const AnchorFrame fr = roofFrame(Vec3(2, 1, 4));
      const auto parts = featureParts(k, s, fr);
      const Extent outer = extent(fr, part(parts, "frame")), pane = extent(fr, part(parts, paneName));
      EXPECT_NEAR(outer.hi[0] - outer.lo[0], s.width, 1e-12);
      EXPECT_NEAR(outer.hi[1] - outer.lo[1], s.height - step, 1e-12);
      // The frame's four members keep their thickness; the pane takes the rest.
      EXPECT_NEAR(pane.lo[0] - outer.lo[0], f, 1e-12);
      EXPECT_NEAR(outer.hi[0] - pane.hi[0], f, 1e-12);
      EXPECT_NEAR(pane.lo[1] - outer.lo[1], f, 1e-12);
      EXPECT_NEAR(outer.hi[1] - pane.hi[1], f, 1e-12);
      EXPECT_NEAR(signedVolume(part(parts, paneName)), (s.width - 2 * f) * (s.height - step - 2 * f) * s.depth / 2, 1e-12)
          << "pane area (W − 2f)(H − 2f), set back by half the depth";
      EXPECT_NEAR(outer.hi[2] - pane.hi[2], s.depth / 2, 1e-12);
    }
  }
}

TEST(FeatureMeshes, InstancesSitWhereTheAnchorFrameSays) {
  // A 10 × 6 house, walls 3 m, 45° hip. Door: absolute anchor 4 m along the front edge (y = 0,
  // facing −y) on the ground. Roof window: on the back slope 1 m above the eaves.
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg));
  s.anchors.push_back({"door", {0, 0, true, 4.0, 0.0}, FeatureKind::Door, {1.0, 2.2, 0.15}});
  s.anchors.push_back({"skylight", {0, 2, false, 0.5, 4.0}, FeatureKind::RoofWindow, {0.8, 1.0, 0.1}});
  s.anchors.push_back({"pot", {0, 1, false, 0.5, 4.5}, FeatureKind::ChimneyPot, {0.3, 0.6, 0.3}});
  const ExtrusionResult r = extrude(s);
  ASSERT_EQ(r.anchors.size(), 3u);
  // Door: world box x 3.4 .. 4.6 (the step's overhang), y −0.3 .. 0 (its back on the wall
  // plane y = 0), z 0 .. 2.2; the frame's bottom centre above the step at the anchor.
  Extent door;
  for (const FeaturePart& p : featureParts(FeatureKind::Door, s.anchors[0].size, r.anchors[0]))
    for (const Vec3& q : p.points) door.lo.minimize(q), door.hi.maximize(q);
  EXPECT_NEAR((door.lo - Vec3(3.4, -0.3, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((door.hi - Vec3(4.6, 0, 2.2)).norm(), 0, 1e-12);
  // Roof window: on the plane of the back slope (y + z = 9 at the anchor (5, 5, 4)), its
  // back on it and its top 1 m up the slope from the anchor.
  const AnchorFrame& sky = r.anchors[1];
  const auto window = featureParts(FeatureKind::RoofWindow, s.anchors[1].size, sky);
  double lowest = 1e300, highest = -1e300;
  for (const FeaturePart& p : window)
    for (const Vec3& q : p.points) {
      const double out = (q[1] + q[2] - 9) / std::sqrt(2.0);  // distance above the slope
      lowest = std::min(lowest, out);
      highest = std::max(highest, out);
    }
  EXPECT_NEAR(lowest, 0, 1e-12);
  EXPECT_NEAR(highest, 0.1, 1e-12);
  const Extent frame = extent(sky, part(window, "frame"));
  const Vec3 topCentre = sky.position + sky.up * frame.hi[1];  // up the slope: towards −y
  EXPECT_NEAR((topCentre - Vec3(5, 5 - std::sqrt(0.5), 4 + std::sqrt(0.5))).norm(), 0, 1e-12);
  // Chimney pot on the right slope, 1.5 m above the eaves: the edge has moved 1.5 m in, to
  // x = 8.5, and runs from y = 1.5 to 4.5. The pot stands vertical, centred at (8.5, 3, 4.5).
  const auto pot = featureParts(FeatureKind::ChimneyPot, s.anchors[2].size, r.anchors[2]);
  Extent body;
  for (const Vec3& q : part(pot, "pot").points) body.lo.minimize(q), body.hi.maximize(q);
  EXPECT_NEAR((body.lo + body.hi)[0] / 2, 8.5, 1e-12);
  EXPECT_NEAR((body.lo + body.hi)[1] / 2, 3, 1e-12);
  EXPECT_NEAR(body.hi[2], 4.5 + 0.6, 1e-12);
  EXPECT_NEAR(body.lo[2], 4.5 - 0.19, 1e-12) << "down to the slope under the rim's far side";
}

// A box house whose walls stay vertical to 8 m: the active edges keep their input length.
ExtrusionSpec tallBox() {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(8, 45 * kDeg));
  return s;
}

TEST(Repeats, ARowBetweenTwoRelativeAnchorsSpreadsColumnsByTheSpacing) {
  // 10 m edge, first at 0.1, last at 0.9, at least 2 m apart: 8 m / 2 m = 4 gaps, 5 columns
  // at 1, 3, 5, 7, 9 m.
  ExtrusionSpec s = tallBox();
  Repeat row{RepeatKind::Row, 0.9, 0.0, 2.0, 3.0};
  s.anchors.push_back({"windows", {0, 0, false, 0.1, 1.0}, FeatureKind::Window, {1.0, 1.2, 0.1}, row});
  EXPECT_EQ(repeatGrid(s, s.anchors[0].anchor, row).columns, 5u);
  const ExtrusionResult r = extrude(s);
  ASSERT_EQ(r.anchors.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_TRUE(r.anchors[i].instanced);
    EXPECT_EQ(r.anchors[i].source, 0);
    EXPECT_NEAR((r.anchors[i].position - Vec3(1 + 2 * i, 0, 1)).norm(), 0, 1e-12) << i;
  }
  EXPECT_EQ(r.anchors[2].name, "windows (3 of 5)");
  // 9 m between 0.05 and 0.95 at 2 m fits 4 gaps too: five columns 2.25 m apart.
  row.along = 0.95;
  s.anchors[0].anchor.along = 0.05;
  s.anchors[0].repeat = row;
  const ExtrusionResult wide = extrude(s);
  ASSERT_EQ(wide.anchors.size(), 5u);
  EXPECT_NEAR(wide.anchors[1].position[0], 0.5 + 2.25, 1e-12);
  // Absolute anchors: 1 m to 9 m at 2.5 m: 3 gaps (8 / 2.5 = 3.2), four columns 8/3 apart.
  s.anchors[0].anchor = {0, 0, true, 1.0, 1.0};
  s.anchors[0].repeat = {RepeatKind::Row, 9.0, 0.0, 2.5, 3.0};
  const ExtrusionResult abs = extrude(s);
  ASSERT_EQ(abs.anchors.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(abs.anchors[i].position[0], 1 + 8.0 / 3 * i, 1e-12);
  // Shorter than the spacing: only the first.
  s.anchors[0].repeat.along = 2.0;
  EXPECT_EQ(extrude(s).anchors.size(), 1u);
}

TEST(Repeats, AGridHasRowsTimesColumnsFirstRowFirst) {
  // Columns 1 .. 9 m at 2 m (5), rows 1 .. 4 m at 1.5 m (3 rows: 1, 2.5, 4).
  ExtrusionSpec s = tallBox();
  const Repeat grid{RepeatKind::Grid, 0.9, 4.0, 2.0, 1.5};
  s.anchors.push_back({"facade", {0, 0, false, 0.1, 1.0}, FeatureKind::Window, {1.0, 1.0, 0.1}, grid});
  const std::vector<Anchor> places = repeatAnchors(s, s.anchors[0].anchor, grid);
  ASSERT_EQ(places.size(), 15u);
  const ExtrusionResult r = extrude(s);
  ASSERT_EQ(r.anchors.size(), 15u);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 5; ++col)
      EXPECT_NEAR((r.anchors[row * 5 + col].position - Vec3(1 + 2 * col, 0, 1 + 1.5 * row)).norm(), 0, 1e-12);
  // Through the kernel registered with SceneSync: 15 windows, each 3 parts, in the object.
  Document doc;
  const ObjectId id = doc.add("block", s);
  SceneSync sync;
  registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  EXPECT_EQ(sync.status().at(id).error, "");
  const ValidityReport v = scene.validate(id);
  for (const auto& p : v.problems()) ADD_FAILURE() << p;
  EXPECT_EQ(v.components, 1u + 15 * 3);
  std::size_t windowFaces = 0;
  for (auto f : scene.faces(id)) windowFaces += scene.faceTag(f) == "window";
  EXPECT_EQ(windowFaces, 15u * (16 + 6 + 6));  // ring 16 faces, pane and sill 6 each
}

TEST(Repeats, ARepeatedDormerStepGivesThatManyDormers) {
  // Dormers on the front slope of a 20 × 8 gabled house, 4 m above the base; one dormer adds
  // a fixed volume, a row of N adds N times it.
  ExtrusionSpec s;
  s.profiles = {wallAndRoofProfile(3, 45 * kDeg), Profile{"gable", {{0, 0}, {0, 1}}, {"gable"}},
                Profile{"front", {{0, 0}, {0, 1}}, {"dormer"}}, Profile{"side", {{0, 0}, {0, 1.2}, {1, 2.2}}, {"dormer", "dormer roof"}}};
  s.loops.push_back({rectangle(20, 8), {0, 1, 0, 1}});
  const double bare = measure(extrude(s).shell).volume;
  PlanStep dormer;
  dormer.name = "dormer";
  dormer.anchor = {0, 0, false, 0.2, 3.5};
  dormer.width = 1.6;
  dormer.depth = 0.5;
  dormer.frontProfile = 2;
  dormer.sideProfile = 3;
  s.steps = {dormer};
  const double one = measure(extrude(s).shell).volume - bare;
  EXPECT_GT(one, 0);
  s.steps[0].repeat = {RepeatKind::Row, 0.8, 0.0, 3.0, 3.0};  // 12 m of 20 at 3 m: 5 dormers
  const ExtrusionResult r = extrude(s);
  EXPECT_TRUE(r.shell.warnings.empty()) << r.shell.warnings.front();
  EXPECT_NEAR(measure(r.shell).volume - bare, 5 * one, 1e-9);
  std::set<double> fronts;  // the dormers' front faces, by where along the edge they are
  for (const ShellFace& f : r.shell.faces)
    if (f.profile == 2 && f.segment == 0) {
      EXPECT_EQ(f.step, 0) << "faces name the repeated step";
      double x = 0;
      for (int v : f.loops[0]) x += r.shell.points[v][0] / f.loops[0].size();
      fronts.insert(std::round(x * 1e6) / 1e6);
    }
  EXPECT_EQ(fronts, (std::set<double>{4, 7, 10, 13, 16})) << "at 0.2 .. 0.8 of 20 m, 3 m apart";
  Scene scene;
  scene.replaceObject(1, Kind::Shell, "x", toMeshData(r.shell, s, "plaster"));
  EXPECT_TRUE(scene.validate(1).closedManifold());
}

TEST(FeatureInstances, AnAnchorThatIsNotPlacedWarnsNamingItsFeature) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg));
  s.anchors.push_back({"attic window", {0, 0, false, 0.5, 12.0}, FeatureKind::Window, {1, 1, 0.1}});
  Document doc;
  const ObjectId id = doc.add("house", s);
  SceneSync sync;
  registerKernel(sync);
  Scene scene;
  sync.update(doc, scene);
  const auto& st = sync.status().at(id);
  EXPECT_EQ(st.error, "");
  ASSERT_EQ(st.warnings.size(), 1u);
  EXPECT_EQ(st.warnings[0].rfind("anchors[0] (attic window): the window is not placed", 0), 0u) << st.warnings[0];
  EXPECT_TRUE(scene.validate(id).closedManifold());
}

TEST(FeatureInstances, BadFeatureValuesAreRefusedNamingTheField) {
  ExtrusionSpec s = uniformSpec({rectangle(10, 6)}, wallAndRoofProfile(3, 45 * kDeg));
  s.anchors.push_back({"w", {0, 0, false, 0.5, 1.0}, FeatureKind::Window, {1, -1, 0.1}});
  auto fault = [&] { return checkSpec(s).value_or("<accepted>"); };
  EXPECT_EQ(fault(), "anchors[0].size[1]: must be greater than 0 and at most 1000 m");
  s.anchors[0].size = {1, 1, std::nan("")};
  EXPECT_EQ(fault(), "anchors[0].size[2]: must be greater than 0 and at most 1000 m");
  s.anchors[0].size = {1, 1, 0.1};
  s.anchors[0].repeat = {RepeatKind::Row, 0.9, 0, 0.0, 1};
  EXPECT_EQ(fault(), "anchors[0].repeat.spacing: must be greater than 0 m");
  s.anchors[0].repeat = {RepeatKind::Row, 1.5, 0, 1.0, 1};
  EXPECT_EQ(fault(), "anchors[0].repeat.along: a relative anchor's repeat ends at a fraction within [0, 1]");
  s.anchors[0].repeat = {RepeatKind::Grid, 0.9, 2, 1.0, 0};
  EXPECT_EQ(fault(), "anchors[0].repeat.row_spacing: must be greater than 0 m");
  s.anchors[0].repeat = {RepeatKind::Grid, 1.0, 3, 1e-4, 1e-4};  // 10 m × 2 m at 0.1 mm
  EXPECT_EQ(fault().rfind("anchors[0].repeat: ", 0), 0u);
  EXPECT_NE(fault().find("more than the limit of 10000"), std::string::npos) << fault();
  EXPECT_THROW(extrude(s), InputError);
  s.anchors[0].repeat = {};
  PlanStep st;
  st.anchor = {0, 0, false, 0.5, 3.5};
  st.repeat = {RepeatKind::Row, 0.9, 0, -2, 1};
  s.steps = {st};
  EXPECT_EQ(fault(), "steps[0].repeat.spacing: must be greater than 0 m");
}

}  // namespace
}  // namespace corbel::extrude::test
