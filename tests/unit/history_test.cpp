// history.h: snapshot undo/redo, merge runs, the saved state and the capacity limit.
#include "core/history.h"

#include <gtest/gtest.h>

#include <set>

namespace {

using corbel::BoxSpec;
using corbel::Document;
using corbel::History;

// A document whose first object's height is `height` (distinct heights → distinct docs).
Document docWithHeight(double height, std::string name = "doc") {
  Document d;
  d.name = std::move(name);
  BoxSpec b;
  b.size = corbel::Vec3(10, 6, height);
  d.add("Box", b);
  return d;
}

double heightOf(const Document& d) { return std::get<BoxSpec>(d.objects.at(0).spec).size[2]; }

TEST(History, StartsCleanWithNothingToUndo) {
  History h(docWithHeight(1));
  EXPECT_FALSE(h.canUndo());
  EXPECT_FALSE(h.canRedo());
  EXPECT_FALSE(h.undo());
  EXPECT_FALSE(h.redo());
  EXPECT_FALSE(h.dirty());
  EXPECT_EQ(h.size(), 1u);
  EXPECT_EQ(h.undoLabel(), "");
  EXPECT_EQ(h.redoLabel(), "");
  EXPECT_EQ(heightOf(h.current()), 1.0);
}

TEST(History, CommitUndoRedoAndLabels) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "Raise");
  h.commit(docWithHeight(3), "Raise more");
  EXPECT_EQ(h.size(), 3u);
  EXPECT_EQ(heightOf(h.current()), 3.0);
  EXPECT_EQ(h.undoLabel(), "Raise more");
  EXPECT_EQ(h.redoLabel(), "");

  ASSERT_TRUE(h.undo());
  EXPECT_EQ(heightOf(h.current()), 2.0);
  EXPECT_EQ(h.undoLabel(), "Raise");
  EXPECT_EQ(h.redoLabel(), "Raise more");
  ASSERT_TRUE(h.undo());
  EXPECT_EQ(heightOf(h.current()), 1.0);
  EXPECT_FALSE(h.canUndo());
  EXPECT_EQ(h.redoLabel(), "Raise");
  EXPECT_FALSE(h.undo());

  ASSERT_TRUE(h.redo());
  EXPECT_EQ(heightOf(h.current()), 2.0);
  ASSERT_TRUE(h.redo());
  EXPECT_EQ(heightOf(h.current()), 3.0);
  EXPECT_FALSE(h.redo());
}

TEST(History, NewCommitDropsTheRedoBranch) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "a");
  h.commit(docWithHeight(3), "b");
  h.undo();
  h.undo();
  ASSERT_TRUE(h.canRedo());
  h.commit(docWithHeight(7), "c");
  EXPECT_FALSE(h.canRedo());
  EXPECT_EQ(h.size(), 2u);
  EXPECT_EQ(h.undoLabel(), "c");
  h.undo();
  EXPECT_EQ(heightOf(h.current()), 1.0);
  h.redo();
  EXPECT_EQ(heightOf(h.current()), 7.0);
}

TEST(History, IdenticalCommitIsIgnored) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "a");
  const auto id = h.stateId();
  h.commit(docWithHeight(2), "same again");
  EXPECT_EQ(h.size(), 2u);
  EXPECT_EQ(h.stateId(), id);
  EXPECT_EQ(h.undoLabel(), "a");
  // Also with a redo branch: an identical commit keeps it.
  h.undo();
  h.commit(docWithHeight(1), "no change");
  EXPECT_TRUE(h.canRedo());
}

TEST(History, MergeKeyCollapsesADragIntoOneStep) {
  History h(docWithHeight(1));
  for (int i = 2; i <= 10; ++i) h.commit(docWithHeight(i), "Drag height", "height-slider");
  EXPECT_EQ(h.size(), 2u);
  EXPECT_EQ(heightOf(h.current()), 10.0);
  EXPECT_EQ(h.undoLabel(), "Drag height");
  h.undo();
  EXPECT_EQ(heightOf(h.current()), 1.0);
  EXPECT_FALSE(h.canUndo());
  h.redo();
  EXPECT_EQ(heightOf(h.current()), 10.0);
}

TEST(History, CloseMergeEndsTheRun) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "Drag", "k");
  h.commit(docWithHeight(3), "Drag", "k");
  h.closeMerge();
  h.commit(docWithHeight(4), "Drag", "k");
  h.commit(docWithHeight(5), "Drag", "k");
  EXPECT_EQ(h.size(), 3u);
  h.undo();
  EXPECT_EQ(heightOf(h.current()), 3.0);
  h.undo();
  EXPECT_EQ(heightOf(h.current()), 1.0);
}

TEST(History, DifferentKeysOrNoKeyDoNotMerge) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "a", "k1");
  h.commit(docWithHeight(3), "b", "k2");
  h.commit(docWithHeight(4), "c");
  h.commit(docWithHeight(5), "d");
  EXPECT_EQ(h.size(), 5u);
  // Undo ends a run too: the next commit with the old key is a new step.
  History g(docWithHeight(1));
  g.commit(docWithHeight(2), "a", "k");
  g.commit(docWithHeight(3), "a", "k");
  g.undo();
  g.commit(docWithHeight(4), "a", "k");
  EXPECT_EQ(g.size(), 2u);
  EXPECT_EQ(heightOf(g.current()), 4.0);
  g.undo();
  EXPECT_EQ(heightOf(g.current()), 1.0);
}

TEST(History, DirtyFollowsTheSavedState) {
  History h(docWithHeight(1));
  EXPECT_FALSE(h.dirty());
  h.commit(docWithHeight(2), "a");
  EXPECT_TRUE(h.dirty());
  h.undo();
  EXPECT_FALSE(h.dirty());  // back at the saved (initial) state
  h.redo();
  EXPECT_TRUE(h.dirty());
  h.markSaved();
  EXPECT_FALSE(h.dirty());
  // Saving keeps the history.
  ASSERT_TRUE(h.canUndo());
  h.undo();
  EXPECT_TRUE(h.dirty());
  EXPECT_EQ(heightOf(h.current()), 1.0);
  h.redo();
  EXPECT_FALSE(h.dirty());
}

TEST(History, MergingPastTheSavedStateIsDirty) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "Drag", "k");
  h.markSaved();
  h.commit(docWithHeight(3), "Drag", "k");  // merged into the saved step
  EXPECT_EQ(h.size(), 2u);
  EXPECT_TRUE(h.dirty());
}

TEST(History, StateIdChangesWithEveryCurrentState) {
  History h(docWithHeight(1));
  std::set<std::uint64_t> seen{h.stateId()};
  h.commit(docWithHeight(2), "a", "k");
  EXPECT_TRUE(seen.insert(h.stateId()).second);
  h.commit(docWithHeight(3), "a", "k");
  EXPECT_TRUE(seen.insert(h.stateId()).second);
  const auto last = h.stateId();
  h.undo();
  EXPECT_TRUE(seen.count(h.stateId()));
  h.redo();
  EXPECT_EQ(h.stateId(), last);
}

TEST(History, CapacityDropsTheOldestStates) {
  History h(docWithHeight(0), 3);
  for (int i = 1; i <= 5; ++i) h.commit(docWithHeight(i), "step " + std::to_string(i));
  EXPECT_EQ(h.size(), 3u);
  EXPECT_EQ(heightOf(h.current()), 5.0);
  EXPECT_TRUE(h.undo());
  EXPECT_TRUE(h.undo());
  EXPECT_EQ(heightOf(h.current()), 3.0);
  EXPECT_FALSE(h.canUndo());
  EXPECT_FALSE(h.undo());
  // The saved (initial) state was dropped: nothing left is clean.
  EXPECT_TRUE(h.dirty());
  EXPECT_EQ(h.redoLabel(), "step 4");
}

TEST(History, CapacityBelowTwoStillKeepsOneUndo) {
  History h(docWithHeight(0), 0);
  h.commit(docWithHeight(1), "a");
  h.commit(docWithHeight(2), "b");
  EXPECT_EQ(h.size(), 2u);
  EXPECT_TRUE(h.undo());
  EXPECT_EQ(heightOf(h.current()), 1.0);
}

TEST(History, ResetStartsFreshAndClean) {
  History h(docWithHeight(1));
  h.commit(docWithHeight(2), "a", "k");
  h.reset(docWithHeight(9, "opened"));
  EXPECT_FALSE(h.dirty());
  EXPECT_FALSE(h.canUndo());
  EXPECT_FALSE(h.canRedo());
  EXPECT_EQ(h.current().name, "opened");
  // The old merge run is over.
  h.commit(docWithHeight(3), "a", "k");
  h.commit(docWithHeight(4), "a", "k");
  EXPECT_EQ(h.size(), 2u);
  h.undo();
  EXPECT_EQ(heightOf(h.current()), 9.0);
}

}  // namespace
