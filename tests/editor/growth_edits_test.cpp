// editor/growth_edits.h: Step and Run take one step more until the growth says every unit
// stopped, and never step a growth that already runs to the end.
#include "editor/growth_edits.h"

#include <gtest/gtest.h>

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
