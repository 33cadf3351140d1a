// A re-optimised region in the application: the new run aligned to the old one pass by pass,
// its speed difference beside the old map. (The same in a headless snapshot:
// tests/cli/optimise_difference_panel_cli_test.cpp.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>

#include "isurface/panels/inspector.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

panels::GlHooks noContext() {
  return {[] {}, [] { return false; }};
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
  EXPECT_NE(inspector.statusText().find("Simulated, the tool runs within"), std::string::npos) << inspector.statusText();
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
  // The comparison still shown says it is the earlier one, of the lines it was made for.
  const nlohmann::json shown = nlohmann::json::parse(inspector.describe())["optimised"];
  EXPECT_EQ(shown["lines"], nlohmann::json::array({105, 400}));
  EXPECT_EQ(shown["superseded_by"], "optimising lines 1-5 failed");
}
