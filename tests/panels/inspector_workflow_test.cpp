// The application's use of the workflow: files opened together, a dump joined only to its own
// program, re-optimisation with the document's machine and measured figures, and remembered
// settings that no longer fit.
#include <gtest/gtest.h>

#include <filesystem>

#include <cstdio>
#include <regex>

#include "isurface/panels/inspector.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

namespace {

panels::GlHooks noContext() {
  return {[] {}, [] { return false; }};
}

// "<label> A -> B" in a status line.
std::pair<double, double> figure(const std::string& status, const std::string& label) {
  std::smatch m;
  if (!std::regex_search(status, m, std::regex(label + " ([0-9.]+) -> ([0-9.]+)"))) return {-1, -1};
  return {std::stod(m[1]), std::stod(m[2])};
}

}  // namespace

TEST(inspectorWorkflow, AProgramAndItsDumpOpenedTogetherAreOneDocument) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  // Opened one right after the other, as the command line `isurface A.nc A.biip` does.
  inspector.open(sourcePath("samples/transition-surface.nc"));
  inspector.open(transitionDump());
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.documentCount(), 1u);
  // Named with its dump: the same program simulated beside it is told apart.
  const std::string name =
      "transition-surface.nc (" + std::filesystem::path(transitionDump()).filename().string() + "):";
  EXPECT_EQ(inspector.statusText().rfind(name, 0), 0u) << inspector.statusText();
}

TEST(inspectorWorkflow, ADumpOfAnotherProgramIsNotJoinedToTheOpenProgram) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/wuzhishan.nc"));
  inspector.waitUntilIdle();
  inspector.open(transitionDump());
  inspector.waitUntilIdle();
  // The program stays as it was; the dump opens by itself, saying why it was not joined.
  EXPECT_EQ(inspector.documentCount(), 2u);
  const std::string status = inspector.statusText();
  EXPECT_NE(status.find("not joined"), std::string::npos) << status;
  EXPECT_NE(status.find("wuzhishan.nc"), std::string::npos) << status;
  EXPECT_NE(status.find("transition-surface"), std::string::npos) << status;
}

TEST(inspectorWorkflow, AProgramGivenWithAnotherProgramsDumpOpensBothApart) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(std::vector<std::string>{sourcePath("samples/wuzhishan.nc"), transitionDump()});
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.documentCount(), 2u);
  // The program, simulated, is the last opened; its status keeps the reason in sight.
  EXPECT_EQ(inspector.statusText().rfind("wuzhishan.nc:", 0), 0u) << inspector.statusText();
  EXPECT_NE(inspector.statusText().find("not joined"), std::string::npos) << inspector.statusText();
}

TEST(inspectorWorkflow, OptimisingUsesTheMachineTheDocumentWasMadeWith) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/transition-surface.nc"));
  inspector.open(simulatedDump("transition-surface", slowMachine(), "slow"));
  inspector.waitUntilIdle();
  inspector.optimise(105, 400);
  inspector.waitUntilIdle();
  // Re-simulated on the default machine, the new program would take far less time than the
  // slow machine's run it is compared with.
  const auto [before, after] = figure(inspector.statusText(), "Machining time");
  ASSERT_GT(before, 0) << inspector.statusText();
  EXPECT_NEAR(after, before, 0.03 * before) << inspector.statusText();
}

TEST(inspectorWorkflow, ATypedRangeReportsTheRegionsFigures) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/transition-surface.nc"));
  inspector.waitUntilIdle();
  inspector.optimise(128, 184);  // one pass, typed
  inspector.waitUntilIdle();
  const auto [before, after] = figure(inspector.statusText(), "speed fluctuation");
  EXPECT_GT(before, 0) << inspector.statusText();
  EXPECT_GT(after, 0) << inspector.statusText();
}

TEST(inspectorWorkflow, OptimisingADumpWithoutItsProgramSaysWhy) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(transitionDump());
  inspector.waitUntilIdle();
  inspector.optimise(105, 400);
  inspector.waitUntilIdle();
  EXPECT_NE(inspector.statusText().find("needs the G-code program of"), std::string::npos) << inspector.statusText();
}

TEST(inspectorWorkflow, RememberedSettingsThatNoLongerFitDoNotBlockOpening) {
  app_model::Settings settings;
  settings.colorMap = "no-such-map";
  settings.quantity = "deviation";  // needs feedback
  // A dump without feedback.
  OpenRunRequest own;
  own.files = {"", transitionDump()};
  Trajectory samples = *openRun(own).samples;
  samples.fbOffsetX.clear(), samples.fbOffsetY.clear(), samples.fbOffsetZ.clear();
  const std::string noFeedback = (scratchDir() / "no-feedback.biip").string();
  writeTrajectoryBiip(samples, noFeedback);

  panels::Inspector inspector(noContext(), settings);
  EXPECT_NE(inspector.statusText().find("settings.json"), std::string::npos) << inspector.statusText();
  inspector.open(noFeedback);
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.documentCount(), 1u) << inspector.statusText();
  EXPECT_NE(inspector.statusText().rfind("error:", 0), 0u) << inspector.statusText();
}
