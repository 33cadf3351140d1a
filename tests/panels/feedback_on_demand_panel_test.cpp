// The window opens a run without its servo positions and loads them the first time something
// shows them: a map by following error, the data bar's columns, a CSV export. What it shows
// then is what it shows when they were loaded with the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"
#include "workflow_fixtures.h"

using namespace isurface;
using test::clickControl, test::settle, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

std::unique_ptr<panels::HeadlessUi> opened(const std::vector<std::string>& files, const app_model::Settings& settings = {}) {
  auto ui = std::make_unique<panels::HeadlessUi>(kWidth, kHeight, settings);
  ui->inspector().open(files);
  waitForJobs(*ui);
  return ui;
}

}  // namespace

TEST(feedbackOnDemandPanel, AFollowingErrorMapLoadsTheFeedbackAndIsTheMapOfARunOpenedWithIt) {
  const std::string program = test::sourcePath("samples/transition-surface.nc");
  auto later = opened({program});
  EXPECT_EQ(described(*later)["documents"][0]["feedback"], "on request");
  later->inspector().colourBy("following_error");
  waitForJobs(*later);
  const nlohmann::json loaded = described(*later);
  EXPECT_EQ(loaded["documents"][0]["feedback"], "loaded") << later->inspector().statusText();
  EXPECT_EQ(loaded["map"]["quantity"], "Following error");
  later.reset();  // one window at a time

  app_model::Settings remembered;
  remembered.quantity = "following_error";  // opened with the feedback from the start
  auto atOnce = opened({program}, remembered);
  const nlohmann::json eager = described(*atOnce);
  EXPECT_EQ(eager["documents"][0]["feedback"], "loaded");
  EXPECT_EQ(eager["map"]["quantity"], "Following error");
  EXPECT_GT(eager["map"]["range"][1].get<double>(), 0.0);
  EXPECT_EQ(loaded["map"]["range"], eager["map"]["range"]);
  EXPECT_EQ(loaded["map"]["vertices"], eager["map"]["vertices"]);
}

TEST(feedbackOnDemandPanel, TheDataBarLoadsADumpsFeedbackOnRequest) {
  auto ui = opened({test::sourcePath("samples/transition-surface.nc"), test::transitionDump()});
  EXPECT_EQ(described(*ui)["documents"][0]["feedback"], "on request");
  clickControl(*ui, "data.feedback");
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["documents"][0]["feedback"], "loaded") << ui->inspector().statusText();
  EXPECT_NE(ui->inspector().statusText().find("feedback loaded"), std::string::npos) << ui->inspector().statusText();
}

TEST(feedbackOnDemandPanel, ACsvExportWaitsForTheFeedbackAndWritesItsColumns) {
  auto ui = opened({test::sourcePath("samples/transition-surface.nc"), test::transitionDump()});
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui);
  const std::filesystem::path csv = test::scratchDir() / "feedback-line-2000.csv";
  std::filesystem::remove(csv);
  tapLetter(*ui, 'E', true);
  clickControl(*ui, "export.csv");
  typeInto(*ui, "export.path", csv.string());
  clickControl(*ui, "export.write");
  waitForJobs(*ui);
  ASSERT_TRUE(std::filesystem::exists(csv)) << ui->inspector().statusText();
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find(",fb_x_mm,fb_y_mm,fb_z_mm"), std::string::npos) << header;
  EXPECT_EQ(described(*ui)["documents"][0]["feedback"], "loaded");
}
