// app_state.h: one recovery slot per open document, held by a lock that frees itself when its
// editor dies. Other editors are played by child processes (fork), so a lock held by a live
// process and one left by a dead one are both the real thing.
#include "core/app_state.h"

#include "core/project_io.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using corbel::BoxSpec;
using corbel::Document;
using corbel::Recovery;
using corbel::RecoveredWork;
using corbel::test::TempDir;

Document withBoxes(int n) {
  Document d;
  for (int i = 0; i < n; ++i) d.add("Box", BoxSpec{});
  return d;
}

// A child process that claims the slot of `path`, writes `doc` there and then either dies at
// once (as a killed editor) or waits to be killed. Returns its pid; the pipe says when it wrote.
pid_t editorProcess(const std::string& state, const std::string& path, const Document& doc, bool stayAlive) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(ready[0]);
    {
      Recovery r(state);
      r.claim(path);
      r.write(doc, path);
      const char ok = 1;
      if (::write(ready[1], &ok, 1) != 1) ::_exit(3);
      if (stayAlive) ::pause();
      ::_exit(0);  // no destructors: as a crash, the files stay and the kernel frees the lock
    }
  }
  ::close(ready[1]);
  char ok = 0;
  if (::read(ready[0], &ok, 1) != 1) ok = 0;
  ::close(ready[0]);
  return ok ? pid : -1;
}

void reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

TEST(Recovery, EachDocumentOfEditorsThatAreGoneIsOfferedNewestFirst) {
  TempDir dir;
  const pid_t house = editorProcess(dir.path(), dir.file("house.corbel"), withBoxes(2), false);
  ASSERT_GT(house, 0);
  reap(house);
  ::usleep(20000);  // the files' times tell which is newer
  const pid_t temple = editorProcess(dir.path(), dir.file("temple.corbel"), withBoxes(3), false);
  ASSERT_GT(temple, 0);
  reap(temple);
  Recovery mine(dir.path());
  mine.claim("");
  std::vector<std::string> problems;
  const std::vector<RecoveredWork> found = mine.orphans(&problems);
  EXPECT_TRUE(problems.empty());
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].originalPath, dir.file("temple.corbel"));
  EXPECT_EQ(found[0].document.objects.size(), 3u);
  EXPECT_EQ(found[1].originalPath, dir.file("house.corbel"));
  EXPECT_EQ(found[1].document.objects.size(), 2u);
  // Taken over, one is this editor's now: no longer offered to others.
  mine.adopt(found[1]);
  Recovery other(dir.path());
  const std::vector<RecoveredWork> left = other.orphans();
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].originalPath, dir.file("temple.corbel"));
  other.discardOrphan(left[0]);
  EXPECT_TRUE(other.orphans().empty());
}

TEST(Recovery, WorkOfARunningEditorIsNotOfferedAndTheSameFileIsToldAndKeptApart) {
  TempDir dir;
  const pid_t running = editorProcess(dir.path(), dir.file("house.corbel"), withBoxes(1), true);
  ASSERT_GT(running, 0);
  Recovery second(dir.path());
  const std::optional<long> other = second.claim(dir.file("house.corbel"));
  ASSERT_TRUE(other.has_value());
  EXPECT_EQ(*other, running);
  EXPECT_TRUE(second.orphans().empty());  // the running editor's work is its own
  second.write(withBoxes(4), dir.file("house.corbel"));
  EXPECT_NE(second.documentPath(), "");
  reap(running);
  // Now the first editor is gone: its work is offered, and the second's file is its own.
  const std::vector<RecoveredWork> found = second.orphans();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].document.objects.size(), 1u);
  EXPECT_NE(found[0].slot, second.slot());
}

TEST(Recovery, ACleanExitLeavesNothingAndAnOlderVersionsFileIsOffered) {
  TempDir dir;
  {
    Recovery r(dir.path());
    r.claim(dir.file("a.corbel"));
    r.write(withBoxes(1), dir.file("a.corbel"));
    r.discard();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.file("recovery")));
  // corbel before recovery slots kept one recovery.corbel beside recovery.json.
  corbel::saveProject(withBoxes(5), dir.file("recovery.corbel"));
  corbel::test::writeText(dir.file("recovery.json"), R"({"original": "/x/old.corbel", "saved_at": "then"})");
  Recovery r(dir.path());
  const std::vector<RecoveredWork> found = r.orphans();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].originalPath, "/x/old.corbel");
  r.adopt(found[0]);
  EXPECT_FALSE(std::filesystem::exists(dir.file("recovery.corbel")));
  EXPECT_EQ(corbel::loadProject(r.documentPath()).document.objects.size(), 5u);
}

}  // namespace
