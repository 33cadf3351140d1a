// Work off the UI thread: progress, cancellation, errors and the one-time finished signal.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "isurface/app_model/background_job.h"

using namespace isurface::app_model;
using namespace std::chrono_literals;

namespace {

// Polls like the UI does, once a "frame"; false if `done` never came true (the test then fails
// instead of hanging).
template <class Done>
bool waitFor(Done&& done, std::chrono::seconds limit = std::chrono::seconds(20)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

// A job that reports progress until cancelled.
void endlessWork(JobControl& control) {
  for (long i = 0;; ++i) {
    control.progress(static_cast<double>(i % 1000) / 1000.0);
    std::this_thread::sleep_for(100us);
  }
}

}  // namespace

TEST(backgroundJob, IdleJob) {
  BackgroundJob job;
  EXPECT_FALSE(job.running());
  EXPECT_EQ(job.progress(), 0.0);
  EXPECT_EQ(job.error(), "");
  EXPECT_FALSE(job.wasCancelled());
  EXPECT_FALSE(job.takeFinished());
  job.cancel();  // nothing to cancel: harmless
}

TEST(backgroundJob, ProgressIsVisibleWhileRunning) {
  BackgroundJob job;
  std::atomic<bool> seen{false};
  job.start("loading", [&](JobControl& control) {
    control.progress(0.25);
    while (!seen) std::this_thread::sleep_for(1ms);
    control.progress(0.75);
  });
  EXPECT_EQ(job.label(), "loading");
  EXPECT_TRUE(waitFor([&] { return job.progress() == 0.25; }));
  EXPECT_TRUE(job.running());
  seen = true;
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_FALSE(job.running());
  EXPECT_EQ(job.progress(), 1.0);  // a job that succeeded is complete
  EXPECT_EQ(job.error(), "");
  EXPECT_FALSE(job.wasCancelled());
}

// What the job says it is doing shows while it runs, and not once it has ended.
TEST(backgroundJob, TheStageIsVisibleWhileRunning) {
  BackgroundJob job;
  std::atomic<bool> seen{false};
  job.start("optimising", [&](JobControl& control) {
    control.stage("candidate 1: each pass its own interval feeds");
    while (!seen) std::this_thread::sleep_for(1ms);
  });
  EXPECT_TRUE(waitFor([&] { return job.stage() == "candidate 1: each pass its own interval feeds"; }));
  seen = true;
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_EQ(job.stage(), "");
}

TEST(backgroundJob, ProgressIsClamped) {
  BackgroundJob job;
  std::atomic<bool> release{false};
  std::atomic<int> step{0};
  job.start("clamp", [&](JobControl& control) {
    control.progress(7);
    step = 1;
    while (step != 2) std::this_thread::sleep_for(1ms);
    control.progress(-1);
    step = 3;
    while (!release) std::this_thread::sleep_for(1ms);
  });
  ASSERT_TRUE(waitFor([&] { return step == 1; }));
  EXPECT_EQ(job.progress(), 1.0);
  step = 2;
  ASSERT_TRUE(waitFor([&] { return step == 3; }));
  EXPECT_EQ(job.progress(), 0.0);
  release = true;
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
}

TEST(backgroundJob, CancelEndsALongJobPromptly) {
  BackgroundJob job;
  job.start("simulating", endlessWork);
  ASSERT_TRUE(waitFor([&] { return job.progress() > 0; }));
  EXPECT_TRUE(job.running());
  job.cancel();
  ASSERT_TRUE(waitFor([&] { return !job.running(); }));
  EXPECT_TRUE(job.takeFinished());
  EXPECT_TRUE(job.wasCancelled());
  EXPECT_EQ(job.error(), "");
}

TEST(backgroundJob, CancelRequestIsVisibleToTheWork) {
  BackgroundJob job;
  std::atomic<bool> noticed{false};
  job.start("polling", [&](JobControl& control) {
    while (!control.cancelRequested()) std::this_thread::sleep_for(1ms);
    noticed = true;
  });
  job.cancel();
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_TRUE(noticed);
  // The work returned by itself: it ended normally, not through JobCancelled.
  EXPECT_FALSE(job.wasCancelled());
}

TEST(backgroundJob, ErrorsAreCaptured) {
  BackgroundJob job;
  job.start("parsing", [](JobControl& control) {
    control.progress(0.5);
    throw std::runtime_error("part.nc:12:3: unknown G-code G99");
  });
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_EQ(job.error(), "part.nc:12:3: unknown G-code G99");
  EXPECT_FALSE(job.wasCancelled());
  EXPECT_FALSE(job.running());

  job.start("odd", [](JobControl&) { throw 42; });
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_FALSE(job.error().empty());

  // The next job starts clean.
  job.start("fine", [](JobControl&) {});
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_EQ(job.error(), "");
}

TEST(backgroundJob, TakeFinishedIsTrueOnceAJob) {
  BackgroundJob job;
  for (int round = 0; round < 3; ++round) {
    job.start("quick", [](JobControl& control) { control.progress(1); });
    ASSERT_TRUE(waitFor([&] { return !job.running(); }));
    EXPECT_TRUE(job.takeFinished());
    EXPECT_FALSE(job.takeFinished());
    EXPECT_FALSE(job.takeFinished());
  }
}

TEST(backgroundJob, StartingAgainCancelsThePreviousJob) {
  BackgroundJob job;
  std::atomic<bool> firstCancelled{false};
  job.start("first", [&](JobControl& control) {
    try {
      endlessWork(control);
    } catch (const JobCancelled&) {
      firstCancelled = true;
      throw;
    }
  });
  ASSERT_TRUE(waitFor([&] { return job.progress() > 0; }));
  std::atomic<bool> secondRan{false};
  job.start("second", [&](JobControl&) { secondRan = true; });
  EXPECT_TRUE(firstCancelled);  // cancelled and waited for before the second began
  EXPECT_EQ(job.label(), "second");
  ASSERT_TRUE(waitFor([&] { return job.takeFinished(); }));
  EXPECT_TRUE(secondRan);
  EXPECT_FALSE(job.wasCancelled());
  EXPECT_FALSE(job.takeFinished());  // the replaced job does not report
}

TEST(backgroundJob, DestructorCancelsAndWaits) {
  std::atomic<bool> ended{false};
  {
    BackgroundJob job;
    job.start("endless", [&](JobControl& control) {
      try {
        endlessWork(control);
      } catch (const JobCancelled&) {
        ended = true;
        throw;
      }
    });
    ASSERT_TRUE(waitFor([&] { return job.progress() > 0; }));
  }
  EXPECT_TRUE(ended);
}
