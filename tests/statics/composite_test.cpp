// statics/composite.h: masonry objects analysed together, against the same structure built
// as one model by the kernel's own composed example (the arch on columns, Fig. 8).
#include "statics/composite.h"

#include "core/error.h"
#include "core/project_io.h"
#include "statics/analysis.h"
#include "statics/examples.h"
#include "statics/kernel.h"
#include "statics/search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace corbel::statics {
namespace {

// The arch on columns as three objects: two one-drum square columns of width w and height h at
// x = ±1 and a semicircular arch (radius 1, 8 voussoirs, thickness t) placed at z = h + lift.
std::vector<CompositePart> arcade(double t, double w, double h, double lift = 0) {
  MasonrySpec column;
  column.model = "column";
  column.parameters = {{"drums", 1}, {"height", h}, {"radius", w / std::sqrt(2.0)}, {"sides", 4}};
  MasonrySpec arch;
  arch.model = "semicircular-arch";
  arch.parameters = {{"radius", 1.0}, {"thickness", t}, {"voussoirs", 8}};
  Placement left, right, top;
  left.translation = Vec3(-1, 0, 0);
  right.translation = Vec3(1, 0, 0);
  top.translation = Vec3(0, 0, h + lift);
  return {{"Left", modelOf(column), left}, {"Right", modelOf(column), right}, {"Arch", modelOf(arch), top}};
}

Assembly built(const ParametricModel& m) { return m.build(m.parameters); }

Assembly example(double t, double w, double h) {
  ParametricModel m = exampleByName("arch-on-columns");
  m.parameters.set("thickness", t);
  m.parameters.set("columnWidth", w);
  m.parameters.set("columnHeight", h);
  return built(m);
}

// Same blocks, same contacts: the same measure (to rounding) and the same strict verdict, for a
// structure that stands and one that does not.
TEST(Composite, ThreeObjectsAnalyseAsTheComposedExampleDoes) {
  for (const auto& [t, w] : {std::pair{0.3, 0.6}, std::pair{0.12, 0.3}}) {
    const Assembly together = built(compositeModel(arcade(t, w, 1.5)));
    const Assembly one = example(t, w, 1.5);
    ASSERT_EQ(together.blocks.size(), one.blocks.size());
    const AnalysisResult a = analyse(together), b = analyse(one);
    EXPECT_EQ(a.interfaces.size(), b.interfaces.size());
    EXPECT_NEAR(a.yNormalised, b.yNormalised, 1e-9 * std::max(b.yNormalised, 1e-12)) << t << " " << w;
    EXPECT_EQ(checkFeasibility(together).feasible, checkFeasibility(one).feasible) << t << " " << w;
  }
  EXPECT_TRUE(checkFeasibility(built(compositeModel(arcade(0.3, 0.6, 1.5)))).feasible);
}

// An arch set 0.5 mm above its columns touches them with a 1 mm contact tolerance (and then
// stands as the exact one does) and floats with the kernel's own.
TEST(Composite, TheContactToleranceJoinsObjectsThatAlmostTouch) {
  const Assembly lifted = built(compositeModel(arcade(0.3, 0.6, 1.5, 0.0005)));
  AnalysisOptions joint;
  joint.contactTolerance = 0.001;
  EXPECT_TRUE(checkFeasibility(lifted, joint).feasible);
  EXPECT_EQ(analyse(lifted, joint).interfaces.size(), analyse(example(0.3, 0.6, 1.5)).interfaces.size());
  EXPECT_THROW(analyse(lifted), Error) << "the arch reaches nothing fixed";
  joint.contactTolerance = -1;
  EXPECT_THROW(analyse(lifted, joint), Error);
}

// Parameters and blocks carry their object's name; the search moves the free parameters of all
// the objects at once and what it finds stands by the strict LP.
TEST(Composite, TheSearchMovesEveryObjectsFreeParameters) {
  const ParametricModel m = compositeModel(arcade(0.12, 0.3, 1.5));
  EXPECT_TRUE(m.parameters.has("Arch/thickness"));
  EXPECT_TRUE(m.parameters.has("Left/radius"));
  EXPECT_EQ(built(m).blocks.front().name, "Left/column/drum 0");
  EXPECT_FALSE(checkFeasibility(built(m)).feasible);
  const std::vector<FreeParameter> free = {{"Arch/thickness", 0.05, 0.5}, {"Left/radius", 0.1, 1.0}, {"Right/radius", 0.1, 1.0}};
  const SearchResult r = searchParameters(m, free, {});
  ASSERT_EQ(r.status, SearchStatus::Feasible) << r.message;
  EXPECT_TRUE(checkFeasibility(m.build(r.values)).feasible);
  EXPECT_EQ(splitCompositeName("Arch/thickness"), std::make_pair(std::string("Arch"), std::string("thickness")));

  auto twice = arcade(0.3, 0.6, 1.5);
  twice[1].name = "Left";
  EXPECT_THROW(compositeModel(twice), Error);
  EXPECT_THROW(compositeModel({}), Error);
}

// An object whose ground is off has no fixed block of its own (nothing of it is drawn as a slab),
// cannot stand alone, and analyses together exactly as with its ground: the composite drops the
// parts' slabs either way.
TEST(Composite, AnObjectWithoutItsGroundRestsOnlyOnOthers) {
  MasonrySpec arch;
  arch.model = "semicircular-arch";
  arch.ground = false;
  const Assembly alone = built(modelOf(arch));
  EXPECT_TRUE(std::none_of(alone.blocks.begin(), alone.blocks.end(), [](const Block& b) { return b.fixed; }));
  EXPECT_THROW(analyse(alone), Error);
  std::vector<CompositePart> parts = arcade(0.3, 0.6, 1.5), off = parts;
  for (CompositePart& p : off) {
    MasonrySpec s;
    s.ground = false;
    s.model = p.name == "Arch" ? "semicircular-arch" : "column";
    s.parameters = p.name == "Arch" ? std::vector<MasonryParameter>{{"radius", 1.0}, {"thickness", 0.3}, {"voussoirs", 8}}
                                    : std::vector<MasonryParameter>{{"drums", 1}, {"height", 1.5}, {"radius", 0.6 / std::sqrt(2.0)}, {"sides", 4}};
    p.model = modelOf(s);
  }
  EXPECT_EQ(analyse(built(compositeModel(off))).yNormalised, analyse(built(compositeModel(parts))).yNormalised);
}

// The shipped arcade: 4 columns of 3 drums and 3 arches of 9 voussoirs are 39 blocks and one
// ground; each inner column carries two springings side by side, each end column one, so 6
// contacts join arches to columns; with its end columns as saved (0.35 m) it does not stand,
// and widened to 0.6 m, as the inner ones, it does.
TEST(Composite, TheShippedArcadeRestsItsArchesOnItsColumns) {
  const LoadedProject p = loadProject(std::string(CORBEL_SOURCE_DIR) + "/assets/examples/masonry-arcade.corbel");
  std::vector<CompositePart> parts;
  for (const DocObject& o : p.document.objects) parts.push_back({o.name, modelOf(std::get<MasonrySpec>(o.spec)), o.placement});
  ASSERT_EQ(parts.size(), 7u);
  ParametricModel m = compositeModel(parts);
  const Assembly a = built(m);
  EXPECT_EQ(a.blocks.size(), 40u);
  const AnalysisResult r = analyse(a);
  int archOnColumn = 0;
  for (const auto& i : r.interfaces) {
    const std::string& x = a.blocks[std::size_t(i.a)].name;
    const std::string& y = a.blocks[std::size_t(i.b)].name;
    archOnColumn += (x.rfind("Column", 0) == 0 && y.rfind("Arch", 0) == 0) || (y.rfind("Column", 0) == 0 && x.rfind("Arch", 0) == 0);
  }
  EXPECT_EQ(archOnColumn, 6);
  EXPECT_FALSE(checkFeasibility(a).feasible);
  m.parameters.set("Column 1/radius", 0.6 / std::sqrt(2.0));
  m.parameters.set("Column 4/radius", 0.6 / std::sqrt(2.0));
  EXPECT_TRUE(checkFeasibility(built(m)).feasible);
}

}  // namespace
}  // namespace corbel::statics
