// Comparing the application's document with a second run, through the inspector itself (its
// panels are only drawn by frame(), so no window is needed).
#include <gtest/gtest.h>

#include <fstream>

#include "dump_fixtures.h"
#include "isurface/panels/inspector.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

panels::GlHooks noContext() {
  return {[] {}, [] { return false; }};
}

// A raster of six 30 mm passes 1 mm apart at the given feed (mm/min).
std::string writeRaster(const std::string& name, int feed) {
  std::string text = "G21 G90 G64\nG1 X0 Y0 F" + std::to_string(feed) + "\n";
  for (int k = 0; k < 6; ++k)
    text += "G1 X" + std::to_string(k % 2 ? 0 : 30) + " Y" + std::to_string(k) + "\nG1 Y" + std::to_string(k + 1) + "\n";
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string simulated(const std::string& program, const std::string& name) {
  const std::string dump = (scratchDir() / name).string();
  EXPECT_TRUE(simulateToDump(program, dump));
  return dump;
}

}  // namespace

TEST(runComparisonPanel, aSecondRunStandsBesideTheDocumentWithItsDifferences) {
  const std::string program = writeRaster("raster.nc", 2000);
  panels::Inspector inspector(noContext(), app_model::Settings{});
  EXPECT_EQ(inspector.runComparison(), nullptr);
  inspector.open(program);
  inspector.waitUntilIdle();
  ASSERT_EQ(inspector.documentCount(), 1u);

  // The same program simulated on the same machine: nothing differs.
  inspector.compareWith(simulated(program, "same.biip"));
  inspector.waitUntilIdle();
  ASSERT_NE(inspector.runComparison(), nullptr) << inspector.statusText();
  EXPECT_EQ(inspector.runComparison()->total.timeDifference, 0.0);
  EXPECT_EQ(inspector.runComparison()->total.maxSpeedDifference, 0.0);
  EXPECT_NE(inspector.statusText().find("same.biip against this run"), std::string::npos) << inspector.statusText();

  // Its lines at half the feed: B takes longer and is slower, and the difference map shows it.
  const std::string slow = writeRaster("raster-slow.nc", 1000);
  inspector.compareWith(simulated(slow, "slow.biip"));
  inspector.waitUntilIdle();
  ASSERT_NE(inspector.runComparison(), nullptr);
  EXPECT_GT(inspector.runComparison()->total.timeDifference, 4.0);  // s: 186 mm at 1000 instead of 2000 mm/min
  EXPECT_LT(inspector.runComparison()->total.meanSpeedDifference, -500);
  inspector.showRunDifference(true);
  EXPECT_NE(inspector.runComparison(), nullptr);

  // A file that is no dump: an error in the status, the last comparison kept.
  inspector.compareWith(program);
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.statusText().rfind("error:", 0), 0u) << inspector.statusText();
  EXPECT_NE(inspector.statusText().find("raster.nc"), std::string::npos) << inspector.statusText();
  ASSERT_NE(inspector.runComparison(), nullptr);
  EXPECT_GT(inspector.runComparison()->total.timeDifference, 4.0);

  // Another document: the comparison belonged to the previous one.
  inspector.open(slow);
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.runComparison(), nullptr);
}

TEST(runComparisonPanel, comparingWithoutADocumentSaysWhatIsMissing) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.compareWith("/nonexistent/run.biip");
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.runComparison(), nullptr);
  EXPECT_NE(inspector.statusText().find("open a program or a dump first"), std::string::npos) << inspector.statusText();
}
