// What the window shows is what the map and the documents are: a document's dump is not
// replaced by a simulation, its warnings stay after the status line moves on, the Colour panel
// says the range of the map shown, and that range does not depend on the window's size.
#include <gtest/gtest.h>
#include <imgui.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"
#include "workflow_fixtures.h"

namespace isurface {
namespace {

using test::clickControl, test::settle, test::tap, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

constexpr int kWidth = 1280, kHeight = 800;

std::unique_ptr<panels::HeadlessUi> openedSample(int width = kWidth, int height = kHeight) {
  auto ui = std::make_unique<panels::HeadlessUi>(width, height, app_model::Settings{});
  settle(*ui);  // laid out first: the map is made for the view's size, as in the window
  ui->inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(*ui);
  return ui;
}

// A document that holds a dump (here a run of the program; a machine's recording alike) is not
// replaced by a simulation: the simulation opens beside it.
TEST(windowTruth, SimulatingADocumentWithADumpKeepsTheDump) {
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  const std::string dump = test::transitionDump();
  ui.inspector().open({test::sourcePath("samples/transition-surface.nc"), dump});
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u) << ui.inspector().statusText();
  tapLetter(ui, 'M');
  typeInto(ui, "machine.velocity.x", "1500");
  clickControl(ui, "machine.simulate");
  waitForJobs(ui);
  const nlohmann::json documents = described(ui)["documents"];
  ASSERT_EQ(documents.size(), 2u) << ui.inspector().statusText();
  EXPECT_EQ(documents[0]["dump"], dump);
  EXPECT_EQ(documents[1]["dump"], "");
  EXPECT_GT(documents[1]["duration_s"].get<double>(), documents[0]["duration_s"].get<double>());
}

// Every warning of every open document stays in the warnings window (W) after the status line
// has moved on, and one that names a line goes there.
TEST(windowTruth, WarningsAreKeptPerDocumentAndGoToTheirLine) {
  const std::filesystem::path program = test::scratchDir() / "inch-comment-raster.nc";
  {
    std::ofstream out(program);
    out << "(OUTPUT IN ABSOLUTE INCHES)\nG90 G17\nG0 X0 Y0 Z0.1\nG1 Z0 F40\n";
    for (int row = 0; row < 12; ++row)
      out << "G1 X" << (row % 2 ? 0 : 20) << " Y" << row << (row == 3 ? " F9991300" : "") << "\nG1 Y" << row + 1
          << (row == 3 ? " F40" : "") << "\n";
    out << "M2\n";
  }
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(program.string());
  waitForJobs(ui);
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 2u) << ui.inspector().statusText();
  EXPECT_EQ(ui.inspector().statusText().find("inches"), std::string::npos) << "the status has moved on";
  const nlohmann::json warnings = described(ui)["documents"][0]["warnings"];
  ASSERT_EQ(warnings.size(), 2u) << warnings;
  EXPECT_NE(warnings[0].get<std::string>().find("its comments speak of inches"), std::string::npos) << warnings;
  EXPECT_NE(warnings[1].get<std::string>().find(program.string() + ":11:"), std::string::npos) << warnings;
  tapLetter(ui, 'W');
  ASSERT_TRUE(described(ui)["windows"]["warnings"].get<bool>());
  clickControl(ui, "warnings.item:0:1");
  settle(ui);
  const nlohmann::json state = described(ui);
  EXPECT_EQ(state["active"], 0);
  EXPECT_EQ(state["selection"]["line"], 11);
}

// Enter in a field of the fixed range applies it; the Colour panel then shows the range of the
// map of whichever document is shown.
TEST(windowTruth, AFixedRangeIsAppliedByEnterAndFollowsTheDocumentShown) {
  auto ui = openedSample();
  clickControl(*ui, "range.fixed");
  waitForJobs(*ui);
  typeInto(*ui, "range.low", "2000");
  tap(*ui, ImGuiKey_Enter);
  waitForJobs(*ui);
  typeInto(*ui, "range.high", "2500");
  tap(*ui, ImGuiKey_Enter);
  waitForJobs(*ui);
  nlohmann::json map = described(*ui)["map"];
  EXPECT_DOUBLE_EQ(map["range"][0].get<double>(), 2000.0) << map;
  EXPECT_DOUBLE_EQ(map["range"][1].get<double>(), 2500.0) << map;
  // A second document, its map at 1-99 %.
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  clickControl(*ui, "range.percentile");
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["colour"]["range_mode"], 0);
  ui->inspector().showDocument(0);
  settle(*ui);
  const nlohmann::json colour = described(*ui)["colour"];
  EXPECT_EQ(colour["range_mode"], 2) << "the panel says what the map shown is: fixed";
  EXPECT_DOUBLE_EQ(colour["fixed"][1].get<double>(), 2500.0);
}

// A small window thins its map more than a large one: the 1-99 % range is still the same (it was
// 210 against 225 mm/min on this sample).
TEST(windowTruth, TheMapsRangeDoesNotDependOnTheWindowsSize) {
  // One window at a time: Dear ImGui has one context.
  const auto mapOf = [](int width, int height) { return described(*openedSample(width, height))["map"]; };
  const nlohmann::json small = mapOf(900, 640), large = mapOf(1800, 1200);
  EXPECT_EQ(small["range"], large["range"]) << small << "\n" << large;
}

}  // namespace
}  // namespace isurface
