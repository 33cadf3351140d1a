// A re-optimised region in the application: the new run aligned to the old one pass by pass,
// its speed difference beside the old map, and the same in a headless snapshot.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/panels/inspector.h"
#include "test_support.h"
#include "image_compare.h"

using namespace isurface;
using namespace isurface::test;

namespace {

panels::GlHooks noContext() {
  return {[] {}, [] { return false; }};
}

// Mean absolute channel difference (0..255) over a rectangle of two images of the same size.
double meanDifferenceIn(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  double sum = 0;
  std::size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++n)
      for (int c = 0; c < 3; ++c) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
  return n ? sum / (3.0 * double(n)) : 0.0;
}

}  // namespace

TEST(optimiseDifferencePanel, TheRegionsPassesAreComparedWithTheirReplacements) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/transition-surface.nc"));
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.optimisedDifference(), nullptr);
  inspector.optimise(105, 400);
  inspector.waitUntilIdle();
  ASSERT_NE(inspector.optimisedDifference(), nullptr) << inspector.statusText();
  const RunComparison& d = *inspector.optimisedDifference();
  EXPECT_NE(inspector.statusText().find("The new passes lie within"), std::string::npos) << inspector.statusText();
  // Every line of the region the old run has is matched (a pass as one group), and the new
  // path stays on the old one.
  std::size_t regionLines = 0, comparedSamples = 0;
  for (const LineDifference& line : d.lines) {
    if (line.line < 105 || line.line > 400) continue;
    ++regionLines;
    comparedSamples += line.figures.comparedSamples;
    EXPECT_TRUE(std::isfinite(line.figures.maxSpeedDifference)) << "line " << line.line;
    EXPECT_LT(line.figures.maxPathDistance, 0.01) << "line " << line.line;  // mm
  }
  EXPECT_GT(regionLines, 3u);
  EXPECT_GT(comparedSamples, 1000u);
  for (const UnmatchedLine& u : d.onlyInA) EXPECT_FALSE(u.line >= 105 && u.line <= 400) << "line " << u.line;
  EXPECT_TRUE(d.onlyInB.empty());
  // The re-fitted passes run at other speeds: the difference is not all zero.
  double largest = 0;
  for (float v : d.speedDifference)
    if (std::isfinite(v)) largest = std::max(largest, double(std::abs(v)));
  EXPECT_GT(largest, 50.0);  // mm/min
  inspector.showOptimisedDifference(true);
  inspector.showOptimisedDifference(false);
  ASSERT_NE(inspector.optimisedDifference(), nullptr);

  // A failed optimisation keeps the last comparison and says why.
  inspector.optimise(1, 5);
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.statusText().rfind("error:", 0), 0u) << inspector.statusText();
  EXPECT_NE(inspector.optimisedDifference(), nullptr);
}

TEST(optimiseDifferencePanel, SnapshotShowsTheDifferenceInPlaceOfTheNewMap) {
  const std::string sideBySide = (scratchDir() / "optimise-side.png").string();
  const std::string difference = (scratchDir() / "optimise-difference.png").string();
  const std::string common = "ui-snapshot " + sourcePath("samples/transition-surface.nc") +
                             " --optimize-lines 105-400 --size 1280x800 -o ";
  const CommandResult a = runCli(common + sideBySide);
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const CommandResult b = runCli(common + difference + " --optimize-view difference");
  ASSERT_EQ(b.exitCode, 0) << b.err;
  const Image left = readPng(sideBySide), right = readPng(difference);
  ASSERT_EQ(left.width, 1280);
  ASSERT_EQ(right.width, 1280);
  // The window's layout puts the view beside the main one at 44-70 % of the width, under the
  // toolbar: there the speed map gives way to the difference map; the main view stays.
  EXPECT_GT(meanDifferenceIn(left, right, 600, 200, 880, 480), 10.0);
  EXPECT_LT(meanDifferenceIn(left, right, 260, 200, 540, 480), 1.0);

  EXPECT_EQ(runCli(common + difference + " --optimize-view sideways").exitCode, 2);
  EXPECT_EQ(runCli("ui-snapshot " + sourcePath("samples/transition-surface.nc") + " --optimize-view difference -o " +
                   (scratchDir() / "never.png").string())
                .exitCode,
            2);
  EXPECT_FALSE(fileExists((scratchDir() / "never.png").string()));
}
