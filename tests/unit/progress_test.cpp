// progress.h: Progress values, and BackgroundJob's progress, cancellation, errors and joining.
#include "core/progress.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace {

using corbel::BackgroundJob;
using corbel::Progress;
using namespace std::chrono_literals;

// Polls `condition` for up to five seconds.
template <class F>
bool eventually(F&& condition) {
  const auto end = std::chrono::steady_clock::now() + 5s;
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(1ms);
  }
  return condition();
}

TEST(Progress, ReportClampsAndKeepsTheStage) {
  Progress p;
  EXPECT_EQ(p.fraction(), 0.0);
  EXPECT_EQ(p.stage(), "");
  EXPECT_FALSE(p.cancelled());
  p.report(0.25, "meshing");
  EXPECT_EQ(p.fraction(), 0.25);
  EXPECT_EQ(p.stage(), "meshing");
  p.report(1.5, "done");
  EXPECT_EQ(p.fraction(), 1.0);
  p.report(-3, "again");
  EXPECT_EQ(p.fraction(), 0.0);
  EXPECT_EQ(p.stage(), "again");
  p.cancel();
  EXPECT_TRUE(p.cancelled());
}

TEST(BackgroundJob, ReportsProgressWhileRunning) {
  std::atomic<bool> go{false};
  BackgroundJob job("build", [&](Progress& p) {
    p.report(0.5, "half way");
    while (!go.load()) std::this_thread::sleep_for(1ms);
    p.report(1.0, "finished");
  });
  EXPECT_EQ(job.title(), "build");
  ASSERT_TRUE(eventually([&] { return job.progress().fraction() == 0.5; }));
  EXPECT_EQ(job.progress().stage(), "half way");
  EXPECT_FALSE(job.finished());
  EXPECT_NO_THROW(job.rethrow());  // nothing to rethrow while running
  go = true;
  job.wait();
  EXPECT_TRUE(job.finished());
  EXPECT_EQ(job.progress().fraction(), 1.0);
  EXPECT_EQ(job.progress().stage(), "finished");
  EXPECT_NO_THROW(job.rethrow());
  job.wait();  // waiting twice is harmless
}

TEST(BackgroundJob, CancelStopsACooperativeLoop) {
  std::atomic<long> iterations{0};
  BackgroundJob job("loop", [&](Progress& p) {
    while (!p.cancelled()) {
      ++iterations;
      std::this_thread::sleep_for(100us);
    }
  });
  ASSERT_TRUE(eventually([&] { return iterations.load() > 3; }));
  EXPECT_FALSE(job.finished());
  job.progress().cancel();
  job.wait();
  EXPECT_TRUE(job.finished());
  const long after = iterations.load();
  std::this_thread::sleep_for(5ms);
  EXPECT_EQ(iterations.load(), after);  // the loop really stopped
  EXPECT_NO_THROW(job.rethrow());
}

TEST(BackgroundJob, CancelledKernelsRethrowCancelled) {
  BackgroundJob job("kernel", [](Progress& p) {
    for (int i = 0;; ++i) {
      if (p.cancelled()) throw corbel::Cancelled();
      p.report(i / 1e9, "working");
      std::this_thread::sleep_for(100us);
    }
  });
  job.progress().cancel();
  job.wait();
  EXPECT_THROW(job.rethrow(), corbel::Cancelled);
}

TEST(BackgroundJob, ExceptionInTheWorkIsRethrown) {
  BackgroundJob job("failing", [](Progress& p) {
    p.report(0.3, "reading");
    throw corbel::Error("the file is damaged");
  });
  job.wait();
  EXPECT_TRUE(job.finished());
  try {
    job.rethrow();
    FAIL() << "no exception";
  } catch (const corbel::Error& e) {
    EXPECT_STREQ(e.what(), "the file is damaged");
  }
  // Every call rethrows the same error.
  EXPECT_THROW(job.rethrow(), corbel::Error);
  EXPECT_EQ(job.progress().stage(), "reading");
}

TEST(BackgroundJob, NonStandardExceptionsAreRethrownToo) {
  BackgroundJob job("odd", [](Progress&) { throw 42; });
  job.wait();
  try {
    job.rethrow();
    FAIL();
  } catch (int v) {
    EXPECT_EQ(v, 42);
  }
}

TEST(BackgroundJob, DestructorCancelsAndJoins) {
  std::atomic<bool> sawCancel{false}, exited{false}, started{false};
  {
    BackgroundJob job("long", [&](Progress& p) {
      started = true;
      while (!p.cancelled()) std::this_thread::sleep_for(100us);
      sawCancel = true;
      std::this_thread::sleep_for(20ms);  // the destructor must wait for this
      exited = true;
    });
    ASSERT_TRUE(eventually([&] { return started.load(); }));
  }
  EXPECT_TRUE(sawCancel.load());
  EXPECT_TRUE(exited.load());
}

TEST(BackgroundJob, DestroyingAFinishedJobIsFine) {
  std::atomic<int> runs{0};
  {
    BackgroundJob job("quick", [&](Progress&) { ++runs; });
    job.wait();
  }
  EXPECT_EQ(runs.load(), 1);
}

}  // namespace
