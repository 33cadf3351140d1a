// The selection shared by the panels: samples, G-code lines and picked points kept in step.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "isurface/analysis/locate.h"
#include "isurface/app_model/selection.h"

using namespace isurface;
using namespace isurface::app_model;

namespace {

// Samples along X at x = index, produced by the given lines.
Trajectory trajectoryWithLines(const std::vector<std::uint32_t>& lines) {
  Trajectory t;
  t.hasLine = true;
  t.line = lines;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    t.time.push_back(0.001 * static_cast<double>(i));
    t.x.push_back(static_cast<double>(i));
    t.y.push_back(0);
    t.z.push_back(0);
  }
  return t;
}

// Lines 3 (samples 0-2), 5 (3-5), 3 again (6-7), unknown (8), 7 (9); line 4 has no sample.
Trajectory smallTrajectory() { return trajectoryWithLines({3, 3, 3, 5, 5, 5, 3, 3, 0, 7}); }

}  // namespace

TEST(selection, StartsEmpty) {
  SelectionModel model;
  EXPECT_EQ(model.trajectory(), nullptr);
  EXPECT_FALSE(model.current().sample);
  EXPECT_FALSE(model.current().line);
}

TEST(selection, SelectSampleSelectsItsLine) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  for (std::size_t k = 0; k < t.size(); ++k) {
    model.selectSample(k);
    ASSERT_EQ(model.current().sample, k);
    if (t.line[k] == 0)
      EXPECT_FALSE(model.current().line) << "sample " << k;
    else
      EXPECT_EQ(model.current().line, t.line[k]) << "sample " << k;
  }
}

TEST(selection, SelectSampleOutOfRangeIsIgnored) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  model.selectSample(4);
  const Selection before = model.current();
  model.selectSample(t.size());
  EXPECT_EQ(model.current().sample, before.sample);
  EXPECT_EQ(model.current().line, before.line);
  EXPECT_EQ(model.current().generation, before.generation);

  SelectionModel withoutSamples;
  withoutSamples.selectSample(0);
  EXPECT_FALSE(withoutSamples.current().sample);
  EXPECT_EQ(withoutSamples.current().generation, 0u);
}

TEST(selection, SelectLineGivesItsFirstSample) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  EXPECT_TRUE(model.selectLine(5));
  EXPECT_EQ(model.current().sample, 3u);
  EXPECT_EQ(model.current().line, 5u);
  EXPECT_TRUE(model.selectLine(3));
  EXPECT_EQ(model.current().sample, 0u);
  EXPECT_TRUE(model.selectLine(7));
  EXPECT_EQ(model.current().sample, 9u);
  // Agrees with the core's locate on every line, with and without samples.
  for (std::uint32_t line = 0; line <= 9; ++line) {
    const bool found = model.selectLine(line);
    EXPECT_EQ(found, firstSampleOfLine(t, line).has_value()) << "line " << line;
    EXPECT_EQ(model.current().sample, firstSampleOfLine(t, line)) << "line " << line;
    EXPECT_EQ(model.current().line, line);
  }
}

TEST(selection, SelectLineWithoutSamplesKeepsTheLineAndClearsTheSample) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  model.selectSample(2);
  EXPECT_FALSE(model.selectLine(4));
  EXPECT_EQ(model.current().line, 4u);
  EXPECT_FALSE(model.current().sample);
}

TEST(selection, SelectLineWithoutTrajectorySelectsTheLineAlone) {
  SelectionModel model;
  EXPECT_FALSE(model.selectLine(12));
  EXPECT_EQ(model.current().line, 12u);
  EXPECT_FALSE(model.current().sample);
  EXPECT_EQ(model.current().generation, 1u);
}

TEST(selection, SelectLineWithoutLineChannelFindsNothing) {
  Trajectory t = smallTrajectory();
  t.hasLine = false;
  t.line.assign(t.size(), 0u);
  SelectionModel model;
  model.setTrajectory(&t);
  EXPECT_FALSE(model.selectLine(0));
  EXPECT_FALSE(model.selectLine(3));
  EXPECT_FALSE(model.current().sample);
  model.selectSample(4);
  EXPECT_EQ(model.current().sample, 4u);
  EXPECT_FALSE(model.current().line);
}

TEST(selection, SelectNearestPicksTheClosestSample) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  EXPECT_TRUE(model.selectNearest(Vec3(4.2, 1.0, -0.5)));
  EXPECT_EQ(model.current().sample, 4u);
  EXPECT_EQ(model.current().line, 5u);
  EXPECT_TRUE(model.selectNearest(Vec3(100, 0, 0)));
  EXPECT_EQ(model.current().sample, 9u);
  EXPECT_EQ(model.current().line, 7u);
}

TEST(selection, SelectNearestWithoutSamplesChangesNothing) {
  SelectionModel model;
  EXPECT_FALSE(model.selectNearest(Vec3(0, 0, 0)));
  const Trajectory empty;
  model.setTrajectory(&empty);
  model.selectLine(2);
  const std::uint64_t generation = model.current().generation;
  EXPECT_FALSE(model.selectNearest(Vec3(0, 0, 0)));
  EXPECT_EQ(model.current().generation, generation);
  EXPECT_EQ(model.current().line, 2u);
}

TEST(selection, GenerationIncrementsOnEveryChange) {
  const Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  std::uint64_t generation = model.current().generation;
  model.selectSample(1);
  EXPECT_EQ(model.current().generation, ++generation);
  model.selectSample(1);  // the same again: panels scroll back to it
  EXPECT_EQ(model.current().generation, ++generation);
  model.selectLine(5);
  EXPECT_EQ(model.current().generation, ++generation);
  model.selectLine(4);
  EXPECT_EQ(model.current().generation, ++generation);
  model.selectNearest(Vec3(0, 0, 0));
  EXPECT_EQ(model.current().generation, ++generation);
  model.clear();
  EXPECT_EQ(model.current().generation, ++generation);
  EXPECT_FALSE(model.current().sample);
  EXPECT_FALSE(model.current().line);
}

TEST(selection, AnotherTrajectoryDropsTheSampleAndKeepsTheLine) {
  const Trajectory first = smallTrajectory();
  const Trajectory second = trajectoryWithLines({1, 5, 5});
  SelectionModel model;
  model.setTrajectory(&first);
  model.selectLine(5);
  const std::uint64_t generation = model.current().generation;
  model.setTrajectory(&second);
  EXPECT_EQ(model.trajectory(), &second);
  EXPECT_FALSE(model.current().sample);
  EXPECT_EQ(model.current().line, 5u);
  EXPECT_GT(model.current().generation, generation);
  EXPECT_TRUE(model.selectLine(5));
  EXPECT_EQ(model.current().sample, 1u);
}

TEST(selection, SettingTheTrajectoryAgainRebuildsTheLineIndex) {
  Trajectory t = smallTrajectory();
  SelectionModel model;
  model.setTrajectory(&t);
  EXPECT_TRUE(model.selectLine(5));
  EXPECT_EQ(model.current().sample, 3u);
  t.line = {5, 5, 3, 3, 3, 3, 3, 3, 3, 3};  // refilled in place
  model.setTrajectory(&t);
  EXPECT_TRUE(model.selectLine(5));
  EXPECT_EQ(model.current().sample, 0u);
  EXPECT_FALSE(model.selectLine(7));
}

TEST(selection, LargeTrajectoryAnswersEveryLineCorrectly) {
  // Two million samples; lines advance every few samples with gaps (lines without samples) and
  // a second pass revisits the first lines, as a finishing pass would.
  constexpr std::size_t kSamples = 2000000;
  std::vector<std::uint32_t> lines(kSamples);
  std::mt19937 random(7);
  std::uint32_t line = 10, maxLine = 0;
  std::size_t i = 0;
  while (i < kSamples) {
    const std::size_t run = 1 + random() % 12;
    for (std::size_t k = 0; k < run && i < kSamples; ++k) lines[i++] = line;
    maxLine = std::max(maxLine, line);
    line += 1 + random() % 3;
    if (i > kSamples * 3 / 4 && line > 2000) line = 10 + random() % 50;  // the revisit
  }
  const Trajectory t = trajectoryWithLines(lines);
  std::vector<std::optional<std::size_t>> expected(maxLine + 200);
  for (std::size_t s = 0; s < kSamples; ++s)
    if (lines[s] < expected.size() && !expected[lines[s]]) expected[lines[s]] = s;

  SelectionModel model;
  model.setTrajectory(&t);
  // The first look-up matches the core's scan; the rest use the index.
  ASSERT_EQ(model.selectLine(lines[kSamples / 2]), true);
  EXPECT_EQ(model.current().sample, firstSampleOfLine(t, lines[kSamples / 2]));
  std::size_t found = 0;
  for (int round = 0; round < 3; ++round) {
    for (std::uint32_t l = 0; l < expected.size(); ++l) {
      const bool hit = model.selectLine(l);
      ASSERT_EQ(hit, expected[l].has_value()) << "line " << l;
      ASSERT_EQ(model.current().sample, expected[l]) << "line " << l;
      found += hit;
    }
  }
  EXPECT_GT(found, 3u * 100000u);
  // Spot checks against the core on lines with and without samples.
  for (const std::uint32_t l : {10u, 11u, 12u, 57u, 1000u, 1001u, maxLine, maxLine + 5}) {
    model.selectLine(l);
    EXPECT_EQ(model.current().sample, firstSampleOfLine(t, l)) << "line " << l;
  }
}
