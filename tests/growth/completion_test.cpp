// Topology generation (Sec. 7.3.1): forms in the requested complexity range, distinct,
// valid, with links that match an independent count of shared boundary pieces.
#include "growth/completion.h"

#include "core/error.h"
#include "core/progress.h"
#include "grid_oracle.h"

#include <gtest/gtest.h>

#include <set>

namespace corbel::growth {
namespace {

TEST(TopologyGeneration, CanonicalRowComplexityIsNMinusOneOverFourN) {
  // n squares in a row: n − 1 links over 4n faces (hand count).
  for (int n = 1; n <= 8; ++n) EXPECT_EQ(formComplexity(canonicalRow(n, 6)).value(), Fraction::of(n - 1, 4 * n)) << n;
}

TEST(TopologyGeneration, FormsFallInTheRangeAndAreDistinct) {
  // Fig. 7.9 asks 5 units for 0.36-0.38.
  const FormRequest rq = test::formRequest(5, Fraction::of(36, 100), Fraction::of(38, 100), 5);
  const FormSet set = generateForms(rq);
  ASSERT_EQ(set.forms.size(), 5u) << set.note;
  std::set<std::string> topologies;
  for (const Form& f : set.forms) {
    std::string why;
    ASSERT_TRUE(f.plan.valid(&why)) << why;
    ASSERT_EQ(f.plan.units().size(), 5u);
    EXPECT_EQ(test::recorded(f.plan), test::sharedPieces(f.plan));
    // F_q from an independent count: links as shared-piece pairs, faces as real leaves.
    std::int64_t faces = 0;
    for (const ShapeTree& t : f.plan.units()) faces += std::int64_t(t.edges().size());
    const Fraction fq = Fraction::of(std::int64_t(test::sharedPieces(f.plan).size()), faces);
    EXPECT_TRUE(rq.lo <= fq && fq <= rq.hi) << fq.value();
    EXPECT_EQ(fq, f.complexity.value());
    topologies.insert(f.topology);
  }
  EXPECT_EQ(topologies.size(), set.forms.size());
}

TEST(TopologyGeneration, SameSeedSameForms) {
  const FormRequest rq = test::formRequest(3, Fraction::of(1, 4), Fraction::of(3, 10), 3);
  const FormSet a = generateForms(rq), b = generateForms(rq);
  ASSERT_EQ(a.forms.size(), b.forms.size());
  for (std::size_t i = 0; i < a.forms.size(); ++i) EXPECT_EQ(a.forms[i].topology, b.forms[i].topology);
}

TEST(TopologyGeneration, RefusesUnusableRequests) {
  FormRequest rq;
  rq.lo = Fraction::of(2, 5);
  rq.hi = Fraction::of(1, 5);
  EXPECT_THROW(generateForms(rq), InputError);
  rq.lo = Fraction::of(1, 5);
  rq.hi = Fraction::of(1, 2);
  EXPECT_THROW(generateForms(rq), InputError);
  rq.hi = Fraction::of(1, 4);
  rq.seeds = 0;
  EXPECT_THROW(generateForms(rq), InputError);
  rq.seeds = 3;
  rq.count = 0;
  EXPECT_THROW(generateForms(rq), InputError);
}

// The editor runs the generation as a background job: it reports its progress and stops at
// Cancel; with a progress that is never cancelled it gives the same forms as without one.
TEST(TopologyGeneration, ReportsProgressAndStopsWhenCancelled) {
  FormRequest rq;
  rq.count = 3;
  Progress p;
  const FormSet with = generateForms(rq, &p);
  const FormSet without = generateForms(rq);
  ASSERT_EQ(with.forms.size(), without.forms.size());
  for (std::size_t i = 0; i < with.forms.size(); ++i) EXPECT_EQ(with.forms[i].topology, without.forms[i].topology);
  EXPECT_GT(p.fraction(), 0.0);
  EXPECT_NE(p.stage().find("attempt"), std::string::npos);
  Progress cancelled;
  cancelled.cancel();
  EXPECT_THROW(generateForms(rq, &cancelled), Cancelled);
}

}  // namespace
}  // namespace corbel::growth
