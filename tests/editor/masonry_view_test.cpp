// editor/masonry_view.h: what the statics panel shows, held against hand computation and the
// known thresholds of the semicircular arch.
#include "editor/masonry_view.h"

#include "core/project_io.h"
#include "statics/arch.h"
#include "statics/tolerances.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace corbel::editor
