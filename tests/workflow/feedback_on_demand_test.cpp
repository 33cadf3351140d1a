// The servo's positions of a run opened without them, loaded later: from its dump again, or
// replayed through the servo of the machine that simulated it. Either way they are the values
// the run would have had, had it been opened with them.
#include <gtest/gtest.h>

#include "isurface/io/biip.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

namespace {

OpenedRun opened(const RunFiles& files, const Machine& machine, bool feedback) {
  OpenRunRequest request;
  request.files = files;
  request.machine = machine;
  request.channels.feedback = feedback;
  return openRun(request);
}

// Every offset the same, bit for bit.
void expectSameFeedback(const FeedbackOffsets& later, const Trajectory& withFeedback) {
  ASSERT_EQ(later.size(), withFeedback.size());
  ASSERT_TRUE(withFeedback.hasFeedback());
  std::size_t differing = 0, moving = 0;
  for (std::size_t i = 0; i < later.size(); ++i) {
    differing += later.x[i] != withFeedback.fbOffsetX[i] || later.y[i] != withFeedback.fbOffsetY[i] ||
                 later.z[i] != withFeedback.fbOffsetZ[i];
    moving += withFeedback.fbOffsetX[i] != 0.0f;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(moving, later.size() / 2) << "a servo that lags while the tool moves";
}

}  // namespace

TEST(feedbackOnDemand, ASimulatedRunsServoReplayedIsTheSimulationsOwn) {
  for (const Machine& machine : {defaultMachine(), slowMachine()}) {
    Machine stiff = machine;
    for (AxisLimits& a : stiff.axes) a.positionGain *= 2.5;  // another servo: another answer
    {
      const RunFiles files{sourcePath("samples/transition-surface.nc"), ""};
      const OpenedRun soft = opened(files, machine, true), hard = opened(files, stiff, true);
      EXPECT_NE(soft.samples->fbOffsetX, hard.samples->fbOffsetX);
    }
    for (const Machine& m : {machine, stiff}) {
      const RunFiles files{sourcePath("samples/transition-surface.nc"), ""};
      const OpenedRun without = opened(files, m, false);
      const OpenedRun with = opened(files, m, true);
      EXPECT_FALSE(without.samples->hasFeedback());
      ASSERT_TRUE(without.feedbackSupply.servo.has_value());
      EXPECT_FALSE(with.feedbackSupply.available()) << "nothing left to load";
      expectSameFeedback(loadFeedback(*without.samples, without.feedbackSupply), *with.samples);
    }
  }
}

TEST(feedbackOnDemand, ADumpsFeedbackReadAgainIsWhatOpeningItWithFeedbackGives) {
  const RunFiles files{sourcePath("samples/transition-surface.nc"), transitionDump()};
  const OpenedRun without = opened(files, defaultMachine(), false);
  const OpenedRun with = opened(files, defaultMachine(), true);
  EXPECT_FALSE(without.samples->hasFeedback());
  ASSERT_TRUE(without.feedbackSupply.dump);
  EXPECT_EQ(without.feedbackSupply.dump->path(), transitionDump());
  EXPECT_FALSE(without.feedbackSupply.servo.has_value()) << "a dump's feedback is the dump's, not a simulation's";
  FeedbackOffsets later = loadFeedback(*without.samples, without.feedbackSupply);
  expectSameFeedback(later, *with.samples);

  Trajectory samples = *without.samples;
  samples.attachFeedback(std::move(later));
  EXPECT_TRUE(samples.hasFeedback());
  EXPECT_EQ(samples.feedback(1000), with.samples->feedback(1000));
}

TEST(feedbackOnDemand, ADumpWithoutFeedbackHasNoneToLoad) {
  // The dump of a trace without encoder channels: x y z and line only.
  const std::string path = (scratchDir() / "commanded-only.biip").string();
  {
    const OpenedRun run = opened({sourcePath("samples/transition-surface.nc"), ""}, defaultMachine(), false);
    writeTrajectoryBiip(*run.samples, path);
  }
  const OpenedRun run = opened({"", path}, defaultMachine(), false);
  EXPECT_FALSE(run.feedbackSupply.available());
  try {
    loadFeedback(*run.samples, run.feedbackSupply);
    FAIL() << "no feedback to load";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no feedback"), std::string::npos) << e.what();
  }
  FeedbackSupply wrongFile;
  wrongFile.dump = std::make_shared<const BiipReader>(path);
  EXPECT_THROW(loadFeedback(*run.samples, wrongFile), InputError);
}

TEST(feedbackOnDemand, OffsetsOfAnotherLengthAreRefused) {
  const OpenedRun run = opened({sourcePath("samples/transition-surface.nc"), transitionDump()}, defaultMachine(), false);
  Trajectory samples = *run.samples;
  FeedbackOffsets shorter = loadFeedback(samples, run.feedbackSupply);
  for (std::vector<float>* axis : {&shorter.x, &shorter.y, &shorter.z}) axis->pop_back();
  EXPECT_THROW(samples.attachFeedback(std::move(shorter)), std::invalid_argument);
  EXPECT_FALSE(samples.hasFeedback());
  // A dump holding other records than the samples it is asked to complete.
  samples.x.pop_back();
  samples.y.pop_back();
  samples.z.pop_back();
  EXPECT_THROW(loadFeedback(samples, run.feedbackSupply), InputError);
}
