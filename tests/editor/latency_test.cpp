// editor/latency.h: a state's latency is counted once, from its frame's earliest event to the
// first frame that presents it; states superseded before they were shown have none.
#include "editor/latency.h"

#include <gtest/gtest.h>

namespace corbel::editor {
namespace {

TEST(FrameLatency, FromTheEarliestEventToTheFirstFrameThatShowsTheState) {
  FrameLatency l;
  l.caused(5, 10.020);
  l.caused(5, 10.000);  // an earlier event of the same frame
  EXPECT_FALSE(l.presented(4, 10.030));  // the Scene still shows the state before
  const auto ms = l.presented(5, 10.045);
  ASSERT_TRUE(ms);
  EXPECT_NEAR(*ms, 0.045, 1e-12);
  EXPECT_FALSE(l.presented(5, 10.060));  // the next frame shows it again: not counted twice
  EXPECT_EQ(l.pending(), 0u);
}

TEST(FrameLatency, SupersededStatesAreNeverShownAndForgotten) {
  FrameLatency l;
  l.caused(7, 1.0);
  l.caused(8, 1.1);
  l.caused(9, 1.2);
  const auto ms = l.presented(8, 1.3);  // 7 was skipped by the live build, 8 shown
  ASSERT_TRUE(ms);
  EXPECT_NEAR(*ms, 0.2, 1e-12);
  EXPECT_EQ(l.pending(), 1u);  // 9 waits
  EXPECT_FALSE(l.presented(std::nullopt, 1.4));
  EXPECT_NEAR(*l.presented(9, 1.5), 0.3, 1e-12);
}

}  // namespace
}  // namespace corbel::editor
