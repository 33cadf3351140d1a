// Playing a run: the selection moves on with the clock, at the speed chosen, from the selected
// sample, and stops at the end; a sample is found by its time on a regular or a recorded clock.
#include <gtest/gtest.h>

#include "isurface/app_model/playback.h"

using namespace isurface;
using namespace isurface::app_model;

namespace {

Trajectory samplesEvery(double cycle, std::size_t n) {
  Trajectory t;
  t.cycle = cycle;
  t.startTime = 5;
  for (std::size_t i = 0; i < n; ++i) t.x.push_back(double(i)), t.y.push_back(0), t.z.push_back(0);
  return t;
}

}  // namespace

TEST(playback, FindsTheSampleRunningAtATime) {
  const Trajectory regular = samplesEvery(0.001, 100);
  EXPECT_EQ(sampleAtTime(regular, 0), 0u);
  EXPECT_EQ(sampleAtTime(regular, 0.0105), 10u);
  EXPECT_EQ(sampleAtTime(regular, 0.010), 10u);
  EXPECT_EQ(sampleAtTime(regular, 99), 99u);
  EXPECT_EQ(sampleAtTime(regular, -1), 0u);
  Trajectory recorded = samplesEvery(0.001, 4);
  recorded.time = {1.0, 1.1, 1.5, 3.0};  // a recorder's irregular clock
  EXPECT_EQ(sampleAtTime(recorded, 0.45), 1u);
  EXPECT_EQ(sampleAtTime(recorded, 0.5), 2u);
  EXPECT_EQ(sampleAtTime(recorded, 5), 3u);
}

TEST(playback, MovesTheSelectionWithTheClockAndStopsAtTheEnd) {
  const Trajectory t = samplesEvery(0.001, 1000);
  SelectionModel selection;
  selection.setTrajectory(&t);
  selection.selectSample(100);
  Playback play;
  play.speed = 10;
  play.toggle(selection);
  ASSERT_TRUE(play.playing);
  play.advance(selection, 0.005);  // 50 ms of the run
  EXPECT_EQ(selection.current().sample, 150u);
  play.toggle(selection);  // pause: the clock moves nothing
  play.advance(selection, 1.0);
  EXPECT_EQ(selection.current().sample, 150u);
  play.toggle(selection);
  play.advance(selection, 10.0);
  EXPECT_EQ(selection.current().sample, 999u);
  EXPECT_FALSE(play.playing);
  play.toggle(selection);  // at the end: from the start again
  play.advance(selection, 0.0);
  EXPECT_EQ(selection.current().sample, 0u);
}
