// editor/masonry_view.h: what the statics panel shows, held against hand computation and the
// known thresholds of the semicircular arch.
#include "editor/masonry_view.h"

#include "core/error.h"
#include "core/project_io.h"
#include "statics/arch.h"
#include "statics/kernel.h"
#include "statics/tolerances.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace corbel::editor {
namespace {

statics::InterfaceForces contact(int a, int b, std::vector<double> tensions) {
  statics::InterfaceForces f;
  f.a = a;
  f.b = b;
  for (double t : tensions) {
    statics::VertexForce v;
    v.tension = t;
    f.vertices.push_back(v);
  }
  return f;
}

MasonrySpec exampleArch() {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-arch.corbel");
  return std::get<MasonrySpec>(p.document.objects.at(0).spec);
}

// The semicircular arch of radius 1 with `blocks` voussoirs as a model of one parameter,
// its thickness (Milankovitch: it stands from t/R ≈ 0.1075 up).
statics::ParametricModel archModel(int blocks) {
  statics::ParametricModel m;
  m.name = "arch";
  m.parameters.add({"thickness", 0.2, 0.01, 1.9, true, "radial thickness"});
  m.build = [blocks](const statics::ParameterSet& p) {
    statics::ArchSpec s;
    s.blocks = blocks;
    s.thickness = p["thickness"];
    return statics::semicircularArch(s);
  };
  return m;
}

TEST(BlockTensionShares, SumsEachBlocksVertexTensionsOverItsInterfacesAndDividesByTheLargest) {
  statics::AnalysisResult r;
  r.totalWeight = 1.0;
  r.interfaces = {contact(0, 1, {2.0, 0.0}), contact(1, 2, {1.0, 1.0})};
  // By hand: T0 = 2, T1 = 2 + 2 = 4, T2 = 2; block 3 takes part in nothing.
  const std::vector<double> s = blockTensionShares(4, r);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s[0], 0.5);
  EXPECT_DOUBLE_EQ(s[1], 1.0);
  EXPECT_DOUBLE_EQ(s[2], 0.5);
  EXPECT_DOUBLE_EQ(s[3], 0.0);
}

TEST(BlockTensionShares, TensionBelowTheSiteThresholdShowsNothing) {
  statics::AnalysisResult r;
  r.totalWeight = 1e6;  // every vertex below kTensionSite·W = 10 N
  r.interfaces = {contact(0, 1, {5.0, 1.0})};
  for (double s : blockTensionShares(2, r)) EXPECT_EQ(s, 0.0);
}

TEST(TensionColor, BlendsStoneIntoBlueLinearlyAndClamps) {
  const auto none = tensionColor(0.0), full = tensionColor(1.0), half = tensionColor(0.5);
  EXPECT_GT(full[2], full[0]);  // tension is blue
  EXPECT_GT(full[2], full[1]);
  EXPECT_LT(none[2], none[0]);  // stone is warm, not blue
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(half[k], 0.5f * (none[k] + full[k]), 1e-6);
    EXPECT_GE(none[k], 0.0f);
    EXPECT_LE(none[k], 1.0f);
  }
  double lastBlueness = -10;
  for (int i = 0; i <= 10; ++i) {
    const auto c = tensionColor(i / 10.0);
    const double blueness = c[2] - c[0];
    EXPECT_GT(blueness, lastBlueness);
    lastBlueness = blueness;
    EXPECT_EQ(c[3], 1.0f);
  }
  EXPECT_EQ(tensionColor(-3.0), none);
  EXPECT_EQ(tensionColor(7.0), full);
  EXPECT_EQ(tensionColor(std::nan("")), none);
}

TEST(ForceArrows, EndAtTheCentreOfPressureAlongTheResultantScaledToTheLongest) {
  statics::AnalysisResult r;
  statics::InterfaceForces a, b, pulled;
  a.normalForce = 2;
  a.resultant = Vec3(0, 0, -2);
  a.centreOfPressure = Vec3(1, 0, 0);
  b.normalForce = 1;
  b.resultant = Vec3(0.6, 0, -0.8);
  b.centreOfPressure = Vec3(2, 0, 0);
  pulled.normalForce = -0.5;  // net tension: no compression arrow
  pulled.resultant = Vec3(0, 0, 0.5);
  pulled.normal = Vec3(0, 0, 1);
  r.interfaces = {a, b, pulled};
  statics::TensionSite site;
  site.interface = 2;
  site.point = Vec3(5, 0, 1);
  site.tension = 0.1;
  statics::TensionSite small = site;
  small.point = Vec3(6, 0, 1);
  small.tension = 0.05;
  r.tensionSites = {site, small};
  const std::vector<ForceArrow> arrows = forceArrows(r, 0.5);
  ASSERT_EQ(arrows.size(), 4u);
  // The largest resultant is 2 N, drawn 0.5 m long: 0.25 m per newton.
  EXPECT_FALSE(arrows[0].tension);
  EXPECT_NEAR((arrows[0].to - Vec3(1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((arrows[0].from - Vec3(1, 0, 0.5)).norm(), 0, 1e-12);
  EXPECT_NEAR((arrows[1].to - arrows[1].from).norm(), 0.25, 1e-12);
  EXPECT_NEAR(OpenMesh::dot((arrows[1].to - arrows[1].from).normalized(), Vec3(0.6, 0, -0.8)), 1.0, 1e-12);
  EXPECT_TRUE(arrows[2].tension);
  EXPECT_NEAR((arrows[2].from - Vec3(5, 0, 1)).norm(), 0, 1e-12);
  // The largest tension, 0.1 N, is drawn half as long as the largest resultant: 0.25 m.
  EXPECT_NEAR((arrows[2].to - Vec3(5, 0, 0.75)).norm(), 0, 1e-12);
  EXPECT_TRUE(arrows[3].tension);
  EXPECT_NEAR((arrows[3].to - Vec3(6, 0, 0.875)).norm(), 0, 1e-12);
  EXPECT_TRUE(forceArrows(statics::AnalysisResult{}, 1.0).empty());
}

TEST(AnalyseMasonry, TheThinExampleArchNeedsTensionAndShowsWhere) {
  const MasonryView v = analyseMasonry(exampleArch());
  ASSERT_TRUE(v.error.empty()) << v.error;
  EXPECT_FALSE(v.result.feasible);
  EXPECT_GT(v.result.yNormalised, statics::kFeasibleMeasure);
  EXPECT_FALSE(v.result.tensionSites.empty());
  ASSERT_EQ(v.blockFaces.size(), v.tensionShare.size());
  ASSERT_EQ(v.blockFaces.size(), v.fixed.size());
  double most = 0;
  for (std::size_t b = 0; b < v.tensionShare.size(); ++b) {
    EXPECT_GE(v.tensionShare[b], 0.0);
    EXPECT_LE(v.tensionShare[b], 1.0);
    most = std::max(most, v.tensionShare[b]);
    for (const auto& face : v.blockFaces[b]) EXPECT_GE(face.size(), 3u);
  }
  EXPECT_EQ(most, 1.0);
  EXPECT_EQ(std::count(v.fixed.begin(), v.fixed.end(), true), 1);  // the ground
}

TEST(AnalyseMasonry, AThickArchOnWideColumnsStandsWithNoTensionShown) {
  MasonrySpec spec = exampleArch();
  spec.parameters = {{"columnWidth", 0.9}, {"thickness", 0.25}};
  const MasonryView v = analyseMasonry(spec);
  ASSERT_TRUE(v.error.empty()) << v.error;
  EXPECT_TRUE(v.result.feasible);
  for (double s : v.tensionShare) EXPECT_EQ(s, 0.0);
}

// The panel shows the strict LP's verdict beside the QP's: the thin example arch fails both
// (the LP misses equilibrium by a positive violation), the thick one stands by both.
TEST(AnalyseMasonry, ShowsTheStrictLpVerdictBesideTheQps) {
  const MasonryView thin = analyseMasonry(exampleArch());
  ASSERT_TRUE(thin.error.empty()) << thin.error;
  EXPECT_FALSE(thin.strict.feasible);
  EXPECT_GT(thin.strict.violation, statics::kFeasibleViolation);
  std::vector<Verdict> v = staticsVerdicts(thin);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_FALSE(v[0].stands);
  EXPECT_NE(v[0].text.find("penalty QP"), std::string::npos) << v[0].text;
  EXPECT_FALSE(v[1].stands);
  EXPECT_NE(v[1].text.find("does not stand (strict LP)"), std::string::npos) << v[1].text;

  MasonrySpec spec = exampleArch();
  spec.parameters = {{"columnWidth", 0.9}, {"thickness", 0.25}};
  const MasonryView thick = analyseMasonry(spec);
  EXPECT_TRUE(thick.strict.feasible);
  EXPECT_LE(thick.strict.violation, statics::kFeasibleViolation);
  v = staticsVerdicts(thick);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(v[0].stands);
  EXPECT_TRUE(v[1].stands);
  EXPECT_NE(v[1].text.find("stands (strict LP)"), std::string::npos) << v[1].text;

  // Where the two disagree (a design on its threshold) a third line says so.
  MasonryView split = thick;
  split.strict.feasible = false;
  v = staticsVerdicts(split);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_TRUE(v[0].stands);
  EXPECT_FALSE(v[1].stands);
  EXPECT_NE(v[2].text.find("disagree"), std::string::npos) << v[2].text;
  // A view with an error has no verdict.
  MasonrySpec unknown;
  unknown.model = "no-such-model";
  EXPECT_TRUE(staticsVerdicts(analyseMasonry(unknown)).empty());
}

TEST(AnalyseMasonry, AnUnknownModelIsAnErrorInTheViewNamingIt) {
  MasonrySpec spec;
  spec.model = "no-such-model";
  const MasonryView v = analyseMasonry(spec);
  EXPECT_NE(v.error.find("no-such-model"), std::string::npos) << v.error;
}

TEST(SampleLandscape, TheArchStandsFromMilankovitchsThicknessUp) {
  // 100 voussoirs: the minimum thickness is t/R = 0.1075 (Sec. 3.3).
  const Landscape l = sampleLandscape(archModel(100), {}, "thickness", 0.06, 0.16, 11);
  ASSERT_EQ(l.measure.size(), 11u);
  for (std::size_t i = 0; i < l.measure.size(); ++i) {
    const double t = l.valueAt(i);
    EXPECT_NEAR(t, 0.06 + 0.01 * double(i), 1e-12);
    if (t < 0.105) {
      EXPECT_GT(l.measure[i], statics::kFeasibleMeasure) << "t = " << t;
    }
    if (t > 0.11) {
      EXPECT_LE(l.measure[i], statics::kFeasibleMeasure) << "t = " << t;
    }
  }
  // Thinner arches need more tension.
  for (std::size_t i = 1; i < 5; ++i) EXPECT_LT(l.measure[i], l.measure[i - 1]);
}

TEST(SampleLandscape, AnUnknownParameterIsRefusedByName) {
  try {
    sampleLandscape(archModel(10), {}, "radius", 0.1, 0.2, 3);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
}

TEST(SampleLandscape, ACancelledJobStopsBeforeSamplingEverything) {
  const statics::ParametricModel model = archModel(100);
  BackgroundJob job("landscape",
                    [&model](Progress& p) { sampleLandscape(model, {}, "thickness", 0.05, 0.3, 5000, &p); });
  while (job.progress().fraction() == 0 && !job.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  job.progress().cancel();
  const auto t0 = std::chrono::steady_clock::now();
  job.wait();
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(job.progress().fraction(), 1.0);
  EXPECT_THROW(job.rethrow(), Cancelled);
  EXPECT_LT(waited, 30.0);  // one analysis at most, not the remaining thousands
}

// Ground reactions (Fig. 1 right): the resultants of interfaces with a fixed block, as the force
// on the structure, scaled among themselves; the others keep their own scale.
TEST(ForceArrows, GroundReactionsAreTheirOwnKindPointingIntoTheStructure) {
  statics::AnalysisResult r;
  statics::InterfaceForces onGround, between, groundAbove;
  onGround.a = 0;  // the ground
  onGround.b = 1;
  onGround.normalForce = 4;
  onGround.resultant = Vec3(0, 0, 4);  // the ground pushes block 1 up
  onGround.centreOfPressure = Vec3(0, 0, 0);
  between.a = 1;
  between.b = 2;
  between.normalForce = 1;
  between.resultant = Vec3(0, 0, 1);
  between.centreOfPressure = Vec3(0, 0, 1);
  groundAbove.a = 2;  // block 2 pushes up on a fixed block 3 above it: the reaction on 2 is down
  groundAbove.b = 3;
  groundAbove.normalForce = 2;
  groundAbove.resultant = Vec3(0, 0, 2);
  groundAbove.centreOfPressure = Vec3(0, 0, 2);
  r.interfaces = {onGround, between, groundAbove};
  const std::vector<ForceArrow> arrows = forceArrows(r, 1.0, {true, false, false, true});
  ASSERT_EQ(arrows.size(), 3u);
  EXPECT_TRUE(arrows[0].reaction);
  EXPECT_FALSE(arrows[0].tension);
  // The largest reaction (4 N) is 1 m long and ends at its centre of pressure, pointing up.
  EXPECT_NEAR((arrows[0].from - Vec3(0, 0, -1)).norm(), 0, 1e-12);
  EXPECT_NEAR((arrows[0].to - Vec3(0, 0, 0)).norm(), 0, 1e-12);
  // Between two free blocks: compression, the only one of its kind, so 1 m long too.
  EXPECT_FALSE(arrows[1].reaction);
  EXPECT_NEAR((arrows[1].to - arrows[1].from).norm(), 1.0, 1e-12);
  // The fixed block is b: the force on the structure (block a) is the opposite of the resultant.
  EXPECT_TRUE(arrows[2].reaction);
  EXPECT_NEAR((arrows[2].to - Vec3(0, 0, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR((arrows[2].from - Vec3(0, 0, 2.5)).norm(), 0, 1e-12);
  // Without the fixed flags every resultant is compression, as before.
  for (const ForceArrow& a : forceArrows(r, 1.0)) EXPECT_FALSE(a.reaction);
  // Three kinds, three colours.
  const ForceArrow t{Vec3(0, 0, 0), Vec3(0, 0, 1), true, false};
  EXPECT_NE(arrowColor(arrows[0]), arrowColor(arrows[1]));
  EXPECT_NE(arrowColor(arrows[0]), arrowColor(t));
  EXPECT_NE(arrowColor(arrows[1]), arrowColor(t));
  EXPECT_EQ(arrowColor(t), kTensionColor);
}

TEST(MasonryPicture, ColoursTheBlocksThatAreNotFixedAndDrawsTheArrows) {
  const MasonryView v = analyseMasonry(exampleArch());
  ASSERT_TRUE(v.error.empty()) << v.error;
  const MasonryPicture p = masonryPicture(v);
  std::size_t faces = 0;
  for (std::size_t b = 0; b < v.blockFaces.size(); ++b)
    if (!v.fixed[b]) faces += v.blockFaces[b].size();
  EXPECT_EQ(p.polygons.size(), faces);
  const std::vector<ForceArrow> arrows = forceArrows(v.result, kLongestArrowOfModel * v.modelSize, v.fixed);
  ASSERT_EQ(p.arrows.size(), arrows.size());
  // The example stands on two columns on the ground: two reactions, and tension somewhere.
  EXPECT_EQ(std::count_if(arrows.begin(), arrows.end(), [](const ForceArrow& a) { return a.reaction; }), 2);
  EXPECT_GT(std::count_if(arrows.begin(), arrows.end(), [](const ForceArrow& a) { return a.tension; }), 0);
  EXPECT_TRUE(masonryPicture(v, false, false).polygons.empty());
  MasonryView broken = v;
  broken.error = "no";
  EXPECT_TRUE(masonryPicture(broken).arrows.empty());
  EXPECT_TRUE(masonryPicture(broken).polygons.empty());
}

// The grid's values against the analysis called directly at each grid point (the oracle shares
// nothing with the sampler but the model), on two threads and on one.
TEST(SampleLandscapeGrid, EachSampleIsTheAnalysisAtItsGridPoint) {
  const statics::ParametricModel model = statics::modelOf(exampleArch());
  const LandscapeAxis x{"thickness", 0.05, 0.5, 4}, y{"columnWidth", 0.1, 1.5, 3};
  const LandscapeGrid g = sampleLandscapeGrid(model, {}, x, y, nullptr, 2);
  ASSERT_EQ(g.measure.size(), 12u);
  ASSERT_EQ(g.stands.size(), 12u);
  int standing = 0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      statics::ParameterSet values = model.parameters;
      const double t = 0.05 + 0.15 * i, w = 0.1 + 0.7 * j;
      EXPECT_NEAR(x.valueAt(i), t, 1e-12);
      EXPECT_NEAR(y.valueAt(j), w, 1e-12);
      values.set("thickness", t);
      values.set("columnWidth", w);
      const statics::AnalysisResult r = statics::analyse(model.build(values), {});
      EXPECT_EQ(g.at(i, j), r.yNormalised) << "t = " << t << ", w = " << w;
      EXPECT_EQ(g.standsAt(i, j), r.feasible) << "t = " << t << ", w = " << w;
      EXPECT_EQ(g.standsAt(i, j), r.yNormalised <= statics::kFeasibleMeasure);
      standing += g.standsAt(i, j);
    }
  EXPECT_GT(standing, 0);  // both kinds occur, so the comparison means something
  EXPECT_LT(standing, 12);
  const LandscapeGrid one = sampleLandscapeGrid(model, {}, x, y, nullptr, 1);
  EXPECT_EQ(one.measure, g.measure);
  EXPECT_EQ(one.stands, g.stands);
}

// Fig. 8 (Sec. 3.2): the arch of the example (8 voussoirs) on its two columns, over its free
// bounds. The paper's surface: y = 0 (its red zero plane) where the arch is thick enough and
// the columns wide enough, rising towards narrow columns, and a ridge along the column-width
// axis: however wide the columns (ground, in effect), the arch thinner than its own limit
// needs tension. So the least y lies in the thick-arch, wide-column part of the grid, the
// thinnest arch never stands, a standing arch keeps standing on wider columns or made thicker,
// and on columns wide enough the arch's own limit (between t = 0.05 and 0.1 for 8 voussoirs)
// no longer moves with their width: the ridge.
TEST(SampleLandscapeGrid, TheArchOnColumnsStandsWhereFigureEightSays) {
  const MasonrySpec spec = exampleArch();
  const LandscapeAxis x{"thickness", 0.05, 0.5, 10}, y{"columnWidth", 0.1, 1.5, 8};
  const LandscapeGrid g = sampleLandscapeGrid(spec, x, y);
  for (double m : g.measure) ASSERT_TRUE(std::isfinite(m));
  int standing = 0;
  for (int j = 0; j < y.samples; ++j) {
    EXPECT_FALSE(g.standsAt(0, j)) << "the thinnest arch on columns " << y.valueAt(j) << " wide";
    EXPECT_GT(g.at(0, j), statics::kFeasibleMeasure);
    for (int i = 0; i < x.samples; ++i) {
      standing += g.standsAt(i, j);
      if (g.standsAt(i, j) && j + 1 < y.samples) {
        EXPECT_TRUE(g.standsAt(i, j + 1)) << i << ", " << j;
      }
      if (g.standsAt(i, j) && i + 1 < x.samples) {
        EXPECT_TRUE(g.standsAt(i + 1, j)) << i << ", " << j;
      }
    }
  }
  for (int j = 0; j < y.samples; ++j)
    if (y.valueAt(j) >= 0.7) {
      EXPECT_TRUE(g.standsAt(1, j)) << "t = 0.1 on columns " << y.valueAt(j) << " wide";
    }
  EXPECT_GT(standing, 0);
  EXPECT_TRUE(g.standsAt(x.samples - 1, y.samples - 1));  // thick arch, wide columns
  EXPECT_FALSE(g.standsAt(x.samples - 1, 0));             // no arch stands on the narrowest columns
  const auto [mi, mj] = g.minimum();
  EXPECT_TRUE(g.standsAt(mi, mj));
  // The worst is the thinnest arch on the narrowest columns.
  double worst = 0;
  int worstI = -1, worstJ = -1;
  for (int j = 0; j < y.samples; ++j)
    for (int i = 0; i < x.samples; ++i)
      if (g.at(i, j) > worst) {
        worst = g.at(i, j);
        worstI = i;
        worstJ = j;
      }
  EXPECT_EQ(worstI, 0);
  EXPECT_EQ(worstJ, 0);
}

TEST(SampleLandscapeGrid, RefusesUnknownOrRepeatedParametersAndTooFewSamples) {
  const statics::ParametricModel model = statics::modelOf(exampleArch());
  const LandscapeAxis t{"thickness", 0.05, 0.5, 3}, w{"columnWidth", 0.1, 1.5, 3};
  EXPECT_THROW(sampleLandscapeGrid(model, {}, t, LandscapeAxis{"radius", 0, 1, 3}), Error);
  EXPECT_THROW(sampleLandscapeGrid(model, {}, t, t), Error);
  EXPECT_THROW(sampleLandscapeGrid(model, {}, t, LandscapeAxis{"columnWidth", 0.1, 1.5, 1}), Error);
  // A value the model refuses is a NaN sample that does not stand, not an error.
  const LandscapeGrid g = sampleLandscapeGrid(model, {}, t, LandscapeAxis{"columnWidth", -1.0, 1.0, 3});
  EXPECT_TRUE(std::isnan(g.at(0, 0)));
  EXPECT_FALSE(g.standsAt(0, 0));
  EXPECT_EQ(landscapeColors(g)[0], kLandscapeMissingColor);
  (void)w;
}

TEST(SampleLandscapeGrid, ACancelledJobStopsEveryThreadEarly) {
  const statics::ParametricModel model = archModel(100);
  statics::ParametricModel two = model;
  two.parameters.add({"unused", 0.0, -1.0, 1.0, true, "moves nothing"});
  BackgroundJob job("landscape", [&two](Progress& p) {
    sampleLandscapeGrid(two, {}, {"thickness", 0.05, 0.3, 100}, {"unused", -1, 1, 100}, &p, 2);
  });
  while (job.progress().fraction() == 0 && !job.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  job.progress().cancel();
  const auto t0 = std::chrono::steady_clock::now();
  job.wait();
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(job.progress().fraction(), 1.0);
  EXPECT_THROW(job.rethrow(), Cancelled);
  EXPECT_LT(waited, 30.0);
}

TEST(LandscapeColors, StandingIsRedMissingGreyAndTheRampRisesWithoutRed) {
  LandscapeGrid g;
  g.x = {"a", 0, 1, 4};
  g.y = {"b", 0, 1, 1};
  g.measure = {0.0, 1e-6, 1e-2, std::nan("")};
  g.stands = {1, 0, 0, 0};
  const auto c = landscapeColors(g);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], kLandscapeStandsColor);
  EXPECT_EQ(c[1], landscapeRampColor(0.0));  // the least positive measure
  EXPECT_EQ(c[2], landscapeRampColor(1.0));  // the largest
  EXPECT_EQ(c[3], kLandscapeMissingColor);
  double lastLight = -1;
  for (int k = 0; k <= 20; ++k) {
    const auto r = landscapeRampColor(k / 20.0);
    const double light = 0.3 * r[0] + 0.59 * r[1] + 0.11 * r[2];
    EXPECT_GT(light, lastLight);  // ordered from dark to light
    lastLight = light;
    // Never the stands red: red is never far above both green and blue.
    EXPECT_LT(r[0] - std::max(r[1], r[2]), 0.3f) << k;
  }
}

}  // namespace
}  // namespace corbel::editor

namespace corbel::editor {
namespace {

// Fig. 8's path on the panel's grid: each evaluation's values of the grid's two parameters,
// whichever order the search listed them in; nothing for a search over other parameters.
TEST(SearchPathOnGrid, TakesEachEvaluationsValuesOfTheGridsParameters) {
  LandscapeGrid g;
  g.x = {"thickness", 0.05, 0.5, 4};
  g.y = {"columnWidth", 0.1, 1.5, 3};
  const std::vector<std::vector<double>> evaluations = {{0.3, 0.2}, {0.4, 0.25}};
  const std::vector<statics::FreeParameter> swapped = {{"columnWidth", 0.1, 1.5}, {"thickness", 0.05, 0.5}};
  const auto path = searchPathOnGrid(g, swapped, evaluations);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[0], std::make_pair(0.2, 0.3));  // thickness is the second value listed
  EXPECT_EQ(path[1], std::make_pair(0.25, 0.4));
  const std::vector<statics::FreeParameter> same = {{"thickness", 0.05, 0.5}, {"columnWidth", 0.1, 1.5}};
  EXPECT_EQ(searchPathOnGrid(g, same, evaluations)[1], std::make_pair(0.4, 0.25));
  const std::vector<statics::FreeParameter> other = {{"thickness", 0.05, 0.5}, {"span", 1, 3}};
  EXPECT_TRUE(searchPathOnGrid(g, other, evaluations).empty());
  EXPECT_TRUE(searchPathOnGrid(g, {same[0]}, {{0.3}}).empty());
}

// ---- Every block in the Scene (analyseSceneBlocks) ----

// Three unit cubes, each shifted by `shift` further in x, from (x0, 0, 0).
MeshData stackMesh(double x0, double shift) {
  MeshData m;
  const int stone = m.addMaterial("stone");
  for (int k = 0; k < 3; ++k) {
    const statics::Block b = statics::boxBlock("c", Vec3(x0 + k * shift, 0, k), Vec3(x0 + k * shift + 1, 1, k + 1));
    const int first = int(m.points.size());
    for (const Vec3& v : b.vertices) m.addPoint(v);
    for (const auto& f : b.faces) {
      std::vector<int> loop;
      for (int v : f) loop.push_back(first + v);
      m.addFace(loop, 0, stone);
    }
  }
  return m;
}

statics::Assembly stackAssembly(double shift) {
  statics::Assembly a;
  for (int k = 0; k < 3; ++k)
    a.blocks.push_back(statics::boxBlock("c", Vec3(k * shift, 0, k), Vec3(k * shift + 1, 1, k + 1)));
  a.blocks.push_back(statics::boxBlock("ground", Vec3(-3, -3, -1), Vec3(4, 4, 0), 2400.0, true));
  return a;
}

// Two stacks ten metres apart share only the fixed ground, so the penalty QP splits into the
// two stacks' own: y of the Scene is the sum of each stack's y analysed alone (both past
// tipping: the upper pair's centroid 0.5 + 1.5 s lies beyond the bottom cube for s > 1/3).
TEST(SceneStatics, TwoSeparateStructuresMeasureTheSumOfTheirOwnTension) {
  Scene scene;
  scene.replaceObject(1, Kind::Block, "left", stackMesh(0, 0.45));
  scene.replaceObject(2, Kind::Block, "right", stackMesh(10, 0.6));
  const MasonryView v = analyseSceneBlocks(scene, {}, {});
  ASSERT_TRUE(v.error.empty()) << v.error;
  EXPECT_TRUE(v.fromScene);
  EXPECT_TRUE(v.groundPlaneAdded);
  ASSERT_EQ(v.blockFaces.size(), 7u);  // six cubes and the ground plane
  EXPECT_EQ(std::count(v.fixed.begin(), v.fixed.end(), true), 1);
  const statics::AnalysisResult a = statics::analyse(stackAssembly(0.45)), b = statics::analyse(stackAssembly(0.6));
  ASSERT_GT(a.y, 0.0);
  ASSERT_GT(b.y, 0.0);
  EXPECT_FALSE(v.result.feasible);
  EXPECT_NEAR(v.result.y, a.y + b.y, 1e-7 * (a.y + b.y));
  EXPECT_NEAR(v.result.totalWeight, 6 * 2400 * 9.81, 1e-9);
  EXPECT_DOUBLE_EQ(*std::max_element(v.tensionShare.begin(), v.tensionShare.end()), 1.0);
}

// A shape chosen as a load is carried by the blocks (its weight counted apart) and adds none; a Scene without blocks is
// an error in the view, not an exception.
TEST(SceneStatics, LoadsAddWeightAndNoBlocksIsAnError) {
  Scene scene;
  scene.replaceObject(1, Kind::Block, "stack", stackMesh(0, 0.0));
  MeshData statue;
  const int metal = statue.addMaterial("metal");
  const statics::Block cube = statics::boxBlock("s", Vec3(0.25, 0.25, 3), Vec3(0.75, 0.75, 3.5));
  for (const Vec3& p : cube.vertices) statue.addPoint(p);
  for (const auto& f : cube.faces) statue.addFace(std::vector<int>(f.begin(), f.end()), 0, metal);
  scene.replaceObject(2, Kind::Mass, "statue", statue);
  statics::SceneBlockOptions blocks;
  blocks.nonstructural = {2};
  const MasonryView v = analyseSceneBlocks(scene, blocks, {});
  ASSERT_TRUE(v.error.empty()) << v.error;
  EXPECT_EQ(v.sceneLoads, 1);
  EXPECT_NEAR(v.sceneLoadWeight, 0.125 * 7850 * 9.81, 1e-9);
  EXPECT_EQ(v.blockFaces.size(), 4u);
  // W, by which y is normalised, is the blocks' weight; the load comes on top of it.
  EXPECT_NEAR(v.result.totalWeight, 3 * 2400 * 9.81, 1e-8);
  EXPECT_TRUE(v.result.feasible);  // centred on a straight stack

  Scene empty;
  empty.replaceObject(2, Kind::Mass, "statue", statue);
  const MasonryView none = analyseSceneBlocks(empty, {}, {});
  EXPECT_FALSE(none.error.empty());
  EXPECT_TRUE(none.blockFaces.empty());
}

}  // namespace
}  // namespace corbel::editor
